#pragma once
// VkResult checking that stays on in release builds (DESIGN decision 8).
#include <string>

#include <vulkan/vulkan.h>

namespace ds::vk {

// "VK_ERROR_DEVICE_LOST", ... ("VkResult(N)" for codes this table does not know).
std::string result_name(VkResult result);

// Throws ds::Error "WHAT failed: VK_ERROR_..." unless `result` is VK_SUCCESS. Positive codes
// (VK_INCOMPLETE, VK_TIMEOUT, ...) are errors too: callers that expect one test for it first.
void check(VkResult result, const char* what);

// A zero-initialised Vulkan struct with sType (and pNext) set; avoids the brace form
// `VkFoo x{VK_STRUCTURE_TYPE_FOO}` that -Wmissing-field-initializers flags.
template <typename T>
T make(VkStructureType type, void* next = nullptr) {
    T value{};
    value.sType = type;
    value.pNext = next;
    return value;
}

}  // namespace ds::vk
