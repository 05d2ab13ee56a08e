#include "renderer/passes/triangle_size.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include <nlohmann/json.hpp>

#include "renderer/gpu_scene/gpu_scene.h"
#include "renderer/readback/host_readback.h"
#include "renderer/vk/context.h"

namespace ds {

double TriangleSizeResult::lower(size_t bin) {
    return bin == 0 ? 0.0 : std::ldexp(1.0, TriangleSizeResult::kMinExponent + int(bin));
}

double TriangleSizeResult::upper(size_t bin) {
    return bin + 1 >= kBins ? std::numeric_limits<double>::infinity()
                            : std::ldexp(1.0, kMinExponent + int(bin) + 1);
}

TriangleSizeResult TriangleSizeResult::from_counts(std::span<const uint32_t, kBins> counts) {
    TriangleSizeResult r;
    for (size_t i = 0; i < kBins; ++i) {
        r.bins[i] = counts[i];
        r.covered += counts[i];
        // Bin edges are powers of two, so these are exact: every area of bin i is below 1
        // (4) exactly when its upper bound is at most 1 (4).
        if (upper(i) <= 1.0) r.under_1 += counts[i];
        if (upper(i) <= 4.0) r.under_4 += counts[i];
    }
    return r;
}

namespace passes {

using graph::Access;

namespace {

// Set 2's bindings (set 0 is the frame's; set 1 the material layout, which
// common/bindings.glsl declares and the shader leaves unused).
enum SizeBinding : uint32_t {
    kSizeSurfaceIds,
    kSizeImage,
    kSizeVertices,
    kSizeIndices,
    kSizeRows,
    kSizeInstances,
    kSizeHistogram,
    kSizeBindings,
};

// triangle_size.comp's push constants.
struct TriangleSizePush {
    uint32_t width, height, instances, pad;
};

// The shader zeroes and adds up one group's bins with one lane each.
static_assert(TriangleSizeResult::kBins <= ComputeKernel::kGroupSize * ComputeKernel::kGroupSize);

// A log heat map in px²: areas span from fractions of a pixel to the whole screen and beyond.
const graph::Display kDisplay{.scale = graph::ValueScale::Log,
                              .range = graph::DisplayRange::min_max(),
                              .palette = graph::Palette::Heat,
                              .unit = "px²",
                              .legend = "triangle area",
                              .hover = "triangle {} px²",
                              .exr_channel = "area"};

constexpr const char* kHistogramBuffer = "triangle_size_histogram";  // its HostReadback buffer
constexpr VkDeviceSize kHistogramBytes = TriangleSizeResult::kBins * sizeof(uint32_t);

}  // namespace

nlohmann::json triangle_size_json(const TriangleSizeResult& r) {
    nlohmann::json bins = nlohmann::json::array();
    for (size_t i = 0; i < TriangleSizeResult::kBins; ++i) {
        if (r.bins[i] == 0) continue;
        const double to = TriangleSizeResult::upper(i);
        bins.push_back({{"from", TriangleSizeResult::lower(i)},
                        {"to", std::isinf(to) ? nlohmann::json(nullptr) : nlohmann::json(to)},
                        {"pixels", r.bins[i]}});
    }
    return {{"unit", "px²"},
            {"covered_pixels", r.covered},
            {"pixels_under_1px2", r.under_1},
            {"pixels_under_4px2", r.under_4},
            {"bins", bins},
            {"bins_note",
             "each bin [from, to) px² of the winning triangle's area, bins [2^k, 2^(k+1)); the "
             "first starts at 0, the last (to null) is unbounded; empty bins left out"}};
}

TriangleSizePass::TriangleSizePass(const PassServices& services)
    : services_(services),
      nearest_(vk::nearest_clamp_sampler(services.context, "triangle size")),
      pipeline_(services, "triangle_size.comp", "triangle size",
                {{"MIN_EXPONENT", std::to_string(TriangleSizeResult::kMinExponent)},
                 {"MAX_EXPONENT", std::to_string(TriangleSizeResult::kMaxExponent)}}) {
    vk::Context& context = services.context;
    const VkShaderStageFlags c = VK_SHADER_STAGE_COMPUTE_BIT;
    std::vector<VkDescriptorSetLayoutBinding> bindings = {
        vk::layout_binding(kSizeSurfaceIds, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, c),
        vk::layout_binding(kSizeImage, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, c)};
    for (uint32_t b = kSizeVertices; b < kSizeBindings; ++b)
        bindings.push_back(vk::layout_binding(b, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, c));
    set_layout_ = vk::DescriptorSetLayout(context, bindings, "triangle size set");
    const VkDescriptorPoolSize sizes[] = {
        {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1},
        {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1},
        {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kSizeBindings - kSizeVertices}};
    pool_ = vk::DescriptorPool(context, 1, sizes, "triangle size");
    set_ = pool_.allocate(set_layout_.handle());
    const VkDescriptorSetLayout sets[] = {services.frame_layout, services.material_layout,
                                          set_layout_.handle()};
    const VkPushConstantRange push{c, 0, sizeof(TriangleSizePush)};
    layout_ = vk::PipelineLayout(context, sets, {&push, 1}, "triangle size layout");
}

void TriangleSizePass::rebuild_pipelines(vk::DestroyList& retired) {
    pipeline_.rebuild(retired);
}

std::vector<SettingDef> TriangleSizePass::knobs() {
    return {bool_knob(kKnob, "diagnostics", false,
                      "prepass on: image triangle_size, per pixel the screen area in px² of the "
                      "triangle that won the prepass depth test (near-plane clipped; msaa > 1: "
                      "sample 0's), and report triangle_size, a histogram over power-of-two bins "
                      "with the pixels under 1 and 4 px² (turns on surface_id)",
                      Invalidates::Nothing)};
}

// It reads the prepass's winner per pixel (surface_id), which the subpass path does not write.
void TriangleSizePass::configure(const FrameSetup& setup, FrameOptions& o) {
    const bool knob = knob_value(setup.settings, kKnob);
    on_ = knob && o.prepass && !o.subpass;
    if (on_) o.requests.surface_id = true;
    if (knob && !o.prepass) set_skipped("prepass off");
    if (knob && o.subpass) {
        set_skipped("render_path=subpass: the prepass writes no surface_id there");
        set_turned_off(kKnob.name);
    }
}

void TriangleSizePass::update_rows(const GpuScene& scene) {
    static_assert(sizeof(InstanceRow) == 16);  // the shader's uvec4 per row
    std::vector<InstanceRow> rows;
    const SurfaceTable& table = scene.surfaces();
    rows.reserve(table.instances.size());
    for (const SurfaceInstance& s : table.instances) {
        const GpuMesh& mesh = scene.meshes().at(s.mesh);
        rows.push_back({s.base, s.triangles, mesh.first_index, mesh.vertex_offset});
    }
    if (rows_buffer_ && rows == rows_) return;
    const VkDeviceSize bytes = std::max<VkDeviceSize>(rows.size() * sizeof(InstanceRow), 16);
    // The last frame that read the old buffer has finished (Renderer::render waits for each).
    if (!rows_buffer_ || rows_buffer_.size() < bytes)
        rows_buffer_ =
            vk::Buffer(services_.context, {bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                           vk::MemoryUsage::Upload, "triangle size rows"});
    if (!rows.empty()) rows_buffer_.write(rows.data(), rows.size() * sizeof(InstanceRow));
    rows_ = std::move(rows);
}

void TriangleSizePass::add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) {
    histogram_ = {};
    if (!on_ || !in.scene || !res.surface_id.valid()) return;
    pipeline_.get(layout_.handle());  // built now, not while the frame records
    update_rows(*in.scene);
    histogram_ = services_.readback.import_storage(graph, kHistogramBuffer, kHistogramBytes,
                                                   kHistogramBytes);
    Bound bound{res.surface_id, {}, histogram_};
    struct Data {
        Bound bound;
    };
    graph.add_pass<Data>(
        {name(), graph::PassKind::Compute},
        [&](graph::PassBuilder& b, Data& d) {
            bound.sizes = b.create_image("triangle_size", {.format = VK_FORMAT_R32_SFLOAT,
                                                           .size = graph::ImageSize::relative(1.0f),
                                                           .semantic = graph::Semantic::Scalar,
                                                           .display = kDisplay});
            b.read(res.frame_uniforms, Access::UniformRead);
            b.read(bound.surfaces, Access::Sampled);
            b.write(bound.sizes, Access::StorageWrite);
            b.write(bound.histogram, Access::StorageReadWrite);
            d = {bound};
        },
        [this, scene = in.scene, frame_set = in.frame_set](graph::PassContext& ctx, const Data& d) {
            record(ctx, d.bound, *scene, frame_set);
        });
}

void TriangleSizePass::record(graph::PassContext& ctx, const Bound& bound, const GpuScene& scene,
                              VkDescriptorSet frame_set) {
    const VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    vk::DescriptorWriter writer;
    writer
        .image(kSizeSurfaceIds, ctx.view(bound.surfaces), nearest_.handle(),
               ctx.layout(bound.surfaces))
        .storage_image(kSizeImage, ctx.view(bound.sizes), ctx.layout(bound.sizes))
        .buffer(kSizeVertices, storage, scene.vertex_buffer())
        .buffer(kSizeIndices, storage, scene.index_buffer())
        .buffer(kSizeRows, storage, rows_buffer_.handle())
        .buffer(kSizeInstances, storage, scene.instance_buffer())
        .buffer(kSizeHistogram, storage, ctx.buffer(bound.histogram));
    writer.update(services_.context.device(), set_);
    const VkExtent2D extent = ctx.extent(bound.sizes);
    VkCommandBuffer cmd = ctx.cmd();
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_.get(layout_.handle()));
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_.handle(), 0, 1, &frame_set,
                            0, nullptr);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_.handle(), 2, 1, &set_, 0,
                            nullptr);
    const TriangleSizePush push{extent.width, extent.height, uint32_t(rows_.size()), 0};
    vkCmdPushConstants(cmd, layout_.handle(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push, &push);
    vkCmdDispatch(cmd, group_count(extent.width), group_count(extent.height), 1);
}

void TriangleSizePass::collect(const FrameCollect& c, std::span<PassResult>, FrameResult& frame) {
    if (!histogram_.valid()) return;
    const std::span<const std::byte> bytes = c.readback.buffer_bytes(histogram_);
    histogram_ = {};
    if (bytes.size() < kHistogramBytes) return;
    std::array<uint32_t, TriangleSizeResult::kBins> counts{};
    std::memcpy(counts.data(), bytes.data(), kHistogramBytes);
    frame.slots.put(TriangleSizeResult::from_counts(counts), &triangle_size_report);
}

void triangle_size_report(const TriangleSizeResult& r, const FrameResult&, nlohmann::json& report) {
    report["triangle_size"] = triangle_size_json(r);
}

}  // namespace passes
}  // namespace ds
