#include "renderer/passes/depth_prepass.h"

#include <array>
#include <cstring>
#include <string>

#include "renderer/common/error.h"
#include "renderer/gpu_scene/gpu_scene.h"
#include "renderer/passes/scene_draw.h"
#include "renderer/readback/host_readback.h"
#include "renderer/shader/compiler.h"
#include "renderer/vk/capabilities.h"
#include "renderer/vk/check.h"
#include "renderer/vk/context.h"
#include "renderer/vk/functions.h"

namespace ds::passes {

using graph::Access;
using scene::AlphaMode;

namespace {
const VkDescriptorPoolSize kDiscardPoolSizes[] = {{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1}};
constexpr VkDeviceSize kDiscardBytes = 2 * sizeof(uint32_t);  // invoked, discarded

vk::DescriptorSetLayout create_discard_set_layout(vk::Context& context) {
    const VkDescriptorSetLayoutBinding binding =
        vk::layout_binding(0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_FRAGMENT_BIT);
    return vk::DescriptorSetLayout(context, {&binding, 1}, "discard count set layout");
}
}  // namespace

DepthPrepass::DepthPrepass(const PassServices& services)
    : services_(services),
      discard_layout_(create_discard_set_layout(services.context)),
      count_layout_(create_count_set_layout(services.context)),
      count_sets_(services.context, 1, kCountPoolSizes, "prepass count sets"),
      discard_sets_(services.context, 1, kDiscardPoolSizes, "prepass discard count sets"),
      rasterized_(services, kName),
      pipelines_([this](const Variant& v) { return compile(v); },
                 [this](const Variant& v, const ShaderStages& s) { return create(v, s); },
                 [](const Variant& v, const ShaderStages& s) {
                     return describe_pipeline(pipeline_name(v), s, v.alpha_to_coverage);
                 }),
      queries_(services.context),
      history_(services, kName,
               {services.frame_layout, services.material_layout, discard_layout_.handle(),
                count_layout_.handle()}) {
    const VkDescriptorSetLayout sets[] = {services.frame_layout, services.material_layout,
                                          discard_layout_.handle(), count_layout_.handle()};
    layout_ = vk::PipelineLayout(services.context, sets, {}, "depth prepass layout");
    const VkFormat depth = services.preferred_depth_format;
    pipelines_.get({.alpha = AlphaTest::Opaque, .depth = depth});
    pipelines_.get({.alpha = AlphaTest::Mask, .depth = depth});
}

void DepthPrepass::rebuild_pipelines(vk::DestroyList& retired) {
    pipelines_.rebuild(retired);
    rasterized_.rebuild_pipelines(retired);
}

ShaderStages DepthPrepass::compile(const Variant& v) const {
    std::vector<shader::Define> defines, vert_defines;
    if (v.alpha != AlphaTest::Opaque)
        defines.push_back({"ALPHA_MASK", std::to_string(int(v.alpha))});
    if (v.counting) add_count_defines(defines, vert_defines, services_.context, v.count_draws);
    if (v.alpha_to_coverage) defines.push_back({"ALPHA_TO_COVERAGE", "1"});
    if (v.count_discards) defines.push_back({"COUNT_DISCARDS", "1"});
    if (v.surface_id) {
        defines.push_back({"SURFACE_ID", "1"});
        vert_defines.push_back({"SURFACE_ID", "1"});
    }
    if (v.render_pass) defines.push_back({"LIGHT_SLOT", "1"});
    if (v.history) {
        for (shader::Define& d :
             PixelHistoryReplay::defines(false, false, v.samples != VK_SAMPLE_COUNT_1_BIT))
            defines.push_back(std::move(d));
        vert_defines.push_back({"PIXEL_HISTORY", "1"});
    }
    if (!v.gbuffer) {
        // Z only: the vertex stage hands on just what the alpha test reads.
        defines.push_back({"GBUFFER", "0"});
        if (v.coverage_slot) defines.push_back({"SURFACE_LOCATION", "1"});
        vert_defines.push_back({"SCENE_VARYINGS", v.alpha == AlphaTest::Opaque ? "0" : "1"});
    }
    ShaderStages s;
    s.vert =
        services_.compiler.compile("depth_prepass.vert", shader::Stage::Vertex, vert_defines).spirv;
    if (!has_fragment_stage(v)) return s;  // depth only (seed 003's null pixel shader)
    s.frag =
        services_.compiler.compile("depth_prepass.frag", shader::Stage::Fragment, defines).spirv;
    return s;
}

bool DepthPrepass::has_fragment_stage(const Variant& v) {
    return v.gbuffer || v.alpha != AlphaTest::Opaque || v.counting || v.surface_id || v.history;
}

std::vector<VkFormat> DepthPrepass::color_formats(const Variant& v) {
    std::vector<VkFormat> formats;
    if (v.gbuffer) {
        formats = {kNormalFormat, kRoughnessFormat};
    } else if (v.coverage_slot) {
        // A slot that is rendered without an image (writes discarded): only output 0's alpha
        // matters. The format is never used; a float one matches the shader's output type,
        // which the validation layer checks even for a slot without an image.
        formats.push_back(kCoverageSlotFormat);
    }
    if (v.surface_id) formats.push_back(kSurfaceFormat);
    return formats;
}

// Distinct for every variant one frame can use; the defines that change the fragment shader's
// early-Z (counting, alpha to coverage, discard counters) show.
std::string DepthPrepass::pipeline_name(const Variant& v) {
    static constexpr const char* kNames[] = {"depth_prepass opaque", "depth_prepass mask",
                                             "depth_prepass unsplit"};
    std::string name = kNames[int(v.alpha)];
    if (!v.gbuffer) name += " z-only";
    if (v.alpha_to_coverage) name += " a2c";
    if (v.count_discards) name += " count_discards";
    if (v.counting) name += " counting";
    if (v.history) name += " history";
    return name;
}

vk::Pipeline DepthPrepass::create(const Variant& v, const ShaderStages& s) const {
    // The Z-only vertex stages fetch only what they read (unread attributes draw warnings).
    const VertexInputs inputs = v.gbuffer                      ? VertexInputs::All
                                : v.alpha == AlphaTest::Opaque ? VertexInputs::Position
                                                               : VertexInputs::PositionUv;
    if (v.history) return history_.create(s, v.samples, pipeline_name(v), inputs);
    vk::GraphicsPipelineBuilder b =
        scene_pipeline_builder(layout_.handle(), s.vert, s.frag, inputs);
    if (v.render_pass) b.color_attachment(kHdrFormat).render_pass(v.render_pass, v.subpass);
    for (VkFormat format : color_formats(v)) b.color_attachment(format);
    return b.depth_attachment(v.depth)
        .samples(v.samples)
        .alpha_to_coverage(v.alpha_to_coverage)
        .build(services_.context, pipeline_name(v).c_str());
}

void DepthPrepass::add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) {
    discards_ = {};
    uses_.clear();
    // Sorted, one draw per instance; else one per group.
    queries_.begin_frame(in.options.count_draws && in.options.prepass,
                         uint32_t(in.scene->instance_groups().size()));
    history_.clear();
    if (!in.options.prepass) return;
    const Variant opaque{.counting = res.prepass_counts.valid(),
                         .surface_id = in.options.surface_id,
                         .samples = in.options.samples,
                         .depth = in.options.depth_format,
                         .count_draws = res.prepass_counts.draws.valid(),
                         .gbuffer = in.options.gbuffer,
                         .coverage_slot = !in.options.gbuffer && in.options.alpha_to_coverage &&
                                          !in.options.subpass};
    // Only the pipeline with the alpha test changes: the opaque one keeps early-Z and its
    // variant, so normal frames share it.
    Variant tested = opaque;
    tested.alpha_to_coverage = in.options.alpha_to_coverage;
    tested.count_discards = count_discards_;
    tested.alpha = masked_split_ ? AlphaTest::Mask : AlphaTest::Unsplit;
    // A subpass's pipelines need the graph's render pass: record() gets them.
    const Draw draw = in.options.subpass ? Draw{} : make_draw(opaque, tested, masked_split_);
    // count_discards=on: two counters in a host buffer, zeroed by the host before the submit.
    const graph::BufferHandle discards =
        count_discards_ ? services_.readback.import_storage(graph, "prepass_discard_counts",
                                                            kDiscardBytes, kDiscardBytes)
                        : graph::BufferHandle{};
    discards_ = discards;
    if (in.pixel) add_history(graph, in, res, opaque, tested);
    struct Data {
        FrameInputs in;
        FrameResources res;
        Msaa msaa;
        Draw draw;
        graph::BufferHandle discards;
        Variant opaque, tested;
    };
    graph.add_pass<Data>(
        kName,
        [&](graph::PassBuilder& b, Data& d) {
            const Msaa msaa =
                in.options.subpass ? declare_subpass(b, in, res) : declare(b, in, res);
            if (discards.valid())
                b.write(discards, Access::StorageReadWrite, graph::Shader::Fragment);
            d = {in, res, msaa, draw, discards, opaque, tested};
        },
        [this](graph::PassContext& ctx, const Data& d) {
            Draw draw = d.draw;
            if (const graph::SubpassTarget target = ctx.subpass_target()) {
                Variant opaque = d.opaque, tested = d.tested;
                opaque.render_pass = tested.render_pass = target.pass;
                opaque.subpass = tested.subpass = target.index;
                draw = make_draw(opaque, tested, masked_split_);
            }
            record(ctx, d.in, d.res, d.msaa, draw, d.discards);
        });
    rasterized_.add(graph, in, res, res.prepass_counts,
                    {.samples = in.options.samples,
                     .modes = {AlphaMode::Opaque, AlphaMode::Mask},
                     .decals = scene_groups(in.options.decal_pass)});
}

