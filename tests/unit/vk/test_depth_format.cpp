// Depth format selection (seed 001) over fake format properties.
#include <map>

#include <gtest/gtest.h>

#include "renderer/common/error.h"
#include "renderer/vk/capabilities.h"

namespace {

using ds::vk::choose_depth_format;
using ds::vk::kDepthFormatCandidates;
using ds::vk::kDepthFormatFeatures;

constexpr VkFormatFeatureFlags kAttachment = VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT;
constexpr VkFormatFeatureFlags kBoth = kDepthFormatFeatures;

// A device whose optimal-tiling features are given per format (others support nothing).
ds::vk::FormatQuery fake(std::map<VkFormat, VkFormatFeatureFlags> optimal,
                         std::map<VkFormat, VkFormatFeatureFlags> linear = {}) {
    return [=](VkFormat f) {
        VkFormatProperties p{};
        if (auto it = optimal.find(f); it != optimal.end()) p.optimalTilingFeatures = it->second;
        if (auto it = linear.find(f); it != linear.end()) p.linearTilingFeatures = it->second;
        return p;
    };
}

TEST(DepthFormat, PrefersD32WhenEverythingIsSupported) {
    auto query = fake({{VK_FORMAT_D32_SFLOAT, kBoth},
                       {VK_FORMAT_D32_SFLOAT_S8_UINT, kBoth},
                       {VK_FORMAT_D24_UNORM_S8_UINT, kBoth},
                       {VK_FORMAT_D16_UNORM, kBoth}});
    EXPECT_EQ(choose_depth_format(kDepthFormatCandidates, kBoth, query), VK_FORMAT_D32_SFLOAT);
    EXPECT_EQ(ds::vk::supported_formats(kDepthFormatCandidates, kBoth, query).size(), 4u);
}

TEST(DepthFormat, FollowsCandidateOrderNotQueryOrder) {
    auto query = fake({{VK_FORMAT_D16_UNORM, kBoth}, {VK_FORMAT_D24_UNORM_S8_UINT, kBoth}});
    EXPECT_EQ(choose_depth_format(kDepthFormatCandidates, kBoth, query),
              VK_FORMAT_D24_UNORM_S8_UINT);
}

TEST(DepthFormat, FallsBackWhenPreferredLacksARequiredFeature) {
    // D32 can be an attachment but not sampled: the renderer samples depth, so skip it.
    auto query = fake({{VK_FORMAT_D32_SFLOAT, kAttachment}, {VK_FORMAT_D32_SFLOAT_S8_UINT, kBoth}});
    EXPECT_EQ(choose_depth_format(kDepthFormatCandidates, kBoth, query),
              VK_FORMAT_D32_SFLOAT_S8_UINT);
    // With only the attachment bit required, D32 is fine again.
    EXPECT_EQ(choose_depth_format(kDepthFormatCandidates, kAttachment, query),
              VK_FORMAT_D32_SFLOAT);
}

TEST(DepthFormat, LinearTilingSupportDoesNotCount) {
    auto query = fake({{VK_FORMAT_D16_UNORM, kBoth}}, {{VK_FORMAT_D32_SFLOAT, kBoth}});
    EXPECT_EQ(choose_depth_format(kDepthFormatCandidates, kBoth, query), VK_FORMAT_D16_UNORM);
}

TEST(DepthFormat, NoneAvailableThrowsListingCandidates) {
    auto query = fake({{VK_FORMAT_D32_SFLOAT, VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT}});
    try {
        choose_depth_format(kDepthFormatCandidates, kBoth, query);
        FAIL() << "expected ds::Error";
    } catch (const ds::Error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("no supported depth format"), std::string::npos) << what;
        EXPECT_NE(what.find("D32_SFLOAT"), std::string::npos) << what;
        EXPECT_NE(what.find("D16_UNORM"), std::string::npos) << what;
    }
}

TEST(DepthFormat, StencilFormatsAreRecognised) {
    EXPECT_FALSE(ds::vk::has_stencil(VK_FORMAT_D32_SFLOAT));
    EXPECT_TRUE(ds::vk::has_stencil(VK_FORMAT_D32_SFLOAT_S8_UINT));
    EXPECT_TRUE(ds::vk::has_stencil(VK_FORMAT_D24_UNORM_S8_UINT));
    EXPECT_FALSE(ds::vk::has_stencil(VK_FORMAT_D16_UNORM));
}

}  // namespace
