#include "renderer/passes/zfight.h"

#include <algorithm>
#include <cstring>
#include <map>
#include <set>

#include <nlohmann/json.hpp>

#include "renderer/common/surface_json.h"
#include "renderer/format/format.h"
#include "renderer/gpu_scene/gpu_scene.h"
#include "renderer/passes/scene_draw.h"
#include "renderer/readback/host_readback.h"
#include "renderer/shader/compiler.h"
#include "renderer/vk/capabilities.h"
#include "renderer/vk/context.h"
#include "renderer/vk/functions.h"

namespace ds::passes {

using graph::Access;

namespace {

const VkDescriptorPoolSize kZfightPoolSizes[] = {{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 2},
                                                 {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1},
                                                 {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1}};
constexpr VkDeviceSize kPairsHeaderBytes = 16;  // count + padding (std430 uvec4 alignment)
constexpr uint32_t kRecordsPerPixel = 2;        // competitor records the buffer holds, on average

constexpr const char* kPipelineName = "zfight";

struct ZfightPush {
    uint32_t max_steps, depth_bits, width, capacity;
};

}  // namespace

ZfightResult zfight_pairs(std::span<const ZfightRecord> records, const SurfaceTable& table) {
    struct Acc {
        std::set<uint32_t> pixels;
        uint32_t min_steps = UINT32_MAX;
    };
    using Key = std::pair<uint32_t, uint32_t>;  // instance indices, low first
    std::map<Key, Acc> by_pair;
    // (pixel, pair): the record with the least steps
    std::map<std::pair<uint32_t, Key>, const ZfightRecord*> least;
    for (const ZfightRecord& r : records) {
        const auto a = table.find(r.winner), b = table.find(r.competitor);
        if (!a || !b) continue;
        const Key key = std::minmax(a->instance, b->instance);
        Acc& acc = by_pair[key];
        acc.pixels.insert(r.pixel);
        acc.min_steps = std::min(acc.min_steps, r.steps());
        auto [it, added] = least.try_emplace({r.pixel, key}, &r);
        if (!added && r.steps() < it->second->steps()) it->second = &r;
    }
    std::vector<std::pair<Key, const Acc*>> order;
    for (const auto& [key, acc] : by_pair) order.push_back({key, &acc});
    std::stable_sort(order.begin(), order.end(), [](const auto& x, const auto& y) {
        return x.second->pixels.size() > y.second->pixels.size();
    });
    ZfightResult out;
    std::map<Key, uint32_t> index_of;
    for (const auto& [key, acc] : order) {
        index_of[key] = uint32_t(out.pairs.size());
        out.pairs.push_back(
            {table.name(key.first), table.name(key.second), acc->pixels.size(), acc->min_steps});
    }
    for (const auto& [where, r] : least)  // ordered by pixel already
        out.hits.push_back({where.first, index_of.at(where.second), r->steps(), r->gap()});
    return out;
}

ZfightPass::ZfightPass(const PassServices& services)
    : services_(services),
      nearest_(vk::nearest_clamp_sampler(services.context, "zfight nearest")),
      sets_(services.context, 1, kZfightPoolSizes, "zfight sets"),
      pipelines_([this](const Variant& v) { return compile(v); },
                 [this](const Variant& v, const ShaderStages& s, const graph::RenderTarget& t) {
                     return create(v, s, t);
                 },
                 [](const Variant&, const ShaderStages& s) {
                     return describe_pipeline(kPipelineName, s, /*alpha_to_coverage=*/false);
                 }),
      bound_(services) {
    const VkShaderStageFlags frag = VK_SHADER_STAGE_FRAGMENT_BIT;
    const VkDescriptorSetLayoutBinding bindings[] = {
        vk::layout_binding(0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, frag),
        vk::layout_binding(1, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, frag),
        vk::layout_binding(2, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, frag),
        vk::layout_binding(3, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, frag)};
    set_layout_ = vk::DescriptorSetLayout(services.context, bindings, "zfight set");
    const VkDescriptorSetLayout sets[] = {services.frame_layout, services.material_layout,
                                          set_layout_.handle()};
    const VkPushConstantRange push{frag, 0, sizeof(ZfightPush)};
    layout_ = vk::PipelineLayout(services.context, sets, {&push, 1}, "zfight layout");
}

ShaderStages ZfightPass::compile(const Variant& v) const {
    // The prepass's vertex shader, handing the surface base on: the same gl_Position.
    const std::vector<shader::Define> surface = {{"SURFACE_ID", "1"}};
    std::vector<shader::Define> frag;
    if (v.per_sample()) frag.push_back({"PER_SAMPLE", "1"});
    return {services_.compiler.compile("depth_prepass.vert", shader::Stage::Vertex, surface).spirv,
            services_.compiler.compile("zfight.frag", shader::Stage::Fragment, frag).spirv};
}

vk::Pipeline ZfightPass::create(const Variant& v, const ShaderStages& s,
                                const graph::RenderTarget& target) const {
    vk::GraphicsPipelineBuilder b = scene_pipeline_builder(layout_.handle(), s.vert, s.frag);
    apply_target(b, target);
    // One invocation per sample (the shader's gl_SampleID asks for it too).
    if (v.per_sample()) b.samples(v.samples).sample_shading(1.0f);
    return b.build(services_.context, kPipelineName);
}

std::vector<SettingDef> ZfightPass::knobs() {
    return {bool_knob(kKnob, "diagnostics", false,
                      "Z-fight detector: re-rasterises opaque and masked geometry and counts, per "
                      "pixel, other surfaces within zfight_steps depth steps of the stored depth "
                      "(image zfight, report zfight); at msaa > 1 per sample, against each "
                      "sample's stored depth and winner (the image sums the samples)",
                      Invalidates::Pipelines),
            int_knob(kSteps, "diagnostics", 4, 0, 1024,
                     "zfight: the largest gap, in representable steps of the depth format (ULPs "
                     "of D32_SFLOAT, unorm steps of D24 / D16), that still counts as a fight",
                     Invalidates::Nothing)};
}

// It compares against the prepass's depth and winner (at msaa > 1 per sample, which takes
// sample-rate shading); it names surfaces (surface_id, every sample's at msaa > 1) and
// measures gaps along the ray (depth_precision).
void ZfightPass::configure(const FrameSetup& setup, FrameOptions& o) {
    const bool knob = knob_value(setup.settings, kKnob);
    steps_ = uint32_t(knob_value(setup.settings, kSteps));
    const vk::DeviceReport& device = services_.context.report();
    const bool per_sample_ok = !o.msaa() || device.sample_rate_shading;
    o.zfight = knob && o.prepass && !o.subpass && per_sample_ok;
    if (o.zfight) o.requests.surface_id = o.requests.depth_precision = true;
    if (o.zfight && o.msaa()) o.requests.surface_id_samples = true;
    if (!knob || o.zfight) return;
    if (!o.prepass)
        set_skipped("prepass off");
    else if (o.subpass)
        set_skipped(subpass_path_reason());
    else
        set_skipped(
            "msaa > 1: it compares per sample, which needs the sampleRateShading "
            "feature, which " +
            device.candidate.name + " does not offer");
    if (o.subpass) set_turned_off(kKnob.name);
}

void ZfightPass::add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) {
    records_ = {};
    uses_.clear();
    if (!in.options.zfight) return;
    const VkExtent2D extent = graph.resources()[res.depth.index].extent;
    // At msaa > 1 too (every fighting sample appends one): N samples of one pixel fill N.
    capacity_ = extent.width * extent.height * kRecordsPerPixel;
    const graph::BufferHandle records = services_.readback.import_storage(
        graph, "zfight_records", kPairsHeaderBytes + VkDeviceSize(capacity_) * 16,
        kPairsHeaderBytes);
    records_ = records;
    const bool msaa = in.options.msaa();
    const Bound bound{msaa ? res.msaa_surface_id : res.surface_id,
                      msaa ? res.msaa_depth : res.depth, bound_.add(graph, in, res, steps_),
                      res.zfight, records};
    struct Data {
        FrameInputs in;
        Bound bound;
    };
    graph.add_pass<Data>(
        name(),
        [&](graph::PassBuilder& b, Data& d) {
            b.read(res.frame_uniforms, Access::UniformRead,
                   graph::Shader::Vertex | graph::Shader::Fragment);
            b.read(bound.surfaces, Access::Sampled);
            b.read(bound.depth, Access::Sampled);
            // No colour: the fragments only count. Layers beyond the limit fail the early test.
            b.depth(bound.limit, {.read_only = true});
            b.write(bound.competitors, Access::StorageReadWrite);
            b.write(bound.records, Access::StorageReadWrite);
            d = {in, bound};
        },
        [this](graph::PassContext& ctx, const Data& d) { record(ctx, d.in, d.bound); });
}

