#include "layer/objects.h"
#include "layer/record.h"

#include "layer/capture.h"

#include <cstdio>
#include <cstring>

namespace ds::layer {

namespace {

VKAPI_ATTR void VKAPI_CALL GetDeviceQueue(VkDevice device, uint32_t family, uint32_t index,
                                          VkQueue* queue) {
    DeviceData& d = device_of(device);
    d.t.GetDeviceQueue(device, family, index, queue);
    std::lock_guard lock(d.mutex);
    d.queue_families[*queue] = family;
}

VKAPI_ATTR void VKAPI_CALL GetDeviceQueue2(VkDevice device, const VkDeviceQueueInfo2* info,
                                           VkQueue* queue) {
    DeviceData& d = device_of(device);
    d.t.GetDeviceQueue2(device, info, queue);
    std::lock_guard lock(d.mutex);
    if (*queue) d.queue_families[*queue] = info->queueFamilyIndex;
}

VKAPI_ATTR VkResult VKAPI_CALL CreateSwapchainKHR(VkDevice device,
                                                  const VkSwapchainCreateInfoKHR* info,
                                                  const VkAllocationCallbacks* alloc,
                                                  VkSwapchainKHR* swapchain) {
    DeviceData& d = device_of(device);
    const VkResult r = d.t.CreateSwapchainKHR(device, info, alloc, swapchain);
    if (r == VK_SUCCESS) process().presenting = true;
    return r;
}

VKAPI_ATTR VkResult VKAPI_CALL AllocateCommandBuffers(VkDevice device,
                                                      const VkCommandBufferAllocateInfo* info,
                                                      VkCommandBuffer* out) {
    DeviceData& d = device_of(device);
    const VkResult r = d.t.AllocateCommandBuffers(device, info, out);
    if (r != VK_SUCCESS) return r;
    std::lock_guard lock(d.mutex);
    for (uint32_t i = 0; i < info->commandBufferCount; ++i) {
        auto s = std::make_unique<CommandBufferState>();
        s->device = device;
        s->pool = info->commandPool;
        s->level = info->level;
        d.command_buffers[out[i]] = std::move(s);
    }
    return r;
}

VKAPI_ATTR void VKAPI_CALL FreeCommandBuffers(VkDevice device, VkCommandPool pool, uint32_t n,
                                              const VkCommandBuffer* cbs) {
    DeviceData& d = device_of(device);
    d.t.FreeCommandBuffers(device, pool, n, cbs);
    std::lock_guard lock(d.mutex);
    for (uint32_t i = 0; i < n; ++i) d.command_buffers.erase(cbs[i]);
}

VKAPI_ATTR void VKAPI_CALL DestroyCommandPool(VkDevice device, VkCommandPool pool,
                                              const VkAllocationCallbacks* alloc) {
    DeviceData& d = device_of(device);
    d.t.DestroyCommandPool(device, pool, alloc);
    std::lock_guard lock(d.mutex);
    std::erase_if(d.command_buffers, [pool](const auto& e) { return e.second->pool == pool; });
}

VKAPI_ATTR VkResult VKAPI_CALL ResetCommandPool(VkDevice device, VkCommandPool pool,
                                                VkCommandPoolResetFlags flags) {
    DeviceData& d = device_of(device);
    const VkResult r = d.t.ResetCommandPool(device, pool, flags);
    std::lock_guard lock(d.mutex);
    for (auto& [cb, s] : d.command_buffers)
        if (s->pool == pool) s->reset();
    return r;
}

VKAPI_ATTR VkResult VKAPI_CALL BeginCommandBuffer(VkCommandBuffer cb,
                                                  const VkCommandBufferBeginInfo* info) {
    DeviceData& d = device_of(cb);
    if (CommandBufferState* s = d.state(cb)) s->reset();
    return d.t.BeginCommandBuffer(cb, info);
}

VKAPI_ATTR VkResult VKAPI_CALL ResetCommandBuffer(VkCommandBuffer cb,
                                                  VkCommandBufferResetFlags flags) {
    DeviceData& d = device_of(cb);
    if (CommandBufferState* s = d.state(cb)) s->reset();
    return d.t.ResetCommandBuffer(cb, flags);
}

void note_render_pass(DeviceData& d, VkRenderPass pass, RenderPassInfo rp) {
    std::lock_guard lock(d.mutex);
    d.render_passes[pass] = std::move(rp);
}

// What a render pass's summary needs, from VkRenderPassCreateInfo or its "2" form;
// `view_mask(i)`: subpass i's multiview mask.
template <typename Info, typename ViewMask>
RenderPassInfo render_pass_info(const Info& info, ViewMask view_mask) {
    RenderPassInfo rp;
    for (uint32_t i = 0; i < info.attachmentCount; ++i) {
        rp.formats.push_back(info.pAttachments[i].format);
        rp.samples.push_back(info.pAttachments[i].samples);
    }
    for (uint32_t i = 0; i < info.subpassCount; ++i) {
        const auto& s = info.pSubpasses[i];
        SubpassInfo sp;
        if (s.pDepthStencilAttachment) sp.depth_attachment = s.pDepthStencilAttachment->attachment;
        sp.view_mask = view_mask(i);
        for (uint32_t c = 0; c < s.colorAttachmentCount; ++c)
            sp.colors.push_back(s.pColorAttachments[c].attachment);
        rp.subpasses.push_back(sp);
    }
    return rp;
}

VKAPI_ATTR VkResult VKAPI_CALL CreateRenderPass(VkDevice device, const VkRenderPassCreateInfo* info,
                                                const VkAllocationCallbacks* alloc,
                                                VkRenderPass* pass) {
    DeviceData& d = device_of(device);
    const VkResult r = d.t.CreateRenderPass(device, info, alloc, pass);
    if (r != VK_SUCCESS) return r;
    const VkRenderPassMultiviewCreateInfo* multiview = nullptr;
    for (auto* s = static_cast<const VkBaseInStructure*>(info->pNext); s; s = s->pNext)
        if (s->sType == VK_STRUCTURE_TYPE_RENDER_PASS_MULTIVIEW_CREATE_INFO)
            multiview = reinterpret_cast<const VkRenderPassMultiviewCreateInfo*>(s);
    note_render_pass(d, *pass, render_pass_info(*info, [multiview](uint32_t i) {
                         return multiview && i < multiview->subpassCount ? multiview->pViewMasks[i]
                                                                         : 0u;
                     }));
    return r;
}

VKAPI_ATTR VkResult VKAPI_CALL CreateRenderPass2(VkDevice device,
                                                 const VkRenderPassCreateInfo2* info,
                                                 const VkAllocationCallbacks* alloc,
                                                 VkRenderPass* pass) {
    DeviceData& d = device_of(device);
    const VkResult r = d.t.CreateRenderPass2(device, info, alloc, pass);
    if (r != VK_SUCCESS) return r;
    note_render_pass(d, *pass, render_pass_info(*info, [info](uint32_t i) {
                         return info->pSubpasses[i].viewMask;
                     }));
    return r;
}

VKAPI_ATTR void VKAPI_CALL DestroyRenderPass(VkDevice device, VkRenderPass pass,
                                   const VkAllocationCallbacks* alloc) {
    destroy_and_forget(device, pass, alloc, &DeviceTable::DestroyRenderPass, &DeviceData::render_passes);
}

VKAPI_ATTR VkResult VKAPI_CALL CreateFramebuffer(VkDevice device,
                                                 const VkFramebufferCreateInfo* info,
                                                 const VkAllocationCallbacks* alloc,
                                                 VkFramebuffer* fb) {
    DeviceData& d = device_of(device);
    const VkResult r = d.t.CreateFramebuffer(device, info, alloc, fb);
    if (r != VK_SUCCESS) return r;
    FramebufferInfo f{{info->width, info->height}, {}};
    if (!(info->flags & VK_FRAMEBUFFER_CREATE_IMAGELESS_BIT))
        f.views.assign(info->pAttachments, info->pAttachments + info->attachmentCount);
    std::lock_guard lock(d.mutex);
    d.framebuffers[*fb] = std::move(f);
    return r;
}

VKAPI_ATTR void VKAPI_CALL DestroyFramebuffer(VkDevice device, VkFramebuffer fb,
                                   const VkAllocationCallbacks* alloc) {
    destroy_and_forget(device, fb, alloc, &DeviceTable::DestroyFramebuffer, &DeviceData::framebuffers);
}

VKAPI_ATTR VkResult VKAPI_CALL CreateImageView(VkDevice device, const VkImageViewCreateInfo* info,
                                               const VkAllocationCallbacks* alloc,
                                               VkImageView* view) {
    DeviceData& d = device_of(device);
    const VkResult r = d.t.CreateImageView(device, info, alloc, view);
    if (r != VK_SUCCESS) return r;
    std::lock_guard lock(d.mutex);
    d.views[*view] = {info->image, info->format};
    return r;
}

VKAPI_ATTR void VKAPI_CALL DestroyImageView(VkDevice device, VkImageView view,
                                   const VkAllocationCallbacks* alloc) {
    destroy_and_forget(device, view, alloc, &DeviceTable::DestroyImageView, &DeviceData::views);
}

}  // namespace

PFN_vkVoidFunction object_function(const char* name) {
    if (std::strcmp(name, "vkCreateRenderPass2KHR") == 0) name = "vkCreateRenderPass2";
#define DS_X(fn) \
    if (std::strcmp(name, "vk" #fn) == 0) return reinterpret_cast<PFN_vkVoidFunction>(&fn);
    DS_X(GetDeviceQueue)
    DS_X(GetDeviceQueue2)
    DS_X(CreateSwapchainKHR)
    DS_X(AllocateCommandBuffers)
    DS_X(FreeCommandBuffers)
    DS_X(DestroyCommandPool)
    DS_X(ResetCommandPool)
    DS_X(BeginCommandBuffer)
    DS_X(ResetCommandBuffer)
    DS_X(CreateRenderPass)
    DS_X(CreateRenderPass2)
    DS_X(DestroyRenderPass)
    DS_X(CreateFramebuffer)
    DS_X(DestroyFramebuffer)
    DS_X(CreateImageView)
    DS_X(DestroyImageView)
#undef DS_X
    return pipeline_object_function(name);
}

void device_created(DeviceData& device) {
    const Config& c = config();
    DS_LAYER_LOG("device %s created (mode %d, capture %s)", device.properties.deviceName,
                 int(c.mode), device.capture_refused.empty() ? "possible"
                                                             : device.capture_refused.c_str());
    if (c.mode != Config::Mode::Passive) {
        std::string error;
        if (!process().frames.open_list(c.out, error))
            std::fprintf(stderr, "depthscope layer: %s\n", error.c_str());
    }
}

void device_destroyed(DeviceData& device) {
    finish_capture(device);
    // The last device: an unfinished frame is written as such.
    if (device_count() == 1) process().frames.finish();
}

}  // namespace ds::layer
