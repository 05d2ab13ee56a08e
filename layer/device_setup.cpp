#include "layer/device_setup.h"

#include <algorithm>
#include <cstring>

#include "layer/extension_commands.h"
#include "layer/record.h"

namespace ds::layer {

namespace {

// An enabled extension with a vkCmd* command the layer does not record, or "".
std::string unrecorded_extension(const VkDeviceCreateInfo& info) {
    for (uint32_t i = 0; i < info.enabledExtensionCount; ++i)
        for (const ExtensionCommand& e : kExtensionCommands)
            if (std::strcmp(e.extension, info.ppEnabledExtensionNames[i]) == 0 &&
                !recorded_command(e.command))
                return std::string(e.extension) + " (" + e.command + ")";
    return "";
}

}  // namespace

// The counters are StorageBuffer-class variables: a device created for Vulkan 1.0 needs
// VK_KHR_storage_buffer_storage_class for them (1.1 made it core).
bool DeviceCreatePatch::enable_storage_buffer_class(InstanceData& instance,
                                                    VkPhysicalDevice physical,
                                                    const VkDeviceCreateInfo& info) {
    constexpr const char* kName = VK_KHR_STORAGE_BUFFER_STORAGE_CLASS_EXTENSION_NAME;
    VkPhysicalDeviceProperties props{};
    instance.t.GetPhysicalDeviceProperties(physical, &props);
    if (std::min(instance.api_version, props.apiVersion) >= VK_API_VERSION_1_1) return true;
    extensions_.assign(info.ppEnabledExtensionNames,
                       info.ppEnabledExtensionNames + info.enabledExtensionCount);
    for (const char* e : extensions_)
        if (std::strcmp(e, kName) == 0) return true;
    uint32_t n = 0;
    instance.t.EnumerateDeviceExtensionProperties(physical, nullptr, &n, nullptr);
    std::vector<VkExtensionProperties> available(n);
    instance.t.EnumerateDeviceExtensionProperties(physical, nullptr, &n, available.data());
    for (const VkExtensionProperties& e : available)
        if (std::strcmp(e.extensionName, kName) == 0) {
            extensions_.push_back(kName);
            info_.enabledExtensionCount = uint32_t(extensions_.size());
            info_.ppEnabledExtensionNames = extensions_.data();
            return true;
        }
    refused_ = std::string("a Vulkan 1.0 device without ") + kName;
    return false;
}

DeviceCreatePatch::DeviceCreatePatch(InstanceData& instance, VkPhysicalDevice physical,
                                     const VkDeviceCreateInfo& info)
    : info_(info) {
    if (config().mode != Config::Mode::Capture) return;
    VkPhysicalDeviceFeatures supported{};
    instance.t.GetPhysicalDeviceFeatures(physical, &supported);
    VkPhysicalDeviceProperties props{};
    instance.t.GetPhysicalDeviceProperties(physical, &props);
    if (!supported.fragmentStoresAndAtomics)
        refused_ = "the device has no fragmentStoresAndAtomics (counters in fragment shaders)";
    else if (!supported.occlusionQueryPrecise)
        refused_ = "the device has no occlusionQueryPrecise (samples passed)";
    else if (props.limits.maxBoundDescriptorSets < 2)
        refused_ = "the device binds fewer than 2 descriptor sets";
    else if (const std::string ext = unrecorded_extension(info); !ext.empty())
        refused_ = "the application enables " + ext + ", a command the layer does not record";
    if (!refused_.empty() || !enable_storage_buffer_class(instance, physical, info)) return;
    for (auto* s = static_cast<const VkBaseInStructure*>(info.pNext); s; s = s->pNext)
        if (s->sType == VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2)
            chained_ = reinterpret_cast<VkPhysicalDeviceFeatures2*>(const_cast<VkBaseInStructure*>(s));
    VkPhysicalDeviceFeatures& f = chained_ ? chained_->features : features_;
    if (chained_)
        chained_before_ = chained_->features;
    else if (info.pEnabledFeatures)
        features_ = *info.pEnabledFeatures;
    f.fragmentStoresAndAtomics = VK_TRUE;
    f.occlusionQueryPrecise = VK_TRUE;
    if (!chained_) info_.pEnabledFeatures = &features_;
}

DeviceCreatePatch::~DeviceCreatePatch() {
    if (chained_) chained_->features = chained_before_;
}

void note_device_facts(DeviceData& d, const std::string& refused) {
    d.capture_refused = refused;
    d.instance->t.GetPhysicalDeviceProperties(d.physical, &d.properties);
    d.instance->t.GetPhysicalDeviceMemoryProperties(d.physical, &d.memory);
    d.counter_set = d.properties.limits.maxBoundDescriptorSets - 1;
}

}  // namespace ds::layer
