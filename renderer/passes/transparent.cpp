#include "renderer/passes/transparent.h"

#include <vector>

#include "renderer/gpu_scene/gpu_scene.h"
#include "renderer/passes/scene_draw.h"
#include "renderer/readback/host_readback.h"
#include "renderer/shader/compiler.h"
#include "renderer/vk/context.h"
#include "renderer/vk/functions.h"

namespace ds::passes {

using graph::Access;

TransparentPass::TransparentPass(const PassServices& services)
    : services_(services),
      drawing_(services, kName),
      rasterized_(services, kName),
      pipelines_([this](const Variant& v) { return compile(v); },
                 [this](const Variant& v, const ShaderStages& s) { return create(v, s); },
                 [](const Variant& v, const ShaderStages& s) {
                     return describe_pipeline(pipeline_name(v), s, /*alpha_to_coverage=*/false);
                 }) {
    pipelines_.get({.depth = services.preferred_depth_format});
}

void TransparentPass::rebuild_pipelines(vk::DestroyList& retired) {
    pipelines_.rebuild(retired);
    rasterized_.rebuild_pipelines(retired);
}

ShaderStages TransparentPass::compile(const Variant& v) const {
    std::vector<shader::Define> defines;
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
std::string TransparentPass::pipeline_name(const Variant& v) {
    std::string name = "transparent";
    if (v.counting) name += " counting";
    return name;
}

vk::Pipeline TransparentPass::create(const Variant& v, const ShaderStages& s) const {
    return scene_pipeline_builder(drawing_.layout(), s.vert, s.frag)
        .color_attachment(kHdrFormat, vk::Blend::Alpha)
        .depth_attachment(v.depth)
        .samples(v.samples)
        .build(services_.context, pipeline_name(v).c_str());
}

void TransparentPass::add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) {
    const Variant v{.counting = res.transparent_counts.valid(),
                    .samples = in.options.samples,
                    .depth = in.options.depth_format,
                    .count_draws = res.transparent_counts.draws.valid()};
    const VkPipeline pipeline = pipelines_.get(v);
    const PipelineInfo info = pipelines_.info(v);
    const VkPipelineLayout layout = drawing_.layout();
    uses_.clear();
    // msaa > 1: the samples are stored too, for the edge count (MsaaProbe) after the graph.
    drawing_.add(graph, kName, in, res, res.transparent_counts, /*resolve=*/true,
                 [this, pipeline, info, layout](VkCommandBuffer cmd, const FrameInputs& in) {
                     const std::vector<InstanceDraw> draws = sort_back_to_front(
                         *in.scene, in.camera_position, scene_groups(in.options.decal_pass));
                     vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
                     uses_.add(info, draw_sorted(cmd, *in.scene, layout, draws).draws);
                 });
    rasterized_.add(graph, in, res, res.transparent_counts,
                    {.samples = in.options.samples,
                     .modes = {scene::AlphaMode::Blend},
                     .decals = scene_groups(in.options.decal_pass)});
}

void TransparentPass::collect(const FrameCollect& c, std::span<PassResult> own, FrameResult&) {
    if (own.empty()) return;
    collect_counts(c.readback, c.res.transparent_counts, own[0]);
    own[0].pipelines = uses_.list();
}

}  // namespace ds::passes
