#include "renderer/passes/forward.h"

#include <vector>

#include "renderer/gpu_scene/gpu_scene.h"
#include "renderer/passes/scene_draw.h"
#include "renderer/readback/host_readback.h"
#include "renderer/shader/compiler.h"
#include "renderer/vk/context.h"
#include "renderer/vk/functions.h"

namespace ds::passes {

using graph::Access;
using scene::AlphaMode;

namespace {
const VkDescriptorPoolSize kInputPoolSizes[] = {{VK_DESCRIPTOR_TYPE_INPUT_ATTACHMENT, 2}};

vk::DescriptorSetLayout create_input_set_layout(vk::Context& context) {
    const VkDescriptorSetLayoutBinding bindings[] = {
        vk::layout_binding(0, VK_DESCRIPTOR_TYPE_INPUT_ATTACHMENT, VK_SHADER_STAGE_FRAGMENT_BIT),
        vk::layout_binding(1, VK_DESCRIPTOR_TYPE_INPUT_ATTACHMENT, VK_SHADER_STAGE_FRAGMENT_BIT)};
    return vk::DescriptorSetLayout(context, bindings, "forward input attachment set layout");
}
}  // namespace

ForwardPass::ForwardPass(const PassServices& services)
    : services_(services),
      lighting_(services.context, services.preferred_depth_format),
      instrument_(services, kName, lighting_.layout()),
      input_layout_(create_input_set_layout(services.context)),
      input_sets_(services.context, 1, kInputPoolSizes, "forward input attachment sets"),
      pipelines_([this](const Variant& v) { return compile(v); },
                 [this](const Variant& v, const ShaderStages& s, const graph::RenderTarget& t) {
                     return create(v, s, t);
                 },
                 [](const Variant& v, const ShaderStages& s) {
                     return describe_pipeline(pipeline_name(v), s, v.alpha_to_coverage);
                 }) {
    std::vector<VkDescriptorSetLayout> sets = instrument_.sets();
    layout_ = vk::PipelineLayout(services.context, sets, {}, "forward layout");
    sets.push_back(input_layout_.handle());
    subpass_layout_ = vk::PipelineLayout(services.context, sets, {}, "forward subpass layout");
    pipelines_.info({.prepass_inputs = true});
}

void ForwardPass::rebuild_pipelines(vk::DestroyList& retired) {
    pipelines_.rebuild(retired);
    instrument_.rebuild_pipelines(retired);
}

void ForwardPass::collect(const FrameCollect& c, std::span<PassResult> own, FrameResult& frame) {
    const FrameOptions& o = c.in.options;
    // With the prepass: its depth, EQUAL (or closer-or-equal), no writes; else cleared, the
    // closer test, writes on (record()).
    instrument_.collect(c, own, frame,
                        {.compare = !o.prepass      ? o.closer()
                                    : o.depth_equal ? VK_COMPARE_OP_EQUAL
                                                    : o.closer_or_equal(),
                         .depth_write = !o.prepass,
                         .clear_depth = o.prepass ? std::nullopt : std::optional(o.far_depth()),
                         .depth_format = o.depth_format});
}

ShaderStages ForwardPass::compile(const Variant& v) const {
    std::vector<shader::Define> vert_defines, frag_defines;
    if (v.non_invariant) vert_defines.push_back({"NON_INVARIANT", "1"});
    if (v.prepass_inputs) frag_defines.push_back({"PREPASS", "1"});
    if (v.gbuffer_inputs)
        frag_defines.push_back({"SUBPASS_INPUTS", std::to_string(int(v.samples))});
    if (v.alpha_mask) frag_defines.push_back({"ALPHA_MASK", "1"});
    if (v.counting) add_count_defines(frag_defines, vert_defines, services_.context, v.count_draws);
    if (v.alpha_to_coverage) frag_defines.push_back({"ALPHA_TO_COVERAGE", "1"});
    if (v.history) {
        const bool msaa = v.samples != VK_SAMPLE_COUNT_1_BIT;
        for (shader::Define& d : PixelHistoryReplay::defines(v.after_prepass, false, msaa))
            frag_defines.push_back(std::move(d));
        vert_defines.push_back({"PIXEL_HISTORY", "1"});
    }
    ShaderStages s;
    s.vert = services_.compiler.compile("forward.vert", shader::Stage::Vertex, vert_defines).spirv;
    s.frag =
        services_.compiler.compile("forward.frag", shader::Stage::Fragment, frag_defines).spirv;
    return s;
}

// Distinct for every variant one frame can use; counting and alpha to coverage change the
// fragment shader (and so maybe its early-Z), so they show.
std::string ForwardPass::pipeline_name(const Variant& v) {
    std::string name = v.alpha_mask ? (v.prepass_inputs ? "forward prepass mask" : "forward mask")
                       : v.prepass_inputs ? "forward prepass"
                                          : "forward opaque";
    if (v.alpha_to_coverage) name += " a2c";
    if (v.counting) name += " counting";
    if (v.history) name += " history";
    if (v.gbuffer_inputs) name += " input attachments";
    return name;
}

vk::Pipeline ForwardPass::create(const Variant& v, const ShaderStages& s,
                                 const graph::RenderTarget& target) const {
    if (v.history) return instrument_.replay().create(s, v.samples, pipeline_name(v));
    vk::GraphicsPipelineBuilder b = scene_pipeline_builder(
        v.gbuffer_inputs ? subpass_layout_.handle() : layout_.handle(), s.vert, s.frag);
    apply_target(b, target);
    return b.samples(v.samples)
        .sample_shading(v.sample_shading ? 1.0f : 0.0f)
        .alpha_to_coverage(v.alpha_to_coverage)
        .build(services_.context, pipeline_name(v).c_str());
}

std::vector<SettingDef> ForwardPass::knobs() {
    return {bool_knob(kInvariant, "prepass and depth", true,
                      "off: forward computes gl_Position with a different but mathematically "
                      "equal expression, to show what EQUAL does without invariance",
                      Invalidates::Pipelines)};
}

void ForwardPass::configure(const FrameSetup& setup, FrameOptions&) {
    invariant_ = knob_value(setup.settings, kInvariant);
}

void ForwardPass::add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) {
    const FrameOptions& o = in.options;
    instrument_.begin_frame(res.forward_counts, o.count_draws && !o.prepass,
                            uint32_t(in.scene->draw_groups().size()));
    // prepass_mode=depth: the prepass left only depth, so forward computes normal and
    // roughness itself (its non-PREPASS path), still under EQUAL without depth writes.
    // render_path=subpass: the G-buffer arrives as input attachments instead.
    Draw draw;
    draw.opaque = {.prepass_inputs = o.gbuffer_prepass() && !o.subpass,
                   .non_invariant = !invariant_,
                   .counting = res.forward_counts.valid(),
                   .sample_shading = o.sample_shading,
                   .samples = o.samples,
                   .count_draws = res.forward_counts.draws.valid(),
                   .gbuffer_inputs = o.subpass && o.gbuffer};
    // The pipelines with the alpha test: alpha-to-coverage replaces their discard.
    draw.mask = draw.opaque;
    draw.mask.alpha_mask = true;
    draw.mask.alpha_to_coverage = o.alpha_to_coverage;
    // Only EQUAL makes the alpha test redundant: with greater_or_equal the cut-out parts of a
    // MASK surface are nearer than what the prepass kept there, and would pass.
    draw.with_mask = !o.prepass || !o.depth_equal;
    draw.opaque_info = pipelines_.info(draw.opaque);
    if (draw.with_mask) draw.mask_info = pipelines_.info(draw.mask);
    draw.layout = draw.opaque.gbuffer_inputs ? subpass_layout_.handle() : VK_NULL_HANDLE;
    const bool sampled_gbuffer = o.gbuffer_prepass() && !o.subpass;
    draw.lighting = {.shadow_map = res.shadow_map,
                     .normals = sampled_gbuffer ? res.normals : graph::ImageHandle{},
                     .roughness = sampled_gbuffer ? res.roughness : graph::ImageHandle{},
                     .ao = res.ao,
                     .contact_shadows = res.contact_shadows};
    // Not between the subpasses: a replay there would split the render pass.
    if (in.pixel && !o.subpass) add_history(graph, in, res, draw);
    struct Data {
        FrameInputs in;
        FrameResources res;
    };
    graph.add_pass<Data>(
        kName,
        [&](graph::PassBuilder& b, Data& d) {
            declare(b, in, res, draw.lighting);
            d = {in, res};
        },
        [this, draw](graph::PassContext& ctx, const Data& d) { record(ctx, d.in, d.res, draw); });
    using Vertex = RasterizedCount::Vertex;
    instrument_.add_measure(graph, in, res,
                            {.vertex = invariant_ ? Vertex::Scene : Vertex::SceneNonInvariant,
                             .samples = o.samples,
                             .modes = {AlphaMode::Opaque, AlphaMode::Mask},
                             .decals = scene_groups(o.decal_pass)});
}

