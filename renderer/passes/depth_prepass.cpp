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
      instrument_(services, kName, discard_layout_.handle()),
      discard_sets_(services.context, 1, kDiscardPoolSizes, "prepass discard count sets"),
      pipelines_([this](const Variant& v) { return compile(v); },
                 [this](const Variant& v, const ShaderStages& s, const graph::RenderTarget& t) {
                     return create(v, s, t);
                 },
                 [](const Variant& v, const ShaderStages& s) {
                     return describe_pipeline(pipeline_name(v), s, v.alpha_to_coverage);
                 }) {
    layout_ = vk::PipelineLayout(services.context, instrument_.sets(), {}, "depth prepass layout");
    pipelines_.info({.alpha = AlphaTest::Opaque});
    pipelines_.info({.alpha = AlphaTest::Mask});
}

void DepthPrepass::rebuild_pipelines(vk::DestroyList& retired) {
    pipelines_.rebuild(retired);
    instrument_.rebuild_pipelines(retired);
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
    if (v.light_slot) defines.push_back({"LIGHT_SLOT", "1"});
    if (v.alpha_mip) {
        // After the colour outputs: normal, roughness (G-buffer) or the coverage slot, then
        // surface_id.
        const int first = v.gbuffer ? 2 : (v.coverage_slot ? 1 : 0);
        defines.push_back({"ALPHA_MIP", "1"});
        defines.push_back({"ALPHA_MIP_LOCATION", std::to_string(first + (v.surface_id ? 1 : 0))});
    }
    if (v.history) {
        for (shader::Define& d :
             PixelHistoryReplay::defines(false, false, v.samples != VK_SAMPLE_COUNT_1_BIT))
            defines.push_back(std::move(d));
        vert_defines.push_back({"PIXEL_HISTORY", "1"});
    }
    if (!v.gbuffer) {
        // Z only: the vertex stage hands on just what the alpha test reads.
        defines.push_back({"GBUFFER", "0"});
        if (v.coverage_slot) {
            defines.push_back({"COVERAGE_SLOT", "1"});
            defines.push_back({"SURFACE_LOCATION", "1"});
        }
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
    return v.gbuffer || v.alpha != AlphaTest::Opaque || v.counting || v.surface_id || v.history ||
           v.alpha_mip;
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
    if (v.alpha_mip) name += " alpha_mip";
    return name;
}

vk::Pipeline DepthPrepass::create(const Variant& v, const ShaderStages& s,
                                  const graph::RenderTarget& target) const {
    // The Z-only vertex stages fetch only what they read (unread attributes draw warnings).
    const VertexInputs inputs = v.gbuffer                      ? VertexInputs::All
                                : v.alpha == AlphaTest::Opaque ? VertexInputs::Position
                                                               : VertexInputs::PositionUv;
    if (v.history) return instrument_.replay().create(s, v.samples, pipeline_name(v), inputs);
    vk::GraphicsPipelineBuilder b =
        scene_pipeline_builder(layout_.handle(), s.vert, s.frag, inputs);
    apply_target(b, target);
    return b.samples(v.samples)
        .alpha_to_coverage(v.alpha_to_coverage)
        .build(services_.context, pipeline_name(v).c_str());
}

void DepthPrepass::add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) {
    discards_ = {};
    // Sorted, one draw per instance; else one per group.
    instrument_.begin_frame(res.prepass_counts, in.options.count_draws && in.options.prepass,
                            uint32_t(in.scene->instance_groups().size()));
    if (!in.options.prepass) return;
    const FrameOptions& o = in.options;
    const Variant opaque{.counting = res.prepass_counts.valid(),
                         .surface_id = o.surface_id,
                         .alpha_mip = alpha_mip_,
                         .samples = o.samples,
                         .count_draws = res.prepass_counts.draws.valid(),
                         .gbuffer = o.gbuffer,
                         .coverage_slot = !o.gbuffer && o.alpha_to_coverage && !o.subpass,
                         .light_slot = o.subpass};
    // Only the pipeline with the alpha test changes: the opaque one keeps early-Z and its
    // variant, so normal frames share it.
    Variant tested = opaque;
    tested.alpha_to_coverage = o.alpha_to_coverage;
    tested.count_discards = count_discards_;
    tested.alpha = masked_split_ ? AlphaTest::Mask : AlphaTest::Unsplit;
    const Draw draw = make_draw(opaque, tested, masked_split_);
    // count_discards=on: two counters in a host buffer, zeroed by the host before the submit.
    const graph::BufferHandle discards =
        count_discards_ ? services_.readback.import_storage(graph, "prepass_discard_counts",
                                                            kDiscardBytes, kDiscardBytes)
                        : graph::BufferHandle{};
    discards_ = discards;
    if (in.pixel) add_history(graph, in, res, draw);
    struct Data {
        FrameInputs in;
    };
    graph.add_pass<Data>(
        kName,
        [&](graph::PassBuilder& b, Data& d) {
            if (o.subpass)
                declare_tiled(b, in, res);
            else
                declare(b, in, res);
            if (discards.valid())
                b.write(discards, Access::StorageReadWrite, graph::Shader::Fragment);
            d = {in};
        },
        [this, draw, discards](graph::PassContext& ctx, const Data& d) {
            record(ctx, d.in, draw, discards);
        });
    instrument_.add_measure(graph, in, res,
                            {.samples = o.samples,
                             .modes = {AlphaMode::Opaque, AlphaMode::Mask},
                             .decals = scene_groups(o.decal_pass)});
}

