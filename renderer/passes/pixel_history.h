#pragma once
// Pixel history (issue 11 part 4), what the geometry passes share (a pass never includes
// another pass): with FrameInputs::pixel each of depth_prepass, forward, decals and
// transparent adds a replay graph pass right before its own (role history). The replay
// records the pass's own draws, through the pass's own drawing code, with instrumented
// variants of the pass's shaders (PIXEL_HISTORY=1, shaders/common/pixel_history.glsl): no
// depth attachment (so no depth test), a stand-in colour target, the scissor the one pixel, so
// every fragment that covers the pixel runs once and appends a record (instance, primitive, sample,
// gl_FragCoord.z, alpha and cutoff, the output colour, and the depth and colour the pass starts
// from there). After the fence the host sorts the records into submission order (draw, instance,
// primitive: the order Vulkan rasterizes in) and replays the pass's depth test, depth writes and
// blending on them in that order (simulate(), pure). Without a query nothing of this exists: no
// pass, no pipeline, no layout, no descriptor.
#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "renderer/common/surface_name.h"
#include "renderer/graph/graph.h"
#include "renderer/passes/frame.h"
#include "renderer/passes/frame_pass.h"
#include "renderer/passes/frame_result.h"
#include "renderer/passes/pass_util.h"
#include "renderer/passes/scene_draw.h"
#include "renderer/shader/compiler.h"
#include "renderer/vk/descriptors.h"
#include "renderer/vk/image.h"
#include "renderer/vk/pipeline.h"

namespace ds {

// pixel history (PixelQuery): one fragment that covered the pixel, as its pass's instrumented
// replay recorded it and the host's simulation of the pass's depth test and blending judged it
// (renderer/passes/pixel_history.h). Names come from the scene (Scene::instance_name).
struct PixelAlphaTest {
    float alpha = 0, cutoff = 0;
    bool passed = true;  // false: discarded
};
struct PixelFragment {
    std::string pass;      // the geometry pass ("depth_prepass", "forward", ...)
    std::string pipeline;  // the real pipeline that drew it (PipelineReport::name)
    uint32_t draw = 0;     // index of its draw in the pass's submission order
    uint32_t instance = 0, primitive = 0, sample = 0;
    float depth = 0;  // gl_FragCoord.z, as the depth format stores it
    bool depth_passed = false;
    float against = 0;  // the depth buffer's value when the fragment was tested
    std::optional<PixelAlphaTest> alpha_test;  // pipelines with an alpha test only
    bool shaded = false;  // the fragment shader ran in the real frame (early-Z: only if passed)
    std::optional<std::array<float, 4>> color;    // the shader's HDR output (not the prepass)
    std::optional<std::array<float, 4>> blended;  // blended passes: the colour after blending
};
struct PixelHistory {
    uint32_t x = 0, y = 0;
    std::vector<PixelFragment> fragments = {};  // submission order: pass, draw, instance, primitive
    uint64_t dropped = 0;  // records past a replay's buffer (then fragments are incomplete)
};

}  // namespace ds

