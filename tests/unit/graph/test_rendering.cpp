// The rendering the graph begins for a pass (rendering.h) and the subpass plan it makes of the
// same declarations (subpass.h assign_subpasses), with no device: attachments as a pass
// declares them (PassBuilder::color / depth / resolve / input / unused_color), load and store
// ops from the whole frame, pipelines' targets, the aspects the graph moves, and which runs of
// passes become one render pass.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "renderer/common/error.h"
#include "renderer/graph/plan.h"
#include "renderer/graph/rendering.h"
#include "renderer/graph/subpass.h"

namespace {

using namespace ds::graph;
using Kind = AttachmentDecl::Kind;

ResourceInfo attachable(const std::string& name, VkFormat format,
                        VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT,
                        VkExtent2D extent = {64, 48}) {
    ResourceInfo r;
    r.name = name;
    r.image.format = format;
    r.image.samples = samples;
    r.extent = extent;
    return r;
}

// A pass's declarations, as PassBuilder makes them: the access and the attachment.
struct Declared {
    PassInfo info;
    explicit Declared(const std::string& name) { info.name = name; }
    Declared& color(uint32_t r, Load load = Load::Keep) {
        info.accesses.push_back({r, Access::ColorAttachment});
        info.attachments.push_back({.kind = Kind::Color, .resource = r, .load = load});
        return *this;
    }
    Declared& unused_color(VkFormat format) {
        info.attachments.push_back({.kind = Kind::UnusedColor, .format = format});
        return *this;
    }
    Declared& depth(uint32_t r, Load load = Load::Keep, bool read_only = false) {
        info.accesses.push_back({r, read_only ? Access::DepthReadOnly : Access::DepthAttachment});
        info.attachments.push_back(
            {.kind = Kind::Depth, .resource = r, .load = load, .read_only = read_only});
        return *this;
    }
    Declared& resolve(uint32_t from, uint32_t into, VkResolveModeFlagBits mode) {
        info.accesses.push_back({into, Access::ResolveDst});
        info.attachments.push_back(
            {.kind = Kind::Resolve, .resource = into, .resolves = from, .mode = mode});
        return *this;
    }
    Declared& input(uint32_t r) {
        info.accesses.push_back({r, Access::InputAttachment});
        info.attachments.push_back({.kind = Kind::Input, .resource = r});
        return *this;
    }
    Declared& reads(uint32_t r, Access access) {
        info.accesses.push_back({r, access, Shader::Fragment});
        return *this;
    }
    operator PassInfo() const { return info; }
};

// A frame like depthscope's: shadow map, prepass (G-buffer, msaa depth), forward (light, depth
// read-only), sky, transparent (resolving the light), tonemap sampling the resolve.
struct TileFrame {
    enum : uint32_t { kShadow, kLight, kNormals, kDepth, kResolved, kFinal, kCount };
    std::vector<ResourceInfo> resources;
    std::vector<PassInfo> passes;

