#include "renderer/vk/debug.h"

#include "renderer/vk/check.h"

namespace ds::vk {

void DebugUtils::load(VkInstance instance) {
    begin_label_ = reinterpret_cast<PFN_vkCmdBeginDebugUtilsLabelEXT>(
        vkGetInstanceProcAddr(instance, "vkCmdBeginDebugUtilsLabelEXT"));
    end_label_ = reinterpret_cast<PFN_vkCmdEndDebugUtilsLabelEXT>(
        vkGetInstanceProcAddr(instance, "vkCmdEndDebugUtilsLabelEXT"));
    set_name_ = reinterpret_cast<PFN_vkSetDebugUtilsObjectNameEXT>(
        vkGetInstanceProcAddr(instance, "vkSetDebugUtilsObjectNameEXT"));
    if (!begin_label_ || !end_label_ || !set_name_) *this = DebugUtils{};
}

void DebugUtils::begin_label(VkCommandBuffer cmd, const char* name,
                             std::array<float, 4> color) const {
    if (!begin_label_) return;
    auto label = make<VkDebugUtilsLabelEXT>(VK_STRUCTURE_TYPE_DEBUG_UTILS_LABEL_EXT);
    label.pLabelName = name;
    for (int i = 0; i < 4; ++i) label.color[i] = color[i];
    begin_label_(cmd, &label);
}

void DebugUtils::end_label(VkCommandBuffer cmd) const {
    if (end_label_) end_label_(cmd);
}

void DebugUtils::set_name(VkDevice device, VkObjectType type, uint64_t handle,
                          const char* name) const {
    if (!set_name_ || !name || !handle) return;
    auto info =
        make<VkDebugUtilsObjectNameInfoEXT>(VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT);
    info.objectType = type;
    info.objectHandle = handle;
    info.pObjectName = name;
    check(set_name_(device, &info), "vkSetDebugUtilsObjectNameEXT");
}

void DebugUtils::clear_name(VkDevice device, VkObjectType type, uint64_t handle) const {
    if (!set_name_ || !handle) return;
    auto info =
        make<VkDebugUtilsObjectNameInfoEXT>(VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT);
    info.objectType = type;
    info.objectHandle = handle;
    info.pObjectName = nullptr;  // "any previously set name is removed"
    // Called on destruction paths (noexcept): a failure leaves a stale name, nothing worse.
    (void)set_name_(device, &info);
}

}  // namespace ds::vk