VkDescriptorSet DepthPrepass::discard_set(graph::PassContext& ctx, const FrameInputs& in,
                                          graph::BufferHandle buffer) {
    const VkDescriptorSet set = discard_sets_.allocate(in.frame_number, discard_layout_.handle());
    vk::DescriptorWriter writer;
    writer.buffer(0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, ctx.buffer(buffer));
    writer.update(services_.context.device(), set);
    return set;
}

void DepthPrepass::collect(const FrameCollect& c, std::span<PassResult> own, FrameResult& frame) {
    PassResult* const own_pass = frame_result(own);
    if (!own_pass) return;
    collect_counts(c.readback, c.res.prepass_counts, *own_pass);
    own_pass->pipelines = uses_.list();
    own_pass->draw_samples_passed = queries_.per_group(c.in.scene->draw_groups().size());
    // The depth buffer starts cleared; the closer test, writes on (draw_scene).
    history_.collect(c, history_pipelines_,
                     {.compare = c.in.options.closer(),
                      .depth_write = true,
                      .clear_depth = c.in.options.far_depth(),
                      .depth_format = c.in.options.depth_format},
                     frame);
    const std::span<const std::byte> bytes = c.readback.buffer_bytes(discards_);
    if (bytes.size() < kDiscardBytes) return;
    uint32_t counts[2] = {};
    std::memcpy(counts, bytes.data(), sizeof counts);
    frame.slots.put(DiscardCounts{counts[0], counts[1]}, &discards_report);
}

