// main() of every test binary that needs a Vulkan device. Before any test runs, one probe
// creates a device the way the renderer does (vk::Context, first suitable, Vulkan 1.3): without
// one the binary FAILS, saying no usable Vulkan device was found and why (a missing ICD, or
// vkCreateInstance's VK_ERROR_INCOMPATIBLE_DRIVER from a driver that did not load), so a
// broken driver install never looks like a passing suite. DEPTHSCOPE_ALLOW_NO_DEVICE=1 turns
// that into a skip, with the same reason. (Left to GoogleTest, a throwing SetUpTestSuite or a
// failing global environment is reported as every test skipped.)
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

}  // namespace

int main(int argc, char** argv) {
    ::testing::InitGoogleTest(&argc, argv);
    // Listing the tests (gtest_discover_tests) needs no device.
    if (!GTEST_FLAG_GET(list_tests)) {
        const std::string why = probe_device();
        if (!why.empty()) {
            // Before any test: GoogleTest marks every test skipped after a failing global
            // set-up (and ctest reports a test whose output says [  SKIPPED ] as skipped).
            if (skipping_allowed()) {
                std::printf(
                    "[  SKIPPED ] no usable Vulkan device found: %s "
                    "(DEPTHSCOPE_ALLOW_NO_DEVICE=1)\n",
                    why.c_str());
                return 0;
            }
            std::printf(
                "[  FAILED  ] no usable Vulkan device found: %s (this binary needs one; "
                "DEPTHSCOPE_ALLOW_NO_DEVICE=1 skips instead)\n",
                why.c_str());
            return 1;
        }
    }
    return RUN_ALL_TESTS();
}
