#include "renderer/passes/msaa_samples.h"

#include "renderer/vk/capabilities.h"

#include <algorithm>
#include <cstring>

#include "renderer/readback/host_readback.h"
#include "renderer/vk/context.h"

namespace ds::passes {
namespace {

constexpr const char* kSamplesShader = "msaa_samples.comp";
constexpr const char* kSamplesBuffer = "msaa_samples";  // its HostReadback buffer

struct SamplesPush {
    int32_t origin[2];
    uint32_t size[2];
    int32_t samples;
};

LazyComputePipeline samples_pipeline(const PassServices& services, bool multisampled,
                                     bool surface_ids) {
    return LazyComputePipeline(
        services, kSamplesShader, "msaa samples",
        {{"MULTISAMPLED", multisampled ? "1" : "0"}, {"SURFACE_ID", surface_ids ? "1" : "0"}});
}

}  // namespace

MsaaSamplesPass::MsaaSamplesPass(const PassServices& services)
    : services_(services),
      nearest_(vk::nearest_clamp_sampler(services.context, "msaa samples")),
      pipelines_{samples_pipeline(services, false, false), samples_pipeline(services, false, true),
                 samples_pipeline(services, true, false), samples_pipeline(services, true, true)} {
    set_ = make_readback_set(services.context, 3, sizeof(SamplesPush), "msaa samples");
}

LazyComputePipeline& MsaaSamplesPass::pipeline(bool multisampled, bool surface_ids) {
    return pipelines_[(multisampled ? 2u : 0u) + (surface_ids ? 1u : 0u)];
}

void MsaaSamplesPass::rebuild_pipelines(vk::DestroyList& retired) {
    for (LazyComputePipeline& p : pipelines_) p.rebuild(retired);
}

void MsaaSamplesPass::configure(const FrameSetup& setup, FrameOptions& o) {
    if (setup.request.samples && o.prepass && !o.subpass && setup.device.geometry_shader)
        o.requests.surface_id = true;
}

void MsaaSamplesPass::add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) {
    out_ = {};
    if (!in.samples) return;
    const bool multi = in.options.msaa();
    Bound bound{multi ? res.msaa_depth : res.depth,
                multi ? res.msaa_hdr : res.hdr,
                multi ? res.msaa_surface_id : res.surface_id,
                {}};
    const VkExtent2D extent = graph.resources()[bound.depth.index].extent;
    // Clamped to the frame (Renderer::render refused a rectangle that starts outside it).
    rect_ = *in.samples;
    rect_.x = std::min(rect_.x, extent.width - 1);
    rect_.y = std::min(rect_.y, extent.height - 1);
    rect_.width = std::clamp(rect_.width, 1u, extent.width - rect_.x);
    rect_.height = std::clamp(rect_.height, 1u, extent.height - rect_.y);
    samples_ = uint32_t(in.options.samples);
    surface_ids_ = bound.surface.valid();
    pipeline(multi, surface_ids_).get(set_.layout.handle());  // built now, not while recording
    const VkDeviceSize bytes =
        VkDeviceSize(rect_.width) * rect_.height * samples_ * sizeof(SampleRecord);
    bound.out = services_.readback.import_storage(graph, kSamplesBuffer, bytes);
    out_ = bound.out;
    struct Data {};
    graph.add_pass<Data>(
        {name(), graph::PassKind::Compute, role()},
        [&](graph::PassBuilder& b, Data&) {
            b.read(bound.depth, graph::Access::Sampled);
            b.read(bound.color, graph::Access::Sampled);
            if (bound.surface.valid()) b.read(bound.surface, graph::Access::Sampled);
            b.write(bound.out, graph::Access::StorageWrite);
        },
        [this, bound, multi](graph::PassContext& ctx, const Data&) { record(ctx, bound, multi); });
}

void MsaaSamplesPass::record(graph::PassContext& ctx, const Bound& bound, bool multisampled) {
    // Without surface ids binding 2 is not read (SURFACE_ID=0); it still names a live image.
    const graph::ImageHandle surface = bound.surface.valid() ? bound.surface : bound.color;
    vk::DescriptorWriter writer;
    writer.image(0, ctx.view(bound.depth), nearest_.handle(), ctx.layout(bound.depth))
        .image(1, ctx.view(bound.color), nearest_.handle(), ctx.layout(bound.color))
        .image(2, ctx.view(surface), nearest_.handle(), ctx.layout(surface))
        .buffer(3, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, ctx.buffer(bound.out));
    writer.update(services_.context.device(), set_.set);
    VkCommandBuffer cmd = ctx.cmd();
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE,
                      pipeline(multisampled, surface_ids_).get(set_.layout.handle()));
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, set_.layout.handle(), 0, 1,
                            &set_.set, 0, nullptr);
    const SamplesPush push{
        {int32_t(rect_.x), int32_t(rect_.y)}, {rect_.width, rect_.height}, int32_t(samples_)};
    vkCmdPushConstants(cmd, set_.layout.handle(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push,
                       &push);
    vkCmdDispatch(cmd, group_count(rect_.width), group_count(rect_.height), 1);
}

void MsaaSamplesPass::collect(const FrameCollect& c, std::span<PassResult>, FrameResult& frame) {
    if (!out_.valid()) return;
    const std::span<const std::byte> bytes = c.readback.buffer_bytes(out_);
    MsaaSamples out;
    out.rect = rect_;
    out.samples = samples_;
    out.surface_ids = surface_ids_;
    const size_t count = size_t(rect_.width) * rect_.height * samples_;
    if (bytes.size() < count * sizeof(SampleRecord)) return;
    out.values.resize(count);
    for (size_t i = 0; i < count; ++i) {
        SampleRecord r;
        std::memcpy(&r, bytes.data() + i * sizeof r, sizeof r);
        out.values[i] = {r.surface, r.depth, r.color};
    }
    frame.slots.put(std::move(out));
}

}  // namespace ds::passes
