#pragma once
// The one table of VkFormat facts (name, texel size, channels, aspects, numeric kind) for the
// formats depthscope creates, samples or decodes: every layer (vk, graph, view, capture)
// reads them here, so they cannot disagree. Vulkan's C format utilities are not packaged in
// Debian 12. Only Vulkan's enums and flag types: no Vulkan calls, so any layer may use it.
#include <cstdint>
#include <span>
#include <string>

#include <vulkan/vulkan.h>

namespace ds::format {

// How the colour (or depth) channels read in a shader. Stencil is always unsigned integer.
enum class Numeric : uint8_t {
    Unorm,
    Snorm,
    Uint,
    Sint,
    Float,  // SFLOAT and UFLOAT
    Srgb,   // UNORM with the sRGB transfer function (alpha linear)
};

struct Info {
    VkFormat format = VK_FORMAT_UNDEFINED;
    const char* name = "";  // "R8G8B8A8_UNORM": the enum's name without VK_FORMAT_
    uint32_t bytes = 0;     // texel block size (Vulkan's: D32_SFLOAT_S8_UINT is 5)
    // Meaningful channels: 1 for depth, stencil and R formats, 2 for RG, 3 for RGB and
    // B10G11R11, 4 for the rest (A2B10G10R10 included).
    uint32_t channels = 0;
    VkImageAspectFlags aspects = VK_IMAGE_ASPECT_COLOR_BIT;
    Numeric numeric = Numeric::Unorm;
    uint32_t depth_bits = 0;  // 16, 24 or 32 for formats with depth, else 0
};

// Every row, in no particular order (VK_FORMAT_UNDEFINED has none).
std::span<const Info> table();
// The row of `format`; null for formats not in the table.
const Info* find(VkFormat format);

// "R8G8B8A8_UNORM"; "UNDEFINED"; "VkFormat(N)" for formats not in the table.
std::string name(VkFormat format);
// Texel block size in bytes; 0 for formats not in the table.
uint32_t bytes_per_texel(VkFormat format);
// DEPTH and/or STENCIL for depth/stencil formats; COLOR otherwise (unknown formats too).
VkImageAspectFlags aspect_flags(VkFormat format);
bool has_depth(VkFormat format);
// 16, 24 or 32 for formats with depth; 0 otherwise (and for formats not in the table).
uint32_t depth_bits(VkFormat format);
bool has_stencil(VkFormat format);
// Read as integers in a shader (usampler / isampler): UINT and SINT formats, S8_UINT included.
bool is_integer(VkFormat format);
bool is_srgb(VkFormat format);

}  // namespace ds::format