void ForwardPass::declare(graph::PassBuilder& b, const FrameInputs& in, FrameResources& res,
                          const LightingInputs& lighting) {
    const FrameOptions& o = in.options;
    const graph::ImageHandle depth = o.msaa() ? res.msaa_depth : res.depth;
    if (o.subpass) {
        // The light the prepass cleared (attachment 0), lit here; res.hdr at 1x is the prepass's.
        b.color(o.msaa() ? res.msaa_hdr : res.hdr);
        b.depth(depth, {.read_only = true});
        if (o.gbuffer) {
            b.input(res.normals);
            b.input(res.roughness);
        }
    } else {
        VkClearColorValue background{};
        for (size_t i = 0; i < 4; ++i) background.float32[i] = kHdrBackground[i];
        // At 1x forward creates res.hdr; at msaa > 1 it is transparent's resolve destination.
        if (!o.msaa())
            res.hdr = b.create_image("hdr", {.format = kHdrFormat,
                                             .size = graph::ImageSize::relative(1.0f),
                                             .semantic = graph::Semantic::HdrColor});
        b.color(o.msaa() ? res.msaa_hdr : res.hdr,
                {.load = graph::Load::Clear, .clear = background});
        // With the prepass the depth is only tested (loaded, never stored); without it cleared
        // and written, and at msaa > 1 resolved to the nearest sample, natively where the
        // device can (else depth_resolve writes res.depth next).
        if (o.prepass) {
            b.depth(depth, {.read_only = true});
        } else {
            b.depth(depth, {.load = graph::Load::Clear, .clear = o.far_depth()});
            if (o.msaa() && native_resolve(o))
                b.resolve(res.msaa_depth, res.depth,
                          native_depth_resolve(services_.context.report(), o));
        }
    }
    LightingSet::declare(b, lighting);
    b.read(res.frame_uniforms, Access::UniformRead,
           graph::Shader::Vertex | graph::Shader::Fragment);
    instrument_.declare(b);
}