void ZfightPass::record(graph::PassContext& ctx, const FrameInputs& in, const Bound& bound) {
    VkCommandBuffer cmd = ctx.cmd();
    const VkDescriptorSet set = sets_.allocate(in.frame_number, set_layout_.handle());
    vk::DescriptorWriter writer;
    writer.image(0, ctx.view(bound.surfaces), nearest_.handle(), ctx.layout(bound.surfaces))
        .image(1, ctx.view(bound.depth), nearest_.handle(), ctx.layout(bound.depth))
        .storage_image(2, ctx.view(bound.competitors), ctx.layout(bound.competitors))
        .buffer(3, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, ctx.buffer(bound.records));
    writer.update(services_.context.device(), set);

    const VkExtent2D extent = ctx.extent(bound.depth);
    const ZfightPush push{steps_, format::depth_bits(ctx.format(bound.depth)), extent.width,
                          capacity_};
    set_depth_state(cmd, /*test=*/true, /*write=*/false, in.options.closer_or_equal());
    bind_geometry(cmd, *in.scene);
    const VkPipelineLayout layout = layout_.handle();
    const Variant variant{.samples = in.options.samples};
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_.get(variant, ctx.target()));
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 0, 1, &in.frame_set, 0,
                            nullptr);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 2, 1, &set, 0, nullptr);
    vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof push, &push);
    const scene::AlphaMode modes[] = {scene::AlphaMode::Opaque, scene::AlphaMode::Mask};
    uses_.add(
        pipelines_.info(variant),
        draw_groups(cmd, *in.scene, layout, modes, scene_groups(in.options.decal_pass)).draws);
}

