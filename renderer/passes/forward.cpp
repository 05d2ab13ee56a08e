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
      count_layout_(create_count_set_layout(services.context)),
      input_layout_(create_input_set_layout(services.context)),
      count_sets_(services.context, 1, kCountPoolSizes, "forward count sets"),
      input_sets_(services.context, 1, kInputPoolSizes, "forward input attachment sets"),
      rasterized_(services, kName),
      pipelines_([this](const Variant& v) { return compile(v); },
                 [this](const Variant& v, const ShaderStages& s) { return create(v, s); },
                 [](const Variant& v, const ShaderStages& s) {
                     return describe_pipeline(pipeline_name(v), s, v.alpha_to_coverage);
                 }),
      queries_(services.context),
      history_(services, kName,
               {services.frame_layout, services.material_layout, lighting_.layout(),
                count_layout_.handle()}) {
    const VkDescriptorSetLayout sets[] = {services.frame_layout, services.material_layout,
                                          lighting_.layout(), count_layout_.handle()};
    layout_ = vk::PipelineLayout(services.context, sets, {}, "forward layout");
    const VkDescriptorSetLayout subpass_sets[] = {services.frame_layout, services.material_layout,
                                                  lighting_.layout(), count_layout_.handle(),
                                                  input_layout_.handle()};
    subpass_layout_ =
        vk::PipelineLayout(services.context, subpass_sets, {}, "forward subpass layout");
    pipelines_.get({.prepass_inputs = true, .depth = services.preferred_depth_format});
}

void ForwardPass::rebuild_pipelines(vk::DestroyList& retired) {
    pipelines_.rebuild(retired);
    rasterized_.rebuild_pipelines(retired);
}

