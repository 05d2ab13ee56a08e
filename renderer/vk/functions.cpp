#include "renderer/vk/functions.h"

#include <string>

#include "renderer/common/error.h"

namespace ds::vk {
namespace {

DeviceFunctions g_functions;

template <typename Pfn>
void load(VkDevice device, Pfn& out, const char* core, const char* ext, bool via_extensions) {
    const char* name = via_extensions ? ext : core;
    out = reinterpret_cast<Pfn>(vkGetDeviceProcAddr(device, name));
    if (!out) throw Error(std::string("Vulkan device lacks ") + name);
}

}  // namespace

void load_device_functions(VkDevice d, bool x) {
    DeviceFunctions f;
    load(d, f.cmd_begin_rendering, "vkCmdBeginRendering", "vkCmdBeginRenderingKHR", x);
    load(d, f.cmd_end_rendering, "vkCmdEndRendering", "vkCmdEndRenderingKHR", x);
    load(d, f.cmd_pipeline_barrier2, "vkCmdPipelineBarrier2", "vkCmdPipelineBarrier2KHR", x);
    load(d, f.cmd_write_timestamp2, "vkCmdWriteTimestamp2", "vkCmdWriteTimestamp2KHR", x);
    load(d, f.queue_submit2, "vkQueueSubmit2", "vkQueueSubmit2KHR", x);
    load(d, f.cmd_set_cull_mode, "vkCmdSetCullMode", "vkCmdSetCullModeEXT", x);
    load(d, f.cmd_set_depth_test_enable, "vkCmdSetDepthTestEnable", "vkCmdSetDepthTestEnableEXT",
         x);
    load(d, f.cmd_set_depth_write_enable, "vkCmdSetDepthWriteEnable", "vkCmdSetDepthWriteEnableEXT",
         x);
    load(d, f.cmd_set_depth_compare_op, "vkCmdSetDepthCompareOp", "vkCmdSetDepthCompareOpEXT", x);
    g_functions = f;
}

const DeviceFunctions& fn() {
    return g_functions;
}

}  // namespace ds::vk
