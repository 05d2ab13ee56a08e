// The one table of VkFormat facts (renderer/format): every format the renderer names has a row,
// and the rows agree with Vulkan-Hpp's format traits (a second, independent source).
#include <set>
#include <string>

#include <gtest/gtest.h>
#include <vulkan/vulkan_format_traits.hpp>

#include "renderer/format/format.h"

namespace {

namespace format = ds::format;

TEST(FormatTable, EveryFormatTheGraphDumpNamesHasARow) {
    // The formats the graph dump printed by name before the table (the graph's images, depth
    // candidates, the display and swapchain formats).
    const std::pair<VkFormat, const char*> named[] = {
        {VK_FORMAT_R8_UNORM, "R8_UNORM"},
        {VK_FORMAT_R8G8_UNORM, "R8G8_UNORM"},
        {VK_FORMAT_R8G8B8A8_UNORM, "R8G8B8A8_UNORM"},
        {VK_FORMAT_R8G8B8A8_SRGB, "R8G8B8A8_SRGB"},
        {VK_FORMAT_B8G8R8A8_UNORM, "B8G8R8A8_UNORM"},
        {VK_FORMAT_B8G8R8A8_SRGB, "B8G8R8A8_SRGB"},
        {VK_FORMAT_A2B10G10R10_UNORM_PACK32, "A2B10G10R10_UNORM_PACK32"},
        {VK_FORMAT_B10G11R11_UFLOAT_PACK32, "B10G11R11_UFLOAT_PACK32"},
        {VK_FORMAT_R16_SFLOAT, "R16_SFLOAT"},
        {VK_FORMAT_R16G16_SFLOAT, "R16G16_SFLOAT"},
        {VK_FORMAT_R16G16B16A16_SFLOAT, "R16G16B16A16_SFLOAT"},
        {VK_FORMAT_R32_UINT, "R32_UINT"},
        {VK_FORMAT_R32_SFLOAT, "R32_SFLOAT"},
        {VK_FORMAT_R32G32_SFLOAT, "R32G32_SFLOAT"},
        {VK_FORMAT_R32G32B32A32_SFLOAT, "R32G32B32A32_SFLOAT"},
        {VK_FORMAT_D16_UNORM, "D16_UNORM"},
        {VK_FORMAT_D32_SFLOAT, "D32_SFLOAT"},
        {VK_FORMAT_D24_UNORM_S8_UINT, "D24_UNORM_S8_UINT"},
        {VK_FORMAT_D32_SFLOAT_S8_UINT, "D32_SFLOAT_S8_UINT"},
    };
    for (const auto& [f, text] : named) {
        const format::Info* info = format::find(f);
        ASSERT_NE(info, nullptr) << text;
        EXPECT_STREQ(info->name, text);
        EXPECT_EQ(format::name(f), text);
    }
    EXPECT_EQ(format::name(VK_FORMAT_UNDEFINED), "UNDEFINED");
    EXPECT_EQ(format::name(VK_FORMAT_ASTC_4x4_UNORM_BLOCK), "VkFormat(157)");
}

TEST(FormatTable, BytesPerTexel) {
    EXPECT_EQ(format::bytes_per_texel(VK_FORMAT_D32_SFLOAT), 4u);
    EXPECT_EQ(format::bytes_per_texel(VK_FORMAT_R32_UINT), 4u);
    EXPECT_EQ(format::bytes_per_texel(VK_FORMAT_R16G16B16A16_SFLOAT), 8u);
    EXPECT_EQ(format::bytes_per_texel(VK_FORMAT_A2B10G10R10_UNORM_PACK32), 4u);
    EXPECT_EQ(format::bytes_per_texel(VK_FORMAT_R8_UNORM), 1u);
    EXPECT_EQ(format::bytes_per_texel(VK_FORMAT_UNDEFINED), 0u);
}

// Vulkan-Hpp's spelling of a numeric format ("UNORM", "SFLOAT", ...) for a row's kind.
bool same_numeric(format::Numeric numeric, const std::string& hpp) {
    switch (numeric) {
        case format::Numeric::Unorm:
            return hpp == "UNORM";
        case format::Numeric::Snorm:
            return hpp == "SNORM";
        case format::Numeric::Uint:
            return hpp == "UINT";
        case format::Numeric::Sint:
            return hpp == "SINT";
        case format::Numeric::Float:
            return hpp == "SFLOAT" || hpp == "UFLOAT";
        case format::Numeric::Srgb:
            return hpp == "SRGB";
    }
    return false;
}

TEST(FormatTable, RowsAreUniqueAndAgreeWithVulkanHppTraits) {
    std::set<VkFormat> formats;
    std::set<std::string> names;
    for (const format::Info& info : format::table()) {
        const auto f = vk::Format(info.format);
        const uint8_t components = vk::componentCount(f);
        EXPECT_TRUE(formats.insert(info.format).second) << info.name;
        EXPECT_TRUE(names.insert(info.name).second) << info.name;
        EXPECT_EQ(info.bytes, vk::blockSize(f)) << info.name;
        EXPECT_TRUE(same_numeric(info.numeric, vk::componentNumericFormat(f, 0))) << info.name;
        bool stencil = false;
        for (uint8_t c = 0; c < components; ++c)
            stencil |= std::string(vk::componentName(f, c)) == "S";
        EXPECT_EQ(stencil, format::has_stencil(info.format)) << info.name;
        if (format::has_depth(info.format)) {
            EXPECT_STREQ(vk::componentName(f, 0), "D") << info.name;
            EXPECT_EQ(info.depth_bits, vk::componentBits(f, 0)) << info.name;
        } else {
            EXPECT_EQ(info.depth_bits, 0u) << info.name;
        }
        // Depth and stencil formats show one quantity; colour formats every component.
        const bool colour = info.aspects == VK_IMAGE_ASPECT_COLOR_BIT;
        EXPECT_EQ(info.channels, colour ? uint32_t(components) : 1u) << info.name;
    }
}

TEST(FormatTable, Aspects) {
    EXPECT_EQ(format::aspect_flags(VK_FORMAT_D32_SFLOAT),
              VkImageAspectFlags(VK_IMAGE_ASPECT_DEPTH_BIT));
    EXPECT_EQ(format::aspect_flags(VK_FORMAT_S8_UINT),
              VkImageAspectFlags(VK_IMAGE_ASPECT_STENCIL_BIT));
    EXPECT_EQ(format::aspect_flags(VK_FORMAT_D24_UNORM_S8_UINT),
              VkImageAspectFlags(VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT));
    EXPECT_EQ(format::aspect_flags(VK_FORMAT_R8G8B8A8_UNORM),
              VkImageAspectFlags(VK_IMAGE_ASPECT_COLOR_BIT));
    // Formats the table does not know are colour (as the vk layer always treated them).
    EXPECT_EQ(format::aspect_flags(VK_FORMAT_ASTC_4x4_UNORM_BLOCK),
              VkImageAspectFlags(VK_IMAGE_ASPECT_COLOR_BIT));
    EXPECT_TRUE(format::has_stencil(VK_FORMAT_D16_UNORM_S8_UINT));
    EXPECT_FALSE(format::has_stencil(VK_FORMAT_X8_D24_UNORM_PACK32));
    EXPECT_TRUE(format::has_depth(VK_FORMAT_X8_D24_UNORM_PACK32));
    EXPECT_FALSE(format::has_depth(VK_FORMAT_R32_SFLOAT));
}

TEST(FormatTable, NumericKinds) {
    EXPECT_TRUE(format::is_integer(VK_FORMAT_R32_UINT));
    EXPECT_TRUE(format::is_integer(VK_FORMAT_R16_SINT));
    EXPECT_FALSE(format::is_integer(VK_FORMAT_R32_SFLOAT));
    EXPECT_FALSE(format::is_integer(VK_FORMAT_R8_UNORM));
    EXPECT_FALSE(format::is_integer(VK_FORMAT_D32_SFLOAT));
    EXPECT_TRUE(format::is_srgb(VK_FORMAT_R8G8B8A8_SRGB));
    EXPECT_TRUE(format::is_srgb(VK_FORMAT_A8B8G8R8_SRGB_PACK32));
    EXPECT_FALSE(format::is_srgb(VK_FORMAT_R8G8B8A8_UNORM));
    EXPECT_FALSE(format::is_srgb(VK_FORMAT_UNDEFINED));
}

TEST(FormatTable, Channels) {
    EXPECT_EQ(format::find(VK_FORMAT_D32_SFLOAT_S8_UINT)->channels, 1u);
    EXPECT_EQ(format::find(VK_FORMAT_R16G16_SFLOAT)->channels, 2u);
    EXPECT_EQ(format::find(VK_FORMAT_B10G11R11_UFLOAT_PACK32)->channels, 3u);
    EXPECT_EQ(format::find(VK_FORMAT_A2B10G10R10_UNORM_PACK32)->channels, 4u);
}

}  // namespace