void ForwardPass::collect(const FrameCollect& c, std::span<PassResult> own, FrameResult& frame) {
    PassResult* const own_pass = frame_result(own);
    if (!own_pass) return;
    collect_counts(c.readback, c.res.forward_counts, *own_pass);
    own_pass->pipelines = uses_.list();
    own_pass->draw_samples_passed = queries_.per_group(c.in.scene->draw_groups().size());
    const FrameOptions& o = c.in.options;
    // With the prepass: its depth, EQUAL (or closer-or-equal), no writes; else cleared, the
    // closer test, writes on (record()).
    history_.collect(c, history_pipelines_,
                     {.compare = !o.prepass      ? o.closer()
                                 : o.depth_equal ? VK_COMPARE_OP_EQUAL
                                                 : o.closer_or_equal(),
                      .depth_write = !o.prepass,
                      .clear_depth = o.prepass ? std::nullopt : std::optional(o.far_depth()),
                      .depth_format = o.depth_format},
                     frame);
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

vk::Pipeline ForwardPass::create(const Variant& v, const ShaderStages& s) const {
    if (v.history) return history_.create(s, v.samples, pipeline_name(v));
    vk::GraphicsPipelineBuilder b = scene_pipeline_builder(
        v.gbuffer_inputs ? subpass_layout_.handle() : layout_.handle(), s.vert, s.frag);
    if (v.render_pass) b.render_pass(v.render_pass, v.subpass);
    return b.color_attachment(kHdrFormat)
        .depth_attachment(v.depth)
        .samples(v.samples)
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
    // prepass_mode=depth: the prepass left only depth, so forward computes normal and
    // roughness itself (its non-PREPASS path), still under EQUAL without depth writes.
    // render_path=subpass: the G-buffer arrives as input attachments instead (subpass 1).
    const Variant opaque{.prepass_inputs = o.gbuffer_prepass() && !o.subpass,
                         .non_invariant = !invariant_,
                         .counting = res.forward_counts.valid(),
                         .sample_shading = o.sample_shading,
                         .samples = o.samples,
                         .depth = o.depth_format,
                         .count_draws = res.forward_counts.draws.valid(),
                         .gbuffer_inputs = o.subpass && o.gbuffer};
    // The pipelines with the alpha test: alpha-to-coverage replaces their discard.
    Variant mask = opaque;
    mask.alpha_mask = true;
    mask.alpha_to_coverage = o.alpha_to_coverage;
    // Only EQUAL makes the alpha test redundant: with greater_or_equal the cut-out parts of a
    // MASK surface are nearer than what the prepass kept there, and would pass.
    const bool with_mask = !o.prepass || !o.depth_equal;
    // A subpass's pipelines need the graph's render pass: record() gets them.
    Draw draw = o.subpass ? Draw{} : make_draw(opaque, mask, with_mask);
    uses_.clear();
    queries_.begin_frame(o.count_draws && !o.prepass, uint32_t(in.scene->draw_groups().size()));
    history_.clear();
    const bool sampled_gbuffer = o.gbuffer_prepass() && !o.subpass;
    draw.lighting = {.shadow_map = res.shadow_map,
                     .normals = sampled_gbuffer ? res.normals : graph::ImageHandle{},
                     .roughness = sampled_gbuffer ? res.roughness : graph::ImageHandle{},
                     .ao = res.ao,
                     .contact_shadows = res.contact_shadows};
    // The record lambda needs the handles setup creates: they travel in the pass's Data.
    // Not between the subpasses: a replay there would split the render pass.
    if (in.pixel && !o.subpass) add_history(graph, in, res, opaque, mask, draw);
    struct Data {
        FrameInputs in;
        FrameResources res;
        Draw draw;
        Variant opaque, mask;
        bool with_mask;
    };
    graph.add_pass<Data>(
        kName,
        [&](graph::PassBuilder& b, Data& d) {
            if (o.subpass)
                declare_subpass(b, in, res, draw.lighting);
            else
                declare(b, in, res, draw.lighting);
            d = {in, res, draw, opaque, mask, with_mask};
        },
        [this](graph::PassContext& ctx, const Data& d) {
            Draw draw = d.draw;
            if (const graph::SubpassTarget target = ctx.subpass_target()) {
                Variant opaque = d.opaque, mask = d.mask;
                opaque.render_pass = mask.render_pass = target.pass;
                opaque.subpass = mask.subpass = target.index;
                const LightingInputs lighting = draw.lighting;
                draw = make_draw(opaque, mask, d.with_mask);
                draw.lighting = lighting;
                draw.layout = opaque.gbuffer_inputs ? subpass_layout_.handle() : VK_NULL_HANDLE;
            }
            record(ctx, d.in, d.res, draw);
        });
    using Vertex = RasterizedCount::Vertex;
    rasterized_.add(graph, in, res, res.forward_counts,
                    {.vertex = invariant_ ? Vertex::Scene : Vertex::SceneNonInvariant,
                     .samples = o.samples,
                     .modes = {AlphaMode::Opaque, AlphaMode::Mask},
                     .decals = scene_groups(o.decal_pass)});
}

void ForwardPass::declare(graph::PassBuilder& b, const FrameInputs& in, FrameResources& res,
                          const LightingInputs& lighting) const {
    const FrameOptions& o = in.options;
    if (o.msaa()) {
        // res.hdr is transparent's resolve destination.
        b.write(res.msaa_hdr, Access::ColorAttachment);
        if (o.prepass) {
            b.read(res.msaa_depth, Access::DepthReadOnly);
        } else {
            b.write(res.msaa_depth, Access::DepthAttachment);
            // Without a native nearest-sample resolve, depth_resolve writes res.depth next.
            if (native_resolve(o)) b.write(res.depth, Access::ResolveDst);
        }
    } else {
        res.hdr = b.create_image("hdr", {.format = kHdrFormat,
                                         .size = graph::ImageSize::relative(1.0f),
                                         .semantic = graph::Semantic::HdrColor});
        b.write(res.hdr, Access::ColorAttachment);
        if (o.prepass)
            b.read(res.depth, Access::DepthReadOnly);
        else
            b.write(res.depth, Access::DepthAttachment);
    }
    LightingSet::declare(b, lighting);
    b.read(res.frame_uniforms, Access::UniformRead,
           graph::Shader::Vertex | graph::Shader::Fragment);
    if (res.forward_counts.valid()) declare_counts(b, res.forward_counts);
}

void ForwardPass::record(graph::PassContext& ctx, const FrameInputs& in, const FrameResources& res,
                         const Draw& draw) {
    VkCommandBuffer cmd = ctx.cmd();
    const FrameOptions& o = in.options;
    VkDescriptorSet counts = VK_NULL_HANDLE;
    if (res.forward_counts.valid()) {
        counts = count_sets_.allocate(in.frame_number, count_layout_.handle());
        write_count_set(ctx, services_.context.device(), counts, res.forward_counts);
    }
    const VkDescriptorSet lighting = lighting_.write(ctx, in.frame_number, draw.lighting);

    queries_.reset(cmd);
    const bool own_rendering = !ctx.subpass_target();  // else subpass 1 of the graph's
    if (own_rendering) begin(ctx, o, res);
    if (draw.layout == subpass_layout_.handle()) {
        const VkDescriptorSet inputs = input_set(ctx, in, res);
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, draw.layout, 4, 1, &inputs, 0,
                                nullptr);
    }
    const VkCompareOp test = !o.prepass      ? o.closer()
                             : o.depth_equal ? VK_COMPARE_OP_EQUAL
                                             : o.closer_or_equal();
    set_depth_state(cmd, /*test=*/true, /*write=*/!o.prepass, test);
    draw_scene(cmd, in, draw, lighting, counts, uses_, nullptr);
    if (own_rendering) vk::fn().cmd_end_rendering(cmd);
}

