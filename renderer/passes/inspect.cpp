#include "renderer/passes/inspect.h"

#include <cstring>
#include <string>
#include <utility>

#include "renderer/format/format.h"
#include "renderer/readback/host_readback.h"

namespace ds::passes {
namespace {

constexpr VkFormat kTexelFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
constexpr const char* kShader = "inspect.comp";
constexpr const char* kFinal = "final";  // read back as it is (ReadbackCopyPass)

ComputeKernel make_kernel(const PassServices& services) {
    return ComputeKernel(services, kShader, {KernelBinding::Sampled, KernelBinding::Storage},
                         sizeof(int32_t));
}

size_t index_of(bool uint_source, bool multisampled) {
    return (uint_source ? 2u : 0u) + (multisampled ? 1u : 0u);
}

std::vector<shader::Define> defines_of(size_t index) {
    return {{"UINT_SOURCE", index & 2u ? "1" : "0"}, {"MULTISAMPLED", index & 1u ? "1" : "0"}};
}

}  // namespace

InspectPass::InspectPass(const PassServices& services)
    : services_(services),
      kernels_{make_kernel(services), make_kernel(services), make_kernel(services),
               make_kernel(services)} {}

ComputeKernel& InspectPass::kernel(bool uint_source, bool multisampled) {
    const size_t i = index_of(uint_source, multisampled);
    if (!built_[i]) {  // built on first use: most sessions never inspect an integer image
        vk::DestroyList nothing_in_flight;
        kernels_[i].rebuild(nothing_in_flight, defines_of(i));
        built_[i] = true;
    }
    return kernels_[i];
}

void InspectPass::rebuild_pipelines(vk::DestroyList& retired) {
    std::array<std::optional<ComputeKernel::Prepared>, 4> prepared;
    for (size_t i = 0; i < kernels_.size(); ++i)
        if (built_[i]) prepared[i] = kernels_[i].prepare(defines_of(i));
    for (size_t i = 0; i < kernels_.size(); ++i)
        if (prepared[i]) kernels_[i].install(std::move(*prepared[i]), retired);
}

void InspectPass::add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources&) {
    texels_ = {};
    const std::string& wanted = in.inspect.resource;
    if (wanted.empty() || wanted == kFinal) return;
    const graph::ImageHandle source = graph.find_image(wanted);
    if (!source.valid()) return;
    const graph::ResourceInfo& info = graph.resources()[source.index];
    const VkExtent2D extent = info.extent;
    const uint32_t samples = uint32_t(info.image.samples);
    info_ = InspectedImage{};
    info_.name = wanted;
    info_.format = info.image.format;
    info_.semantic = info.image.semantic;
    info_.width = extent.width;
    info_.height = extent.height;
    info_.samples = samples;
    info_.sample = in.inspect.sample < samples ? in.inspect.sample : 0;
    ComputeKernel& k = kernel(format::is_integer(info_.format), samples > 1);
    const int32_t sample_index = int32_t(info_.sample);
    graph.add_pass(
        name(),
        [&](graph::PassBuilder& b) {
            const graph::ImageHandle texels = b.create_image(
                "inspect_texels", {.format = kTexelFormat,
                                   .size = graph::ImageSize::fixed(extent.width, extent.height),
                                   .semantic = graph::Semantic::Other});
            texels_ = texels;
            b.read(source, graph::Access::Sampled);
            b.write(texels, graph::Access::StorageWrite);
            return [&k, source, texels, sample_index, extent, frame_set = in.frame_set,
                    frame = in.frame_number](graph::PassContext& ctx) {
                const BoundImage images[] = {{ctx.view(source), ctx.layout(source)},
                                             {ctx.view(texels), ctx.layout(texels)}};
                k.dispatch(ctx.cmd(), frame_set, frame, images, &sample_index, extent);
            };
        },
        graph::PassKind::Compute);
    services_.readback.add_copy_pass(graph, "readback_inspect", {texels_});
}

void InspectPass::collect(const FrameCollect& c, std::span<PassResult>, FrameResult& frame) {
    const std::span<const std::byte> bytes = c.readback.image_bytes(texels_);
    if (bytes.empty()) return;
    InspectedImage image = info_;
    image.texels.resize(size_t(image.width) * image.height * 4);
    std::memcpy(image.texels.data(), bytes.data(),
                std::min(bytes.size(), image.texels.size() * sizeof(float)));
    frame.inspected = std::move(image);
}

}  // namespace ds::passes
