// The objects a counting copy of a pipeline is built from: shader modules (their SPIR-V),
// pipeline layouts, graphics pipelines (their recipes) and the application's object names;
// and the one limit the layer takes from the application (a descriptor set slot).
#include <chrono>
#include <cstring>

#include "layer/objects.h"
#include "layer/record.h"

namespace ds::layer {

namespace {

bool capturing() { return config().mode == Config::Mode::Capture; }

using CreationClock = std::chrono::steady_clock;
uint64_t ns_since(CreationClock::time_point t) {
    return uint64_t(
        std::chrono::duration_cast<std::chrono::nanoseconds>(CreationClock::now() - t).count());
}

// Times a creation call: the layers below, and the whole wrapper.
struct CreationTimer {
    DeviceData& d;
    CreationClock::time_point start = CreationClock::now();
    CreationClock::time_point next_start{};
    void next_begins() { next_start = CreationClock::now(); }
    void next_ends() { d.creation_next_ns += ns_since(next_start); }
    ~CreationTimer() { d.creation_total_ns += ns_since(start); }
};

VKAPI_ATTR VkResult VKAPI_CALL CreateShaderModule(VkDevice device,
                                                  const VkShaderModuleCreateInfo* info,
                                                  const VkAllocationCallbacks* alloc,
                                                  VkShaderModule* module) {
    DeviceData& d = device_of(device);
    CreationTimer timer{d};
    timer.next_begins();
    const VkResult r = d.t.CreateShaderModule(device, info, alloc, module);
    timer.next_ends();
    if (r != VK_SUCCESS || !capturing()) return r;
    auto code = std::make_shared<const std::vector<uint32_t>>(info->pCode,
                                                              info->pCode + info->codeSize / 4);
    std::lock_guard lock(d.mutex);
    d.modules[*module] = std::move(code);
    return r;
}

VKAPI_ATTR void VKAPI_CALL DestroyShaderModule(VkDevice device, VkShaderModule module,
                                   const VkAllocationCallbacks* alloc) {
    destroy_and_forget(device, module, alloc, &DeviceTable::DestroyShaderModule, &DeviceData::modules);
}

VKAPI_ATTR VkResult VKAPI_CALL CreatePipelineLayout(VkDevice device,
                                                    const VkPipelineLayoutCreateInfo* info,
                                                    const VkAllocationCallbacks* alloc,
                                                    VkPipelineLayout* layout) {
    DeviceData& d = device_of(device);
    const VkResult r = d.t.CreatePipelineLayout(device, info, alloc, layout);
    if (r != VK_SUCCESS || !capturing()) return r;
    LayoutRecipe l;
    l.sets.assign(info->pSetLayouts, info->pSetLayouts + info->setLayoutCount);
    l.push_constants.assign(info->pPushConstantRanges,
                            info->pPushConstantRanges + info->pushConstantRangeCount);
    std::lock_guard lock(d.mutex);
    d.layouts[*layout] = std::move(l);
    return r;
}

VKAPI_ATTR void VKAPI_CALL DestroyPipelineLayout(VkDevice device, VkPipelineLayout layout,
                                   const VkAllocationCallbacks* alloc) {
    destroy_and_forget(device, layout, alloc, &DeviceTable::DestroyPipelineLayout, &DeviceData::layouts);
}

VKAPI_ATTR VkResult VKAPI_CALL CreateGraphicsPipelines(VkDevice device, VkPipelineCache cache,
                                                       uint32_t n,
                                                       const VkGraphicsPipelineCreateInfo* infos,
                                                       const VkAllocationCallbacks* alloc,
                                                       VkPipeline* out) {
    DeviceData& d = device_of(device);
    CreationTimer timer{d};
    timer.next_begins();
    const VkResult r = d.t.CreateGraphicsPipelines(device, cache, n, infos, alloc, out);
    timer.next_ends();
    if (r < 0 || !capturing()) return r;
    std::lock_guard lock(d.mutex);
    const auto code = [&d](VkShaderModule m) {
        auto it = d.modules.find(m);
        return it == d.modules.end() ? nullptr : it->second;
    };
    for (uint32_t i = 0; i < n; ++i) {
        if (out[i] == VK_NULL_HANDLE) continue;
        PipelineRecord record;
        record.recipe = copy_recipe(infos[i], code, record.why);
        d.pipelines[out[i]] = std::move(record);
    }
    return r;
}

VKAPI_ATTR void VKAPI_CALL DestroyPipeline(VkDevice device, VkPipeline pipeline,
                                   const VkAllocationCallbacks* alloc) {
    destroy_and_forget(device, pipeline, alloc, &DeviceTable::DestroyPipeline, &DeviceData::pipelines);
}

VKAPI_ATTR VkResult VKAPI_CALL CreateDescriptorSetLayout(
    VkDevice device, const VkDescriptorSetLayoutCreateInfo* info,
    const VkAllocationCallbacks* alloc, VkDescriptorSetLayout* layout) {
    DeviceData& d = device_of(device);
    const VkResult r = d.t.CreateDescriptorSetLayout(device, info, alloc, layout);
    if (r != VK_SUCCESS || !capturing()) return r;
    uint32_t dynamic = 0;
    for (uint32_t i = 0; i < info->bindingCount; ++i) {
        const VkDescriptorType t = info->pBindings[i].descriptorType;
        if (t == VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC ||
            t == VK_DESCRIPTOR_TYPE_STORAGE_BUFFER_DYNAMIC)
            dynamic += info->pBindings[i].descriptorCount;
    }
    std::lock_guard lock(d.mutex);
    d.dynamic_descriptors[*layout] = dynamic;
    return r;
}

VKAPI_ATTR VkResult VKAPI_CALL CreateQueryPool(VkDevice device,
                                               const VkQueryPoolCreateInfo* info,
                                               const VkAllocationCallbacks* alloc,
                                               VkQueryPool* pool) {
    DeviceData& d = device_of(device);
    const VkResult r = d.t.CreateQueryPool(device, info, alloc, pool);
    if (r != VK_SUCCESS) return r;
    std::lock_guard lock(d.mutex);
    d.query_types[*pool] = info->queryType;
    return r;
}

VKAPI_ATTR VkResult VKAPI_CALL SetDebugUtilsObjectNameEXT(VkDevice device,
                                                          const VkDebugUtilsObjectNameInfoEXT* i) {
    DeviceData& d = device_of(device);
    const VkResult r = d.t.SetDebugUtilsObjectNameEXT(device, i);
    std::lock_guard lock(d.mutex);
    if (i->pObjectName && *i->pObjectName)
        d.names[i->objectHandle] = i->pObjectName;
    else
        d.names.erase(i->objectHandle);
    return r;
}

// The application sees one descriptor set fewer: the last slot is the layer's.
VKAPI_ATTR void VKAPI_CALL GetPhysicalDeviceProperties(VkPhysicalDevice physical,
                                                       VkPhysicalDeviceProperties* p) {
    InstanceData* instance = instance_data(dispatch_key(physical));
    instance->t.GetPhysicalDeviceProperties(physical, p);
    if (capturing() && p->limits.maxBoundDescriptorSets > 1) --p->limits.maxBoundDescriptorSets;
}

VKAPI_ATTR void VKAPI_CALL GetPhysicalDeviceProperties2(VkPhysicalDevice physical,
                                                        VkPhysicalDeviceProperties2* p) {
    InstanceData* instance = instance_data(dispatch_key(physical));
    auto fn = instance->t.GetPhysicalDeviceProperties2 ? instance->t.GetPhysicalDeviceProperties2
                                                       : instance->t.GetPhysicalDeviceProperties2KHR;
    fn(physical, p);
    if (capturing() && p->properties.limits.maxBoundDescriptorSets > 1)
        --p->properties.limits.maxBoundDescriptorSets;
}

}  // namespace

PFN_vkVoidFunction pipeline_object_function(const char* name) {
#define DS_X(fn) \
    if (std::strcmp(name, "vk" #fn) == 0) return reinterpret_cast<PFN_vkVoidFunction>(&fn);
    DS_X(CreateShaderModule)
    DS_X(DestroyShaderModule)
    DS_X(CreatePipelineLayout)
    DS_X(DestroyPipelineLayout)
    DS_X(CreateGraphicsPipelines)
    DS_X(DestroyPipeline)
    DS_X(SetDebugUtilsObjectNameEXT)
    DS_X(CreateDescriptorSetLayout)
    DS_X(CreateQueryPool)
#undef DS_X
    return nullptr;
}

PFN_vkVoidFunction instance_function(const char* name) {
    if (std::strcmp(name, "vkGetPhysicalDeviceProperties2KHR") == 0)
        name = "vkGetPhysicalDeviceProperties2";
#define DS_X(fn) \
    if (std::strcmp(name, "vk" #fn) == 0) return reinterpret_cast<PFN_vkVoidFunction>(&fn);
    DS_X(GetPhysicalDeviceProperties)
    DS_X(GetPhysicalDeviceProperties2)
#undef DS_X
    return nullptr;
}

}  // namespace ds::layer
