// Subpass groups (subpass.h) and seed 002's tiler questions (tiler.h), planned with no device:
// the seed's own G-buffer layout, then each way a group can be malformed or fail to merge.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>

#include "renderer/common/error.h"
#include "renderer/graph/plan.h"
#include "renderer/graph/subpass.h"
#include "renderer/graph/tiler.h"

namespace {

using namespace ds::graph;

ResourceInfo attachment(const std::string& name, VkFormat format,
                        VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT) {
    ResourceInfo r;
    r.name = name;
    r.image.format = format;
    r.image.samples = samples;
    r.extent = {64, 48};
    return r;
}

PassInfo subpass(const std::string& name, uint32_t index, std::vector<AccessInfo> accesses,
                 const std::string& group = "gbuffer_lighting") {
    PassInfo p;
    p.name = name;
    p.accesses = std::move(accesses);
    p.group = group;
    p.subpass = index;
    return p;
}

// Each pass's attachment declarations from its accesses, as PassBuilder::color / depth /
// input / resolve would make them (a resolve takes the pass's first multisampled colour); a
// pass named "gbuffer" clears what it attaches (seed 002's subpass 0).
void attach(std::vector<PassInfo>& passes, const std::vector<ResourceInfo>& resources) {
    using Kind = AttachmentDecl::Kind;
    for (PassInfo& p : passes) {
        p.attachments.clear();
        const Load load = p.name == "gbuffer" ? Load::Clear : Load::Keep;
        for (const AccessInfo& a : p.accesses) {
            if (a.access == Access::ColorAttachment)
                p.attachments.push_back(
                    {.kind = Kind::Color, .resource = a.resource, .load = load});
            if (a.access == Access::DepthAttachment || a.access == Access::DepthReadOnly)
                p.attachments.push_back({.kind = Kind::Depth,
                                         .resource = a.resource,
                                         .load = load,
                                         .read_only = a.access == Access::DepthReadOnly});
            if (a.access == Access::InputAttachment)
                p.attachments.push_back({.kind = Kind::Input, .resource = a.resource});
            if (a.access != Access::ResolveDst) continue;
            uint32_t from = kNoResource;
            for (const AccessInfo& c : p.accesses)
                if (c.access == Access::ColorAttachment && resources[c.resource].multisampled() &&
                    from == kNoResource)
                    from = c.resource;
            p.attachments.push_back({.kind = Kind::Resolve,
                                     .resource = a.resource,
                                     .resolves = from,
                                     .mode = VK_RESOLVE_MODE_AVERAGE_BIT});
        }
    }
}

std::vector<GroupPlan> groups_of(std::vector<PassInfo>& passes,
                                 const std::vector<ResourceInfo>& resources) {
    attach(passes, resources);
    return find_subpass_groups(resources, passes);
}

PassInfo alone(const std::string& name, std::vector<AccessInfo> accesses) {
    PassInfo p;
    p.name = name;
    p.accesses = std::move(accesses);
    return p;
}

// Seed 002's layout with this renderer's formats: light (RGBA16F) first, normals
// (A2B10G10R10), roughness (R8), depth; a tonemap samples the light afterwards.
struct SeedFrame {
    enum : uint32_t { kLight, kNormals, kRoughness, kDepth };
    std::vector<ResourceInfo> resources;
    std::vector<PassInfo> passes;

    explicit SeedFrame(VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT) {
        resources = {attachment("light", VK_FORMAT_R16G16B16A16_SFLOAT, samples),
                     attachment("normals", VK_FORMAT_A2B10G10R10_UNORM_PACK32, samples),
                     attachment("roughness", VK_FORMAT_R8_UNORM, samples),
                     attachment("depth", VK_FORMAT_D32_SFLOAT, samples)};
        PassInfo gbuffer = subpass("gbuffer", 0,
                                   {{kLight, Access::ColorAttachment},
                                    {kNormals, Access::ColorAttachment},
                                    {kRoughness, Access::ColorAttachment},
                                    {kDepth, Access::DepthAttachment}});
        passes = {gbuffer,
                  subpass("lighting", 1,
                          {{kLight, Access::ColorAttachment},
                           {kNormals, Access::InputAttachment},
                           {kRoughness, Access::InputAttachment},
                           {kDepth, Access::DepthReadOnly}}),
                  alone("tonemap", {{kLight, Access::Sampled, Shader::Fragment}})};
    }

