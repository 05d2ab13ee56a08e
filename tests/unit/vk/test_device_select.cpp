// Device selection rules and their error messages, over hand-made candidates.
#include <gtest/gtest.h>
#include <vulkan/vulkan.h>

#include "renderer/common/error.h"
#include "renderer/vk/device_select.h"

namespace {

using ds::vk::DeviceCandidate;
using ds::vk::select_device;

DeviceCandidate good(uint32_t index, std::string name) {
    DeviceCandidate c;
    c.index = index;
    c.name = std::move(name);
    c.type = "discrete-gpu";
    c.api_version = VK_MAKE_API_VERSION(0, 1, 3, 230);
    c.dynamic_rendering = c.synchronization2 = c.extended_dynamic_state = true;
    c.graphics_compute_queue = true;
    return c;
}

DeviceCandidate old_device(uint32_t index, std::string name) {
    DeviceCandidate c = good(index, std::move(name));
    c.api_version = VK_MAKE_API_VERSION(0, 1, 2, 0);
    c.dynamic_rendering = false;
    return c;
}

std::string error_of(const std::vector<DeviceCandidate>& list, std::string_view request) {
    try {
        select_device(list, request);
    } catch (const ds::Error& e) {
        return e.what();
    }
    ADD_FAILURE() << "expected ds::Error for request '" << request << "'";
    return {};
}

TEST(DeviceSelect, DefaultIsFirstSuitable) {
    std::vector<DeviceCandidate> list{old_device(0, "Old GPU"), good(1, "llvmpipe"),
                                      good(2, "NVIDIA RTX")};
    EXPECT_EQ(select_device(list, ""), 1u);
}

TEST(DeviceSelect, ByIndex) {
    std::vector<DeviceCandidate> list{good(0, "llvmpipe"), good(1, "NVIDIA RTX")};
    EXPECT_EQ(select_device(list, "1"), 1u);
    EXPECT_EQ(select_device(list, "0"), 0u);
}

TEST(DeviceSelect, ByNameSubstringCaseInsensitive) {
    std::vector<DeviceCandidate> list{good(0, "llvmpipe (LLVM 15.0.6, 256 bits)"),
                                      good(1, "NVIDIA GeForce RTX 4090")};
    EXPECT_EQ(select_device(list, "nvidia"), 1u);
    EXPECT_EQ(select_device(list, "LLVMpipe"), 0u);
}

TEST(DeviceSelect, NameSkipsUnsuitableMatches) {
    std::vector<DeviceCandidate> list{old_device(0, "GPU A"), good(1, "GPU B")};
    EXPECT_EQ(select_device(list, "GPU"), 1u);
}

TEST(DeviceSelect, NoNameMatchListsDevices) {
    std::vector<DeviceCandidate> list{good(0, "llvmpipe"), old_device(1, "Old GPU")};
    const std::string e = error_of(list, "radeon");
    EXPECT_NE(e.find("no device name contains 'radeon'"), std::string::npos) << e;
    EXPECT_NE(e.find("0: llvmpipe"), std::string::npos) << e;
    EXPECT_NE(e.find("1: Old GPU"), std::string::npos) << e;
    EXPECT_NE(e.find("Vulkan 1.2.0 < 1.3"), std::string::npos) << e;
}

TEST(DeviceSelect, IndexOutOfRange) {
    std::vector<DeviceCandidate> list{good(0, "llvmpipe")};
    EXPECT_NE(error_of(list, "3").find("no device with index 3"), std::string::npos);
}

TEST(DeviceSelect, IndexOfUnsuitableDeviceSaysWhy) {
    std::vector<DeviceCandidate> list{old_device(0, "Old GPU"), good(1, "llvmpipe")};
    const std::string e = error_of(list, "0");
    EXPECT_NE(e.find("does not meet the requirements"), std::string::npos) << e;
    EXPECT_NE(e.find("no dynamicRendering"), std::string::npos) << e;
}

TEST(DeviceSelect, NothingSuitable) {
    DeviceCandidate no_queue = good(0, "Compute only");
    no_queue.graphics_compute_queue = false;
    const std::string e = error_of({no_queue}, "");
    EXPECT_NE(e.find("no Vulkan device meets the requirements"), std::string::npos) << e;
    EXPECT_NE(e.find("no graphics+compute queue"), std::string::npos) << e;
    EXPECT_NE(error_of({}, "").find("no Vulkan devices were found"), std::string::npos);
}

TEST(DeviceSelect, UnmetRequirementsAreAllListed) {
    DeviceCandidate c;
    c.api_version = VK_MAKE_API_VERSION(0, 1, 1, 0);
    EXPECT_EQ(ds::vk::unmet_requirements(c).size(), 5u);
    EXPECT_TRUE(ds::vk::unmet_requirements(good(0, "x")).empty());
}

}  // namespace

namespace {

// lavapipe under RenderDoc: Vulkan 1.2, the 1.3 features offered as extensions.
TEST(DeviceSelect, Vulkan12WithTheExtensionsIsAccepted) {
    DeviceCandidate c = good(0, "llvmpipe under RenderDoc");
    c.api_version = VK_MAKE_API_VERSION(0, 1, 2, 0);
    EXPECT_FALSE(ds::vk::unmet_requirements(c).empty()) << "1.2 without the extensions";
    c.via_extensions = true;
    EXPECT_TRUE(ds::vk::unmet_requirements(c).empty());
    EXPECT_EQ(select_device({c}, ""), 0u);
    c.dynamic_rendering = false;  // the extension is there but its feature is off
    EXPECT_FALSE(ds::vk::unmet_requirements(c).empty());
}

TEST(DeviceSelect, Vulkan11IsRefusedEvenWithExtensions) {
    DeviceCandidate c = good(0, "ancient");
    c.api_version = VK_MAKE_API_VERSION(0, 1, 1, 0);
    c.via_extensions = true;
    EXPECT_FALSE(ds::vk::unmet_requirements(c).empty());
}

}  // namespace