void ForwardPass::record(graph::PassContext& ctx, const FrameInputs& in, const FrameResources& res,
                         const Draw& draw) {
    VkCommandBuffer cmd = ctx.cmd();
    const FrameOptions& o = in.options;
    const VkPipelineLayout layout = draw.layout ? draw.layout : layout_.handle();
    instrument_.bind_counts(ctx, in.frame_number, layout);
    const VkDescriptorSet lighting = lighting_.write(ctx, in.frame_number, draw.lighting);
    if (draw.opaque.gbuffer_inputs) {
        const VkDescriptorSet inputs = input_set(ctx, in, res);
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 4, 1, &inputs, 0,
                                nullptr);
    }
    const VkCompareOp test = !o.prepass      ? o.closer()
                             : o.depth_equal ? VK_COMPARE_OP_EQUAL
                                             : o.closer_or_equal();
    set_depth_state(cmd, /*test=*/true, /*write=*/!o.prepass, test);
    draw_scene(ctx, in, draw, lighting, nullptr);
}

void ForwardPass::add_history(graph::RenderGraph& graph, const FrameInputs& in,
                              const FrameResources& res, const Draw& real) {
    auto twin = [&in](Variant v) {
        v.counting = false;  // the frame's counts stay the frame's
        v.count_draws = false;
        v.history = true;
        v.after_prepass = in.options.prepass;  // in either prepass_mode
        return v;
    };
    Draw draw = real;
    draw.layout = instrument_.replay().layout();
    draw.opaque = twin(real.opaque);
    draw.mask = twin(real.mask);
    std::vector<HistoryPipeline> pipelines = {history_pipeline(real.opaque_info)};
    if (real.with_mask) pipelines.push_back(history_pipeline(real.mask_info));
    const FrameOptions& o = in.options;
    const graph::ImageHandle depth = !o.prepass ? graph::ImageHandle{}
                                     : o.msaa() ? res.msaa_depth
                                                : res.depth;
    const graph::BufferHandle uniforms = res.frame_uniforms;
    instrument_.add_history(
        graph, in, {.depth = depth, .extent_of = res.depth},
        [uniforms, lighting = draw.lighting](graph::PassBuilder& b) {
            LightingSet::declare(b, lighting);
            b.read(uniforms, Access::UniformRead, graph::Shader::Vertex | graph::Shader::Fragment);
        },
        [this, in, draw](graph::PassContext& ctx, DrawLog& log) {
            const VkDescriptorSet lighting = lighting_.write(ctx, in.frame_number, draw.lighting);
            draw_scene(ctx, in, draw, lighting, &log);
        },
        std::move(pipelines));
}

