#include "renderer/readback/host_readback.h"

#include <cstring>

#include "renderer/common/error.h"
#include "renderer/format/format.h"
#include "renderer/vk/context.h"

namespace ds {
namespace {

// Bytes one texel takes in a buffer copy of its depth (or colour) aspect: depth copies out
// as 2 bytes (D16) or 4 (D24 in the low bits of a word, D32 as a float), whatever stencil the
// format has.
VkDeviceSize copy_texel_bytes(VkFormat format) {
    if (const uint32_t depth_bits = format::depth_bits(format)) return depth_bits == 16 ? 2 : 4;
    return format::bytes_per_texel(format);
}

// The previous frame's host read of this buffer finished before its fence signalled.
graph::ExternalState host_wrote() {
    return {VK_IMAGE_LAYOUT_UNDEFINED, VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_WRITE_BIT};
}

}  // namespace

void HostReadback::begin_frame(vk::DestroyList& retired) {
    retired_ = &retired;
    frame_.clear();
}

vk::Buffer& HostReadback::buffer(const std::string& name, VkDeviceSize bytes,
                                 VkBufferUsageFlags usage) {
    vk::Buffer& b = buffers_[name];
    if (!b || b.size() != bytes) {
        if (b) retired_->defer(std::move(b));
        b = vk::Buffer(context_, {bytes, usage, vk::MemoryUsage::Readback, name.c_str()});
    }
    return b;
}

graph::BufferHandle HostReadback::declare_copy(graph::RenderGraph& graph,
                                               graph::PassBuilder& builder,
                                               graph::ImageHandle image) {
    const graph::ResourceInfo& info = graph.resources()[image.index];
    if (info.image.samples != VK_SAMPLE_COUNT_1_BIT)
        throw Error("read-back: '" + info.name + "' is multisampled and cannot be copied");
    const VkDeviceSize bytes =
        VkDeviceSize(info.extent.width) * info.extent.height * copy_texel_bytes(info.image.format);
    const std::string name = "readback_" + info.name;
    vk::Buffer& b = buffer(name, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    graph::ExternalBuffer ext;
    ext.buffer = b.handle();
    ext.size = bytes;
    ext.initial = graph::ExternalState::host_read();  // last frame's data was read, then fenced
    ext.final = graph::ExternalState::host_read();
    const graph::BufferHandle handle = graph.import_buffer(name, ext);
    builder.read(image, graph::Access::TransferSrc);
    builder.write(handle, graph::Access::TransferDst);
    frame_[image.index] = {&b, bytes};
    return handle;
}

void HostReadback::add_copy_pass(graph::RenderGraph& graph, const std::string& name,
                                 std::vector<graph::ImageHandle> images) {
    struct Data {
        std::vector<graph::ImageHandle> images;
        std::vector<graph::BufferHandle> targets;
    };
    graph.add_pass<Data>(
        {name, graph::PassKind::Transfer, graph::PassRole::ReadBack},
        [&](graph::PassBuilder& b, Data& d) {
            for (graph::ImageHandle image : images)
                d.targets.push_back(declare_copy(graph, b, image));
            d.images = std::move(images);
        },
        [this](graph::PassContext& ctx, const Data& d) {
            for (size_t i = 0; i < d.images.size(); ++i)
                record_copy(ctx, d.images[i], d.targets[i]);
        });
}

void HostReadback::record_copy(graph::PassContext& ctx, graph::ImageHandle image,
                               graph::BufferHandle buffer) const {
    const VkExtent2D extent = ctx.extent(image);
    const VkImageAspectFlags aspect = format::aspect_flags(ctx.format(image));
    VkBufferImageCopy region{};  // bufferRowLength 0: tightly packed, row 0 = top
    region.imageSubresource = {aspect & ~VkImageAspectFlags(VK_IMAGE_ASPECT_STENCIL_BIT), 0, 0, 1};
    region.imageExtent = {extent.width, extent.height, 1};
    vkCmdCopyImageToBuffer(ctx.cmd(), ctx.image(image), ctx.layout(image), ctx.buffer(buffer), 1,
                           &region);
}

graph::BufferHandle HostReadback::import_storage(graph::RenderGraph& graph, const std::string& name,
                                                 VkDeviceSize bytes, VkDeviceSize zeroed) {
    // Shaders write it; transfer passes may fill or copy into it too.
    vk::Buffer& b =
        buffer(name, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    if (zeroed) {
        const std::vector<std::byte> zeros(zeroed);
        b.write(zeros.data(), zeros.size());  // flushed; the submit makes it visible
    }
    graph::ExternalBuffer ext;
    ext.buffer = b.handle();
    ext.size = bytes;
    ext.initial = host_wrote();
    ext.final = graph::ExternalState::host_read();
    const graph::BufferHandle handle = graph.import_buffer(name, ext);
    frame_[handle.index] = {&b, bytes};
    return handle;
}

std::span<const std::byte> HostReadback::bytes_of(uint32_t resource) const {
    const auto it = frame_.find(resource);
    if (it == frame_.end()) return {};
    it->second.buffer->invalidate();
    return {it->second.buffer->mapped(), size_t(it->second.bytes)};
}

std::span<const std::byte> HostReadback::image_bytes(graph::ImageHandle image) const {
    return image.valid() ? bytes_of(image.index) : std::span<const std::byte>{};
}

std::span<const std::byte> HostReadback::buffer_bytes(graph::BufferHandle buffer) const {
    return buffer.valid() ? bytes_of(buffer.index) : std::span<const std::byte>{};
}

std::optional<uint64_t> HostReadback::u32_sum(graph::ImageHandle image) const {
    const std::span<const std::byte> bytes = image_bytes(image);
    if (bytes.empty()) return std::nullopt;
    uint64_t sum = 0;
    for (size_t i = 0; i + 4 <= bytes.size(); i += 4) {
        uint32_t v;
        std::memcpy(&v, bytes.data() + i, 4);
        sum += v;
    }
    return sum;
}

void HostReadback::release(const std::string& name) {
    const auto it = buffers_.find(name);
    if (it == buffers_.end()) return;
    for (auto e = frame_.begin(); e != frame_.end();)
        e = e->second.buffer == &it->second ? frame_.erase(e) : std::next(e);
    if (retired_) retired_->defer(std::move(it->second));
    buffers_.erase(it);
}

void HostReadback::reset() {
    frame_.clear();
    buffers_.clear();
}

}  // namespace ds
