// main() of every test binary that needs a Vulkan device. Before any test runs, one probe
// creates a device the way the renderer does (vk::Context, first suitable, Vulkan 1.3): without
// one the binary FAILS, saying no usable Vulkan device was found and why (a missing ICD, or
// vkCreateInstance's VK_ERROR_INCOMPATIBLE_DRIVER from a driver that did not load), so a
// broken driver install never looks like a passing suite. DEPTHSCOPE_ALLOW_NO_DEVICE=1 turns
// that into a skip of every test, with the same reason. (Without this, a fixture's throwing
// SetUpTestSuite is reported by GoogleTest as its tests being skipped.)
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>

#include <gtest/gtest.h>

#include "renderer/vk/context.h"

namespace {

// Empty when a device could be created; else why not.
std::string probe_device() {
    try {
        ds::vk::Context context(ds::vk::ContextOptions{});
        return {};
    } catch (const std::exception& e) {
        return e.what();
    }
}

bool skipping_allowed() {
    const char* env = std::getenv("DEPTHSCOPE_ALLOW_NO_DEVICE");
    return env && std::strcmp(env, "1") == 0;
}

class VulkanDevice : public ::testing::Environment {
  public:
    void SetUp() override {
        const std::string why = probe_device();
        if (why.empty()) return;
        const std::string message = "no usable Vulkan device found: " + why;
        if (skipping_allowed()) {
            // GoogleTest prints a global skip without its [  SKIPPED ] tag; ctest's skip
            // pattern (gtest_discover_tests) needs the tag to report the test as skipped.
            std::printf("[  SKIPPED ] %s (DEPTHSCOPE_ALLOW_NO_DEVICE=1)\n", message.c_str());
            GTEST_SKIP() << message;
        }
        GTEST_FAIL() << message
                     << " (this test needs one; DEPTHSCOPE_ALLOW_NO_DEVICE=1 skips instead)";
    }
};

}  // namespace

int main(int argc, char** argv) {
    ::testing::InitGoogleTest(&argc, argv);
    ::testing::AddGlobalTestEnvironment(new VulkanDevice);  // GoogleTest owns it
    return RUN_ALL_TESTS();
}
