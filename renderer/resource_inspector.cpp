#include "renderer/resource_inspector.h"

#include <cstring>
#include <string>
#include <utility>

#include "renderer/vk/barrier.h"
#include "renderer/vk/context.h"

namespace ds {
namespace {

constexpr VkFormat kTexelFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
constexpr const char* kShader = "inspect.comp";

bool is_integer(VkFormat format) {
    switch (format) {
        case VK_FORMAT_R8_UINT:
        case VK_FORMAT_R16_UINT:
        case VK_FORMAT_R32_UINT:
        case VK_FORMAT_R32G32_UINT:
        case VK_FORMAT_R32G32B32A32_UINT:
        case VK_FORMAT_R8_SINT:
        case VK_FORMAT_R16_SINT:
        case VK_FORMAT_R32_SINT:
            return true;
        default:
            return false;
    }
}

passes::ComputeKernel make_kernel(const passes::PassServices& services) {
    return passes::ComputeKernel(services, kShader,
                                 {passes::KernelBinding::Sampled, passes::KernelBinding::Storage},
                                 sizeof(int32_t));
}

size_t index_of(bool uint_source, bool multisampled) {
    return (uint_source ? 2u : 0u) + (multisampled ? 1u : 0u);
}

std::vector<shader::Define> defines_of(size_t index) {
    return {{"UINT_SOURCE", index & 2u ? "1" : "0"}, {"MULTISAMPLED", index & 1u ? "1" : "0"}};
}

}  // namespace

ResourceInspector::ResourceInspector(const passes::PassServices& services)
    : context_(services.context),
      kernels_{make_kernel(services), make_kernel(services), make_kernel(services),
               make_kernel(services)} {}

passes::ComputeKernel& ResourceInspector::kernel(bool uint_source, bool multisampled) {
    const size_t i = index_of(uint_source, multisampled);
    if (!built_[i]) {  // built on first use: most sessions never inspect an integer image
        vk::DestroyList nothing_in_flight;
        kernels_[i].rebuild(nothing_in_flight, defines_of(i));
        built_[i] = true;
    }
    return kernels_[i];
}

void ResourceInspector::rebuild_pipelines(vk::DestroyList& retired) {
    std::array<std::optional<passes::ComputeKernel::Prepared>, 4> prepared;
    for (size_t i = 0; i < kernels_.size(); ++i)
        if (built_[i]) prepared[i] = kernels_[i].prepare(defines_of(i));
    for (size_t i = 0; i < kernels_.size(); ++i)
        if (prepared[i]) kernels_[i].install(std::move(*prepared[i]), retired);
}

void ResourceInspector::ensure_target(VkExtent2D extent, vk::DestroyList& retired) {
    if (texels_ && texels_.width() == extent.width && texels_.height() == extent.height) return;
    if (texels_) retired.defer(std::move(texels_));
    if (readback_) retired.defer(std::move(readback_));
    texels_ = vk::Image(context_, {extent.width, extent.height, 1, kTexelFormat,
                                   VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                   VK_SAMPLE_COUNT_1_BIT, "inspect texels"});
    readback_ = vk::Buffer(context_, {VkDeviceSize(extent.width) * extent.height * 16,
                                      VK_BUFFER_USAGE_TRANSFER_DST_BIT, vk::MemoryUsage::Readback,
                                      "inspect read-back"});
}

bool ResourceInspector::add(graph::RenderGraph& graph, const passes::FrameInputs& in,
                            std::string_view name, uint32_t sample, vk::DestroyList& retired) {
    const graph::ImageHandle source = graph.find_image(name);
    if (!source.valid()) return false;
    const graph::ResourceInfo& info = graph.resources()[source.index];
    const VkExtent2D extent = info.extent;
    const uint32_t samples = uint32_t(info.image.samples);
    info_ = InspectedImage{};
    info_.name = std::string(name);
    info_.format = info.image.format;
    info_.semantic = info.image.semantic;
    info_.width = extent.width;
    info_.height = extent.height;
    info_.samples = samples;
    info_.sample = sample < samples ? sample : 0;
    ensure_target(extent, retired);

    graph::ExternalImage out;
    out.image = texels_.handle();
    out.view = texels_.view();
    out.desc = {.format = kTexelFormat,
                .size = graph::ImageSize::fixed(extent.width, extent.height),
                .semantic = graph::Semantic::Other};
    // The previous frame's copy read it last; its contents are not needed.
    out.initial = {VK_IMAGE_LAYOUT_UNDEFINED, VK_PIPELINE_STAGE_2_COPY_BIT,
                   VK_ACCESS_2_TRANSFER_READ_BIT};
    out.final = graph::ExternalState::transfer_src();
    const graph::ImageHandle target = graph.import_image("inspect_texels", out);

    passes::ComputeKernel& k = kernel(is_integer(info_.format), samples > 1);
    const int32_t sample_index = int32_t(info_.sample);
    graph.add_pass(
        kPassName,
        [&](graph::PassBuilder& b) {
            b.read(source, graph::Access::Sampled);
            b.write(target, graph::Access::StorageWrite);
            return [&k, source, target, sample_index, extent, frame_set = in.frame_set,
                    frame = in.frame_number](graph::PassContext& ctx) {
                const passes::BoundImage images[] = {{ctx.view(source), ctx.layout(source)},
                                                     {ctx.view(target), ctx.layout(target)}};
                k.dispatch(ctx.cmd(), frame_set, frame, images, &sample_index, extent);
            };
        },
        graph::PassKind::Compute);
    return true;
}

void ResourceInspector::record_read_back(VkCommandBuffer cmd) const {
    VkBufferImageCopy region{};  // tightly packed, row 0 = top
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {texels_.width(), texels_.height(), 1};
    vkCmdCopyImageToBuffer(cmd, texels_.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                           readback_.handle(), 1, &region);
    vk::memory_barrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                       VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
}

InspectedImage ResourceInspector::result() const {
    InspectedImage image = info_;
    readback_.invalidate();
    image.texels.resize(size_t(image.width) * image.height * 4);
    std::memcpy(image.texels.data(), readback_.mapped(), image.texels.size() * sizeof(float));
    return image;
}

}  // namespace ds
