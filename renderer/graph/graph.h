#pragma once
// The render graph (DESIGN decisions 5-7), Filament-shaped: every frame, each pass is declared
// with a setup lambda (what it reads, writes, creates and renders to) and a record lambda (its
// commands). compile() keeps the declaration order (no reordering, no culling), gives
// graph-owned resources their images and buffers from a cache that persists across frames,
// and works out layouts, barriers and each graphics pass's rendering (plan.h, rendering.h,
// subpass.h). execute() records each pass inside a debug label, a timestamp pair and a
// pipeline-statistics query, with all its barriers in one vkCmdPipelineBarrier2; for a pass
// that renders it begins the dynamic rendering (or the render pass and subpass) and ends it,
// so a record lambda records draws only.
//
//   graph.begin_frame({width, height}, frame.retired);
//   const ImageHandle out = graph.import_image("result", {...});
//   struct Clear { ImageHandle colour; };
//   const Clear& clear = graph.add_pass<Clear>("clear",
//       [&](PassBuilder& b, Clear& d) {
//           d.colour = b.create_image("colour", {.format = VK_FORMAT_R8G8B8A8_UNORM,
//                                                .size = ImageSize::relative(1.0f),
//                                                .semantic = Semantic::LdrColor});
//           b.color(d.colour, {.load = Load::Clear, .clear = {{0, 0, 0, 1}}});
//       },
//       [](PassContext& ctx, const Clear& d) { /* draws, with pipelines for ctx.target() */ });
//   struct Blit { ImageHandle source; };
//   graph.add_pass<Blit>({"blit", PassKind::Transfer},
//       [&](PassBuilder& b, Blit& d) {
//           d.source = b.read(clear.colour, Access::TransferSrc);
//           b.write(out, Access::TransferDst);
//       },
//       [out](PassContext& ctx, const Blit& d) { ... ctx.layout(d.source) ... });
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
#include "renderer/graph/rendering.h"
#include "renderer/graph/subpass.h"
#include "renderer/graph/types.h"

namespace ds::vk {
class Context;
}

namespace ds::graph {

class RenderGraph;

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
    // write() only writing ones; buffer-only kinds never apply to images and vice versa; an
    // attachment is declared with color() / depth() / resolve() / input() instead.
    ImageHandle read(ImageHandle image, Access access, Shader shader = Shader::Default);
    ImageHandle write(ImageHandle image, Access access, Shader shader = Shader::Default);
    BufferHandle read(BufferHandle buffer, Access access, Shader shader = Shader::Default);
    BufferHandle write(BufferHandle buffer, Access access, Shader shader = Shader::Default);

    // A graphics pass's attachments (rendering.h): the graph begins the rendering with them,
    // colour attachments in the order declared, and ends it after the record lambda.
    ImageHandle color(ImageHandle image, const ColorUse& use = {});
    // A colour slot without an image: what the fragment shader writes there is dropped (its
    // alpha still makes alpha-to-coverage's mask). Pipelines see `format` in that slot.
    void unused_color(VkFormat format);
    ImageHandle depth(ImageHandle image, const DepthUse& use = {});
    // `into` receives the resolve of attachment `from` (colour or depth) when the rendering
    // ends. Inside a subpass group a colour resolve becomes the subpass's resolve attachment.
    ImageHandle resolve(ImageHandle from, ImageHandle into,
                        VkResolveModeFlagBits mode = VK_RESOLVE_MODE_AVERAGE_BIT);
    // Read at the fragment's own pixel (subpassLoad): only inside a subpass group, which the
    // graph plans where the frame asked for one (RenderGraph::plan_subpasses).
    ImageHandle input(ImageHandle image);
    // Rendering without attachments, over `extent` (the fragments only write storage).
    void render_area(VkExtent2D extent);
    // A VkRenderPass of its own (one subpass) rather than dynamic rendering: for pipelines
    // made for render passes (Dear ImGui 1.86's).
    void render_pass();
    // Commands recorded before the rendering begins (inside a subpass group: before the render
    // pass), for what Vulkan forbids inside one (query pool resets).
    void outside_rendering(std::function<void(VkCommandBuffer)> record);

    VkExtent2D output_extent() const;
    VkExtent2D extent(ImageHandle image) const;

  private:
    friend class RenderGraph;
    PassBuilder(RenderGraph& graph, uint32_t pass) : graph_(graph), pass_(pass) {}
    void declare(uint32_t resource, bool image, Access access, Shader shader, bool write);
    PassInfo& attaching(const char* what);

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
    // What this pass renders into, for its pipelines (rendering.h): the declared formats, or
    // inside a subpass group the render pass and subpass.
    const RenderTarget& target() const;  // planned at compile()

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
    void bind_import(ImageHandle image, VkImage handle, VkImageView view,
                     VkImageView attachment_view = VK_NULL_HANDLE);
    // render_path=subpass: runs of graphics passes that share a depth attachment are planned
    // as the subpasses of one render pass named `group` (subpass.h); empty (begin_frame()'s
    // default): every pass renders on its own.
    void plan_subpasses(std::string group);

    // The one form (Filament's): `setup` runs now and fills a Data with what it declared;
    // `record` runs in execute() and gets the Data back. The Data lives until the next
    // begin_frame(), so later passes may read its handles. `decl` names the pass and gives its
    // kind and role (a string alone: a graphics pass of the frame's own work).
    template <typename Data, typename SetupFn, typename RecordFn>
    const Data& add_pass(const PassDecl& decl, SetupFn&& setup, RecordFn&& record);

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
        // What renderings attach (vk::Image::attachment_view); null: `view`.
        VkImageView attachment_view = VK_NULL_HANDLE;
        VkImageView attached() const { return attachment_view ? attachment_view : view; }
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
    PassBuilder begin_pass(const PassDecl& decl);
    void record_pass(VkCommandBuffer cmd, uint32_t pass);
    void begin_rendering(VkCommandBuffer cmd, uint32_t pass) const;
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
    std::string subpass_group_;  // plan_subpasses()

    // The frame being declared / compiled.
    std::vector<ResourceInfo> resources_;
    std::vector<Binding> bindings_;
    std::vector<PassInfo> passes_;
    std::vector<Record> records_;
    std::vector<std::vector<std::function<void(VkCommandBuffer)>>> prologues_;  // per pass
    std::vector<RenderingPlan> renderings_;  // per pass, after compile(): passes outside groups
    std::vector<RenderTarget> targets_;      // per pass, after compile(): what pipelines meet
    std::vector<HistoryRequest> histories_;
    std::vector<std::shared_ptr<void>> pass_data_;  // add_pass<Data>'s, until begin_frame()
    BarrierPlan plan_;
    std::vector<GroupPlan> groups_;
    std::vector<VkRenderPass> group_passes_;  // per group
};

std::ostream& operator<<(std::ostream& out, const RenderGraph& graph);

template <typename Data, typename SetupFn, typename RecordFn>
const Data& RenderGraph::add_pass(const PassDecl& decl, SetupFn&& setup, RecordFn&& record) {
    auto data = std::make_shared<Data>();
    pass_data_.push_back(data);
    PassBuilder builder = begin_pass(decl);
    setup(builder, *data);
    records_.back() = [data, record = std::forward<RecordFn>(record)](PassContext& ctx) {
        record(ctx, *data);
    };
    return *data;
}

}  // namespace ds::graph
