#include "renderer/vk/image.h"

#include <algorithm>
#include <bit>
#include <string>
#include <utility>

#include "renderer/common/error.h"
#include "renderer/vk/capabilities.h"
#include "renderer/vk/check.h"
#include "renderer/vk/context.h"

namespace ds::vk {

uint32_t mip_level_count(uint32_t width, uint32_t height) {
    return uint32_t(std::bit_width(std::max({width, height, 1u})));
}

namespace {

// "image 'hdr' 16384x16384 R16G16B16A16_SFLOAT x4": how an error names the image.
std::string describe(const ImageDesc& desc) {
    std::string text = std::string("image '") + (desc.name ? desc.name : "unnamed") + "' " +
                       std::to_string(desc.width) + "x" + std::to_string(desc.height) + " " +
                       format::name(desc.format);
    if (desc.samples != VK_SAMPLE_COUNT_1_BIT) text += " x" + std::to_string(int(desc.samples));
    return text;
}

// Before vkCreateImage, whose behaviour past these limits is undefined: the device's own
// answer for this format, usage and sample count (maxExtent, sampleCounts, maxResourceSize)
// and maxImageDimension2D as the context has it (DEPTHSCOPE_DEVICE_LIMITS lowers it).
void check_image_limits(const Context& context, const VkImageCreateInfo& info,
                        const ImageDesc& desc) {
    VkImageFormatProperties props{};
    const VkResult result = vkGetPhysicalDeviceImageFormatProperties(
        context.physical_device(), info.format, info.imageType, info.tiling, info.usage, info.flags,
        &props);
    if (result != VK_SUCCESS)
        throw Error(describe(desc) + ": the device cannot create it with this usage (" +
                    result_name(result) + ")");
    const uint32_t limit = std::min(
        {props.maxExtent.width, props.maxExtent.height, context.limits().maxImageDimension2D});
    if (desc.width > limit || desc.height > limit)
        throw Error(describe(desc) + " exceeds the device's largest 2D image, " +
                    std::to_string(limit) + "x" + std::to_string(limit) + " (maxImageDimension2D " +
                    std::to_string(context.limits().maxImageDimension2D) + ")");
    if (!(props.sampleCounts & desc.samples))
        throw Error(describe(desc) + ": the device supports sample counts " +
                    sample_counts_text(props.sampleCounts) + " for this format");
    const uint64_t texels = uint64_t(desc.width) * desc.height * uint32_t(desc.samples);
    const uint64_t bytes = texels * std::max(format::bytes_per_texel(desc.format), 1u);
    if (bytes > props.maxResourceSize)
        throw Error(describe(desc) + " needs " + bytes_text(bytes) +
                    ", more than the device's maxResourceSize (" +
                    bytes_text(props.maxResourceSize) + ")");
}

}  // namespace

Image::Image(Context& context, const ImageDesc& desc) : context_(&context), desc_(desc) {
    auto info = make<VkImageCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO);
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = desc.format;
    info.extent = {desc.width, desc.height, 1};
    info.mipLevels = desc.mip_levels;
    info.arrayLayers = 1;
    info.samples = desc.samples;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = desc.usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkDevice device = context.device();
    check_image_limits(context, info, desc);
    check(vkCreateImage(device, &info, nullptr, &image_),
          ("vkCreateImage for " + describe(desc)).c_str());
    try {
        auto dedicated =
            make<VkMemoryDedicatedRequirements>(VK_STRUCTURE_TYPE_MEMORY_DEDICATED_REQUIREMENTS);
        auto req = make<VkMemoryRequirements2>(VK_STRUCTURE_TYPE_MEMORY_REQUIREMENTS_2, &dedicated);
        auto req_info = make<VkImageMemoryRequirementsInfo2>(
            VK_STRUCTURE_TYPE_IMAGE_MEMORY_REQUIREMENTS_INFO_2);
        req_info.image = image_;
        vkGetImageMemoryRequirements2(device, &req_info, &req);
        AllocationRequest request;
        request.requirements = req.memoryRequirements;
        // A transient attachment (tile memory only) takes lazily allocated memory if any.
        request.usage = desc.usage & VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT ? MemoryUsage::Lazy
                                                                             : MemoryUsage::GpuOnly;
        request.kind = ResourceKind::Optimal;
        request.dedicated =
            dedicated.prefersDedicatedAllocation || dedicated.requiresDedicatedAllocation;
        request.image = image_;
        request.name = desc.name;
        allocation_ = context.allocator().allocate(request);
        check(vkBindImageMemory(device, image_, allocation_.memory, allocation_.offset),
              "vkBindImageMemory");

        auto view = make<VkImageViewCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO);
        view.image = image_;
        view.viewType = VK_IMAGE_VIEW_TYPE_2D;
        view.format = desc.format;
        // A sampled view of a depth/stencil image may name only one aspect.
        VkImageAspectFlags aspect = aspect_flags(desc.format);
        if (aspect & VK_IMAGE_ASPECT_DEPTH_BIT) aspect = VK_IMAGE_ASPECT_DEPTH_BIT;
        view.subresourceRange = {aspect, 0, desc.mip_levels, 0, 1};
        check(vkCreateImageView(device, &view, nullptr, &view_), "vkCreateImageView");
        if (aspect != aspect_flags(desc.format) &&
            (desc.usage & VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT)) {
            view.subresourceRange.aspectMask = aspect_flags(desc.format);
            check(vkCreateImageView(device, &view, nullptr, &attachment_view_),
                  "vkCreateImageView");
        }
    } catch (...) {
        reset();
        throw;
    }
    context.set_name(VK_OBJECT_TYPE_IMAGE, image_, desc.name);
    context.set_name(VK_OBJECT_TYPE_IMAGE_VIEW, view_, desc.name);
}