DepthPrepass::Draw DepthPrepass::make_draw(const Variant& opaque, const Variant& tested,
                                           bool split) {
    Draw draw;
    draw.opaque = split ? opaque : tested;
    draw.mask = tested;
    draw.split = split;
    draw.opaque_info = pipelines_.info(draw.opaque);
    if (split) draw.mask_info = pipelines_.info(tested);
    return draw;
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
    // The depth buffer starts cleared; the closer test, writes on (draw_scene).
    const FrameOptions& o = c.in.options;
    if (!instrument_.collect(c, own, frame,
                             {.compare = o.closer(),
                              .depth_write = true,
                              .clear_depth = o.far_depth(),
                              .depth_format = o.depth_format}))
        return;
    const std::span<const std::byte> bytes = c.readback.buffer_bytes(discards_);
    if (bytes.size() < kDiscardBytes) return;
    uint32_t counts[2] = {};
    std::memcpy(counts, bytes.data(), sizeof counts);
    frame.slots.put(DiscardCounts{counts[0], counts[1]}, &discards_report);
}

void DepthPrepass::record(graph::PassContext& ctx, const FrameInputs& in, Draw draw,
                          graph::BufferHandle discards) {
    if (discards.valid()) draw.discards = discard_set(ctx, in, discards);
    instrument_.bind_counts(ctx, in.frame_number, layout_.handle());
    draw_scene(ctx, in, draw, nullptr);
}

void DepthPrepass::add_history(graph::RenderGraph& graph, const FrameInputs& in,
                               FrameResources& res, const Draw& real) {
    auto twin = [](const Variant& v) {  // no counting: the frame's counts stay the frame's
        return Variant{.alpha = v.alpha,
                       .alpha_to_coverage = v.alpha_to_coverage,
                       .history = true,
                       .samples = v.samples,
                       .gbuffer = v.gbuffer};
    };
    Draw draw = real;
    draw.opaque = twin(real.opaque);
    draw.mask = twin(real.mask);
    draw.layout = instrument_.replay().layout();
    std::vector<HistoryPipeline> pipelines = {history_pipeline(real.opaque_info)};
    if (real.split) pipelines.push_back(history_pipeline(real.mask_info));
    const graph::BufferHandle uniforms = res.frame_uniforms;
    instrument_.add_history(
        graph, in, {.extent_of = res.depth},
        [uniforms](graph::PassBuilder& b) {
            b.read(uniforms, Access::UniformRead, graph::Shader::Vertex | graph::Shader::Fragment);
        },
        [this, in, draw](graph::PassContext& ctx, DrawLog& log) {
            draw_scene(ctx, in, draw, &log);
        },
        std::move(pipelines));
}

void DepthPrepass::draw_scene(graph::PassContext& ctx, const FrameInputs& in, const Draw& draw,
                              DrawLog* log) {
    VkCommandBuffer cmd = ctx.cmd();
    set_depth_state(cmd, /*test=*/true, /*write=*/true, in.options.closer());
    bind_geometry(cmd, *in.scene);
    const VkPipelineLayout layout = draw.layout ? draw.layout : layout_.handle();
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 0, 1, &in.frame_set, 0,
                            nullptr);
    if (draw.discards)
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, kDiscardSet, 1,
                                &draw.discards, 0, nullptr);
    // prepass_sort: nearest instances first, so the depth test rejects hidden layers before
    // their (normal-mapped) fragment shader runs; off: instanced groups in authored order.
    // prepass_mode=depth sorts whole instanced groups instead: its opaque fragments cost only
    // a depth test, less than the ten times more draw calls per-instance order takes (atrium
    // 1280x720 on lavapipe: the Z-only prepass took longer sorted per instance than unsorted).
    // The frame's draws are queried (count_draws); a history replay's (with `log`) are not.
    const DrawHooks hooks = instrument_.hooks(log);
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
    // The log's tags: 0 the first pipeline, 1 the MASK one (add_history's order). A replay's
    // draws are not the frame's pipelines' (they report the frame's draws only).
    auto step = [&](const Variant& v, const PipelineInfo& info, uint32_t tag,
                    std::span<const AlphaMode> modes) {
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_.get(v, ctx.target()));
        if (log) log->pipeline = tag;
        const uint32_t draws = draw_modes(modes).draws;
        if (!log) instrument_.used(info, draws);
    };
    if (draw.split) {
        const AlphaMode opaque[] = {AlphaMode::Opaque};
        const AlphaMode mask[] = {AlphaMode::Mask};
        step(draw.opaque, draw.opaque_info, 0, opaque);
        step(draw.mask, draw.mask_info, 1, mask);
    } else {
        // One pipeline with discard for opaque and MASK alike.
        const AlphaMode all[] = {AlphaMode::Opaque, AlphaMode::Mask};
        step(draw.opaque, draw.opaque_info, 0, all);
    }
}

// count_discards=on: report.json's "masked_discards".

}  // namespace ds::passes