void ZfightPass::collect(const FrameCollect& c, std::span<PassResult> own, FrameResult& frame) {
    if (!own.empty()) own.back().pipelines = uses_.list();  // after zfight_bound's
    const std::span<const std::byte> bytes = c.readback.buffer_bytes(records_);
    if (bytes.size() < kPairsHeaderBytes) return;
    uint32_t appended = 0;
    std::memcpy(&appended, bytes.data(), sizeof appended);
    const uint32_t kept = std::min(appended, capacity_);
    std::vector<ZfightRecord> records(kept);
    // An empty vector's data() may be null, and memcpy from or to null is undefined even for 0
    // bytes (UBSan's nonnull-attribute check, on a frame without a single near-tie).
    if (kept > 0)
        std::memcpy(records.data(), bytes.data() + kPairsHeaderBytes, kept * sizeof(ZfightRecord));
    ZfightResult result = zfight_pairs(records, c.in.scene->surfaces());
    result.steps = steps_;
    result.dropped = appended - kept;
    const std::span<const std::byte> counts = c.readback.image_bytes(c.res.zfight);
    for (size_t i = 0; i + 4 <= counts.size(); i += 4) {
        uint32_t v;
        std::memcpy(&v, counts.data() + i, 4);
        result.pixels += v != 0;
    }
    frame.slots.put(std::move(result), &zfight_report);
}

void zfight_report(const ZfightResult& z, const FrameResult&, nlohmann::json& report) {
    nlohmann::json pairs = nlohmann::json::array();
    for (const ZfightPair& p : z.pairs)
        pairs.push_back({{"a", surface_json(p.a)},
                         {"b", surface_json(p.b)},
                         {"pixels", p.pixels},
                         {"min_steps", p.min_steps}});
    nlohmann::json json = {{"steps", z.steps}, {"pixels", z.pixels}, {"pairs", pairs}};
    if (z.dropped) json["dropped_records"] = z.dropped;
    report["zfight"] = std::move(json);
}

}  // namespace ds::passes
