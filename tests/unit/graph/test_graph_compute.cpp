// A compute pass on the real device with synchronization validation: a storage image written
// in compute and sampled in a fragment shader, over several frames (each frame's compute
// write must wait for the previous frame's sampling).
#include <cstring>
#include <utility>
#include <vector>

#include "renderer/shader/compiler.h"
#include "renderer/vk/buffer.h"
#include "renderer/vk/pipeline.h"
#include "tests/unit/graph/graph_fixture.h"
#include "tests/unit/graph/swizzle.h"

namespace ds::graph::test {
namespace {

constexpr VkExtent2D kComputeSize{64, 48};

// pattern.comp: one storage image, 8x8 groups.
struct Pattern {
    VkDevice device;
    vk::DescriptorSetLayout set_layout;
    vk::PipelineLayout layout;
    vk::Pipeline pipeline;
    vk::DescriptorPool pool;
    VkDescriptorSet set = VK_NULL_HANDLE;

    explicit Pattern(vk::Context& context) : device(context.device()) {
        shader::Compiler compiler(DS_GRAPH_TEST_SHADERS, "");
        const auto spirv = compiler.compile("pattern.comp", shader::Stage::Compute).spirv;
        const VkDescriptorSetLayoutBinding binding =
            vk::layout_binding(0, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_SHADER_STAGE_COMPUTE_BIT);
        set_layout = vk::DescriptorSetLayout(context, {&binding, 1}, "pattern set");
        const VkDescriptorSetLayout sets[] = {set_layout.handle()};
        layout = vk::PipelineLayout(context, sets, {}, "pattern layout");
        const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1};
        pool = vk::DescriptorPool(context, 1, {&size, 1}, "pattern pool");
        set = pool.allocate(set_layout.handle());

        pipeline = vk::create_compute_pipeline(context, layout.handle(), spirv, "pattern");
    }

    void record(const PassContext& ctx, ImageHandle target) const {
        // Every earlier frame has finished: the set is free to rewrite.
        const VkDescriptorImageInfo image{VK_NULL_HANDLE, ctx.view(target), ctx.layout(target)};
        auto write = vk::make<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
        write.dstSet = set;
        write.descriptorCount = 1;
        write.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
        write.pImageInfo = &image;
        vkUpdateDescriptorSets(device, 1, &write, 0, nullptr);
        VkCommandBuffer cmd = ctx.cmd();
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.handle());
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout.handle(), 0, 1, &set, 0,
                                nullptr);
        const VkExtent2D e = ctx.extent(target);
        vkCmdDispatch(cmd, (e.width + 7) / 8, (e.height + 7) / 8, 1);
    }
};

void declare(RenderGraph& g, const Pattern& pattern, const Swizzle& swizzle,
             const vk::Buffer& readback) {
    const BufferHandle rb = g.import_buffer(
        "readback", {readback.handle(), readback.size(), {}, ExternalState::host_read()});
    const ImageDesc desc{.format = kSwizzleFormat,
                         .size = ImageSize::relative(1.0f),
                         .semantic = Semantic::LdrColor};
    struct Image {
        ImageHandle image;
    };
    const ImageHandle image =
        g.add_pass<Image>(
             {"pattern", PassKind::Compute},
             [&](PassBuilder& b, Image& d) {
                 d.image = b.create_image("pattern", desc);
                 // a compute pass: the compute stage
                 b.write(d.image, Access::StorageWrite);
             },
             [&pattern](PassContext& ctx, const Image& d) { pattern.record(ctx, d.image); })
            .image;
    const ImageHandle swizzled =
        g.add_pass<Image>(
             "swizzle",
             [&](PassBuilder& b, Image& d) {
                 d.image = b.create_image("swizzled", desc);
                 b.read(image, Access::Sampled);  // a graphics pass: the fragment stage
                 b.color(d.image, {.load = Load::Clear});
             },
             [&swizzle, image](PassContext& ctx, const Image&) { swizzle.record(ctx, image); })
            .image;
    add(
        g, {"readback", PassKind::Transfer},
        [&](PassBuilder& b) {
            b.read(swizzled, Access::TransferSrc);
            b.write(rb, Access::TransferDst);
        },
        [swizzled, rb](PassContext& ctx) { copy_to_buffer(ctx, swizzled, rb); });
}

TEST_F(GraphVk, ComputeStorageImageSampledByAFragmentShader) {
    const Pattern pattern(*context_);
    const Swizzle swizzle(*context_);
    const vk::Buffer readback(
        *context_, {VkDeviceSize(kComputeSize.width) * kComputeSize.height * 4,
                    VK_BUFFER_USAGE_TRANSFER_DST_BIT, vk::MemoryUsage::Readback, "readback"});
    for (int f = 0; f < 3; ++f) {
        const uint64_t id =
            frame(kComputeSize, [&](RenderGraph& g) { declare(g, pattern, swizzle, readback); });
        readback.invalidate();
        size_t right = 0;
        for (uint32_t y = 0; y < kComputeSize.height; ++y)
            for (uint32_t x = 0; x < kComputeSize.width; ++x) {
                uint8_t p[4];
                std::memcpy(p, readback.mapped() + (size_t(y) * kComputeSize.width + x) * 4, 4);
                right += p[0] == 255 && p[1] == y && p[2] == x && p[3] == 255;
            }
        EXPECT_EQ(right, size_t(kComputeSize.width) * kComputeSize.height) << "frame " << f;
        const std::vector<PassResult> results = graph_->collect(id);
        ASSERT_EQ(results.size(), 3u);
        if (graph_->has_statistics()) {
            EXPECT_GE(results[0].compute_invocations,
                      uint64_t(kComputeSize.width) * kComputeSize.height);
            EXPECT_EQ(results[0].vertex_invocations, 0u);
            EXPECT_EQ(results[1].compute_invocations, 0u);
        }
    }
    const std::string dump = graph_->dump();
    for (const char* expected :
         {"1. pattern (compute)", "write pattern: storage write (compute) [GENERAL]",
          "barrier pattern: UNDEFINED -> GENERAL, FRAGMENT_SHADER/NONE -> "
          "COMPUTE_SHADER/SHADER_STORAGE_WRITE",
          "barrier pattern: GENERAL -> SHADER_READ_ONLY_OPTIMAL, "
          "COMPUTE_SHADER/SHADER_STORAGE_WRITE -> FRAGMENT_SHADER/SHADER_SAMPLED_READ"})
        EXPECT_NE(dump.find(expected), std::string::npos) << expected << "\n" << dump;
    EXPECT_EQ(context_->validation_message_count(), 0u);
}

}  // namespace
}  // namespace ds::graph::test
