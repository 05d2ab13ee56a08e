#pragma once
// The layer's records of the instances, devices and objects it has seen, found by the
// loader's dispatch key (the first word of every dispatchable handle).
#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <unordered_map>
#include <vector>

#include <vulkan/vk_layer.h>
#include <vulkan/vulkan.h>

#include "layer/commands.h"
#include "layer/config.h"
#include "layer/dispatch.h"
#include "layer/frames.h"
#include "layer/pipelines.h"

namespace ds::layer {

struct FrameCapture;  // capture_state.h

template <typename Handle>
void* dispatch_key(Handle h) {
    return *reinterpret_cast<void**>(h);
}

struct InstanceData {
    VkInstance instance = VK_NULL_HANDLE;
    InstanceTable t;
    std::string application;  // VkApplicationInfo's name, if any
    uint32_t api_version = VK_API_VERSION_1_0;  // VkApplicationInfo's (the device's at most)
};

struct SubpassInfo {
    uint32_t depth_attachment = VK_ATTACHMENT_UNUSED;
    uint32_t view_mask = 0;
    std::vector<uint32_t> colors;
};
struct RenderPassInfo {
    std::vector<VkFormat> formats;
    std::vector<VkSampleCountFlagBits> samples;
    std::vector<SubpassInfo> subpasses;
};
struct FramebufferInfo {
    VkExtent2D extent{};
    std::vector<VkImageView> views;  // empty for an imageless framebuffer
};
struct ViewInfo {
    VkImage image = VK_NULL_HANDLE;
    VkFormat format = VK_FORMAT_UNDEFINED;
};

struct DeviceData {
    VkDevice device = VK_NULL_HANDLE;
    VkPhysicalDevice physical = VK_NULL_HANDLE;
    InstanceData* instance = nullptr;
    DeviceTable t;
    PFN_vkSetDeviceLoaderData set_loader_data = nullptr;

    std::mutex mutex;  // guards the maps below
    std::unordered_map<VkCommandBuffer, std::unique_ptr<CommandBufferState>> command_buffers;
    std::unordered_map<VkRenderPass, RenderPassInfo> render_passes;
    std::unordered_map<VkFramebuffer, FramebufferInfo> framebuffers;
    std::unordered_map<VkImageView, ViewInfo> views;
    std::unordered_map<VkQueue, uint32_t> queue_families;
    std::unordered_map<VkShaderModule, std::shared_ptr<const std::vector<uint32_t>>> modules;
    std::unordered_map<VkPipelineLayout, LayoutRecipe> layouts;
    std::unordered_map<VkDescriptorSetLayout, uint32_t> dynamic_descriptors;  // per set layout
    std::unordered_map<VkQueryPool, VkQueryType> query_types;
    std::unordered_map<VkPipeline, PipelineRecord> pipelines;
    std::unordered_map<uint64_t, std::string> names;  // vkSetDebugUtilsObjectNameEXT
    // Pipeline and shader module creation: time in the layers below and in total (ns), so
    // the capture can state what copying the recipes costs.
    std::atomic<uint64_t> creation_next_ns{0}, creation_total_ns{0};

    // Capture mode: what the layer changed at device creation and the device's facts.
    uint32_t counter_set = 0;          // the descriptor set slot the layer keeps (the last)
    std::string capture_refused;       // why this device's frames cannot be captured
    VkPhysicalDeviceProperties properties{};
    VkPhysicalDeviceMemoryProperties memory{};
    FrameCapture* capture = nullptr;   // during the chosen frame (capture.cpp owns it)

    CommandBufferState* state(VkCommandBuffer cb);  // null for one the layer never saw
};

// Registration and lookup (thread-safe).
InstanceData* add_instance(VkInstance instance);
InstanceData* instance_data(void* key);
void remove_instance(void* key);
DeviceData* add_device(VkDevice device);
DeviceData* device_data(void* key);
void remove_device(void* key);

// Frames are the process's: a present on any device ends one (an application may render on
// one device and present on another, as depthscope's inspector does). The capture of the
// chosen frame happens on the first device that submits a depth pass in it.
struct Process {
    FrameTracker frames;
    std::atomic<bool> presenting{false};  // a device of the process made a swapchain
    std::mutex capture_mutex;             // held while a submission is captured or written
    DeviceData* capturing = nullptr;      // the device capturing the chosen frame
    bool captured = false;                // the chosen frame is written
};
Process& process();
size_t device_count();

template <typename Handle>
DeviceData& device_of(Handle h) {
    return *device_data(dispatch_key(h));
}


}  // namespace ds::layer
