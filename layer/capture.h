#pragma once
// Capturing the chosen frame: each of its submissions with a depth pass is recorded again by
// CountingRecorder into the layer's command buffers, submitted in place of the application's
// (same semaphores and fence), waited for, and its counts read back; at the frame's end
// (its present, or the device's end) the results go to DEPTHSCOPE_LAYER_OUT
// (capture_output.h), which `depthscope layer` turns into a capture folder.
#include <vector>

#include <vulkan/vulkan.h>

#include "layer/state.h"

namespace ds::layer {

// Submits `submits` (or `submits2`) with the recordable command buffers replaced by counting
// copies. Returns the submission's result.
VkResult capture_submit(DeviceData& d, VkQueue queue, uint32_t n, const VkSubmitInfo* submits,
                        VkFence fence);
VkResult capture_submit2(DeviceData& d, VkQueue queue, uint32_t n, const VkSubmitInfo2* submits,
                         VkFence fence);
// The chosen frame is over: its results are written and the capture's objects destroyed.
// finish_locked: with process().capture_mutex held.
void finish_capture(DeviceData& d);
void finish_locked(DeviceData& d);

}  // namespace ds::layer
