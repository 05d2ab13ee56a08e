// The pure barrier computation (plan.h): layouts, stages and access masks per access kind,
// with no device. Each test declares a tiny frame and checks the barriers it needs.
#include <gtest/gtest.h>

#include "renderer/graph/dump.h"
#include "renderer/graph/plan.h"

namespace {

using namespace ds::graph;

constexpr VkPipelineStageFlags2 kFragment = VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
constexpr VkPipelineStageFlags2 kCompute = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
constexpr VkPipelineStageFlags2 kColorOut = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
constexpr VkPipelineStageFlags2 kDepthTests =
    VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
constexpr VkPipelineStageFlags2 kCopyBlitResolve =
    VK_PIPELINE_STAGE_2_COPY_BIT | VK_PIPELINE_STAGE_2_BLIT_BIT | VK_PIPELINE_STAGE_2_RESOLVE_BIT;
constexpr VkAccessFlags2 kColorRW =
    VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT;
constexpr VkAccessFlags2 kDepthRW =
    VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;

ResourceInfo image(const std::string& name, VkFormat format = VK_FORMAT_R8G8B8A8_UNORM,
                   VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT) {
    ResourceInfo r;
    r.name = name;
    r.image.format = format;
    r.image.samples = samples;
    r.extent = {64, 48};
    return r;
}

ResourceInfo buffer(const std::string& name) {
    ResourceInfo r;
    r.name = name;
    r.is_image = false;
    r.size = 1024;
    return r;
}

ResourceInfo external(ResourceInfo r, ExternalState initial, std::optional<ExternalState> final) {
    r.lifetime = Lifetime::External;
    r.initial = ResourceState::from_external(initial);
    r.final = final;
    return r;
}

PassInfo pass(const std::string& name, std::vector<AccessInfo> accesses,
              PassKind kind = PassKind::Graphics) {
    PassInfo p;
    p.name = name;
    p.kind = kind;
    p.accesses = std::move(accesses);
    return p;
}

void expect_barrier(const Barrier& b, VkImageLayout old_layout, VkImageLayout new_layout,
                    VkPipelineStageFlags2 src_stages, VkAccessFlags2 src_access,
                    VkPipelineStageFlags2 dst_stages, VkAccessFlags2 dst_access) {
    EXPECT_EQ(b.old_layout, old_layout);
    EXPECT_EQ(b.new_layout, new_layout);
    EXPECT_EQ(b.src_stages, src_stages);
    EXPECT_EQ(b.src_access, src_access);
    EXPECT_EQ(b.dst_stages, dst_stages);
    EXPECT_EQ(b.dst_access, dst_access);
}

TEST(GraphPlan, ColourAttachmentThenSampledIsReadAfterWrite) {
    const std::vector<ResourceInfo> res = {image("colour")};
    const std::vector<PassInfo> passes = {pass("draw", {{0, Access::ColorAttachment}}),
                                          pass("post", {{0, Access::Sampled, Shader::Fragment}})};
    const BarrierPlan plan = plan_barriers(res, passes);
    ASSERT_EQ(plan.passes.size(), 2u);
    ASSERT_EQ(plan.passes[0].barriers.size(), 1u);
    // First use: contents discarded, nothing earlier to wait for.
    expect_barrier(plan.passes[0].barriers[0], VK_IMAGE_LAYOUT_UNDEFINED,
                   VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_NONE,
                   VK_ACCESS_2_NONE, kColorOut, kColorRW);
    ASSERT_EQ(plan.passes[1].barriers.size(), 1u);
    expect_barrier(plan.passes[1].barriers[0], VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                   VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, kColorOut,
                   VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, kFragment,
                   VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
    EXPECT_EQ(plan.passes[1].uses[0].use.layout, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
}

TEST(GraphPlan, ReadAfterReadInTheSameLayoutNeedsNoBarrier) {
    const std::vector<ResourceInfo> res = {image("colour")};
    const std::vector<PassInfo> passes = {pass("draw", {{0, Access::ColorAttachment}}),
                                          pass("a", {{0, Access::Sampled, Shader::Fragment}}),
                                          pass("b", {{0, Access::Sampled, Shader::Fragment}})};
    const BarrierPlan plan = plan_barriers(res, passes);
    EXPECT_EQ(plan.passes[1].barriers.size(), 1u);
    EXPECT_TRUE(plan.passes[2].barriers.empty());
}

TEST(GraphPlan, ReadInAnotherStageChainsThroughTheFirstRead) {
    // The write was made visible to the fragment shader only: a compute read needs its own
    // visibility, chained after the fragment read (no access to flush, no layout change).
    const std::vector<ResourceInfo> res = {image("colour")};
    const std::vector<PassInfo> passes = {
        pass("draw", {{0, Access::ColorAttachment}}),
        pass("a", {{0, Access::Sampled, Shader::Fragment}}),
        pass("b", {{0, Access::Sampled, Shader::Compute}}, PassKind::Compute)};
    const BarrierPlan plan = plan_barriers(res, passes);
    ASSERT_EQ(plan.passes[2].barriers.size(), 1u);
    expect_barrier(plan.passes[2].barriers[0], VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                   VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, kFragment, VK_ACCESS_2_NONE, kCompute,
                   VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
}

TEST(GraphPlan, ReadsInDifferentLayoutsNeedATransition) {
    const std::vector<ResourceInfo> res = {image("depth", VK_FORMAT_D32_SFLOAT)};
    const std::vector<PassInfo> passes = {pass("prepass", {{0, Access::DepthAttachment}}),
                                          pass("gtao", {{0, Access::Sampled, Shader::Fragment}}),
                                          pass("forward", {{0, Access::DepthReadOnly}})};
    const BarrierPlan plan = plan_barriers(res, passes);
    ASSERT_EQ(plan.passes[1].barriers.size(), 1u);
    expect_barrier(plan.passes[1].barriers[0], VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
                   VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, kDepthTests,
                   VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, kFragment,
                   VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
    // The transition writes the image: it waits for the sampling (WAR), no access to flush.
    ASSERT_EQ(plan.passes[2].barriers.size(), 1u);
    expect_barrier(plan.passes[2].barriers[0], VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                   VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL, kFragment, VK_ACCESS_2_NONE,
                   kDepthTests, VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT);
}

TEST(GraphPlan, WriteAfterWrite) {
    const std::vector<ResourceInfo> res = {image("ao", VK_FORMAT_R8_UNORM)};
    const std::vector<PassInfo> passes = {
        pass("gtao", {{0, Access::StorageWrite, Shader::Compute}}, PassKind::Compute),
        pass("denoise", {{0, Access::StorageReadWrite, Shader::Compute}}, PassKind::Compute)};
    const BarrierPlan plan = plan_barriers(res, passes);
    ASSERT_EQ(plan.passes[1].barriers.size(), 1u);
    expect_barrier(plan.passes[1].barriers[0], VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_GENERAL,
                   kCompute, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, kCompute,
                   VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
}

TEST(GraphPlan, WriteAfterReadIsAnExecutionDependencyOnly) {
    const std::vector<ResourceInfo> res = {image("colour"), buffer("counts")};
    const std::vector<PassInfo> passes = {
        pass("draw", {{0, Access::ColorAttachment}, {1, Access::StorageWrite, Shader::Fragment}}),
        pass("post",
             {{0, Access::Sampled, Shader::Fragment}, {1, Access::StorageRead, Shader::Fragment}}),
        pass("draw again", {{0, Access::ColorAttachment}, {1, Access::TransferDst}})};
    const BarrierPlan plan = plan_barriers(res, passes);
    ASSERT_EQ(plan.passes[2].barriers.size(), 2u);
    expect_barrier(plan.passes[2].barriers[0], VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                   VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, kFragment, VK_ACCESS_2_NONE, kColorOut,
                   kColorRW);
    const Barrier& b = plan.passes[2].barriers[1];
    EXPECT_FALSE(b.is_image);
    expect_barrier(b, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_UNDEFINED, kFragment,
                   VK_ACCESS_2_NONE, kCopyBlitResolve | VK_PIPELINE_STAGE_2_CLEAR_BIT,
                   VK_ACCESS_2_TRANSFER_WRITE_BIT);
}

TEST(GraphPlan, DepthTestReadOnlyAndSampledInOnePass) {
    const std::vector<ResourceInfo> res = {image("depth", VK_FORMAT_D32_SFLOAT)};
    const std::vector<PassInfo> passes = {
        pass("prepass", {{0, Access::DepthAttachment}}),
        pass("decals", {{0, Access::DepthReadOnly}, {0, Access::Sampled, Shader::Fragment}})};
    const BarrierPlan plan = plan_barriers(res, passes);
    ASSERT_EQ(plan.passes[0].barriers.size(), 1u);
    expect_barrier(plan.passes[0].barriers[0], VK_IMAGE_LAYOUT_UNDEFINED,
                   VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_NONE,
                   VK_ACCESS_2_NONE, kDepthTests, kDepthRW);
    ASSERT_EQ(plan.passes[1].barriers.size(), 1u) << "one barrier serves both accesses";
    expect_barrier(
        plan.passes[1].barriers[0], VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
        VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL, kDepthTests,
        VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, kDepthTests | kFragment,
        VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
    ASSERT_EQ(plan.passes[1].uses.size(), 1u);
    EXPECT_EQ(plan.passes[1].uses[0].use.layout, VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL);
}

TEST(GraphPlan, StorageAndSampledInOnePassUseGeneral) {
    const std::vector<ResourceInfo> res = {image("hiz", VK_FORMAT_R32_SFLOAT)};
    const std::vector<PassInfo> passes = {
        pass("downsample",
             {{0, Access::Sampled, Shader::Compute}, {0, Access::StorageWrite, Shader::Compute}},
             PassKind::Compute)};
    const BarrierPlan plan = plan_barriers(res, passes);
    EXPECT_EQ(plan.passes[0].uses[0].use.layout, VK_IMAGE_LAYOUT_GENERAL);
}

TEST(GraphPlan, FirstUseDiscardsTransientsButKeepsImportedLayouts) {
    ResourceInfo transient = image("colour");
    // Last frame sampled it: this frame's first write still waits for that read.
    transient.initial.read_stages = kFragment;
    transient.initial.write_stages = kColorOut;
    const ResourceInfo imported =
        external(image("result"), ExternalState::transfer_src(), std::nullopt);
    const std::vector<ResourceInfo> res = {transient, imported};
    const std::vector<PassInfo> passes = {
        pass("draw", {{0, Access::ColorAttachment}, {1, Access::ColorAttachment}})};
    const BarrierPlan plan = plan_barriers(res, passes);
    ASSERT_EQ(plan.passes[0].barriers.size(), 2u);
    expect_barrier(plan.passes[0].barriers[0], VK_IMAGE_LAYOUT_UNDEFINED,
                   VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, kFragment, VK_ACCESS_2_NONE, kColorOut,
                   kColorRW);
    expect_barrier(plan.passes[0].barriers[1], VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                   VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_COPY_BIT,
                   VK_ACCESS_2_NONE, kColorOut, kColorRW);
}

TEST(GraphPlan, DiscardedStateKeepsStagesAndDropsTheLayout) {
    ResourceState s;
    s.layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    s.read_stages = kFragment;
    const ResourceState d = s.discarded();
    EXPECT_EQ(d.layout, VK_IMAGE_LAYOUT_UNDEFINED);
    EXPECT_EQ(d.read_stages, kFragment);
}

TEST(GraphPlan, BufferWrittenByComputeThenIndirectAndVertexInput) {
    const std::vector<ResourceInfo> res = {buffer("draws"), buffer("positions")};
    const std::vector<PassInfo> passes = {
        pass("cull",
             {{0, Access::StorageWrite, Shader::Compute},
              {1, Access::StorageWrite, Shader::Compute}},
             PassKind::Compute),
        pass("draw", {{0, Access::IndirectRead}, {1, Access::VertexRead}}),
        pass("stats", {{1, Access::StorageRead, Shader::Compute}}, PassKind::Compute)};
    const BarrierPlan plan = plan_barriers(res, passes);
    EXPECT_TRUE(plan.passes[0].barriers.empty()) << "fresh buffers: nothing to wait for";
    ASSERT_EQ(plan.passes[1].barriers.size(), 2u);
    expect_barrier(plan.passes[1].barriers[0], VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_UNDEFINED,
                   kCompute, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                   VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT, VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT);
    expect_barrier(plan.passes[1].barriers[1], VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_UNDEFINED,
                   kCompute, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                   VK_PIPELINE_STAGE_2_VERTEX_ATTRIBUTE_INPUT_BIT,
                   VK_ACCESS_2_VERTEX_ATTRIBUTE_READ_BIT);
    EXPECT_FALSE(plan.passes[1].barriers[0].is_image);
    ASSERT_EQ(plan.passes[2].barriers.size(), 1u);
    expect_barrier(plan.passes[2].barriers[0], VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_UNDEFINED,
                   kCompute, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, kCompute,
                   VK_ACCESS_2_SHADER_STORAGE_READ_BIT);
}

TEST(GraphPlan, AllBarriersOfAPassAreMerged) {
    const std::vector<ResourceInfo> res = {image("depth", VK_FORMAT_D32_SFLOAT),
                                           image("normal", VK_FORMAT_A2B10G10R10_UNORM_PACK32),
                                           image("roughness", VK_FORMAT_R8_UNORM), buffer("frame")};
    const std::vector<PassInfo> passes = {
        pass("prepass", {{0, Access::DepthAttachment},
                         {1, Access::ColorAttachment},
                         {2, Access::ColorAttachment},
                         {3, Access::TransferDst}}),
        pass("forward", {{0, Access::DepthReadOnly},
                         {1, Access::Sampled},
                         {2, Access::Sampled},
                         {3, Access::UniformRead, Shader::Vertex | Shader::Fragment}})};
    const BarrierPlan plan = plan_barriers(res, passes);
    ASSERT_EQ(plan.passes[1].barriers.size(), 4u);
    for (uint32_t i = 0; i < 4; ++i) EXPECT_EQ(plan.passes[1].barriers[i].resource, i);
    EXPECT_EQ(plan.passes[1].barriers[3].dst_stages,
              VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | kFragment);
    EXPECT_EQ(plan.passes[1].barriers[3].dst_access, VK_ACCESS_2_UNIFORM_READ_BIT);
}

TEST(GraphPlan, ExternalFinalStatesAtTheEnd) {
    const std::vector<ResourceInfo> res = {
        external(image("swapchain"), {}, ExternalState::present()),
        external(image("capture"), {}, ExternalState::transfer_src()),
        external(buffer("readback"), {}, ExternalState::host_read()),
        external(image("untouched final"), {}, std::nullopt)};
    const std::vector<PassInfo> passes = {
        pass("draw", {{0, Access::ColorAttachment},
                      {1, Access::ColorAttachment},
                      {3, Access::ColorAttachment}}),
        pass("copy", {{1, Access::TransferSrc}, {2, Access::TransferDst}})};
    const BarrierPlan plan = plan_barriers(res, passes);
    ASSERT_EQ(plan.final_barriers.size(), 2u) << "capture is already TRANSFER_SRC and visible";
    expect_barrier(plan.final_barriers[0], VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                   VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, kColorOut,
                   VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_NONE,
                   VK_ACCESS_2_NONE);
    EXPECT_EQ(plan.final_barriers[1].resource, 2u);
    expect_barrier(plan.final_barriers[1], VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_UNDEFINED,
                   kCopyBlitResolve | VK_PIPELINE_STAGE_2_CLEAR_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                   VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
    EXPECT_EQ(plan.end_states[0].layout, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR);
    EXPECT_EQ(plan.end_states[3].layout, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
}

TEST(GraphPlan, SwapchainAcquireStageIsWaitedFor) {
    // The acquire semaphore is waited at COLOR_ATTACHMENT_OUTPUT: the transition chains on it.
    const ExternalState acquired{VK_IMAGE_LAYOUT_UNDEFINED, kColorOut, VK_ACCESS_2_NONE};
    const std::vector<ResourceInfo> res = {
        external(image("swapchain"), acquired, ExternalState::present())};
    const std::vector<PassInfo> passes = {pass("ui", {{0, Access::ColorAttachment}})};
    const BarrierPlan plan = plan_barriers(res, passes);
    ASSERT_EQ(plan.passes[0].barriers.size(), 1u);
    EXPECT_EQ(plan.passes[0].barriers[0].src_stages, kColorOut);
    EXPECT_EQ(plan.passes[0].barriers[0].src_access, VK_ACCESS_2_NONE);
}

TEST(GraphPlan, ResolveDestinationsAndTheirSources) {
    const std::vector<ResourceInfo> res = {
        image("msaa colour", VK_FORMAT_R8G8B8A8_UNORM, VK_SAMPLE_COUNT_4_BIT),
        image("msaa depth", VK_FORMAT_D32_SFLOAT, VK_SAMPLE_COUNT_4_BIT), image("colour"),
        image("depth", VK_FORMAT_D32_SFLOAT)};
    const std::vector<PassInfo> passes = {pass("prepass", {{0, Access::ColorAttachment},
                                                           {1, Access::DepthAttachment},
                                                           {2, Access::ResolveDst},
                                                           {3, Access::ResolveDst}}),
                                          pass("gtao", {{3, Access::Sampled}})};
    const BarrierPlan plan = plan_barriers(res, passes);
    const auto& b = plan.passes[0].barriers;
    ASSERT_EQ(b.size(), 4u);
    // The resolve reads the multisampled depth in COLOR_ATTACHMENT_OUTPUT.
    EXPECT_EQ(b[1].dst_stages, kDepthTests | kColorOut);
    EXPECT_EQ(b[1].dst_access, kDepthRW | VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT);
    expect_barrier(b[2], VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                   VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE, kColorOut, kColorRW);
    expect_barrier(b[3], VK_IMAGE_LAYOUT_UNDEFINED,
                   VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_NONE,
                   VK_ACCESS_2_NONE, kColorOut, kColorRW);
    ASSERT_EQ(plan.passes[1].barriers.size(), 1u);
    expect_barrier(plan.passes[1].barriers[0], VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
                   VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, kColorOut,
                   VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, kFragment,
                   VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
}

TEST(GraphPlan, UsageFollowsTheAccesses) {
    const std::vector<ResourceInfo> res = {image("colour"), image("depth", VK_FORMAT_D32_SFLOAT),
                                           buffer("counts")};
    const std::vector<PassInfo> passes = {
        pass("draw", {{0, Access::ColorAttachment},
                      {1, Access::DepthAttachment},
                      {2, Access::StorageReadWrite, Shader::Fragment}}),
        pass("post", {{0, Access::Sampled}, {1, Access::ResolveDst}})};
    const std::vector<VkFlags> usage = derive_usage(res, passes);
    EXPECT_EQ(usage[0], VkFlags(VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                                VK_IMAGE_USAGE_TRANSFER_SRC_BIT));
    EXPECT_EQ(usage[1], VkFlags(VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT |
                                VK_IMAGE_USAGE_TRANSFER_SRC_BIT));
    EXPECT_EQ(usage[2],
              VkFlags(VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT));
}

TEST(GraphPlan, DumpListsPassesResourcesAndBarriers) {
    std::vector<ResourceInfo> res = {image("colour"), image("depth", VK_FORMAT_D32_SFLOAT)};
    res[1].image.semantic = Semantic::ReverseZDepth;
    res[1].image.size = ImageSize::fixed(2048, 2048);
    res[1].extent = {2048, 2048};
    const std::vector<PassInfo> passes = {
        pass("shadow", {{1, Access::DepthAttachment}}),
        pass("lighting", {{0, Access::ColorAttachment}, {1, Access::Sampled, Shader::Fragment}})};
    const std::string text = dump_graph({64, 48}, res, passes, plan_barriers(res, passes));
    for (const char* expected :
         {"output 64x48", "1. shadow (graphics)", "2. lighting", "colour: image R8G8B8A8_UNORM",
          "64x48 (output x1)", "D32_SFLOAT 2048x2048 (fixed)", "ReverseZDepth", "transient",
          "write depth: depth attachment [DEPTH_STENCIL_ATTACHMENT_OPTIMAL]",
          "read depth: sampled (fragment) [SHADER_READ_ONLY_OPTIMAL]",
          "barrier depth: DEPTH_STENCIL_ATTACHMENT_OPTIMAL -> SHADER_READ_ONLY_OPTIMAL, "
          "EARLY_FRAGMENT_TESTS|LATE_FRAGMENT_TESTS/DEPTH_STENCIL_ATTACHMENT_WRITE -> "
          "FRAGMENT_SHADER/SHADER_SAMPLED_READ"})
        EXPECT_NE(text.find(expected), std::string::npos) << expected << "\n" << text;
}

}  // namespace
