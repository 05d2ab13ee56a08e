#include "layer/state.h"

namespace ds::layer {

namespace {

std::mutex g_mutex;
std::unordered_map<void*, std::unique_ptr<InstanceData>> g_instances;
std::unordered_map<void*, std::unique_ptr<DeviceData>> g_devices;

}  // namespace

CommandBufferState* DeviceData::state(VkCommandBuffer cb) {
    std::lock_guard lock(mutex);
    auto it = command_buffers.find(cb);
    return it == command_buffers.end() ? nullptr : it->second.get();
}

InstanceData* add_instance(VkInstance instance) {
    std::lock_guard lock(g_mutex);
    auto& slot = g_instances[dispatch_key(instance)];
    slot = std::make_unique<InstanceData>();
    slot->instance = instance;
    return slot.get();
}

InstanceData* instance_data(void* key) {
    std::lock_guard lock(g_mutex);
    auto it = g_instances.find(key);
    return it == g_instances.end() ? nullptr : it->second.get();
}

void remove_instance(void* key) {
    std::lock_guard lock(g_mutex);
    g_instances.erase(key);
}

DeviceData* add_device(VkDevice device) {
    std::lock_guard lock(g_mutex);
    auto& slot = g_devices[dispatch_key(device)];
    slot = std::make_unique<DeviceData>();
    slot->device = device;
    return slot.get();
}

DeviceData* device_data(void* key) {
    std::lock_guard lock(g_mutex);
    auto it = g_devices.find(key);
    return it == g_devices.end() ? nullptr : it->second.get();
}

void remove_device(void* key) {
    std::lock_guard lock(g_mutex);
    g_devices.erase(key);
}

Process& process() {
    static Process p;
    return p;
}

size_t device_count() {
    std::lock_guard lock(g_mutex);
    return g_devices.size();
}

const Config& config() {
    static const Config c = Config::from_environment();
    return c;
}

}  // namespace ds::layer
