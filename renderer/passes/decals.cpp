#include "renderer/passes/decals.h"

#include <array>
#include <vector>

#include "renderer/gpu_scene/gpu_scene.h"
#include "renderer/passes/scene_draw.h"
#include "renderer/readback/host_readback.h"
#include "renderer/shader/compiler.h"
#include "renderer/vk/context.h"
#include "renderer/vk/functions.h"

namespace ds::passes {

using scene::AlphaMode;

namespace {

// Towards the camera: 4 steps of the depth format plus one pixel's depth slope.
constexpr float kBiasSteps = 4.0f;
constexpr float kBiasSlope = 1.0f;

}  // namespace

DecalsPass::DecalsPass(const PassServices& services)
    : services_(services),
      drawing_(services, kName),
      rasterized_(services, kName),
      pipelines_([this](const Variant& v) { return compile(v); },
                 [this](const Variant& v, const ShaderStages& s) { return create(v, s); },
                 [](const Variant& v, const ShaderStages& s) {
                     return describe_pipeline(pipeline_name(v), s, /*alpha_to_coverage=*/false);
                 }),
      history_(services, kName, drawing_.set_layouts()) {}

ShaderStages DecalsPass::compile(const Variant& v) const {
    std::vector<shader::Define> defines = {{"ALPHA_MODE", std::to_string(int(v.mode))}};
    std::vector<shader::Define> vert_defines;
    if (v.counting) add_count_defines(defines, vert_defines, services_.context, v.count_draws);
    if (v.history) {
        for (shader::Define& d :
             PixelHistoryReplay::defines(true, true, v.samples != VK_SAMPLE_COUNT_1_BIT))
            defines.push_back(std::move(d));
        vert_defines.push_back({"PIXEL_HISTORY", "1"});
    }
    return {
        services_.compiler.compile("transparent.vert", shader::Stage::Vertex, vert_defines).spirv,
        services_.compiler.compile("transparent.frag", shader::Stage::Fragment, defines).spirv};
}

// Distinct for every variant one frame can use (counting changes the fragment shader).
std::string DecalsPass::pipeline_name(const Variant& v) {
    std::string name = v.mode == AlphaMode::Opaque ? "decals opaque"
                       : v.mode == AlphaMode::Mask ? "decals mask"
                                                   : "decals blend";
    if (v.counting) name += " counting";
    if (v.history) name += " history";
    return name;
}

vk::Pipeline DecalsPass::create(const Variant& v, const ShaderStages& s) const {
    if (v.history) return history_.create(s, v.samples, pipeline_name(v));
    const float towards_camera = v.reverse_z ? 1.0f : -1.0f;
    vk::GraphicsPipelineBuilder b = scene_pipeline_builder(drawing_.layout(), s.vert, s.frag);
    if (v.render_pass) b.render_pass(v.render_pass, v.subpass);
    return b
        .color_attachment(kHdrFormat,
                          v.mode == AlphaMode::Blend ? vk::Blend::Alpha : vk::Blend::None)
        .depth_attachment(v.depth)
        .samples(v.samples)
        .depth_bias(towards_camera * kBiasSteps, towards_camera * kBiasSlope)
        .build(services_.context, pipeline_name(v).c_str());
}

std::vector<SettingDef> DecalsPass::knobs() {
    return {bool_knob(kKnob, "passes", true,
                      "coplanar overlays (classified at load: triangles lying on another surface "
                      "and inside it) skip shadow, prepass and forward and are drawn once by the "
                      "decals pass after forward; off: drawn like any surface (they Z-fight)",
                      Invalidates::Nothing)};
}

// The other geometry passes leave decal groups to this one when it runs (scene_groups).
void DecalsPass::configure(const FrameSetup& setup, FrameOptions& o) {
    o.decal_pass = knob_value(setup.settings, kKnob) && setup.scene.decal_groups() > 0;
}

void DecalsPass::add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) {
    uses_.clear();
    history_.clear();
    if (!in.options.decal_pass) return;
    struct Step {
        AlphaMode mode;
        Variant variant;  // its pipeline: for the render pass drawn in (none: own rendering)
        PipelineInfo info;
    };
    using Steps = std::array<Step, 3>;
    auto step = [&](AlphaMode mode, bool history) {
        const Variant v{.mode = mode,
                        .counting = res.decal_counts.valid() && !history,
                        .reverse_z = in.options.reverse_z,
                        .history = history,
                        .samples = in.options.samples,
                        .depth = in.options.depth_format,
                        .count_draws = res.decal_counts.draws.valid()};
        pipelines_.get(v);  // built now (a replay's also sets the replay's descriptors up)
        return Step{mode, v, pipelines_.info(v)};
    };
    auto steps = [&](bool history) {
        return Steps{step(AlphaMode::Opaque, history), step(AlphaMode::Mask, history),
                     step(AlphaMode::Blend, history)};
    };
    // Opaque, MASK, BLEND overlays in authored order; the log's tag is the step.
    auto draw_with = [this](Steps order, PipelineUses* uses) {
        return
            [this, order, uses](VkCommandBuffer cmd, const FrameInputs& in, VkPipelineLayout layout,
                                DrawLog* log, graph::SubpassTarget target) {
                for (uint32_t i = 0; i < order.size(); ++i) {
                    const Step& s = order[i];
                    Variant v = s.variant;
                    v.render_pass = target.pass;
                    v.subpass = target.index;
                    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_.get(v));
                    if (log) log->pipeline = i;
                    const DrawCounts n = draw_groups(cmd, *in.scene, layout, {&s.mode, 1},
                                                     Decals::Only, std::nullopt, {.log = log});
                    if (uses) uses->add(s.info, n.draws);
                }
            };
    };
    const Steps order = steps(false);
    if (in.pixel && !in.options.subpass) {  // a replay would split the render pass
        history_pipelines_.clear();
        for (const Step& s : order)
            history_pipelines_.push_back(history_pipeline(s.info, s.mode == AlphaMode::Blend));
        drawing_.add_history(graph, in, res, history_, draw_with(steps(true), nullptr));
    }
    drawing_.add(graph, kName, in, res, res.decal_counts, /*resolve=*/false,
                 draw_with(order, &uses_));
    rasterized_.add(graph, in, res, res.decal_counts,
                    {.samples = in.options.samples,
                     .modes = {AlphaMode::Opaque, AlphaMode::Mask, AlphaMode::Blend},
                     .decals = Decals::Only});
}

void DecalsPass::collect(const FrameCollect& c, std::span<PassResult> own, FrameResult& frame) {
    PassResult* const own_pass = frame_result(own);
    if (!own_pass) return;
    collect_counts(c.readback, c.res.decal_counts, *own_pass);
    own_pass->pipelines = uses_.list();
    // Against the scene depth, closer-or-equal, no writes (the bias: decals.h).
    history_.collect(
        c, history_pipelines_,
        {.compare = c.in.options.closer_or_equal(), .depth_format = c.in.options.depth_format},
        frame);
}

}  // namespace ds::passes
