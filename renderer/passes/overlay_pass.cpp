#include "renderer/passes/overlay_pass.h"

#include "renderer/gpu_scene/gpu_scene.h"
#include "renderer/passes/scene_draw.h"
#include "renderer/shader/compiler.h"
#include "renderer/vk/context.h"

namespace ds::passes {

namespace {

const char* mode_name(scene::AlphaMode mode) {
    return mode == scene::AlphaMode::Opaque ? "opaque"
           : mode == scene::AlphaMode::Mask ? "mask"
                                            : "blend";
}

}  // namespace

OverlayPass::OverlayPass(const PassServices& services, const char* name, bool resolve)
    : services_(services),
      name_(name),
      resolve_(resolve),
      lighting_(services.context, services.preferred_depth_format),
      instrument_(services, name, lighting_.layout()),
      pipelines_([this](const Variant& v) { return compile(v); },
                 [this](const Variant& v, const ShaderStages& s, const graph::RenderTarget& t) {
                     return create(v, s, t);
                 },
                 [this](const Variant& v, const ShaderStages& s) {
                     return describe_pipeline(pipeline_name(v), s, /*alpha_to_coverage=*/false);
                 }) {
    layout_ =
        vk::PipelineLayout(services.context, instrument_.sets(), {}, (name_ + " layout").c_str());
}

void OverlayPass::rebuild_pipelines(vk::DestroyList& retired) {
    pipelines_.rebuild(retired);
    instrument_.rebuild_pipelines(retired);
}

ShaderStages OverlayPass::compile(const Variant& v) const {
    const Step step = steps().at(size_t(v.step));
    std::vector<shader::Define> defines, vert_defines;
    if (step.mode) defines.push_back({"ALPHA_MODE", std::to_string(int(*step.mode))});
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
std::string OverlayPass::pipeline_name(const Variant& v) const {
    const Step step = steps().at(size_t(v.step));
    std::string name = name_;
    if (step.mode) name += std::string(" ") + mode_name(*step.mode);
    if (v.counting) name += " counting";
    if (v.history) name += " history";
    return name;
}

vk::Pipeline OverlayPass::create(const Variant& v, const ShaderStages& s,
                                 const graph::RenderTarget& target) const {
    if (v.history) return instrument_.replay().create(s, v.samples, pipeline_name(v));
    const Step step = steps().at(size_t(v.step));
    vk::GraphicsPipelineBuilder b = scene_pipeline_builder(layout_.handle(), s.vert, s.frag);
    apply_target(b, target, step.blend ? vk::Blend::Alpha : vk::Blend::None);
    b.samples(v.samples);
    if (step.bias_steps != 0.0f || step.bias_slope != 0.0f) {
        const float towards_camera = v.reverse_z ? 1.0f : -1.0f;
        b.depth_bias(towards_camera * step.bias_steps, towards_camera * step.bias_slope);
    }
    return b.build(services_.context, pipeline_name(v).c_str());
}

void OverlayPass::add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) {
    const CountImages& counts = this->counts(res);
    instrument_.begin_frame(counts, /*queries=*/false, 0);
    if (!runs(in.options)) return;
    std::vector<Variant> variants;
    for (size_t i = 0; i < steps().size(); ++i) {
        variants.push_back({.step = int8_t(i),
                            .counting = counts.valid(),
                            .reverse_z = in.options.reverse_z,
                            .samples = in.options.samples,
                            .count_draws = counts.draws.valid()});
        pipelines_.info(variants.back());
    }
    // Not in the prepass: no prepass normal or roughness.
    const LightingInputs lighting = {.shadow_map = res.shadow_map,
                                     .normals = {},
                                     .roughness = {},
                                     .ao = res.ao,
                                     .contact_shadows = res.contact_shadows};
    // Not inside the render pass of render_path=subpass: a replay would split it.
    if (in.pixel && !in.options.subpass) add_history(graph, in, res, variants, lighting);
    struct Data {
        FrameInputs in;
    };
    graph.add_pass<Data>(
        name_,
        [&](graph::PassBuilder& b, Data& d) {
            declare_hdr_over_depth(b, res, in.options.msaa(), resolve_);
            LightingSet::declare(b, lighting);
            b.read(res.frame_uniforms, graph::Access::UniformRead,
                   graph::Shader::Vertex | graph::Shader::Fragment);
            instrument_.declare(b);
            d = {in};
        },
        [this, variants, lighting](graph::PassContext& ctx, const Data& d) {
            instrument_.bind_counts(ctx, d.in.frame_number, layout_.handle());
            draw_steps(ctx, d.in, layout_.handle(), variants, lighting, nullptr);
        });
    instrument_.add_measure(graph, in, res, measured(in));
}

void OverlayPass::draw_steps(graph::PassContext& ctx, const FrameInputs& in,
                             VkPipelineLayout layout, const std::vector<Variant>& variants,
                             const LightingInputs& lighting, DrawLog* log) {
    VkCommandBuffer cmd = ctx.cmd();
    const VkDescriptorSet lighting_set = lighting_.write(ctx, in.frame_number, lighting);
    // The replay has set its own depth state (no test: pixel_history.h).
    if (!log) set_depth_state(cmd, /*test=*/true, /*write=*/false, in.options.closer_or_equal());
    bind_geometry(cmd, *in.scene);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 0, 1, &in.frame_set, 0,
                            nullptr);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 2, 1, &lighting_set, 0,
                            nullptr);
    const std::vector<Step> order = steps();
    // The log's tag is the step.
    for (size_t i = 0; i < variants.size(); ++i) {
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS,
                          pipelines_.get(variants[i], ctx.target()));
        if (log) log->pipeline = uint32_t(i);
        const DrawCounts n = draw(cmd, in, layout, order[i], instrument_.hooks(log));
        if (!log) instrument_.used(pipelines_.info(variants[i]), n.draws);
    }
}

