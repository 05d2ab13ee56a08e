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
                 }),
      history_(services, kName, drawing_.set_layouts()) {
    pipelines_.get({.depth = services.preferred_depth_format});
}

void TransparentPass::rebuild_pipelines(vk::DestroyList& retired) {
    pipelines_.rebuild(retired);
    rasterized_.rebuild_pipelines(retired);
}

ShaderStages TransparentPass::compile(const Variant& v) const {
    std::vector<shader::Define> defines, vert_defines;
    if (v.counting) add_count_defines(defines, vert_defines, services_.context, v.count_draws);
    if (v.history) {
        defines = PixelHistoryReplay::defines(true, true, v.samples != VK_SAMPLE_COUNT_1_BIT);
        vert_defines.push_back({"PIXEL_HISTORY", "1"});
    }
    return {
        services_.compiler.compile("transparent.vert", shader::Stage::Vertex, vert_defines).spirv,
        services_.compiler.compile("transparent.frag", shader::Stage::Fragment, defines).spirv};
}

// Distinct for every variant one frame can use (counting changes the fragment shader).
std::string TransparentPass::pipeline_name(const Variant& v) {
    std::string name = "transparent";
    if (v.counting) name += " counting";
    if (v.history) name += " history";
    return name;
}

vk::Pipeline TransparentPass::create(const Variant& v, const ShaderStages& s) const {
    if (v.history) return history_.create(s, v.samples, pipeline_name(v));
    vk::GraphicsPipelineBuilder b = scene_pipeline_builder(drawing_.layout(), s.vert, s.frag);
    if (v.render_pass) b.render_pass(v.render_pass, v.subpass);
    return b.color_attachment(kHdrFormat, vk::Blend::Alpha)
        .depth_attachment(v.depth)
        .samples(v.samples)
        .build(services_.context, pipeline_name(v).c_str());
}

void TransparentPass::add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) {
    const Variant v{.counting = res.transparent_counts.valid(),
                    .samples = in.options.samples,
                    .depth = in.options.depth_format,
                    .count_draws = res.transparent_counts.draws.valid()};
    const PipelineInfo info = pipelines_.info(v);
    uses_.clear();
    history_.clear();
    // Back to front, one instance at a time; the replay draws the same with its own pipeline.
    // The pipeline is the variant's for the render pass it draws in (none: its own rendering).
    auto draw_with = [this](Variant variant, PipelineInfo drawn, PipelineUses* uses) {
        return [this, variant, drawn, uses](VkCommandBuffer cmd, const FrameInputs& in,
                                            VkPipelineLayout layout, DrawLog* log,
                                            graph::SubpassTarget target) {
            const std::vector<InstanceDraw> draws = sort_back_to_front(
                *in.scene, in.camera_position, scene_groups(in.options.decal_pass));
            Variant v = variant;
            v.render_pass = target.pass;
            v.subpass = target.index;
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_.get(v));
            const DrawCounts n = draw_sorted(cmd, *in.scene, layout, draws, {.log = log});
            if (uses) uses->add(drawn, n.draws);
        };
    };
    if (in.pixel && !in.options.subpass) {  // a replay would split the render pass
        const Variant twin{.history = true, .samples = v.samples, .depth = v.depth};
        history_pipelines_ = {history_pipeline(info, /*blend=*/true)};
        pipelines_.get(twin);  // built now: building it sets the replay's descriptors up
        drawing_.add_history(graph, in, res, history_, draw_with(twin, info, nullptr));
    }
    // msaa > 1: the samples are stored too, for the edge count (MsaaProbe) after the graph.
    drawing_.add(graph, kName, in, res, res.transparent_counts, /*resolve=*/true,
                 draw_with(v, info, &uses_));
    rasterized_.add(graph, in, res, res.transparent_counts,
                    {.samples = in.options.samples,
                     .modes = {scene::AlphaMode::Blend},
                     .decals = scene_groups(in.options.decal_pass)});
}

void TransparentPass::collect(const FrameCollect& c, std::span<PassResult> own,
                              FrameResult& frame) {
    PassResult* const own_pass = frame_result(own);
    if (!own_pass) return;
    collect_counts(c.readback, c.res.transparent_counts, *own_pass);
    own_pass->pipelines = uses_.list();
    // Against the scene depth, closer-or-equal, no writes; blended over the HDR colour.
    history_.collect(
        c, history_pipelines_,
        {.compare = c.in.options.closer_or_equal(), .depth_format = c.in.options.depth_format},
        frame);
}

}  // namespace ds::passes