DepthPrepass::Msaa DepthPrepass::declare(graph::PassBuilder& b, const FrameInputs& in,
                                         FrameResources& res) const {
    const graph::ImageSize full = graph::ImageSize::relative(1.0f);
    const bool gbuffer = in.options.gbuffer;
    // prepass_mode=depth: no normals or roughness exist (nor are they listed anywhere).
    if (gbuffer) {
        res.normals = b.create_image(
            "normals",
            {.format = kNormalFormat, .size = full, .semantic = graph::Semantic::EncodedNormal});
        res.roughness = b.create_image(
            "roughness",
            {.format = kRoughnessFormat, .size = full, .semantic = graph::Semantic::UnormScalar});
    }
    b.read(res.frame_uniforms, Access::UniformRead,
           graph::Shader::Vertex | graph::Shader::Fragment);
    if (res.prepass_counts.valid()) declare_counts(b, res.prepass_counts);
    if (in.options.surface_id)
        res.surface_id = b.create_image(
            "surface_id",
            {.format = kSurfaceFormat, .size = full, .semantic = graph::Semantic::SurfaceId});
    Msaa msaa;
    if (!in.options.msaa()) {
        b.write(res.depth, Access::DepthAttachment);
        if (gbuffer) {
            b.write(res.normals, Access::ColorAttachment);
            b.write(res.roughness, Access::ColorAttachment);
        }
        if (res.surface_id.valid()) b.write(res.surface_id, Access::ColorAttachment);
        return msaa;
    }
    const VkSampleCountFlagBits samples = in.options.samples;
    if (gbuffer) {
        msaa.normals = b.create_image("msaa_normals", {.format = kNormalFormat,
                                                       .size = full,
                                                       .samples = samples,
                                                       .semantic = graph::Semantic::EncodedNormal});
        msaa.roughness =
            b.create_image("msaa_roughness", {.format = kRoughnessFormat,
                                              .size = full,
                                              .samples = samples,
                                              .semantic = graph::Semantic::UnormScalar});
        b.write(msaa.normals, Access::ColorAttachment);
        b.write(msaa.roughness, Access::ColorAttachment);
        b.write(res.normals, Access::ResolveDst);
        b.write(res.roughness, Access::ResolveDst);
    }
    b.write(res.msaa_depth, Access::DepthAttachment);
    if (res.surface_id.valid()) {
        msaa.surface_id =
            b.create_image("msaa_surface_id", {.format = kSurfaceFormat,
                                               .size = full,
                                               .samples = samples,
                                               .semantic = graph::Semantic::SurfaceId});
        b.write(msaa.surface_id, Access::ColorAttachment);
        b.write(res.surface_id, Access::ResolveDst);
        res.msaa_surface_id = msaa.surface_id;
    }
    // Without a native nearest-sample resolve, depth_resolve writes res.depth next.
    if (native_depth_resolve(services_.context.report(), in.options))
        b.write(res.depth, Access::ResolveDst);
    return msaa;
}

