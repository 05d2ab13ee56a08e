#include "renderer/vk/check.h"

#include <string>

#include "renderer/common/error.h"

namespace ds::vk {

std::string result_name(VkResult result) {
    switch (result) {
#define DS_RESULT(name) \
    case name:          \
        return #name;
        DS_RESULT(VK_SUCCESS)
        DS_RESULT(VK_NOT_READY)
        DS_RESULT(VK_TIMEOUT)
        DS_RESULT(VK_EVENT_SET)
        DS_RESULT(VK_EVENT_RESET)
        DS_RESULT(VK_INCOMPLETE)
        DS_RESULT(VK_ERROR_OUT_OF_HOST_MEMORY)
        DS_RESULT(VK_ERROR_OUT_OF_DEVICE_MEMORY)
        DS_RESULT(VK_ERROR_INITIALIZATION_FAILED)
        DS_RESULT(VK_ERROR_DEVICE_LOST)
        DS_RESULT(VK_ERROR_MEMORY_MAP_FAILED)
        DS_RESULT(VK_ERROR_LAYER_NOT_PRESENT)
        DS_RESULT(VK_ERROR_EXTENSION_NOT_PRESENT)
        DS_RESULT(VK_ERROR_FEATURE_NOT_PRESENT)
        DS_RESULT(VK_ERROR_INCOMPATIBLE_DRIVER)
        DS_RESULT(VK_ERROR_TOO_MANY_OBJECTS)
        DS_RESULT(VK_ERROR_FORMAT_NOT_SUPPORTED)
        DS_RESULT(VK_ERROR_FRAGMENTED_POOL)
        DS_RESULT(VK_ERROR_UNKNOWN)
        DS_RESULT(VK_ERROR_OUT_OF_POOL_MEMORY)
        DS_RESULT(VK_ERROR_INVALID_EXTERNAL_HANDLE)
        DS_RESULT(VK_ERROR_FRAGMENTATION)
        DS_RESULT(VK_ERROR_INVALID_OPAQUE_CAPTURE_ADDRESS)
        DS_RESULT(VK_PIPELINE_COMPILE_REQUIRED)
        DS_RESULT(VK_ERROR_SURFACE_LOST_KHR)
        DS_RESULT(VK_ERROR_NATIVE_WINDOW_IN_USE_KHR)
        DS_RESULT(VK_SUBOPTIMAL_KHR)
        DS_RESULT(VK_ERROR_OUT_OF_DATE_KHR)
        DS_RESULT(VK_ERROR_VALIDATION_FAILED_EXT)
#undef DS_RESULT
        default:
            return "VkResult(" + std::to_string(int(result)) + ")";
    }
}

void check(VkResult result, const char* what) {
    if (result == VK_SUCCESS) return;
    std::string text = result_name(result);
    if (result == VK_ERROR_DEVICE_LOST) text += " (the device was lost)";
    throw Error(std::string(what) + " failed: " + text);
}

}  // namespace ds::vk
