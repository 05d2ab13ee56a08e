#pragma once
// VK_EXT_debug_utils labels and object names. They show up in RenderDoc and in validation
// messages; every call is a no-op when the extension is missing.
#include <array>
#include <cstdint>

#include <vulkan/vulkan.h>

namespace ds::vk {

class DebugUtils {
  public:
    void load(VkInstance instance);  // leaves everything null when the extension is off
    bool available() const { return begin_label_ != nullptr; }

    void begin_label(VkCommandBuffer cmd, const char* name,
                     std::array<float, 4> color = {0.4f, 0.6f, 0.9f, 1.0f}) const;
    void end_label(VkCommandBuffer cmd) const;
    void set_name(VkDevice device, VkObjectType type, uint64_t handle, const char* name) const;

    template <typename Handle>
    void set_name(VkDevice device, VkObjectType type, Handle handle, const char* name) const {
        set_name(device, type, reinterpret_cast<uint64_t>(handle), name);
    }
    // Removes a name before its object is destroyed. The validation layer keeps every name in a
    // map until it is removed; objects recreated every frame (the soak) would grow it forever.
    void clear_name(VkDevice device, VkObjectType type, uint64_t handle) const;

  private:
    PFN_vkCmdBeginDebugUtilsLabelEXT begin_label_ = nullptr;
    PFN_vkCmdEndDebugUtilsLabelEXT end_label_ = nullptr;
    PFN_vkSetDebugUtilsObjectNameEXT set_name_ = nullptr;
};

// Label around a scope of recorded commands: `ScopedLabel label(debug, cmd, "forward");`
class ScopedLabel {
  public:
    ScopedLabel(const DebugUtils& debug, VkCommandBuffer cmd, const char* name)
        : debug_(debug), cmd_(cmd) {
        debug_.begin_label(cmd_, name);
    }
    ~ScopedLabel() { debug_.end_label(cmd_); }
    ScopedLabel(const ScopedLabel&) = delete;
    ScopedLabel& operator=(const ScopedLabel&) = delete;

  private:
    const DebugUtils& debug_;
    VkCommandBuffer cmd_;
};

}  // namespace ds::vk