std::vector<VkRenderingAttachmentInfo> DepthPrepass::color_attachments(graph::PassContext& ctx,
                                                                       const FrameInputs& in,
                                                                       const FrameResources& res,
                                                                       const Msaa& msaa) const {
    const std::array<float, 4> no_normal = {0.5f, 0.5f, 0.5f, 0.0f};  // the zero vector
    const bool multi = in.options.msaa();
    // At 1x everything is stored (forward, GTAO, contact shadows and captures read it); at
    // msaa > 1 only the resolved images are read later, so the samples need no store.
    auto image = [&](graph::ImageHandle single, graph::ImageHandle samples,
                     std::array<float, 4> clear) {
        if (!multi) return color_attachment(ctx.view(single), VK_ATTACHMENT_LOAD_OP_CLEAR, clear);
        return resolving_color_attachment(ctx.view(samples), ctx.view(single),
                                          VK_ATTACHMENT_LOAD_OP_CLEAR,
                                          VK_ATTACHMENT_STORE_OP_DONT_CARE, clear);
    };
    std::vector<VkRenderingAttachmentInfo> colors;
    if (in.options.gbuffer) {
        colors.push_back(image(res.normals, msaa.normals, no_normal));
        colors.push_back(image(res.roughness, msaa.roughness, {}));
    } else if (in.options.alpha_to_coverage) {
        // The coverage slot: no image, so the alpha it receives only makes the sample mask.
        colors.push_back(
            vk::make<VkRenderingAttachmentInfo>(VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO));
    }
    if (res.surface_id.valid()) {  // cleared to 0, none
        colors.push_back(image(res.surface_id, msaa.surface_id, {}));
        if (multi) colors.back().resolveMode = VK_RESOLVE_MODE_SAMPLE_ZERO_BIT;  // integers
        // The sample view (msaa_samples) and zfight read every sample later in the frame.
        if (multi && (in.samples || in.options.requests.surface_id_samples))
            colors.back().storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    }
    return colors;
}

void DepthPrepass::begin(graph::PassContext& ctx, const FrameInputs& in, const FrameResources& res,
                         const Msaa& msaa) const {
    const std::vector<VkRenderingAttachmentInfo> colors = color_attachments(ctx, in, res, msaa);
    if (!in.options.msaa()) {
        const VkRenderingAttachmentInfo depth = depth_attachment(
            ctx.view(res.depth), ctx.layout(res.depth), VK_ATTACHMENT_LOAD_OP_CLEAR,
            VK_ATTACHMENT_STORE_OP_STORE, in.options.far_depth());
        begin_rendering(ctx.cmd(), ctx.extent(res.depth), colors, &depth);
        return;
    }
    // STORE: forward, skybox and transparent LOAD these samples (seed 000's lesson).
    VkRenderingAttachmentInfo depth = depth_attachment(
        ctx.view(res.msaa_depth), ctx.layout(res.msaa_depth), VK_ATTACHMENT_LOAD_OP_CLEAR,
        VK_ATTACHMENT_STORE_OP_STORE, in.options.far_depth());
    if (const VkResolveModeFlagBits mode =
            native_depth_resolve(services_.context.report(), in.options)) {
        depth.resolveMode = mode;
        depth.resolveImageView = ctx.view(res.depth);
        depth.resolveImageLayout = ctx.layout(res.depth);
    }
    begin_rendering(ctx.cmd(), ctx.extent(res.depth), colors, &depth);
}

void DepthPrepass::record(graph::PassContext& ctx, const FrameInputs& in, const FrameResources& res,
                          const Msaa& msaa, Draw draw, graph::BufferHandle discards) {
    VkCommandBuffer cmd = ctx.cmd();
    if (discards.valid()) draw.discards = discard_set(ctx, in, discards);
    if (res.prepass_counts.valid()) {
        draw.counts = count_sets_.allocate(in.frame_number, count_layout_.handle());
        write_count_set(ctx, services_.context.device(), draw.counts, res.prepass_counts);
    }
    queries_.reset(cmd);
    const bool own_rendering = !ctx.subpass_target();  // else a subpass of the graph's
    if (own_rendering) begin(ctx, in, res, msaa);
    draw_scene(cmd, in, draw, uses_, nullptr);
    if (own_rendering) vk::fn().cmd_end_rendering(cmd);
}

