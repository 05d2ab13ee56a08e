#pragma once
// The objects whose creation the layer notes: queues, swapchains, command pools and buffers,
// render passes, framebuffers and image views; and the device's start and end.
#include <vulkan/vulkan.h>

#include "layer/state.h"

namespace ds::layer {

PFN_vkVoidFunction object_function(const char* name);
PFN_vkVoidFunction pipeline_object_function(const char* name);  // objects_pipeline.cpp
PFN_vkVoidFunction instance_function(const char* name);
void device_created(DeviceData& device);
void device_destroyed(DeviceData& device);

}  // namespace ds::layer
