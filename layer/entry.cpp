// The layer's entry points: the loader's negotiation, instance and device creation, the
// function lookup, and the objects whose creation the layer notes (render passes,
// framebuffers, views, queues, command buffers).
#include <cstring>

#include "layer/device_setup.h"
#include "layer/objects.h"
#include "layer/record.h"
#include "layer/state.h"
#include "layer/submit.h"

#define DS_LAYER_EXPORT extern "C" __attribute__((visibility("default")))

namespace ds::layer {

namespace {

template <typename Info, typename Kind>
Info* chain_info(const void* next, VkStructureType type, Kind function) {
    for (auto* s = static_cast<const VkBaseInStructure*>(next); s; s = s->pNext) {
        auto* info = reinterpret_cast<Info*>(const_cast<VkBaseInStructure*>(s));
        if (s->sType == type && info->function == function) return info;
    }
    return nullptr;
}

VKAPI_ATTR VkResult VKAPI_CALL CreateInstance(const VkInstanceCreateInfo* info,
                                              const VkAllocationCallbacks* alloc,
                                              VkInstance* instance) {
    auto* link = chain_info<VkLayerInstanceCreateInfo>(
        info->pNext, VK_STRUCTURE_TYPE_LOADER_INSTANCE_CREATE_INFO, VK_LAYER_LINK_INFO);
    if (!link) return VK_ERROR_INITIALIZATION_FAILED;
    PFN_vkGetInstanceProcAddr next = link->u.pLayerInfo->pfnNextGetInstanceProcAddr;
    link->u.pLayerInfo = link->u.pLayerInfo->pNext;
    auto create = reinterpret_cast<PFN_vkCreateInstance>(next(nullptr, "vkCreateInstance"));
    const VkResult r = create(info, alloc, instance);
    if (r != VK_SUCCESS) return r;
    InstanceData* data = add_instance(*instance);
    data->t.load(*instance, next);
    if (info->pApplicationInfo && info->pApplicationInfo->pApplicationName)
        data->application = info->pApplicationInfo->pApplicationName;
    if (info->pApplicationInfo && info->pApplicationInfo->apiVersion)
        data->api_version = info->pApplicationInfo->apiVersion;
    return r;
}

VKAPI_ATTR void VKAPI_CALL DestroyInstance(VkInstance instance,
                                           const VkAllocationCallbacks* alloc) {
    void* key = dispatch_key(instance);
    InstanceData* data = instance_data(key);
    if (!data) return;
    data->t.DestroyInstance(instance, alloc);
    remove_instance(key);
}

VKAPI_ATTR VkResult VKAPI_CALL CreateDevice(VkPhysicalDevice physical,
                                            const VkDeviceCreateInfo* info,
                                            const VkAllocationCallbacks* alloc,
                                            VkDevice* device) {
    InstanceData* instance = instance_data(dispatch_key(physical));
    auto* link = chain_info<VkLayerDeviceCreateInfo>(
        info->pNext, VK_STRUCTURE_TYPE_LOADER_DEVICE_CREATE_INFO, VK_LAYER_LINK_INFO);
    auto* loader = chain_info<VkLayerDeviceCreateInfo>(
        info->pNext, VK_STRUCTURE_TYPE_LOADER_DEVICE_CREATE_INFO, VK_LOADER_DATA_CALLBACK);
    if (!instance || !link) return VK_ERROR_INITIALIZATION_FAILED;
    PFN_vkGetInstanceProcAddr next_gipa = link->u.pLayerInfo->pfnNextGetInstanceProcAddr;
    PFN_vkGetDeviceProcAddr next_gdpa = link->u.pLayerInfo->pfnNextGetDeviceProcAddr;
    link->u.pLayerInfo = link->u.pLayerInfo->pNext;
    auto create = reinterpret_cast<PFN_vkCreateDevice>(
        next_gipa(instance->instance, "vkCreateDevice"));
    std::string refused;
    VkResult r = VK_SUCCESS;
    {
        const DeviceCreatePatch patch(*instance, physical, *info);
        r = create(physical, patch.info(), alloc, device);
        refused = patch.refused();
    }
    if (r != VK_SUCCESS) return r;
    DeviceData* data = add_device(*device);
    data->physical = physical;
    data->instance = instance;
    data->t.load(*device, next_gdpa);
    data->set_loader_data = loader ? loader->u.pfnSetDeviceLoaderData : nullptr;
    note_device_facts(*data, refused);
    device_created(*data);
    return r;
}

VKAPI_ATTR void VKAPI_CALL DestroyDevice(VkDevice device, const VkAllocationCallbacks* alloc) {
    void* key = dispatch_key(device);
    DeviceData* data = device_data(key);
    if (!data) return;
    device_destroyed(*data);
    data->t.DestroyDevice(device, alloc);
    remove_device(key);
}

// Functions the layer provides for the device, whatever records them.
PFN_vkVoidFunction device_function(const char* name) {
#define DS_X(fn) \
    if (std::strcmp(name, "vk" #fn) == 0) return reinterpret_cast<PFN_vkVoidFunction>(&fn);
    DS_X(DestroyDevice)
#undef DS_X
    if (auto f = object_function(name)) return f;
    if (auto f = submit_function(name)) return f;
    return recorded_command(name);
}

}  // namespace

PFN_vkVoidFunction recorded_command(const char* name) {
#define DS_X(alias, core) \
    if (std::strcmp(name, "vk" #alias) == 0) name = "vk" #core;
    DS_LAYER_COMMAND_ALIASES(DS_X)
#undef DS_X
    if (auto f = recorded_state_command(name)) return f;
    if (auto f = recorded_pass_command(name)) return f;
    return recorded_transfer_command(name);
}

VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL GetDeviceProcAddr(VkDevice device, const char* name) {
    DeviceData* data = device ? device_data(dispatch_key(device)) : nullptr;
    if (!data || !name) return nullptr;
    // Only what the device offers: an extension's function is null where it is not enabled.
    PFN_vkVoidFunction next = data->t.GetDeviceProcAddr(device, name);
    if (!next) return nullptr;
    if (std::strcmp(name, "vkGetDeviceProcAddr") == 0)
        return reinterpret_cast<PFN_vkVoidFunction>(&GetDeviceProcAddr);
    PFN_vkVoidFunction own = device_function(name);
    return own ? own : next;
}

VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL GetInstanceProcAddr(VkInstance instance,
                                                             const char* name) {
#define DS_X(fn)                                       \
    if (std::strcmp(name, "vk" #fn) == 0)              \
        return reinterpret_cast<PFN_vkVoidFunction>(&fn);
    DS_X(CreateInstance)
    DS_X(DestroyInstance)
    DS_X(CreateDevice)
    DS_X(GetInstanceProcAddr)
    DS_X(GetDeviceProcAddr)
#undef DS_X
    if (auto f = instance_function(name)) return f;
    if (!instance) return nullptr;
    InstanceData* data = instance_data(dispatch_key(instance));
    if (!data) return nullptr;
    // Device functions asked for through the instance: the layer's, where the driver has one.
    PFN_vkVoidFunction next = data->t.GetInstanceProcAddr(instance, name);
    if (next && std::strncmp(name, "vkCmd", 5) == 0)
        if (auto own = device_function(name)) return own;
    return next;
}

}  // namespace ds::layer

DS_LAYER_EXPORT VKAPI_ATTR VkResult VKAPI_CALL
vkNegotiateLoaderLayerInterfaceVersion(VkNegotiateLayerInterface* v) {
    if (!v || v->sType != LAYER_NEGOTIATE_INTERFACE_STRUCT) return VK_ERROR_INITIALIZATION_FAILED;
    if (v->loaderLayerInterfaceVersion >= 2) {
        v->pfnGetInstanceProcAddr = ds::layer::GetInstanceProcAddr;
        v->pfnGetDeviceProcAddr = ds::layer::GetDeviceProcAddr;
        v->pfnGetPhysicalDeviceProcAddr = nullptr;
        v->loaderLayerInterfaceVersion = 2;
    }
    return VK_SUCCESS;
}

DS_LAYER_EXPORT VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL vkGetInstanceProcAddr(VkInstance i,
                                                                               const char* n) {
    return ds::layer::GetInstanceProcAddr(i, n);
}

DS_LAYER_EXPORT VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL vkGetDeviceProcAddr(VkDevice d,
                                                                             const char* n) {
    return ds::layer::GetDeviceProcAddr(d, n);
}
