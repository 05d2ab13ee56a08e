#pragma once
// The render graph (DESIGN decisions 5-7), Filament-shaped: every frame, each pass is declared
// with a setup lambda (what it reads, writes and creates) and a record lambda (its commands).
// compile() keeps the declaration order (no reordering, no culling), gives graph-owned
// resources their images and buffers from a cache that persists across frames, and works out
// layouts and barriers (plan.h). execute() records each pass inside a debug label, a timestamp
// pair and a pipeline-statistics query, with all its barriers in one vkCmdPipelineBarrier2.
//
//   graph.begin_frame({width, height}, frame.retired);
//   const ImageHandle out = graph.import_image("result", {...});
//   struct Clear { ImageHandle colour; };
//   const Clear& clear = graph.add_pass<Clear>("clear",
//       [&](PassBuilder& b, Clear& d) {
//           d.colour = b.create_image("colour", {.format = VK_FORMAT_R8G8B8A8_UNORM,
//                                                .size = ImageSize::relative(1.0f),
//                                                .semantic = Semantic::LdrColor});
//           b.write(d.colour, Access::ColorAttachment);
//       },
//       [](PassContext& ctx, const Clear& d) { /* begin rendering on ctx.view(d.colour) */ });
//   graph.add_pass("blit", [&](PassBuilder& b) {
//       b.read(clear.colour, Access::Sampled);
//       b.write(out, Access::ColorAttachment);
//       return [source = clear.colour, out](PassContext& ctx) { ... ctx.layout(source) ... };
//   });
//   graph.compile();
//   const uint64_t id = graph.execute(frame.cmd);
//   ... submit, wait for the fence ...
//   for (const PassResult& r : graph.collect(id)) ...
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <vulkan/vulkan.h>
#include <nlohmann/json_fwd.hpp>

#include "renderer/graph/access.h"
#include "renderer/graph/cache.h"
#include "renderer/graph/plan.h"
#include "renderer/graph/profiler.h"
#include "renderer/graph/render_pass.h"
#include "renderer/graph/subpass.h"
#include "renderer/graph/types.h"

namespace ds::vk {
class Context;
}

namespace ds::graph {

class RenderGraph;

// The render pass and subpass a pass records in (render_path=subpass); empty: its own
// rendering. Pipeline variants keep both: a pipeline is made for one subpass.
struct SubpassTarget {
    VkRenderPass pass = VK_NULL_HANDLE;
    uint32_t index = 0;
    explicit operator bool() const { return pass != VK_NULL_HANDLE; }
    bool operator==(const SubpassTarget&) const = default;
};

// "Read previous, write current": a temporal pass samples `previous` (last frame's `current`)
// and writes `current`; at the end of the frame the two swap. PassContext::history_valid()
// says whether `previous` holds anything (not after a resize or invalidate_history()).
struct HistoryImage {
    ImageHandle previous;
    ImageHandle current;
};

class PassBuilder {
  public:
    ImageHandle create_image(const std::string& name, const ImageDesc& desc);
    HistoryImage create_history(const std::string& name, const ImageDesc& desc);
    BufferHandle create_buffer(const std::string& name, const BufferDesc& desc);

    // Throw ds::Error when the access kind does not fit: read() takes only reading kinds,
    // write() only writing ones; buffer-only kinds never apply to images and vice versa.
    ImageHandle read(ImageHandle image, Access access, Shader shader = Shader::Default);
    ImageHandle write(ImageHandle image, Access access, Shader shader = Shader::Default);
    BufferHandle read(BufferHandle buffer, Access access, Shader shader = Shader::Default);
    BufferHandle write(BufferHandle buffer, Access access, Shader shader = Shader::Default);

    // This pass is subpass `index` of render pass `group` (graph/subpass.h): the graph begins
    // the render pass before the group's first pass, steps subpasses and ends it after the
    // last; the pass records draws only, with pipelines made for PassContext::subpass_target().
    // Call first, before declaring accesses.
    void subpass(const std::string& group, uint32_t index);
    // In a subpass: the attachment's LOAD_OP_CLEAR value (a render pass clears on load).
    void clear(ImageHandle image, const VkClearValue& value);

