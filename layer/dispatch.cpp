#include "layer/dispatch.h"

namespace ds::layer {

void InstanceTable::load(VkInstance instance, PFN_vkGetInstanceProcAddr next) {
#define DS_X(name) name = reinterpret_cast<PFN_vk##name>(next(instance, "vk" #name));
    DS_LAYER_INSTANCE_FUNCTIONS(DS_X)
#undef DS_X
    CreateDevice = reinterpret_cast<PFN_vkCreateDevice>(next(instance, "vkCreateDevice"));
}

void DeviceTable::load(VkDevice device, PFN_vkGetDeviceProcAddr next) {
#define DS_X(name) name = reinterpret_cast<PFN_vk##name>(next(device, "vk" #name));
    DS_LAYER_RECORDED_COMMANDS(DS_X)
    DS_LAYER_DEVICE_FUNCTIONS(DS_X)
#undef DS_X
    // Extension names of core functions, where the device offers only the extension.
#define DS_X(alias, core) \
    if (!core) core = reinterpret_cast<PFN_vk##core>(next(device, "vk" #alias));
    DS_LAYER_COMMAND_ALIASES(DS_X)
    DS_X(QueueSubmit2KHR, QueueSubmit2)
    DS_X(CreateRenderPass2KHR, CreateRenderPass2)
#undef DS_X
}

}  // namespace ds::layer
