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
                 }) {}

ShaderStages DecalsPass::compile(const Variant& v) const {
    std::vector<shader::Define> defines = {{"ALPHA_MODE", std::to_string(int(v.mode))}};
    if (v.counting) add_count_defines(defines, services_.context);
    std::vector<shader::Define> vert_defines;
    if (v.count_draws) {
        vert_defines.push_back({"COUNT_DRAWS", "1"});
        defines.push_back({"COUNT_DRAWS", "1"});
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
    return name;
}

vk::Pipeline DecalsPass::create(const Variant& v, const ShaderStages& s) const {
    const float towards_camera = v.reverse_z ? 1.0f : -1.0f;
    return scene_pipeline_builder(drawing_.layout(), s.vert, s.frag)
        .color_attachment(kHdrFormat,
                          v.mode == AlphaMode::Blend ? vk::Blend::Alpha : vk::Blend::None)
        .depth_attachment(v.depth)
        .samples(v.samples)
        .depth_bias(towards_camera * kBiasSteps, towards_camera * kBiasSlope)
        .build(services_.context, pipeline_name(v).c_str());
}

void DecalsPass::add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) {
    uses_.clear();
    if (!in.options.decal_pass) return;
    struct Step {
        AlphaMode mode;
        VkPipeline pipeline;
        PipelineInfo info;
    };
    auto step = [&](AlphaMode mode) {
        const Variant v{.mode = mode,
                        .counting = res.decal_counts.valid(),
                        .reverse_z = in.options.reverse_z,
                        .samples = in.options.samples,
                        .depth = in.options.depth_format,
                        .count_draws = res.decal_counts.draws.valid()};
        return Step{mode, pipelines_.get(v), pipelines_.info(v)};
    };
    const std::array<Step, 3> order = {step(AlphaMode::Opaque), step(AlphaMode::Mask),
                                       step(AlphaMode::Blend)};
    const VkPipelineLayout layout = drawing_.layout();
    drawing_.add(graph, kName, in, res, res.decal_counts, /*resolve=*/false,
                 [this, order, layout](VkCommandBuffer cmd, const FrameInputs& in) {
                     for (const Step& s : order) {
                         vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, s.pipeline);
                         uses_.add(
                             s.info,
                             draw_groups(cmd, *in.scene, layout, {&s.mode, 1}, Decals::Only).draws);
                     }
                 });
    rasterized_.add(graph, in, res, res.decal_counts,
                    {.samples = in.options.samples,
                     .modes = {AlphaMode::Opaque, AlphaMode::Mask, AlphaMode::Blend},
                     .decals = Decals::Only});
}

void DecalsPass::collect(const FrameCollect& c, std::span<PassResult> own, FrameResult&) {
    if (own.empty()) return;
    collect_counts(c.readback, c.res.decal_counts, own[0]);
    own[0].pipelines = uses_.list();
}

}  // namespace ds::passes
