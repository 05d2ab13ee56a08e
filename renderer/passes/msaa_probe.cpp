#include "renderer/passes/msaa_probe.h"

#include <cstring>

#include "renderer/passes/compute_kernel.h"
#include "renderer/readback/host_readback.h"
#include "renderer/shader/compiler.h"
#include "renderer/vk/context.h"

namespace ds::passes {
namespace {

constexpr VkDeviceSize kProbeHeaderBytes = 16;  // edge_pixels + padding (std430 array alignment)
constexpr const char* kBuffer = "msaa_probe";   // its HostReadback buffer

struct ProbePush {
    uint32_t width, height;
    int32_t samples, copy_depth;
};

}  // namespace

MsaaProbePass::MsaaProbePass(const PassServices& services)
    : services_(services),
      nearest_(vk::nearest_clamp_sampler(services.context, "msaa probe")),
      pipeline_(services, "msaa_probe.comp", "msaa probe") {
    set_ = make_readback_set(services.context, 2, sizeof(ProbePush), "msaa probe");
}

void MsaaProbePass::rebuild_pipelines(vk::DestroyList& retired) {
    pipeline_.rebuild(retired);
}

void MsaaProbePass::on_sample_count_changed(VkSampleCountFlagBits samples) {
    if (samples == VK_SAMPLE_COUNT_1_BIT) services_.readback.release(kBuffer);
}

void MsaaProbePass::add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) {
    out_ = {};
    const bool full = reads_back_fully(in.read_back);
    if (!in.options.msaa() || !full) return;  // the exact count reads every sample: costly
    pipeline_.get(set_.layout.handle());      // built now, not while the frame records
    const bool copy_depth = in.read_back == ReadBack::WithMsaaDepth;
    const VkExtent2D extent = graph.resources()[res.msaa_depth.index].extent;
    depth_values_ =
        copy_depth ? VkDeviceSize(extent.width) * extent.height * uint32_t(in.options.samples) : 0;
    const graph::BufferHandle out = services_.readback.import_storage(
        graph, kBuffer, kProbeHeaderBytes + depth_values_ * sizeof(float), kProbeHeaderBytes);
    out_ = out;
    const graph::ImageHandle depth = res.msaa_depth, color = res.msaa_hdr;
    const int32_t samples = int32_t(in.options.samples);
    struct Data {};
    graph.add_pass<Data>(
        {name(), graph::PassKind::Compute, role()},
        [&](graph::PassBuilder& b, Data&) {
            b.read(depth, graph::Access::Sampled);
            b.read(color, graph::Access::Sampled);
            b.write(out, graph::Access::StorageReadWrite);
        },
        [this, depth, color, out, samples, copy_depth](graph::PassContext& ctx, const Data&) {
            record(ctx, {depth, color, out}, samples, copy_depth);
        });
}

void MsaaProbePass::record(graph::PassContext& ctx, const Bound& bound, int32_t samples,
                           bool copy_depth) {
    const auto [depth, color, out] = bound;
    const VkExtent2D extent = ctx.extent(depth);
    vk::DescriptorWriter writer;
    writer.image(0, ctx.view(depth), nearest_.handle(), ctx.layout(depth))
        .image(1, ctx.view(color), nearest_.handle(), ctx.layout(color))
        .buffer(2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, ctx.buffer(out));
    writer.update(services_.context.device(), set_.set);
    VkCommandBuffer cmd = ctx.cmd();
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_.get(set_.layout.handle()));
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, set_.layout.handle(), 0, 1,
                            &set_.set, 0, nullptr);
    const ProbePush push{extent.width, extent.height, samples, copy_depth ? 1 : 0};
    vkCmdPushConstants(cmd, set_.layout.handle(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push,
                       &push);
    vkCmdDispatch(cmd, group_count(extent.width), group_count(extent.height), 1);
}

void MsaaProbePass::collect(const FrameCollect& c, std::span<PassResult>, FrameResult& frame) {
    const std::span<const std::byte> bytes = c.readback.buffer_bytes(out_);
    if (bytes.size() < kProbeHeaderBytes) return;
    uint32_t edges = 0;
    std::memcpy(&edges, bytes.data(), sizeof edges);
    frame.msaa.edge_pixels = edges;
    frame.msaa.depth_samples.resize(depth_values_);
    if (depth_values_)
        std::memcpy(frame.msaa.depth_samples.data(), bytes.data() + kProbeHeaderBytes,
                    depth_values_ * sizeof(float));
}

}  // namespace ds::passes
