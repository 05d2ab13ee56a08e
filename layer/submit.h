#pragma once
// Queue submissions and presents: where frames are counted, and where the chosen frame's
// command buffers are replaced by counting copies (capture.h).
#include <vulkan/vulkan.h>

namespace ds::layer {

PFN_vkVoidFunction submit_function(const char* name);

}  // namespace ds::layer
