#pragma once
// Instance, optional validation, device selection, logical device, queue and memory allocator:
// everything every other vk object needs. The queue is used from several threads (the
// inspector's render thread, its UI thread presenting, a diagnosis running beside them), and
// Vulkan requires the host to synchronize a VkQueue: every submit, present and device wait goes
// through the Context, which holds one lock for them. The validation counter is shared: the
// messenger counts into it until vkDestroyInstance, so whoever holds it reads what teardown
// reported (objects still alive at vkDestroyDevice) after the Context is gone.
#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "renderer/vk/capabilities.h"
#include "renderer/vk/debug.h"
#include "renderer/vk/memory.h"

namespace ds::vk {

struct ContextOptions {
    bool validate = false;        // VK_LAYER_KHRONOS_validation + messenger
    bool sync_validation = true;  // with validate: also report synchronization hazards
    std::string device;           // "" = first suitable, "N" = index, else a name substring
    // A window (the inspector): the instance extensions its surface needs
    // (glfwGetRequiredInstanceExtensions) and VK_KHR_swapchain on the device.
    std::vector<std::string> instance_extensions;
    bool swapchain = false;
};

class Context {
  public:
    explicit Context(const ContextOptions& options);  // throws ds::Error
    ~Context();
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;

    VkInstance instance() const { return instance_; }
    VkPhysicalDevice physical_device() const { return physical_device_; }
    VkDevice device() const { return device_; }
    VkQueue queue() const { return queue_; }  // for ImGui's init info only: submit() below
    uint32_t queue_family() const { return report_.queue_family; }
    const DeviceReport& report() const { return report_; }
    const VkPhysicalDeviceLimits& limits() const { return limits_; }
    const DebugUtils& debug() const { return debug_; }
    Allocator& allocator() { return *allocator_; }
    VkFormatProperties format_properties(VkFormat format) const;

    // Warning- and error-severity messages from the validation layer since creation.
    uint64_t validation_message_count() const { return validation_messages_->load(); }
    // The same count, readable after this Context is destroyed (teardown's messages included).
    std::shared_ptr<const std::atomic<uint64_t>> validation_counter() const {
        return validation_messages_;
    }

    template <typename Handle>
    void set_name(VkObjectType type, Handle handle, const char* name) const {
        debug_.set_name(device_, type, handle, name);
    }
    template <typename Handle>
    void clear_name(VkObjectType type, Handle handle) const {
        debug_.clear_name(device_, type, reinterpret_cast<uint64_t>(handle));
    }

    // Records `record` into a one-time command buffer, submits it and waits on its fence
    // (uploads, layout set-up). Not for per-frame work.
    void submit_once(const std::function<void(VkCommandBuffer)>& record);
    // The queue's operations, each under the queue lock.
    void submit(const VkSubmitInfo2& submit, VkFence fence) const;
    VkResult present(const VkPresentInfoKHR& info) const;  // the caller handles OUT_OF_DATE
    void wait_idle() const;
    void drain() const noexcept;  // wait_idle for teardown: an error there has nowhere to go

  private:
    void create_instance(const ContextOptions& options);
    void pick_physical_device(const std::string& request);
    void create_device();
    void require_swapchain() const;
    void create_once_objects();
    void destroy();  // explicit teardown order; safe on a partly built context

    std::shared_ptr<std::atomic<uint64_t>> validation_messages_ =
        std::make_shared<std::atomic<uint64_t>>(0);
    bool swapchain_ = false;
    VkInstance instance_ = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
    VkPhysicalDevice physical_device_ = VK_NULL_HANDLE;
    VkDevice device_ = VK_NULL_HANDLE;
    VkQueue queue_ = VK_NULL_HANDLE;
    // submit_once's command buffer and fence, made once and reused: allocating and freeing a
    // command buffer per call grew the synchronization validation's memory without bound
    // (VVL 1.3.239; a 30-minute soak with --validate, +0.44 MiB a minute).
    VkCommandPool once_pool_ = VK_NULL_HANDLE;
    VkCommandBuffer once_cmd_ = VK_NULL_HANDLE;
    VkFence once_fence_ = VK_NULL_HANDLE;
    std::mutex once_mutex_;           // submit_once's command buffer and fence
    mutable std::mutex queue_mutex_;  // queue_, and vkDeviceWaitIdle (which uses every queue)
    DeviceReport report_;
    VkPhysicalDeviceLimits limits_{};
    DebugUtils debug_;
    std::unique_ptr<Allocator> allocator_;
};

}  // namespace ds::vk