    std::vector<GroupPlan> plan() {
        std::vector<GroupPlan> groups = groups_of(passes, resources);
        BarrierPlan barriers = plan_barriers(resources, passes, store_writes(groups, passes));
        plan_subpass_groups(groups, resources, passes, barriers);
        for (uint32_t p = 0; p < 2; ++p) EXPECT_TRUE(barriers.passes[p].barriers.empty());
        return groups;
    }
};

TEST(SubpassGroup, SeedLayoutPlansOneRenderPassWithTwoSubpasses) {
    SeedFrame frame;
    const std::vector<GroupPlan> groups = frame.plan();
    ASSERT_EQ(groups.size(), 1u);
    const GroupPlan& g = groups[0];
    ASSERT_EQ(g.subpasses.size(), 2u);
    ASSERT_EQ(g.attachments.size(), 4u);
    EXPECT_EQ(g.attachments[0].resource, SeedFrame::kLight);  // the light is attachment 0
    // Only the light is read after the group: the G-buffer and depth stay in tile memory.
    EXPECT_EQ(g.attachments[0].store, VK_ATTACHMENT_STORE_OP_STORE);
    EXPECT_FALSE(g.attachments[0].transient);
    for (uint32_t a : {1u, 2u, 3u}) {
        EXPECT_EQ(g.attachments[a].store, VK_ATTACHMENT_STORE_OP_DONT_CARE) << a;
        EXPECT_TRUE(g.attachments[a].transient) << a;
        EXPECT_EQ(g.attachments[a].load, VK_ATTACHMENT_LOAD_OP_CLEAR) << a;
    }
    const SubpassPlan& lighting = g.subpasses[1];
    ASSERT_EQ(lighting.inputs.size(), 2u);
    EXPECT_EQ(lighting.inputs[0].layout, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    ASSERT_TRUE(lighting.depth);
    EXPECT_TRUE(lighting.depth_read_only);
    EXPECT_EQ(lighting.depth->layout, VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL);
    EXPECT_EQ(g.attachments[1].final, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
}

TEST(SubpassGroup, DependencyIsByRegionWithSeed002Masks) {
    SeedFrame frame;
    const GroupPlan g = frame.plan()[0];
    ASSERT_EQ(g.dependencies.size(), 1u);
    const SubpassDependency& d = g.dependencies[0];
    EXPECT_EQ(d.src, 0u);
    EXPECT_EQ(d.dst, 1u);
    EXPECT_TRUE(d.by_region);
    // Seed 002: src COLOR_ATTACHMENT_OUTPUT | EARLY | LATE tests, colour and depth writes;
    // dst FRAGMENT_SHADER | COLOR_ATTACHMENT_OUTPUT | EARLY | LATE tests, input attachment,
    // colour and depth reads.
    EXPECT_EQ(d.src_stages, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT |
                                VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT |
                                VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT);
    EXPECT_EQ(d.src_access, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT |
                                VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT);
    const VkPipelineStageFlags2 dst_stages =
        VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT |
        VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
    EXPECT_EQ(d.dst_stages & dst_stages, dst_stages);
    const VkAccessFlags2 dst_access =
        VK_ACCESS_2_INPUT_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT |
        VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT;
    EXPECT_EQ(d.dst_access & dst_access, dst_access);
}

TEST(SubpassGroup, AStoredAttachmentIsWrittenByTheStoreForWhatComesNext) {
    SeedFrame frame;
    // The depth read back after the frame: stored, and the copy waits for the store's write.
    frame.passes.push_back(alone("readback", {{SeedFrame::kDepth, Access::TransferSrc}}));
    std::vector<GroupPlan> groups = groups_of(frame.passes, frame.resources);
    BarrierPlan plan =
        plan_barriers(frame.resources, frame.passes, store_writes(groups, frame.passes));
    plan_subpass_groups(groups, frame.resources, frame.passes, plan);
    EXPECT_EQ(groups[0].attachments[3].store, VK_ATTACHMENT_STORE_OP_STORE);
    EXPECT_FALSE(groups[0].attachments[3].transient);
    const auto& copy = plan.passes[3].barriers;
    ASSERT_EQ(copy.size(), 1u);
    EXPECT_TRUE(copy[0].src_access & VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT);
    EXPECT_TRUE(copy[0].src_stages & VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT);
}

TEST(SubpassGroup, MultisampledColourResolvesInItsSubpass) {
    SeedFrame frame(VK_SAMPLE_COUNT_4_BIT);
    frame.resources.push_back(attachment("resolved", VK_FORMAT_R16G16B16A16_SFLOAT));
    frame.passes[1].accesses.push_back({4, Access::ResolveDst});
    frame.passes[2] = alone("tonemap", {{4, Access::Sampled, Shader::Fragment}});
    const GroupPlan g = frame.plan()[0];
    ASSERT_EQ(g.subpasses[1].resolves.size(), 1u);
    EXPECT_EQ(g.attachments[g.subpasses[1].resolves[0].attachment].resource, 4u);
    // The samples are resolved, not stored; the resolve destination is.
    EXPECT_EQ(g.attachments[0].store, VK_ATTACHMENT_STORE_OP_DONT_CARE);
    EXPECT_EQ(g.attachments[4].store, VK_ATTACHMENT_STORE_OP_STORE);
}

TEST(SubpassGroup, MalformedGroupsAreErrors) {
    {  // a group that comes back after another pass
        SeedFrame frame;
        frame.passes.push_back(subpass("again", 1, {{SeedFrame::kLight, Access::ColorAttachment}}));
        EXPECT_THROW(groups_of(frame.passes, frame.resources), ds::Error);
    }
    {  // subpass indices skip
        SeedFrame frame;
        frame.passes[1].subpass = 2;
        EXPECT_THROW(groups_of(frame.passes, frame.resources), ds::Error);
    }
    {  // an input attachment outside a group
        SeedFrame frame;
        frame.passes[2].accesses = {{SeedFrame::kNormals, Access::InputAttachment}};
        EXPECT_THROW(groups_of(frame.passes, frame.resources), ds::Error);
    }
    {  // a buffer one subpass writes and the next reads: no barrier fits in a render pass
        SeedFrame frame;
        ResourceInfo counts;
        counts.name = "counts";
        counts.is_image = false;
        counts.size = 64;
        frame.resources.push_back(counts);
        frame.passes[0].accesses.push_back({4, Access::StorageWrite, Shader::Fragment});
        frame.passes[1].accesses.push_back({4, Access::StorageRead, Shader::Fragment});
        EXPECT_THROW(frame.plan(), ds::Error);
    }
}

TEST(Tiler, SeedLayoutIs104BitsPerPixelAndMerges) {
    SeedFrame frame;
    const GroupPlan g = frame.plan()[0];
    const std::array<bool, 4> lazy{};
    const TilerReport t = tiler_report(g, frame.resources, lazy);
    EXPECT_EQ(t.bits_per_pixel, 104u);  // 64 + 32 + 8: depth is not tile colour
    EXPECT_EQ(t.tile_bits_per_pixel, 104u);
    EXPECT_TRUE(t.fits_128);
    EXPECT_TRUE(t.mergeable) << t.verdict;
    EXPECT_EQ(t.verdict, "a tiler can merge these subpasses: yes");
    ASSERT_EQ(t.conditions.size(), 5u);
    for (const TilerCondition& c : t.conditions) EXPECT_TRUE(c.ok) << c.name << ": " << c.detail;
}

TEST(Tiler, FourSamplesOverflowTheBudgetButStillMerge) {
    SeedFrame frame(VK_SAMPLE_COUNT_4_BIT);
    const TilerReport t = tiler_report(frame.plan()[0], frame.resources, {});
    EXPECT_EQ(t.bits_per_pixel, 104u);
    EXPECT_EQ(t.tile_bits_per_pixel, 416u);
    EXPECT_FALSE(t.fits_256);
    EXPECT_TRUE(t.mergeable);
}

TEST(Tiler, EachBrokenConditionSaysWhy) {
    {  // nine colour attachments
        SeedFrame frame;
        for (int i = 0; i < 6; ++i) {
            frame.resources.push_back(attachment("extra" + std::to_string(i), VK_FORMAT_R8_UNORM));
            frame.passes[0].accesses.push_back(
                {uint32_t(frame.resources.size() - 1), Access::ColorAttachment});
        }
        const TilerReport t = tiler_report(frame.plan()[0], frame.resources, {});
        EXPECT_FALSE(t.mergeable);
        EXPECT_NE(t.verdict.find("fewer than nine"), std::string::npos) << t.verdict;
    }
    {  // different sample counts
        SeedFrame frame;
        frame.resources[SeedFrame::kRoughness].image.samples = VK_SAMPLE_COUNT_4_BIT;
        const TilerReport t = tiler_report(frame.plan()[0], frame.resources, {});
        EXPECT_FALSE(t.mergeable);
        EXPECT_NE(t.verdict.find("equal sample counts"), std::string::npos) << t.verdict;
    }
    {  // nothing shared: the lighting reads no input and has no depth
        SeedFrame frame;
        frame.passes[1].accesses = {{SeedFrame::kLight, Access::ColorAttachment}};
        const TilerReport t = tiler_report(frame.plan()[0], frame.resources, {});
        EXPECT_FALSE(t.mergeable);
        EXPECT_NE(t.verdict.find("one depth attachment throughout"), std::string::npos);
        EXPECT_NE(t.verdict.find("saves a write-out"), std::string::npos) << t.verdict;
    }
}

}  // namespace