    VkExtent2D output_extent() const;
    VkExtent2D extent(ImageHandle image) const;

  private:
    friend class RenderGraph;
    PassBuilder(RenderGraph& graph, uint32_t pass) : graph_(graph), pass_(pass) {}
    void declare(uint32_t resource, bool image, Access access, Shader shader, bool write);

    RenderGraph& graph_;
    uint32_t pass_;
};

class PassContext {
  public:
    VkCommandBuffer cmd() const { return cmd_; }
    const std::string& pass_name() const;

    // Throw ds::Error for a resource this pass did not declare: what it touches undeclared
    // would get no barrier.
    VkImage image(ImageHandle image) const;
    VkImageView view(ImageHandle image) const;
    VkImageLayout layout(ImageHandle image) const;  // during this pass (descriptor writes)
    VkBuffer buffer(BufferHandle buffer) const;

    VkExtent2D extent(ImageHandle image) const;
    VkFormat format(ImageHandle image) const;
    VkDeviceSize size(BufferHandle buffer) const;
    bool history_valid(const HistoryImage& history) const;
    // Inside a subpass group: its VkRenderPass (pipelines are made for it) and this pass's
    // subpass index; an empty target for a pass on its own (dynamic rendering).
    SubpassTarget subpass_target() const;

    // A dependency between two steps inside this pass (two dispatches, where the second reads
    // what the first wrote), in the graph's terms: `before` and `after` must both be declared
    // on `image`; the barrier keeps the pass's layout. Passes record no barrier themselves.
    void dependency(ImageHandle image, Access before, Access after) const;

  private:
    friend class RenderGraph;
    PassContext(const RenderGraph& graph, uint32_t pass, VkCommandBuffer cmd)
        : graph_(graph), pass_(pass), cmd_(cmd) {}
    const PassUse& use(uint32_t resource) const;

    const RenderGraph& graph_;
    uint32_t pass_;
    VkCommandBuffer cmd_;
};

class RenderGraph {
  public:
    using Setup = std::function<void(PassBuilder&)>;
    using Record = std::function<void(PassContext&)>;

    explicit RenderGraph(vk::Context& context);
    ~RenderGraph();  // destroys cached images at once: the device must be idle
    RenderGraph(const RenderGraph&) = delete;
    RenderGraph& operator=(const RenderGraph&) = delete;

    // Starts declaring a frame. Images replaced during it go to `retired` (an earlier frame
    // may still use them). A new output size invalidates every history.
    void begin_frame(VkExtent2D output, vk::DestroyList& retired);
    ImageHandle import_image(const std::string& name, const ExternalImage& image);
    BufferHandle import_buffer(const std::string& name, const ExternalBuffer& buffer);
    // An image imported before it existed (null handles: the frame's targets, made once the
    // frame's memory estimate passed) gets its handles here, before compile().
    void bind_import(ImageHandle image, VkImage handle, VkImageView view);
    // The role of the passes added from now on (begin_frame() resets it to Frame).
    void set_role(PassRole role) { role_ = role; }

    // `setup` runs now; `record` runs in execute(). Beware: `record` is built before `setup`
    // runs, so a handle it captures by value is the one from before setup assigned it
    // (invalid). Capture by reference, or use one of the two forms below.
    void add_pass(const std::string& name, const Setup& setup, Record record,
                  PassKind kind = PassKind::Graphics);
    // `setup` declares and returns the record lambda, which captures the handles by value:
    //   graph.add_pass("gtao", [&](PassBuilder& b) {
    //       const ImageHandle ao = b.create_image(...);
    //       b.write(ao, Access::StorageWrite);
    //       return [=](PassContext& ctx) { ... ctx.view(ao) ... };
    //   }, PassKind::Compute);
    using SetupRecord = std::function<Record(PassBuilder&)>;
    void add_pass(const std::string& name, const SetupRecord& setup,
                  PassKind kind = PassKind::Graphics);
    // Filament's form: setup fills a Data, record gets it back; the Data lives until the next
    // begin_frame(), so later passes may read its handles.
    template <typename Data, typename SetupFn, typename RecordFn>
    const Data& add_pass(const std::string& name, SetupFn&& setup, RecordFn&& record,
                         PassKind kind = PassKind::Graphics);