namespace ds::passes {

// std430 twin of HistoryRecord in shaders/common/pixel_history.glsl.
struct HistoryRecord {
    uint32_t instance = 0, primitive = 0, sample = 0, flags = 0;
    float depth = 0, start_depth = 0, alpha = 0, cutoff = 0;
    std::array<float, 4> color{}, dst{};
};
static_assert(sizeof(HistoryRecord) == 64);
inline constexpr uint32_t kHistoryAlphaTested = 1u;
inline constexpr uint32_t kHistoryDiscarded = 2u;
inline constexpr uint32_t kHistoryColor = 4u;

// A real pipeline of the pass, as its fragments are judged: DrawLog::Draw::pipeline indexes
// these.
struct HistoryPipeline {
    std::string name;
    bool early_z = true;  // part 3's verdict "guaranteed": the shader runs only if the test passed
    bool blend = false;   // SRC_ALPHA / ONE_MINUS_SRC_ALPHA into the HDR image
};
HistoryPipeline history_pipeline(const PipelineInfo& info, bool blend = false);

// The pass's depth state, for the simulation.
struct HistoryRules {
    VkCompareOp compare = VK_COMPARE_OP_ALWAYS;
    bool depth_write = false;
    std::optional<float> clear_depth =
        std::nullopt;  // the pass clears first; none: the records' start_depth
    VkFormat depth_format = VK_FORMAT_D32_SFLOAT;
};

// Sorts `records` into submission order through `log` (records whose instance no draw of the
// log holds are dropped) and judges each in that order. Pure.
std::vector<PixelFragment> simulate(const char* pass, std::span<const HistoryRecord> records,
                                    const DrawLog& log, std::span<const HistoryPipeline> pipelines,
                                    const HistoryRules& rules);

class PixelHistoryReplay {
  public:
    static constexpr uint32_t kSet = 4;         // after every pass's own sets
    static constexpr uint32_t kCapacity = 512;  // records per pass and frame

    // `pass_sets`: the pass's pipeline layout's sets, which the replay layout repeats, so the
    // sets the pass's drawing code binds stay bound for the instrumented pipelines.
    PixelHistoryReplay(const PassServices& services, std::string pass,
                       std::vector<VkDescriptorSetLayout> pass_sets);

    // The instrumented pipelines' layout (created on first use).
    VkPipelineLayout layout() const;
    // An instrumented pipeline: the scene's vertex layout (the attributes `inputs` names: the
    // depth-only prepass's read fewer), the stand-in target, `samples`.
    vk::Pipeline create(const ShaderStages& stages, VkSampleCountFlagBits samples,
                        const std::string& name, VertexInputs inputs = VertexInputs::All) const;
    // The instrumented variant's fragment defines (the vertex stage takes PIXEL_HISTORY=1).
    static std::vector<shader::Define> defines(bool reads_depth, bool reads_dst, bool msaa);

    // Starts a frame: forgets the last one's records and draws.
    void clear();
    struct Reads {
        graph::ImageHandle depth = {};      // the depth the pass starts from (invalid: it clears)
        graph::ImageHandle dst = {};        // the HDR colour it draws over (invalid: none)
        graph::ImageHandle extent_of = {};  // an image of the frame's size (the scene depth)
    };
    using Declare = std::function<void(graph::PassBuilder&)>;
    using Draw = std::function<void(graph::PassContext&, DrawLog&)>;
    // Graph pass "<pass>_history" (role history) for in.pixel: declares its stand-in target,
    // its buffer, `reads` and what `declare` adds; records inside the rendering (one-pixel
    // scissor, depth test off, set 4 bound) `draw`, which binds and draws as the pass does.
    void add(graph::RenderGraph& graph, const FrameInputs& in, const Reads& reads,
             const Declare& declare, Draw draw);
    // After the fence: this frame's fragments, simulated, appended to frame.pixel_history.
    void collect(const FrameCollect& c, std::span<const HistoryPipeline> pipelines,
                 const HistoryRules& rules, FrameResult& frame) const;

  private:
    void record(graph::PassContext& ctx, const FrameInputs& in, const Reads& reads,
                graph::BufferHandle buffer, const Draw& draw);

    PassServices services_;
    std::string pass_;
    std::vector<VkDescriptorSetLayout> pass_sets_;
    // Created on first use (layout()): a frame without a query creates none of them.
    mutable vk::DescriptorSetLayout set_layout_;
    mutable vk::PipelineLayout layout_;
    mutable std::optional<FrameDescriptorPool> sets_;
    mutable vk::Sampler sampler_;
    mutable vk::Image unused_;    // bound where the variant reads no depth or colour
    graph::BufferHandle buffer_;  // this frame's records (invalid: no query)
    DrawLog log_;                 // what the replay drew, in order
};

}  // namespace ds::passes
