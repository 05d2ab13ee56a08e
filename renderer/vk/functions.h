#pragma once
// Entry points of the Vulkan 1.3 commands depthscope uses, loaded per device: the core names on
// a 1.3 device, the KHR/EXT names on a 1.2 device that offers them as extensions (lavapipe
// under RenderDoc). The loader's exported core symbols would be null there. One device per
// process, so the table is process-wide, like volk's.
#include <vulkan/vulkan.h>

namespace ds::vk {

struct DeviceFunctions {
    PFN_vkCmdBeginRendering cmd_begin_rendering = nullptr;
    PFN_vkCmdEndRendering cmd_end_rendering = nullptr;
    PFN_vkCmdPipelineBarrier2 cmd_pipeline_barrier2 = nullptr;
    PFN_vkCmdWriteTimestamp2 cmd_write_timestamp2 = nullptr;
    PFN_vkQueueSubmit2 queue_submit2 = nullptr;
    PFN_vkCmdSetCullMode cmd_set_cull_mode = nullptr;
    PFN_vkCmdSetDepthTestEnable cmd_set_depth_test_enable = nullptr;
    PFN_vkCmdSetDepthWriteEnable cmd_set_depth_write_enable = nullptr;
    PFN_vkCmdSetDepthCompareOp cmd_set_depth_compare_op = nullptr;
};

// Throws ds::Error naming the first entry point the device does not provide.
void load_device_functions(VkDevice device, bool via_extensions);
const DeviceFunctions& fn();

}  // namespace ds::vk