void ForwardPass::draw_scene(graph::PassContext& ctx, const FrameInputs& in, const Draw& draw,
                             VkDescriptorSet lighting, DrawLog* log) {
    VkCommandBuffer cmd = ctx.cmd();
    bind_geometry(cmd, *in.scene);
    const VkPipelineLayout layout = draw.layout ? draw.layout : layout_.handle();
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 0, 1, &in.frame_set, 0,
                            nullptr);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 2, 1, &lighting, 0,
                            nullptr);
    const Decals decals = scene_groups(in.options.decal_pass);
    // The log's tags: 0 the opaque pipeline, 1 the MASK one (add_history's order). The frame's
    // draws are queried (count_draws with prepass=off); a history replay's (with `log`) are
    // neither queried nor the frame's pipelines' draws.
    const DrawHooks hooks = instrument_.hooks(log);
    auto step = [&](const Variant& v, const PipelineInfo& info, uint32_t tag, AlphaMode mode,
                    bool bind) {
        if (bind)
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS,
                              pipelines_.get(v, ctx.target()));
        if (log) log->pipeline = tag;
        const uint32_t draws =
            draw_groups(cmd, *in.scene, layout, {&mode, 1}, decals, std::nullopt, hooks).draws;
        if (!log) instrument_.used(info, draws);
    };
    step(draw.opaque, draw.opaque_info, 0, AlphaMode::Opaque, true);
    // MASK after opaque either way: with the prepass and EQUAL the same pipeline (EQUAL does
    // the alpha test's work), otherwise the discard pipeline, testing against opaque depth.
    if (draw.with_mask)
        step(draw.mask, draw.mask_info, 1, AlphaMode::Mask, true);
    else
        step(draw.opaque, draw.opaque_info, 0, AlphaMode::Mask, false);
}

bool ForwardPass::native_resolve(const FrameOptions& o) const {
    return native_depth_resolve(services_.context.report(), o) != VK_RESOLVE_MODE_NONE;
}

VkDescriptorSet ForwardPass::input_set(graph::PassContext& ctx, const FrameInputs& in,
                                       const FrameResources& res) {
    const VkDescriptorSet set = input_sets_.allocate(in.frame_number, input_layout_.handle());
    vk::DescriptorWriter writer;
    writer.input_attachment(0, ctx.view(res.normals), ctx.layout(res.normals));
    writer.input_attachment(1, ctx.view(res.roughness), ctx.layout(res.roughness));
    writer.update(services_.context.device(), set);
    return set;
}

}  // namespace ds::passes