    explicit TileFrame(bool tiled) {
        const VkSampleCountFlagBits four = VK_SAMPLE_COUNT_4_BIT;
        resources = {attachable("shadow", VK_FORMAT_D32_SFLOAT, VK_SAMPLE_COUNT_1_BIT, {256, 256}),
                     attachable("light", VK_FORMAT_R16G16B16A16_SFLOAT, four),
                     attachable("normals", VK_FORMAT_A2B10G10R10_UNORM_PACK32, four),
                     attachable("depth", VK_FORMAT_D24_UNORM_S8_UINT, four),
                     attachable("hdr", VK_FORMAT_R16G16B16A16_SFLOAT),
                     attachable("final", VK_FORMAT_R8G8B8A8_UNORM)};
        Declared prepass("depth_prepass");
        if (tiled) prepass.color(kLight, Load::Clear);
        prepass.color(kNormals, Load::Clear).depth(kDepth, Load::Clear);
        Declared forward("forward");
        forward.color(kLight, tiled ? Load::Keep : Load::Clear).depth(kDepth, Load::Keep, true);
        if (tiled) forward.input(kNormals);
        passes = {
            Declared("shadow").depth(kShadow, Load::Clear),
            prepass,
            forward,
            Declared("skybox").color(kLight).depth(kDepth, Load::Keep, true),
            Declared("transparent")
                .color(kLight)
                .depth(kDepth, Load::Keep, true)
                .resolve(kLight, kResolved, VK_RESOLVE_MODE_AVERAGE_BIT),
            Declared("tonemap").reads(kResolved, Access::Sampled).color(kFinal, Load::DontCare)};
    }
    BarrierPlan plan() const { return plan_barriers(resources, passes); }
};

TEST(Rendering, LoadAndStoreOpsComeFromTheWholeFrame) {
    const TileFrame f(false);
    const BarrierPlan plan = f.plan();
    // The prepass clears; its depth samples are read on (stored), its normals never (dropped).
    const RenderingPlan prepass = plan_rendering(1, f.resources, f.passes, plan);
    EXPECT_EQ(prepass.extent.width, 64u);
    ASSERT_EQ(prepass.colors.size(), 1u);
    EXPECT_EQ(prepass.colors[0].load, VK_ATTACHMENT_LOAD_OP_CLEAR);
    EXPECT_EQ(prepass.colors[0].store, VK_ATTACHMENT_STORE_OP_DONT_CARE);
    ASSERT_TRUE(prepass.depth);
    EXPECT_EQ(prepass.depth->store, VK_ATTACHMENT_STORE_OP_STORE);
    EXPECT_EQ(prepass.depth->layout, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL);
    // The sky keeps what forward drew and tests the depth without writing it.
    const RenderingPlan sky = plan_rendering(3, f.resources, f.passes, plan);
    EXPECT_EQ(sky.colors[0].load, VK_ATTACHMENT_LOAD_OP_LOAD);
    EXPECT_EQ(sky.colors[0].store, VK_ATTACHMENT_STORE_OP_STORE);
    EXPECT_EQ(sky.depth->load, VK_ATTACHMENT_LOAD_OP_LOAD);
    EXPECT_EQ(sky.depth->store, VK_ATTACHMENT_STORE_OP_NONE);
    EXPECT_EQ(sky.depth->layout, VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL);
    // Transparent resolves the light; nothing reads the samples after it.
    const RenderingPlan transparent = plan_rendering(4, f.resources, f.passes, plan);
    EXPECT_EQ(transparent.colors[0].resolve, uint32_t(TileFrame::kResolved));
    EXPECT_EQ(transparent.colors[0].mode, VK_RESOLVE_MODE_AVERAGE_BIT);
    EXPECT_EQ(transparent.colors[0].resolve_layout, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
    EXPECT_EQ(transparent.colors[0].store, VK_ATTACHMENT_STORE_OP_DONT_CARE);
    // The tonemap covers every pixel: nothing is loaded.
    EXPECT_EQ(plan_rendering(5, f.resources, f.passes, plan).colors[0].load,
              VK_ATTACHMENT_LOAD_OP_DONT_CARE);
}

TEST(Rendering, WhatArrivesFullIsLoadedAndWhatLeavesIsStored) {
    std::vector<ResourceInfo> resources = {attachable("target", VK_FORMAT_R8G8B8A8_UNORM)};
    resources[0].lifetime = Lifetime::External;
    resources[0].initial.layout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;  // the last frame's
    const std::vector<PassInfo> passes = {Declared("draw").color(0)};
    const RenderingPlan r = plan_rendering(0, resources, passes, plan_barriers(resources, passes));
    EXPECT_EQ(r.colors[0].load, VK_ATTACHMENT_LOAD_OP_LOAD);
    EXPECT_EQ(r.colors[0].store, VK_ATTACHMENT_STORE_OP_STORE) << "an import outlives the frame";
}

TEST(Rendering, UnusedSlotsRenderAreasAndBadDeclarations) {
    std::vector<ResourceInfo> resources = {
        attachable("ids", VK_FORMAT_R32_UINT), attachable("depth", VK_FORMAT_D32_SFLOAT),
        attachable("small", VK_FORMAT_R8_UNORM, VK_SAMPLE_COUNT_1_BIT, {32, 24})};
    // Alpha to coverage's slot 0 without an image, then the surface ids.
    std::vector<PassInfo> passes = {
        Declared("prepass").unused_color(VK_FORMAT_R8_UNORM).color(0, Load::Clear).depth(1)};
    const RenderingPlan r = plan_rendering(0, resources, passes, plan_barriers(resources, passes));
    ASSERT_EQ(r.colors.size(), 2u);
    EXPECT_EQ(r.colors[0].resource, kNoResource);
    const RenderTarget t = render_target(passes[0], resources);
    EXPECT_EQ(t.colors, (std::vector<VkFormat>{VK_FORMAT_R8_UNORM, VK_FORMAT_R32_UINT}));
    EXPECT_EQ(t.depth, VK_FORMAT_D32_SFLOAT);
    EXPECT_EQ(t.render_pass, VK_NULL_HANDLE);
    // Counting without attachments: the declared area.
    PassInfo counts = Declared("rasterized").reads(0, Access::StorageReadWrite);
    counts.render_area = {64, 48};
    EXPECT_TRUE(counts.renders());
    passes = {counts};
    EXPECT_EQ(plan_rendering(0, resources, passes, plan_barriers(resources, passes)).extent.height,
              48u);
    // Attachments of two sizes; a resolve of an image the pass does not render to.
    passes = {Declared("mixed").color(0).color(2)};
    EXPECT_THROW(plan_rendering(0, resources, passes, plan_barriers(resources, passes)), ds::Error);
    passes = {Declared("stray").color(0).resolve(2, 0, VK_RESOLVE_MODE_AVERAGE_BIT)};
    EXPECT_THROW(plan_rendering(0, resources, passes, plan_barriers(resources, passes)), ds::Error);
}

// Per aspect: a depth-stencil image is planned and moved as a whole (its attachment view names
// both aspects, so a render pass's own transitions move the stencil with the depth).
TEST(Rendering, DepthStencilImagesMoveBothAspects) {
    EXPECT_EQ(attachable("d24", VK_FORMAT_D24_UNORM_S8_UINT).aspects(),
              VkImageAspectFlags(VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT));
    EXPECT_EQ(attachable("d32", VK_FORMAT_D32_SFLOAT).aspects(),
              VkImageAspectFlags(VK_IMAGE_ASPECT_DEPTH_BIT));
    EXPECT_EQ(attachable("hdr", VK_FORMAT_R16G16B16A16_SFLOAT).aspects(),
              VkImageAspectFlags(VK_IMAGE_ASPECT_COLOR_BIT));
}

TEST(SubpassPlan, WithoutAGroupNameEveryPassRendersAlone) {
    TileFrame f(false);
    assign_subpasses(f.passes, f.resources, "");
    for (const PassInfo& p : f.passes) EXPECT_TRUE(p.group.empty()) << p.name;
    EXPECT_TRUE(find_subpass_groups(f.resources, f.passes).empty());
}

TEST(SubpassPlan, TheRunSharingTheSceneDepthBecomesOneRenderPass) {
    TileFrame f(true);
    assign_subpasses(f.passes, f.resources, "gbuffer_lighting");
    // The shadow map has its own depth and the tonemap none: alone. Forward reads what the
    // prepass wrote as an input attachment: the next subpass; sky and transparent share it.
    const std::vector<std::pair<std::string, int>> expected = {{"", 0},
                                                               {"gbuffer_lighting", 0},
                                                               {"gbuffer_lighting", 1},
                                                               {"gbuffer_lighting", 1},
                                                               {"gbuffer_lighting", 1},
                                                               {"", 0}};
    for (size_t i = 0; i < f.passes.size(); ++i) {
        EXPECT_EQ(f.passes[i].group, expected[i].first) << f.passes[i].name;
        EXPECT_EQ(int(f.passes[i].subpass), expected[i].second) << f.passes[i].name;
    }
    std::vector<GroupPlan> groups = find_subpass_groups(f.resources, f.passes);
    ASSERT_EQ(groups.size(), 1u);
    BarrierPlan plan = plan_barriers(f.resources, f.passes, store_writes(groups, f.passes));
    plan_subpass_groups(groups, f.resources, f.passes, plan);
    const GroupPlan& g = groups[0];
    ASSERT_EQ(g.subpasses.size(), 2u);
    EXPECT_EQ(g.attachments[0].resource, uint32_t(TileFrame::kLight));  // the light first
    EXPECT_EQ(g.attachments[0].load, VK_ATTACHMENT_LOAD_OP_CLEAR);
    EXPECT_EQ(g.subpasses[1].inputs.size(), 1u);
    EXPECT_TRUE(g.subpasses[1].depth_read_only);
    // Transparent's resolve is the subpass's resolve attachment for the light.
    ASSERT_EQ(g.subpasses[1].resolves.size(), 1u);
    EXPECT_EQ(g.attachments[g.subpasses[1].resolves[0].attachment].resource,
              uint32_t(TileFrame::kResolved));
}

TEST(SubpassPlan, DepthUseAndColourSlotsSplitSubpasses) {
    const TileFrame f(true);
    // prepass_mode=depth on the tiled path: the prepass writes only the light and the depth,
    // forward reads no input but tests that depth read-only: the next subpass all the same.
    std::vector<PassInfo> passes = {
        Declared("depth_prepass")
            .color(TileFrame::kLight, Load::Clear)
            .depth(TileFrame::kDepth, Load::Clear),
        Declared("forward").color(TileFrame::kLight).depth(TileFrame::kDepth, Load::Keep, true),
        Declared("skybox").color(TileFrame::kLight).depth(TileFrame::kDepth, Load::Keep, true)};
    assign_subpasses(passes, f.resources, "g");
    EXPECT_EQ(passes[1].subpass, 1u);
    EXPECT_EQ(passes[2].subpass, 1u);
    // Other colour slots in the run: the next subpass.
    passes[2] =
        Declared("skybox").color(TileFrame::kNormals).depth(TileFrame::kDepth, Load::Keep, true);
    assign_subpasses(passes, f.resources, "g");
    EXPECT_EQ(passes[2].subpass, 2u);
}

TEST(SubpassPlan, ARenderPassOfItsOwnAndASecondRun) {
    TileFrame f(true);
    // A pass that asked for a render pass (Dear ImGui's pipelines need one): a group of one.
    f.passes[5].render_pass = true;
    // A second run on the shadow map: shadow twice.
    f.passes.insert(f.passes.begin() + 1, Declared("shadow_2").depth(TileFrame::kShadow));
    assign_subpasses(f.passes, f.resources, "g");
    EXPECT_EQ(f.passes[0].group, "g");  // runs are named in frame order
    EXPECT_EQ(f.passes[1].group, "g");
    EXPECT_EQ(f.passes[2].group, "g#2");
    EXPECT_EQ(f.passes[6].group, "tonemap");
    EXPECT_EQ(find_subpass_groups(f.resources, f.passes).size(), 3u);
}

}  // namespace
