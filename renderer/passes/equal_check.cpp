#include "renderer/passes/equal_check.h"

#include <algorithm>
#include <cstring>
#include <map>

#include <nlohmann/json.hpp>

#include "renderer/common/surface_json.h"
#include "renderer/gpu_scene/gpu_scene.h"
#include "renderer/passes/compute_kernel.h"
#include "renderer/passes/pass_util.h"
#include "renderer/readback/host_readback.h"
#include "renderer/shader/compiler.h"
#include "renderer/vk/context.h"

namespace ds::passes {
namespace {

constexpr VkDeviceSize kResultHeaderBytes = 16;  // holes, multiple, appended, padding
constexpr size_t kTopSurfaces = 10;

struct EqualCheckPush {
    uint32_t width, height;
    float far_depth;
    uint32_t capacity;
};

}  // namespace

EqualCheckPass::EqualCheckPass(const PassServices& services)
    : services_(services),
      nearest_(vk::nearest_clamp_sampler(services.context, "equal check")),
      pipeline_(services, "equal_check.comp", "equal check") {
    vk::Context& context = services.context;
    const VkShaderStageFlags c = VK_SHADER_STAGE_COMPUTE_BIT;
    const VkDescriptorSetLayoutBinding bindings[] = {
        vk::layout_binding(0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, c),
        vk::layout_binding(1, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, c),
        vk::layout_binding(2, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, c),
        vk::layout_binding(3, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, c),
        vk::layout_binding(4, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, c)};
    set_layout_ = vk::DescriptorSetLayout(context, bindings, "equal check set");
    const VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 3},
                                          {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1},
                                          {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1}};
    pool_ = vk::DescriptorPool(context, 1, sizes, "equal check");
    set_ = pool_.allocate(set_layout_.handle());
    const VkDescriptorSetLayout sets[] = {set_layout_.handle()};
    const VkPushConstantRange push{c, 0, sizeof(EqualCheckPush)};
    layout_ = vk::PipelineLayout(context, sets, {&push, 1}, "equal check layout");
}

void EqualCheckPass::rebuild_pipelines(vk::DestroyList& retired) {
    pipeline_.rebuild(retired);
}

std::vector<SettingDef> EqualCheckPass::knobs() {
    return {bool_knob(kKnob, "diagnostics", false,
                      "prepass on, depth_compare=equal, msaa=1: marks pixels the prepass covered "
                      "that forward did not shade (holes) and pixels forward shaded more than "
                      "once (ties); image equal_check, report equal_check (turns on "
                      "count_fragments)",
                      Invalidates::Pipelines)};
}

// It reads forward's per-pixel counts (per pixel, not per sample) and names the surfaces that
// won (surface_id).
void EqualCheckPass::configure(const FrameSetup& setup, FrameOptions& o) {
    const bool knob = knob_value(setup.settings, kKnob);
    on_ = knob && o.prepass && o.depth_equal && !o.msaa() && !o.subpass;
    if (on_) o.requests.counts = o.requests.surface_id = true;
    if (!knob || on_) return;
    if (!o.prepass)
        set_skipped("prepass off");
    else if (o.subpass)
        set_skipped(subpass_path_reason());
    else if (!o.depth_equal)
        set_skipped("depth_compare is not equal");
    else
        set_skipped("msaa > 1: forward counts fragments per pixel, not per sample");
    if (o.subpass) set_turned_off(kKnob.name);
}

