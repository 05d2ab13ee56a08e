#pragma once
// Recording: every intercepted vkCmd* function passes the call on and keeps a copy of it in
// the command buffer's state (commands.h). The copies own their arrays; a structure the layer
// cannot copy faithfully (an unknown pNext) marks the buffer unrecordable instead.
#include <string>
#include <utility>
#include <vector>

#include "layer/commands.h"
#include "layer/state.h"

namespace ds::layer {

// Passive (no DEPTHSCOPE_LAYER_OUT): nothing is kept, calls only pass through.
inline void record(DeviceData& d, VkCommandBuffer cb, Op op, Payload payload, Call call) {
    if (config().mode == Config::Mode::Passive) return;
    if (CommandBufferState* s = d.state(cb))
        s->commands.push_back({op, std::move(call), std::move(payload)});
}

inline void unrecordable(DeviceData& d, VkCommandBuffer cb, const std::string& why) {
    if (CommandBufferState* s = d.state(cb))
        if (s->unrecordable.empty()) s->unrecordable = why;
}

// A command whose arguments are all values: passed on, and recorded as they are.
template <typename Pfn, typename... Args>
void plain_as(Op op, VkCommandBuffer cb, Pfn DeviceTable::*fn, Args... args) {
    DeviceData& d = device_of(cb);
    (d.t.*fn)(cb, args...);
    record(d, cb, op, {},
           [fn, args...](const DeviceTable& t, VkCommandBuffer c) { (t.*fn)(c, args...); });
}
template <typename Pfn, typename... Args>
void plain(VkCommandBuffer cb, Pfn DeviceTable::*fn, Args... args) {
    plain_as(Op::Other, cb, fn, args...);
}
// The same for a command that only sets state (replayed by the Z-fight re-draws too).
template <typename Pfn, typename... Args>
void plain_state(VkCommandBuffer cb, Pfn DeviceTable::*fn, Args... args) {
    plain_as(Op::State, cb, fn, args...);
}

template <typename T>
std::vector<T> copy(const T* items, uint32_t count) {
    return items ? std::vector<T>(items, items + count) : std::vector<T>{};
}
template <typename T>
const T* data_or_null(const std::vector<T>& v) {
    return v.empty() ? nullptr : v.data();
}

// A vkDestroy* that the layer passes on and then forgets the object's record in `map`.
template <typename Handle, typename Map, typename Pfn>
void destroy_and_forget(VkDevice device, Handle handle, const VkAllocationCallbacks* alloc,
                        Pfn DeviceTable::*fn, Map DeviceData::*map) {
    DeviceData& d = device_of(device);
    (d.t.*fn)(device, handle, alloc);
    std::lock_guard lock(d.mutex);
    (d.*map).erase(handle);
}

// The layer's vkCmd* functions by name ("vkCmdDraw"), or null.
PFN_vkVoidFunction recorded_command(const char* name);
PFN_vkVoidFunction recorded_state_command(const char* name);
PFN_vkVoidFunction recorded_pass_command(const char* name);
PFN_vkVoidFunction recorded_transfer_command(const char* name);

}  // namespace ds::layer
