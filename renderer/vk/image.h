#pragma once
// VkImage + memory + a view of every mip level, and VkSampler; move-only.
#include <cstdint>

#include <vulkan/vulkan.h>

#include "renderer/format/format.h"
#include "renderer/vk/memory.h"

namespace ds::vk {

class Context;

struct ImageDesc {
    uint32_t width = 1;
    uint32_t height = 1;
    uint32_t mip_levels = 1;
    VkFormat format = VK_FORMAT_UNDEFINED;
    VkImageUsageFlags usage = 0;
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
    const char* name = nullptr;
};

uint32_t mip_level_count(uint32_t width, uint32_t height);  // full chain down to 1x1
// Every aspect of the format (barriers), from the format table; the view of a depth/stencil
// format names depth only (a sampled view may name one aspect), its attachment view both.
using format::aspect_flags;

class Image {
  public:
    Image() = default;
    Image(Context& context, const ImageDesc& desc);  // throws ds::Error
    ~Image() { reset(); }
    Image(Image&& other) noexcept { *this = std::move(other); }
    Image& operator=(Image&& other) noexcept;
    Image(const Image&) = delete;
    Image& operator=(const Image&) = delete;

    void reset();
    explicit operator bool() const { return image_ != VK_NULL_HANDLE; }
    VkImage handle() const { return image_; }
    VkImageView view() const { return view_; }
    // What a rendering attaches: of a depth/stencil attachment image, a view of both aspects, so
    // a render pass's layout transitions move both, as every barrier does; else view().
    VkImageView attachment_view() const { return attachment_view_ ? attachment_view_ : view_; }
    VkFormat format() const { return desc_.format; }
    uint32_t width() const { return desc_.width; }
    uint32_t height() const { return desc_.height; }
    VkExtent2D extent() const { return {desc_.width, desc_.height}; }
    uint32_t mip_levels() const { return desc_.mip_levels; }
    VkSampleCountFlagBits samples() const { return desc_.samples; }
    VkImageAspectFlags aspect() const { return aspect_flags(desc_.format); }
    bool lazily_allocated() const { return allocation_.lazily_allocated; }

  private:
    Context* context_ = nullptr;
    VkImage image_ = VK_NULL_HANDLE;
    VkImageView view_ = VK_NULL_HANDLE;
    VkImageView attachment_view_ = VK_NULL_HANDLE;  // depth/stencil attachments only
    ImageDesc desc_;
    Allocation allocation_;
};

class Sampler {
  public:
    Sampler() = default;
    Sampler(Context& context, const VkSamplerCreateInfo& info, const char* name = nullptr);
    ~Sampler() { reset(); }
    Sampler(Sampler&& other) noexcept { *this = std::move(other); }
    Sampler& operator=(Sampler&& other) noexcept;
    Sampler(const Sampler&) = delete;
    Sampler& operator=(const Sampler&) = delete;

    void reset();
    VkSampler handle() const { return sampler_; }

  private:
    VkDevice device_ = VK_NULL_HANDLE;
    VkSampler sampler_ = VK_NULL_HANDLE;
};

// Nearest, clamp to edge, no mips: for shaders that read exact texels (texelFetch, resolves).
Sampler nearest_clamp_sampler(Context& context, const char* name);

}  // namespace ds::vk
