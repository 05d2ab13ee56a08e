// The vk layer on the real device (lavapipe in CI): probing, selection errors, memory,
// uploads. Validation stays on where a Context is created.
#include <cstring>
#include <numeric>

#include <gtest/gtest.h>

#include "renderer/common/error.h"
#include "renderer/vk/barrier.h"
#include "renderer/vk/buffer.h"
#include "renderer/vk/capabilities.h"
#include "renderer/vk/context.h"
#include "renderer/vk/destroy_list.h"
#include "renderer/vk/image.h"
#include "renderer/vk/upload.h"

namespace {

using namespace ds::vk;

ContextOptions validated() {
    ContextOptions o;
    o.validate = true;
    return o;
}

TEST(VkDevice, ProbeReportsEveryDevice) {
    const std::vector<DeviceReport> reports = probe_all_devices();
    ASSERT_FALSE(reports.empty());
    for (const DeviceReport& r : reports) {
        const std::string text = format_report(r);
        EXPECT_NE(text.find(r.candidate.name), std::string::npos) << text;
        EXPECT_NE(text.find("depth resolve modes"), std::string::npos) << text;
        if (r.candidate.name.find("llvmpipe") == std::string::npos) continue;
        // DESIGN.md's lavapipe facts, as this probe sees them.
        EXPECT_TRUE(r.unmet.empty()) << text;
        EXPECT_EQ(r.depth_format, VK_FORMAT_D32_SFLOAT);
        EXPECT_EQ(r.depth_resolve_modes, VkResolveModeFlags(VK_RESOLVE_MODE_SAMPLE_ZERO_BIT |
                                                            VK_RESOLVE_MODE_AVERAGE_BIT));
        EXPECT_TRUE(r.timestamps);
        EXPECT_GT(r.timestamp_valid_bits, 0u);
        EXPECT_TRUE(r.pipeline_statistics);
        EXPECT_FALSE(r.descriptor_indexing);
        EXPECT_NE(text.find("MAX: shader fallback"), std::string::npos) << text;
    }
}

TEST(VkDevice, UnknownDeviceNameIsAClearError) {
    ContextOptions o;
    o.device = "no-such-gpu";
    try {
        Context context(o);
        FAIL() << "expected ds::Error";
    } catch (const ds::Error& e) {
        EXPECT_NE(std::string(e.what()).find("no device name contains 'no-such-gpu'"),
                  std::string::npos)
            << e.what();
    }
    ContextOptions by_index;
    by_index.device = "0";
    EXPECT_NO_THROW(Context{by_index});
}

TEST(VkDevice, AllocatorSubAllocatesSmallAndDedicatesLarge) {
    Context context(validated());
    Allocator& allocator = context.allocator();
    {
        std::vector<Buffer> small;
        for (int i = 0; i < 64; ++i)
            small.emplace_back(context, BufferDesc{1024, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                                   MemoryUsage::GpuOnly, "small"});
        EXPECT_EQ(allocator.stats().blocks, 1u) << "64 KiB fit in one block";
        EXPECT_EQ(allocator.stats().dedicated, 0u);
        EXPECT_GE(allocator.stats().used_bytes, 64u * 1024u);

        Buffer big(context, BufferDesc{48ull << 20, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                       MemoryUsage::GpuOnly, "big"});
        EXPECT_EQ(allocator.stats().dedicated, 1u);
        Image image(context, ImageDesc{256, 256, 1, VK_FORMAT_R8G8B8A8_UNORM,
                                       VK_IMAGE_USAGE_SAMPLED_BIT, VK_SAMPLE_COUNT_1_BIT, "img"});
        EXPECT_EQ(allocator.stats().blocks, 2u) << "images and buffers never share a block";
    }
    EXPECT_EQ(allocator.stats().used_bytes, 0u);
    EXPECT_EQ(allocator.stats().dedicated, 0u);
    EXPECT_EQ(context.validation_message_count(), 0u);
}

TEST(VkDevice, StagingUploadRoundTrips) {
    Context context(validated());
    std::vector<uint32_t> data(4096);
    std::iota(data.begin(), data.end(), 7u);
    const size_t bytes = data.size() * sizeof(uint32_t);
    Buffer gpu(context, {bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                         MemoryUsage::GpuOnly, "gpu"});
    Buffer readback(context,
                    {bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUsage::Readback, "readback"});
    UploadBatch batch(context);
    batch.buffer(gpu, data.data(), bytes);
    batch.submit();
    context.submit_once([&](VkCommandBuffer cmd) {
        const VkBufferCopy region{0, 0, bytes};
        vkCmdCopyBuffer(cmd, gpu.handle(), readback.handle(), 1, &region);
        memory_barrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                       VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
    });
    readback.invalidate();
    ASSERT_NE(readback.mapped(), nullptr);
    EXPECT_EQ(std::memcmp(readback.mapped(), data.data(), bytes), 0);
    EXPECT_EQ(context.validation_message_count(), 0u);
}

TEST(VkDevice, TexturesGetBlittedMipsWhenTheFormatAllows) {
    Context context(validated());
    const VkFormat format = VK_FORMAT_R8G8B8A8_SRGB;
    Image image(context, ImageDesc{64, 32, mip_level_count(64, 32), format,
                                   VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                                       VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                   VK_SAMPLE_COUNT_1_BIT, "mipped"});
    std::vector<uint8_t> texels(64 * 32 * 4, 128);
    UploadBatch batch(context);
    const MipFill fill = batch.texture(image, texels.data());
    batch.submit();
    EXPECT_EQ(fill, supports_blit_mips(context, format) ? MipFill::Blit : MipFill::Cpu);
    EXPECT_EQ(image.mip_levels(), 7u);
    EXPECT_EQ(context.validation_message_count(), 0u);
}

TEST(VkDevice, DestroyListKeepsObjectsUntilFlushed) {
    Context context(validated());
    DestroyList list;
    Buffer buffer(context, {256, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, MemoryUsage::Upload, "b"});
    list.defer(std::move(buffer));
    EXPECT_FALSE(buffer);
    EXPECT_EQ(list.size(), 1u);
    EXPECT_GT(context.allocator().stats().used_bytes, 0u);
    list.flush();
    EXPECT_EQ(list.size(), 0u);
    EXPECT_EQ(context.allocator().stats().used_bytes, 0u);
}

}  // namespace
