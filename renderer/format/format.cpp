#include "renderer/format/format.h"

#include <array>

namespace ds::format {
namespace {

constexpr VkImageAspectFlags kColor = VK_IMAGE_ASPECT_COLOR_BIT;
constexpr VkImageAspectFlags kDepth = VK_IMAGE_ASPECT_DEPTH_BIT;
constexpr VkImageAspectFlags kStencil = VK_IMAGE_ASPECT_STENCIL_BIT;
constexpr VkImageAspectFlags kDepthStencil = kDepth | kStencil;

using enum Numeric;

constexpr Info row(VkFormat format, const char* name, uint32_t bytes, uint32_t channels,
                   VkImageAspectFlags aspects, Numeric numeric, uint32_t depth_bits) {
    return {format, name, bytes, channels, aspects, numeric, depth_bits};
}

// The name is the enum's own spelling, so it cannot drift from the format.
#define DS_FORMAT(f, ...) row(VK_FORMAT_##f, #f, __VA_ARGS__)

// Columns: format, bytes per texel, channels, aspects, numeric kind, depth bits.
constexpr std::array kTable{
    // Depth and stencil.
    DS_FORMAT(D16_UNORM, 2, 1, kDepth, Unorm, 16),
    DS_FORMAT(X8_D24_UNORM_PACK32, 4, 1, kDepth, Unorm, 24),
    DS_FORMAT(D32_SFLOAT, 4, 1, kDepth, Float, 32),
    DS_FORMAT(S8_UINT, 1, 1, kStencil, Uint, 0),
    DS_FORMAT(D16_UNORM_S8_UINT, 3, 1, kDepthStencil, Unorm, 16),
    DS_FORMAT(D24_UNORM_S8_UINT, 4, 1, kDepthStencil, Unorm, 24),
    DS_FORMAT(D32_SFLOAT_S8_UINT, 5, 1, kDepthStencil, Float, 32),
    // One channel.
    DS_FORMAT(R8_UNORM, 1, 1, kColor, Unorm, 0),
    DS_FORMAT(R8_SNORM, 1, 1, kColor, Snorm, 0),
    DS_FORMAT(R8_UINT, 1, 1, kColor, Uint, 0),
    DS_FORMAT(R8_SINT, 1, 1, kColor, Sint, 0),
    DS_FORMAT(R8_SRGB, 1, 1, kColor, Srgb, 0),
    DS_FORMAT(R16_UNORM, 2, 1, kColor, Unorm, 0),
    DS_FORMAT(R16_SNORM, 2, 1, kColor, Snorm, 0),
    DS_FORMAT(R16_UINT, 2, 1, kColor, Uint, 0),
    DS_FORMAT(R16_SINT, 2, 1, kColor, Sint, 0),
    DS_FORMAT(R16_SFLOAT, 2, 1, kColor, Float, 0),
    DS_FORMAT(R32_UINT, 4, 1, kColor, Uint, 0),
    DS_FORMAT(R32_SINT, 4, 1, kColor, Sint, 0),
    DS_FORMAT(R32_SFLOAT, 4, 1, kColor, Float, 0),
    // Two channels.
    DS_FORMAT(R8G8_UNORM, 2, 2, kColor, Unorm, 0),
    DS_FORMAT(R8G8_SNORM, 2, 2, kColor, Snorm, 0),
    DS_FORMAT(R8G8_UINT, 2, 2, kColor, Uint, 0),
    DS_FORMAT(R8G8_SINT, 2, 2, kColor, Sint, 0),
    DS_FORMAT(R8G8_SRGB, 2, 2, kColor, Srgb, 0),
    DS_FORMAT(R16G16_UNORM, 4, 2, kColor, Unorm, 0),
    DS_FORMAT(R16G16_SNORM, 4, 2, kColor, Snorm, 0),
    DS_FORMAT(R16G16_UINT, 4, 2, kColor, Uint, 0),
    DS_FORMAT(R16G16_SINT, 4, 2, kColor, Sint, 0),
    DS_FORMAT(R16G16_SFLOAT, 4, 2, kColor, Float, 0),
    DS_FORMAT(R32G32_UINT, 8, 2, kColor, Uint, 0),
    DS_FORMAT(R32G32_SINT, 8, 2, kColor, Sint, 0),
    DS_FORMAT(R32G32_SFLOAT, 8, 2, kColor, Float, 0),
    // Three channels.
    DS_FORMAT(R8G8B8_UNORM, 3, 3, kColor, Unorm, 0),
    DS_FORMAT(R8G8B8_SRGB, 3, 3, kColor, Srgb, 0),
    DS_FORMAT(B8G8R8_UNORM, 3, 3, kColor, Unorm, 0),
    DS_FORMAT(B8G8R8_SRGB, 3, 3, kColor, Srgb, 0),
    DS_FORMAT(R16G16B16_SFLOAT, 6, 3, kColor, Float, 0),
    DS_FORMAT(R32G32B32_SFLOAT, 12, 3, kColor, Float, 0),
    DS_FORMAT(B10G11R11_UFLOAT_PACK32, 4, 3, kColor, Float, 0),
    DS_FORMAT(E5B9G9R9_UFLOAT_PACK32, 4, 3, kColor, Float, 0),
    // Four channels.
    DS_FORMAT(R8G8B8A8_UNORM, 4, 4, kColor, Unorm, 0),
    DS_FORMAT(R8G8B8A8_SRGB, 4, 4, kColor, Srgb, 0),
    DS_FORMAT(B8G8R8A8_UNORM, 4, 4, kColor, Unorm, 0),
    DS_FORMAT(B8G8R8A8_SRGB, 4, 4, kColor, Srgb, 0),
    DS_FORMAT(A8B8G8R8_SRGB_PACK32, 4, 4, kColor, Srgb, 0),
    DS_FORMAT(A2B10G10R10_UNORM_PACK32, 4, 4, kColor, Unorm, 0),
    DS_FORMAT(R16G16B16A16_SFLOAT, 8, 4, kColor, Float, 0),
    DS_FORMAT(R32G32B32A32_UINT, 16, 4, kColor, Uint, 0),
    DS_FORMAT(R32G32B32A32_SFLOAT, 16, 4, kColor, Float, 0),
};

#undef DS_FORMAT

}  // namespace

std::span<const Info> table() {
    return kTable;
}

const Info* find(VkFormat format) {
    for (const Info& info : kTable) {
        if (info.format == format) return &info;
    }
    return nullptr;
}

std::string name(VkFormat format) {
    if (format == VK_FORMAT_UNDEFINED) return "UNDEFINED";
    if (const Info* info = find(format)) return info->name;
    return "VkFormat(" + std::to_string(int(format)) + ")";
}

uint32_t bytes_per_texel(VkFormat format) {
    const Info* info = find(format);
    return info ? info->bytes : 0;
}

VkImageAspectFlags aspect_flags(VkFormat format) {
    const Info* info = find(format);
    return info ? info->aspects : kColor;
}

uint32_t depth_bits(VkFormat format) {
    const Info* info = find(format);
    return info ? info->depth_bits : 0;
}

bool has_depth(VkFormat format) {
    return (aspect_flags(format) & kDepth) != 0;
}

bool has_stencil(VkFormat format) {
    return (aspect_flags(format) & kStencil) != 0;
}

bool is_integer(VkFormat format) {
    const Info* info = find(format);
    return info && (info->numeric == Uint || info->numeric == Sint);
}

bool is_srgb(VkFormat format) {
    const Info* info = find(format);
    return info && info->numeric == Srgb;
}

}  // namespace ds::format