void EqualCheckPass::add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) {
    result_ = {};
    if (!on_) return;
    pipeline_.get(layout_.handle());  // built now, not while the frame records
    const VkExtent2D extent = graph.resources()[res.depth.index].extent;
    capacity_ = extent.width * extent.height;
    result_ = services_.readback.import_storage(graph, "equal_check_result",
                                                kResultHeaderBytes + VkDeviceSize(capacity_) * 8,
                                                kResultHeaderBytes);
    Bound bound{res.forward_counts.shaded, res.depth, res.surface_id, {}, result_};
    const float far_depth = in.options.far_depth();
    struct Data {
        Bound bound;
    };
    graph.add_pass<Data>(
        {name(), graph::PassKind::Compute},
        [&](graph::PassBuilder& b, Data& d) {
            bound.marks = b.create_image("equal_check", {.format = VK_FORMAT_R32_UINT,
                                                         .size = graph::ImageSize::relative(1.0f),
                                                         .semantic = graph::Semantic::Count});
            res.equal_check = bound.marks;
            b.read(bound.counts, graph::Access::Sampled);
            b.read(bound.depth, graph::Access::Sampled);
            b.read(bound.surfaces, graph::Access::Sampled);
            b.write(bound.marks, graph::Access::StorageWrite);
            b.write(bound.result, graph::Access::StorageReadWrite);
            d = {bound};
        },
        [this, far_depth](graph::PassContext& ctx, const Data& d) {
            record(ctx, d.bound, far_depth);
        });
}

void EqualCheckPass::record(graph::PassContext& ctx, const Bound& bound, float far_depth) {
    vk::DescriptorWriter writer;
    writer.image(0, ctx.view(bound.counts), nearest_.handle(), ctx.layout(bound.counts))
        .image(1, ctx.view(bound.depth), nearest_.handle(), ctx.layout(bound.depth))
        .image(2, ctx.view(bound.surfaces), nearest_.handle(), ctx.layout(bound.surfaces))
        .storage_image(3, ctx.view(bound.marks), ctx.layout(bound.marks))
        .buffer(4, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, ctx.buffer(bound.result));
    writer.update(services_.context.device(), set_);
    const VkExtent2D extent = ctx.extent(bound.marks);
    VkCommandBuffer cmd = ctx.cmd();
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_.get(layout_.handle()));
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_.handle(), 0, 1, &set_, 0,
                            nullptr);
    const EqualCheckPush push{extent.width, extent.height, far_depth, capacity_};
    vkCmdPushConstants(cmd, layout_.handle(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push, &push);
    vkCmdDispatch(cmd, group_count(extent.width), group_count(extent.height), 1);
}

void EqualCheckPass::collect(const FrameCollect& c, std::span<PassResult>, FrameResult& frame) {
    const std::span<const std::byte> bytes = c.readback.buffer_bytes(result_);
    if (bytes.size() < kResultHeaderBytes) return;
    uint32_t header[3] = {};
    std::memcpy(header, bytes.data(), sizeof header);
    EqualCheckResult result{.holes = header[0], .multiple = header[1], .surfaces = {}};
    // Per instance: its holes and ties, most involved first.
    const SurfaceTable& table = c.in.scene->surfaces();
    std::map<uint32_t, std::pair<uint64_t, uint64_t>> by_instance;
    const uint32_t kept = std::min(header[2], capacity_);
    for (uint32_t i = 0; i < kept; ++i) {
        uint32_t record[2];
        std::memcpy(record, bytes.data() + kResultHeaderBytes + i * 8, sizeof record);
        if (const auto ref = table.find(record[0])) {
            auto& [holes, multiple] = by_instance[ref->instance];
            (record[1] == 1 ? holes : multiple) += 1;
        }
    }
    for (const auto& [instance, counts] : by_instance) {
        result.surfaces.push_back({table.name(instance), counts.first, counts.second});
    }
    std::stable_sort(
        result.surfaces.begin(), result.surfaces.end(),
        [](const auto& a, const auto& b) { return a.holes + a.multiple > b.holes + b.multiple; });
    if (result.surfaces.size() > kTopSurfaces) result.surfaces.resize(kTopSurfaces);
    frame.slots.put(std::move(result), &equal_check_report);
}

void equal_check_report(const EqualCheckResult& e, const FrameResult&, nlohmann::json& report) {
    nlohmann::json surfaces = nlohmann::json::array();
    for (const EqualCheckSurface& s : e.surfaces) {
        nlohmann::json entry = surface_json(s.name);
        entry["holes"] = s.holes;
        entry["multiple"] = s.multiple;
        surfaces.push_back(std::move(entry));
    }
    report["equal_check"] = {{"holes", e.holes}, {"multiple", e.multiple}, {"surfaces", surfaces}};
}

}  // namespace ds::passes
