#pragma once
// A move-only owner of one device-level handle destroyed by a vkDestroy* function: for the
// objects that need nothing but creation and destruction (render passes, framebuffers,
// semaphores, image views of swapchain images).
#include <utility>

#include <vulkan/vulkan.h>

namespace ds::vk {

template <typename T, void (*Destroy)(VkDevice, T, const VkAllocationCallbacks*)>
class DeviceHandle {
  public:
    DeviceHandle() = default;
    DeviceHandle(VkDevice device, T handle) : device_(device), handle_(handle) {}
    ~DeviceHandle() { reset(); }
    DeviceHandle(DeviceHandle&& other) noexcept { *this = std::move(other); }
    DeviceHandle& operator=(DeviceHandle&& other) noexcept {
        if (this != &other) {
            reset();
            device_ = std::exchange(other.device_, VkDevice{VK_NULL_HANDLE});
            handle_ = std::exchange(other.handle_, T{VK_NULL_HANDLE});
        }
        return *this;
    }
    DeviceHandle(const DeviceHandle&) = delete;
    DeviceHandle& operator=(const DeviceHandle&) = delete;

    void reset() {
        if (handle_ != VK_NULL_HANDLE) Destroy(device_, handle_, nullptr);
        handle_ = VK_NULL_HANDLE;
    }
    explicit operator bool() const { return handle_ != VK_NULL_HANDLE; }
    T handle() const { return handle_; }

  private:
    VkDevice device_ = VK_NULL_HANDLE;
    T handle_ = VK_NULL_HANDLE;
};

using RenderPass = DeviceHandle<VkRenderPass, vkDestroyRenderPass>;
using Framebuffer = DeviceHandle<VkFramebuffer, vkDestroyFramebuffer>;
using Semaphore = DeviceHandle<VkSemaphore, vkDestroySemaphore>;
using ImageView = DeviceHandle<VkImageView, vkDestroyImageView>;

}  // namespace ds::vk