Image& Image::operator=(Image&& other) noexcept {
    if (this == &other) return *this;
    reset();
    context_ = std::exchange(other.context_, nullptr);
    image_ = std::exchange(other.image_, VK_NULL_HANDLE);
    view_ = std::exchange(other.view_, VK_NULL_HANDLE);
    attachment_view_ = std::exchange(other.attachment_view_, VK_NULL_HANDLE);
    desc_ = std::exchange(other.desc_, ImageDesc{});
    allocation_ = std::exchange(other.allocation_, Allocation{});
    return *this;
}

void Image::reset() {
    if (!context_) return;
    VkDevice device = context_->device();
    if (view_) context_->clear_name(VK_OBJECT_TYPE_IMAGE_VIEW, view_);
    if (image_) context_->clear_name(VK_OBJECT_TYPE_IMAGE, image_);
    if (view_) vkDestroyImageView(device, view_, nullptr);
    if (attachment_view_) vkDestroyImageView(device, attachment_view_, nullptr);
    if (image_) vkDestroyImage(device, image_, nullptr);
    context_->allocator().free(allocation_);
    view_ = attachment_view_ = VK_NULL_HANDLE;
    image_ = VK_NULL_HANDLE;
    context_ = nullptr;
}

Sampler::Sampler(Context& context, const VkSamplerCreateInfo& info, const char* name)
    : device_(context.device()) {
    check(vkCreateSampler(device_, &info, nullptr, &sampler_), "vkCreateSampler");
    context.set_name(VK_OBJECT_TYPE_SAMPLER, sampler_, name);
}

Sampler nearest_clamp_sampler(Context& context, const char* name) {
    auto info = make<VkSamplerCreateInfo>(VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO);
    info.magFilter = info.minFilter = VK_FILTER_NEAREST;
    info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    info.addressModeU = info.addressModeV = info.addressModeW =
        VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    info.maxLod = 0.0f;
    return Sampler(context, info, name);
}

Sampler& Sampler::operator=(Sampler&& other) noexcept {
    if (this == &other) return *this;
    reset();
    device_ = std::exchange(other.device_, VK_NULL_HANDLE);
    sampler_ = std::exchange(other.sampler_, VK_NULL_HANDLE);
    return *this;
}

void Sampler::reset() {
    if (sampler_) vkDestroySampler(device_, sampler_, nullptr);
    sampler_ = VK_NULL_HANDLE;
}

}  // namespace ds::vk
