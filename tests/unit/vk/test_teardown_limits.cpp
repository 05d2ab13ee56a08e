// Issue 12 on the real device: what the validation layer reports while the device is destroyed
// (objects never destroyed) counts, through Context and Renderer::shutdown(); resources beyond
// the device's limits are refused before Vulkan sees them, naming the resource and the limit.
#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

#include "renderer/common/error.h"
#include "renderer/renderer.h"
#include "renderer/scene/loader.h"
#include "renderer/vk/buffer.h"
#include "renderer/vk/check.h"
#include "renderer/vk/context.h"
#include "renderer/vk/image.h"

namespace {

using namespace ds;

vk::ContextOptions validated_options() {
    vk::ContextOptions o;
    o.validate = true;
    return o;
}

// A sampler created behind the vk layer's back and never destroyed: a leak the layer's object
// tracker reports at vkDestroyDevice.
void leak_a_sampler(const vk::Context& context) {
    auto info = vk::make<VkSamplerCreateInfo>(VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO);
    VkSampler sampler = VK_NULL_HANDLE;
    ASSERT_EQ(vkCreateSampler(context.device(), &info, nullptr, &sampler), VK_SUCCESS);
}

// DEPTHSCOPE_DEVICE_LIMITS for one scope.
class ScopedLimits {
  public:
    explicit ScopedLimits(const char* text) { ::setenv("DEPTHSCOPE_DEVICE_LIMITS", text, 1); }
    ~ScopedLimits() { ::unsetenv("DEPTHSCOPE_DEVICE_LIMITS"); }
};

TEST(VkTeardown, LeakedObjectIsCountedAtDeviceDestruction) {
    auto context = std::make_unique<vk::Context>(validated_options());
    const auto counter = context->validation_counter();
    leak_a_sampler(*context);
    EXPECT_EQ(*counter, 0u) << "nothing is reported before the device is destroyed";
    context.reset();
    EXPECT_GT(*counter, 0u) << "the layer reports the sampler at vkDestroyDevice";
}

TEST(VkTeardown, ContextWithoutLeaksReportsNothingAtDestruction) {
    auto context = std::make_unique<vk::Context>(validated_options());
    const auto counter = context->validation_counter();
    context.reset();
    EXPECT_EQ(*counter, 0u);
}

TEST(VkTeardown, RendererShutdownCountsWhatTeardownReports) {
    RendererOptions options;
    options.validate = true;
    Renderer renderer(options);
    const scene::Scene scene = scene::load_scene("edges", Settings{});
    renderer.set_scene(scene);
    renderer.render(scene.camera, Settings{}, {.width = 64, .height = 36});
    leak_a_sampler(renderer.context());
    EXPECT_EQ(renderer.validation_message_count(), 0u);
    renderer.shutdown();
    EXPECT_GT(renderer.validation_message_count(), 0u)
        << "the exit code reads this after shutdown(): a leak must make it 3";
    EXPECT_THROW(renderer.render(scene.camera, Settings{}, {.width = 64, .height = 36}), ds::Error);
}

TEST(VkLimits, ImageBeyondTheDimensionLimitIsRefusedByName) {
    vk::Context context(validated_options());
    const uint32_t too_wide = context.limits().maxImageDimension2D + 1;
    try {
        vk::Image image(context, {too_wide, 4, 1, VK_FORMAT_R8G8B8A8_UNORM,
                                  VK_IMAGE_USAGE_SAMPLED_BIT, VK_SAMPLE_COUNT_1_BIT, "too_wide"});
        FAIL() << "expected ds::Error";
    } catch (const ds::Error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("image 'too_wide' " + std::to_string(too_wide) + "x4"),
                  std::string::npos)
            << what;
        EXPECT_NE(what.find("maxImageDimension2D"), std::string::npos) << what;
    }
    EXPECT_EQ(context.validation_message_count(), 0u) << "vkCreateImage never saw it";
}

TEST(VkLimits, LoweredDimensionLimitAppliesToImages) {
    const ScopedLimits limits("image=256");
    vk::Context context(validated_options());
    EXPECT_EQ(context.limits().maxImageDimension2D, 256u);
    EXPECT_TRUE(context.report().limits.lowered);
    EXPECT_NO_THROW(
        vk::Image(context, {256, 256, 1, VK_FORMAT_R8G8B8A8_UNORM, VK_IMAGE_USAGE_SAMPLED_BIT,
                            VK_SAMPLE_COUNT_1_BIT, "fits"}));
    EXPECT_THROW(vk::Image(context, {257, 16, 1, VK_FORMAT_R8G8B8A8_UNORM,
                                     VK_IMAGE_USAGE_SAMPLED_BIT, VK_SAMPLE_COUNT_1_BIT, "wide"}),
                 ds::Error);
}

TEST(VkLimits, AllocationAboveTheLargestIsRefusedByName) {
    const ScopedLimits limits("allocation_mib=1");
    vk::Context context(validated_options());
    try {
        vk::Buffer big(context, {2u << 20, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                 vk::MemoryUsage::GpuOnly, "two_mib"});
        FAIL() << "expected ds::Error";
    } catch (const ds::Error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("buffer 'two_mib' (2097152 bytes"), std::string::npos) << what;
        EXPECT_NE(what.find("maxMemoryAllocationSize (1.0 MiB)"), std::string::npos) << what;
    }
    EXPECT_EQ(context.allocator().stats().used_bytes, 0u);
}

TEST(VkLimits, RendererRefusesAFrameOverTheHeapBeforeAllocatingIt) {
    const ScopedLimits limits("heap_mib=32");
    RendererOptions options;
    options.validate = true;
    Renderer renderer(options);
    const scene::Scene scene = scene::load_scene("edges", Settings{});
    renderer.set_scene(scene);
    EXPECT_NO_THROW(renderer.render(scene.camera, Settings{}, {.width = 64, .height = 36}));
    try {
        renderer.render(scene.camera, Settings{}, {.width = 1280, .height = 720});
        FAIL() << "expected ds::Error";
    } catch (const ds::Error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("a 1280x720 frame at msaa=1 needs about"), std::string::npos) << what;
        EXPECT_NE(what.find("the 32.0 MiB device-local heap"), std::string::npos) << what;
    }
    // The refused frame was never submitted: the renderer goes on at a size that fits.
    EXPECT_NO_THROW(renderer.render(scene.camera, Settings{}, {.width = 64, .height = 36}));
    renderer.shutdown();
    EXPECT_EQ(renderer.validation_message_count(), 0u);
}

}  // namespace