    void compile();
    uint64_t execute(VkCommandBuffer cmd);  // returns the id collect() takes
    // Per-pass results of frame `id`, in execution order; call after that frame's fence.
    std::vector<PassResult> collect(uint64_t id) const;

    // A camera cut: temporal passes must not blend with the previous frame.
    void invalidate_history();

    // The compiled frame, for dump(), the inspector and the capture layer.
    std::string dump() const;
    nlohmann::json dump_json() const;  // graph/dump_json.h
    VkExtent2D output_extent() const { return output_; }
    std::span<const ResourceInfo> resources() const { return resources_; }
    std::span<const PassInfo> passes() const { return passes_; }
    const BarrierPlan& plan() const { return plan_; }
    // The frame's subpass groups (render passes), after compile().
    std::span<const GroupPlan> subpass_groups() const { return groups_; }
    // A graph-owned image in LAZILY_ALLOCATED memory (a transient attachment, where the
    // device has such memory); after compile().
    bool lazily_allocated(ImageHandle image) const;
    ImageHandle find_image(std::string_view name) const;  // invalid handle when none
    VkImage image(ImageHandle image) const;               // after compile()
    VkImageView view(ImageHandle image) const;
    VkBuffer buffer(BufferHandle buffer) const;
    bool has_timestamps() const { return profiler_.has_timestamps(); }
    bool has_statistics() const { return profiler_.has_statistics(); }
    uint64_t images_created() const { return cache_.images_created(); }

  private:
    friend class PassBuilder;
    friend class PassContext;

    struct Binding {  // what a resource resolves to this frame
        VkImage image = VK_NULL_HANDLE;
        VkImageView view = VK_NULL_HANDLE;
        VkBuffer buffer = VK_NULL_HANDLE;
        ResourceState* persistent = nullptr;  // graph-owned: where the end state goes
        bool lazily_allocated = false;
    };
    struct HistoryRequest {
        std::string name;
        uint32_t previous, current;  // resource indices
        HistoryPair* pair = nullptr;
    };

    uint32_t add_resource(ResourceInfo info);
    const ResourceInfo& resource(uint32_t index, bool image, const char* what) const;
    void require_declaring(const char* what) const;
    void realize_resources();
    void realize_history(HistoryRequest& request);
    void record_barriers(VkCommandBuffer cmd, std::span<const Barrier> barriers) const;
    void record_pass(VkCommandBuffer cmd, uint32_t pass);
    void execute_group(VkCommandBuffer cmd, uint32_t group);
    VkRenderPass render_pass_of(uint32_t pass) const;
    void commit_states();

    vk::Context& context_;
    ResourceCache cache_;
    PassProfiler profiler_;
    RenderPassCache render_passes_;
    vk::DestroyList* retired_ = nullptr;
    VkExtent2D output_{0, 0};
    uint64_t frames_ = 0;
    enum class Phase : uint8_t { Idle, Declaring, Compiled, Executed } phase_ = Phase::Idle;
    PassRole role_ = PassRole::Frame;

    // The frame being declared / compiled.
    std::vector<ResourceInfo> resources_;
    std::vector<Binding> bindings_;
    std::vector<PassInfo> passes_;
    std::vector<Record> records_;
    std::vector<HistoryRequest> histories_;
    std::vector<std::shared_ptr<void>> pass_data_;  // add_pass<Data>'s, until begin_frame()
    BarrierPlan plan_;
    std::vector<GroupPlan> groups_;
    std::vector<VkRenderPass> group_passes_;  // per group
};

std::ostream& operator<<(std::ostream& out, const RenderGraph& graph);

template <typename Data, typename SetupFn, typename RecordFn>
const Data& RenderGraph::add_pass(const std::string& name, SetupFn&& setup, RecordFn&& record,
                                  PassKind kind) {
    auto data = std::make_shared<Data>();
    pass_data_.push_back(data);
    add_pass(
        name, [&](PassBuilder& builder) { setup(builder, *data); },
        [data, record = std::forward<RecordFn>(record)](PassContext& ctx) { record(ctx, *data); },
        kind);
    return *data;
}

}  // namespace ds::graph