void ForwardPass::add_history(graph::RenderGraph& graph, const FrameInputs& in,
                              const FrameResources& res, const Variant& opaque, const Variant& mask,
                              const Draw& real) {
    auto twin = [&in](Variant v) {
        v.counting = false;  // the frame's counts stay the frame's
        v.count_draws = false;
        v.history = true;
        v.after_prepass = in.options.prepass;  // in either prepass_mode
        return v;
    };
    Draw draw = real;
    draw.layout = history_.layout();
    draw.opaque = pipelines_.get(twin(opaque));
    history_pipelines_ = {history_pipeline(real.opaque_info)};
    if (real.mask) {
        draw.mask = pipelines_.get(twin(mask));
        history_pipelines_.push_back(history_pipeline(real.mask_info));
    }
    const FrameOptions& o = in.options;
    const graph::ImageHandle depth = !o.prepass ? graph::ImageHandle{}
                                     : o.msaa() ? res.msaa_depth
                                                : res.depth;
    const graph::BufferHandle uniforms = res.frame_uniforms;
    history_.add(
        graph, in, {.depth = depth, .extent_of = res.depth},
        [uniforms, lighting = draw.lighting](graph::PassBuilder& b) {
            LightingSet::declare(b, lighting);
            b.read(uniforms, Access::UniformRead, graph::Shader::Vertex | graph::Shader::Fragment);
        },
        [this, in, draw](graph::PassContext& ctx, DrawLog& log) {
            const VkDescriptorSet lighting = lighting_.write(ctx, in.frame_number, draw.lighting);
            PipelineUses unused;  // the frame's pipelines report the frame's draws only
            draw_scene(ctx.cmd(), in, draw, lighting, VK_NULL_HANDLE, unused, &log);
        });
}

void ForwardPass::draw_scene(VkCommandBuffer cmd, const FrameInputs& in, const Draw& draw,
                             VkDescriptorSet lighting, VkDescriptorSet counts, PipelineUses& uses,
                             DrawLog* log) {
    const FrameOptions& o = in.options;
    bind_geometry(cmd, *in.scene);
    const VkPipelineLayout layout = draw.layout ? draw.layout : layout_.handle();
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 0, 1, &in.frame_set, 0,
                            nullptr);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 2, 1, &lighting, 0,
                            nullptr);
    if (counts)
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, kCountSet, 1, &counts,
                                0, nullptr);
    const AlphaMode opaque[] = {AlphaMode::Opaque};
    const AlphaMode mask[] = {AlphaMode::Mask};
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, draw.opaque);
    const Decals decals = scene_groups(o.decal_pass);
    // The log's tags: 0 the opaque pipeline, 1 the MASK one (add_history's order). The frame's
    // draws are queried (count_draws with prepass=off); a history replay's (with `log`) are not.
    const DrawHooks hooks{.queries = log ? nullptr : &queries_, .log = log};
    if (log) log->pipeline = 0;
    uses.add(draw.opaque_info,
             draw_groups(cmd, *in.scene, layout, opaque, decals, std::nullopt, hooks).draws);
    // MASK after opaque either way: with the prepass and EQUAL the same pipeline (EQUAL does
    // the alpha test's work), otherwise the discard pipeline, testing against opaque depth.
    if (draw.mask) vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, draw.mask);
    if (log && draw.mask) log->pipeline = 1;
    uses.add(draw.mask ? draw.mask_info : draw.opaque_info,
             draw_groups(cmd, *in.scene, layout, mask, decals, std::nullopt, hooks).draws);
}

bool ForwardPass::native_resolve(const FrameOptions& o) const {
    return native_depth_resolve(services_.context.report(), o) != VK_RESOLVE_MODE_NONE;
}

void ForwardPass::begin(graph::PassContext& ctx, const FrameOptions& o,
                        const FrameResources& res) const {
    const graph::ImageHandle color_image = o.msaa() ? res.msaa_hdr : res.hdr;
    const graph::ImageHandle depth_image = o.msaa() ? res.msaa_depth : res.depth;
    const VkRenderingAttachmentInfo color =
        color_attachment(ctx.view(color_image), VK_ATTACHMENT_LOAD_OP_CLEAR, kHdrBackground);
    // With the prepass the depth is only tested: loaded, never stored (STORE_OP_NONE keeps
    // the contents and needs no write access), in the read-only layout the graph chose.
    VkRenderingAttachmentInfo depth =
        o.prepass ? depth_attachment(ctx.view(depth_image), ctx.layout(depth_image),
                                     VK_ATTACHMENT_LOAD_OP_LOAD, VK_ATTACHMENT_STORE_OP_NONE)
                  : depth_attachment(ctx.view(depth_image), ctx.layout(depth_image),
                                     VK_ATTACHMENT_LOAD_OP_CLEAR, VK_ATTACHMENT_STORE_OP_STORE,
                                     o.far_depth());
    if (o.msaa() && !o.prepass && native_resolve(o)) {
        depth.resolveMode = native_depth_resolve(services_.context.report(), o);
        depth.resolveImageView = ctx.view(res.depth);
        depth.resolveImageLayout = ctx.layout(res.depth);
    }
    begin_rendering(ctx.cmd(), ctx.extent(color_image), {&color, 1}, &depth);
}

}  // namespace ds::passes