void DepthPrepass::add_history(graph::RenderGraph& graph, const FrameInputs& in,
                               FrameResources& res, const Variant& opaque, const Variant& tested) {
    Variant replay_opaque = opaque, replay_tested = tested;
    for (Variant* v : {&replay_opaque, &replay_tested}) {
        *v = {.alpha = v->alpha,
              .alpha_to_coverage = v->alpha_to_coverage,
              .history = true,
              .samples = v->samples,
              .depth = v->depth,
              .gbuffer = v->gbuffer};  // no counting: the frame's counts stay the frame's
    }
    Draw draw;
    draw.layout = history_.layout();
    if (masked_split_) {
        draw.opaque = pipelines_.get(replay_opaque);
        draw.mask = pipelines_.get(replay_tested);
        history_pipelines_ = {history_pipeline(pipelines_.info(opaque)),
                              history_pipeline(pipelines_.info(tested))};
    } else {
        draw.opaque = pipelines_.get(replay_tested);
        history_pipelines_ = {history_pipeline(pipelines_.info(tested))};
    }
    const graph::BufferHandle uniforms = res.frame_uniforms;
    history_.add(
        graph, in, {.extent_of = res.depth},
        [uniforms](graph::PassBuilder& b) {
            b.read(uniforms, Access::UniformRead, graph::Shader::Vertex | graph::Shader::Fragment);
        },
        [this, in, draw](graph::PassContext& ctx, DrawLog& log) {
            PipelineUses unused;  // the frame's pipelines report the frame's draws only
            draw_scene(ctx.cmd(), in, draw, unused, &log);
        });
}

void DepthPrepass::draw_scene(VkCommandBuffer cmd, const FrameInputs& in, const Draw& draw,
                              PipelineUses& uses, DrawLog* log) {
    set_depth_state(cmd, /*test=*/true, /*write=*/true, in.options.closer());
    bind_geometry(cmd, *in.scene);
    const VkPipelineLayout layout = draw.layout ? draw.layout : layout_.handle();
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 0, 1, &in.frame_set, 0,
                            nullptr);
    if (draw.counts)
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, kCountSet, 1,
                                &draw.counts, 0, nullptr);
    if (draw.discards)
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, kDiscardSet, 1,
                                &draw.discards, 0, nullptr);
    // prepass_sort: nearest instances first, so the depth test rejects hidden layers before
    // their (normal-mapped) fragment shader runs; off: instanced groups in authored order.
    // prepass_mode=depth sorts whole instanced groups instead: its opaque fragments cost only
    // a depth test, less than the ten times more draw calls per-instance order takes (atrium
    // 1280x720 on lavapipe: the Z-only prepass took longer sorted per instance than unsorted).
    // The frame's draws are queried (count_draws); a history replay's (with `log`) are not.
    const DrawHooks hooks{.queries = log ? nullptr : &queries_, .log = log};
    auto draw_modes = [&](std::span<const AlphaMode> modes) {
        const Decals decals = scene_groups(in.options.decal_pass);
        if (!prepass_sort_)
            return draw_groups(cmd, *in.scene, layout, modes, decals, std::nullopt, hooks);
        const auto sorted =
            in.options.gbuffer
                ? sort_by_distance(*in.scene, in.camera_position, modes, DrawOrder::FrontToBack,
                                   decals)
                : sort_groups_front_to_back(*in.scene, in.camera_position, modes, decals);
        return draw_sorted(cmd, *in.scene, layout, sorted, hooks);
    };
    // The log's tags: 0 the first pipeline, 1 the MASK one (add_history's order).
    auto tag = [log](uint32_t pipeline) {
        if (log) log->pipeline = pipeline;
    };
    if (draw.mask) {
        const AlphaMode opaque[] = {AlphaMode::Opaque};
        const AlphaMode mask[] = {AlphaMode::Mask};
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, draw.opaque);
        tag(0);
        uses.add(draw.opaque_info, draw_modes(opaque).draws);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, draw.mask);
        tag(1);
        uses.add(draw.mask_info, draw_modes(mask).draws);
    } else {
        // One pipeline with discard for opaque and MASK alike.
        const AlphaMode all[] = {AlphaMode::Opaque, AlphaMode::Mask};
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, draw.opaque);
        tag(0);
        uses.add(draw.opaque_info, draw_modes(all).draws);
    }
}

// count_discards=on: report.json's "masked_discards".

}  // namespace ds::passes