// Pixel history: the replay's graph pass, before the pass, reading the depth and the HDR colour
// the pass starts from, drawing the same steps with the instrumented pipelines.
void OverlayPass::add_history(graph::RenderGraph& graph, const FrameInputs& in,
                              const FrameResources& res, const std::vector<Variant>& frame_variants,
                              const LightingInputs& lighting) {
    std::vector<Variant> variants;
    std::vector<HistoryPipeline> pipelines;
    const std::vector<Step> order = steps();
    for (const Variant& v : frame_variants) {
        variants.push_back({.step = v.step, .history = true, .samples = v.samples});
        pipelines.push_back(history_pipeline(pipelines_.info(v), order[size_t(v.step)].blend));
    }
    const bool msaa = in.options.msaa();
    const graph::BufferHandle uniforms = res.frame_uniforms;
    // The replay's layout: binding with the pass's would disturb set 4.
    const VkPipelineLayout layout = instrument_.replay().layout();
    instrument_.add_history(
        graph, in,
        {.depth = msaa ? res.msaa_depth : res.depth,
         .dst = msaa ? res.msaa_hdr : res.hdr,
         .extent_of = res.depth},
        [lighting, uniforms](graph::PassBuilder& b) {
            LightingSet::declare(b, lighting);
            b.read(uniforms, graph::Access::UniformRead,
                   graph::Shader::Vertex | graph::Shader::Fragment);
        },
        [this, in, layout, variants, lighting](graph::PassContext& ctx, DrawLog& log) {
            draw_steps(ctx, in, layout, variants, lighting, &log);
        },
        std::move(pipelines));
}

void OverlayPass::collect(const FrameCollect& c, std::span<PassResult> own, FrameResult& frame) {
    // Against the scene depth, closer-or-equal, no writes (decals' bias: decals.h); blended
    // steps over the HDR colour.
    instrument_.collect(
        c, own, frame,
        {.compare = c.in.options.closer_or_equal(), .depth_format = c.in.options.depth_format});
}

}  // namespace ds::passes
