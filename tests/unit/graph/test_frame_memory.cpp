// The frame memory estimate and the size check (pure): what the renderer refuses before
// allocating, and the one line it says.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "renderer/common/error.h"
#include "renderer/frame/frame_memory.h"

namespace {

using namespace ds;

graph::ResourceInfo image(const char* name, VkFormat format, VkExtent2D extent,
                          VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT) {
    graph::ResourceInfo r;
    r.name = name;
    r.image.format = format;
    r.image.samples = samples;
    r.extent = extent;
    return r;
}

vk::DeviceLimits limits(uint64_t heap_bytes) {
    vk::DeviceLimits l;
    l.max_image_dimension_2d = 16384;
    l.max_framebuffer_width = 16384;
    l.max_framebuffer_height = 8192;
    l.heap_index = 0;
    l.heap_bytes = heap_bytes;
    return l;
}

TEST(FrameMemory, ImageBytesCountSamplesAndMips) {
    EXPECT_EQ(image_bytes(VK_FORMAT_R16G16B16A16_SFLOAT, {16384, 16384}, VK_SAMPLE_COUNT_1_BIT),
              2ull << 30);
    EXPECT_EQ(image_bytes(VK_FORMAT_D32_SFLOAT, {100, 10}, VK_SAMPLE_COUNT_4_BIT), 16000u);
    // 4x4 + 2x2 + 1x1 texels of 4 bytes
    EXPECT_EQ(image_bytes(VK_FORMAT_R8G8B8A8_UNORM, {4, 4}, VK_SAMPLE_COUNT_1_BIT, 3), 84u);
}

TEST(FrameMemory, SumsImagesAndBuffersAndNamesTheLargest) {
    std::vector<graph::ResourceInfo> resources{
        image("final", VK_FORMAT_R8G8B8A8_SRGB, {1000, 1000}),
        image("hdr", VK_FORMAT_R16G16B16A16_SFLOAT, {1000, 1000})};
    graph::ResourceInfo buffer;
    buffer.name = "counts";
    buffer.is_image = false;
    buffer.size = 1000;
    resources.push_back(buffer);
    const FrameMemory m = frame_memory(resources);
    EXPECT_EQ(m.bytes, 4'000'000u + 8'000'000u + 1000u);
    EXPECT_EQ(m.largest, "hdr");
    EXPECT_EQ(m.largest_bytes, 8'000'000u);
}

TEST(FrameMemory, OverTheHeapIsOneLineWithTheEstimate) {
    FrameMemory frame;
    frame.add("hdr", 2ull << 30);
    frame.add("depth", 1ull << 30);
    const FrameShape shape{"llvmpipe", {16384, 16384}, VK_SAMPLE_COUNT_1_BIT};
    EXPECT_NO_THROW(check_frame_memory(frame, 1ull << 30, 4ull << 30, limits(4ull << 30), shape));
    try {
        check_frame_memory(frame, 1ull << 30, 2ull << 30, limits(2ull << 30), shape);
        FAIL() << "expected ds::Error";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()),
                  "a 16384x16384 frame at msaa=1 needs about 4.0 GiB of device memory (its images "
                  "and buffers 3.0 GiB, the largest 'hdr' 2.0 GiB; the scene 1.0 GiB): more than "
                  "the 2.0 GiB device-local heap of llvmpipe");
    }
}

TEST(FrameMemory, SizeBeyondTheFramebufferLimitNamesIt) {
    const FrameShape fits{"gpu", {16384, 8192}, VK_SAMPLE_COUNT_4_BIT};
    EXPECT_NO_THROW(check_frame_size(limits(1), fits));
    const FrameShape tall{"gpu", {100, 8193}, VK_SAMPLE_COUNT_4_BIT};
    try {
        check_frame_size(limits(1), tall);
        FAIL() << "expected ds::Error";
    } catch (const Error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("a 100x8193 frame at msaa=4 is larger than gpu allows: at most "
                            "16384x8192"),
                  std::string::npos)
            << what;
        EXPECT_NE(what.find("maxFramebufferHeight 8192"), std::string::npos) << what;
    }
}

}  // namespace
