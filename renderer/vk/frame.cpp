#include "renderer/vk/frame.h"
#include "renderer/vk/functions.h"

#include "renderer/vk/check.h"
#include "renderer/vk/context.h"

namespace ds::vk {

FrameRing::FrameRing(Context& context) : context_(context) {
    VkDevice device = context.device();
    for (Frame& f : frames_) {
        auto pool = make<VkCommandPoolCreateInfo>(VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO);
        pool.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
        pool.queueFamilyIndex = context.queue_family();
        check(vkCreateCommandPool(device, &pool, nullptr, &f.pool), "vkCreateCommandPool");
        auto alloc =
            make<VkCommandBufferAllocateInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO);
        alloc.commandPool = f.pool;
        alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
        alloc.commandBufferCount = 1;
        check(vkAllocateCommandBuffers(device, &alloc, &f.cmd), "vkAllocateCommandBuffers");
        auto fence = make<VkFenceCreateInfo>(VK_STRUCTURE_TYPE_FENCE_CREATE_INFO);
        check(vkCreateFence(device, &fence, nullptr, &f.fence), "vkCreateFence");
    }
}

FrameRing::~FrameRing() {
    VkDevice device = context_.device();
    context_.drain();
    for (Frame& f : frames_) {
        f.retired.flush();
        if (f.fence) vkDestroyFence(device, f.fence, nullptr);
        if (f.pool) vkDestroyCommandPool(device, f.pool, nullptr);  // frees f.cmd too
    }
}

Frame& FrameRing::begin() {
    current_ = uint32_t(count_ % kFramesInFlight);
    Frame& f = frames_[current_];
    wait(f);
    // Frames older than this slot's last one were waited by the begin() calls between.
    f.retired.flush();
    check(vkResetCommandPool(context_.device(), f.pool, 0), "vkResetCommandPool");
    auto begin = make<VkCommandBufferBeginInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO);
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    check(vkBeginCommandBuffer(f.cmd, &begin), "vkBeginCommandBuffer");
    f.number = count_++;
    return f;
}

void FrameRing::submit(Frame& f, const SubmitSemaphores& semaphores) {
    check(vkEndCommandBuffer(f.cmd), "vkEndCommandBuffer");
    check(vkResetFences(context_.device(), 1, &f.fence), "vkResetFences");
    auto cmd = make<VkCommandBufferSubmitInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO);
    cmd.commandBuffer = f.cmd;
    auto wait = make<VkSemaphoreSubmitInfo>(VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO);
    wait.semaphore = semaphores.wait;
    wait.stageMask = semaphores.wait_stages;
    auto signal = make<VkSemaphoreSubmitInfo>(VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO);
    signal.semaphore = semaphores.signal;
    signal.stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    auto submit = make<VkSubmitInfo2>(VK_STRUCTURE_TYPE_SUBMIT_INFO_2);
    submit.commandBufferInfoCount = 1;
    submit.pCommandBufferInfos = &cmd;
    if (semaphores.wait) {
        submit.waitSemaphoreInfoCount = 1;
        submit.pWaitSemaphoreInfos = &wait;
    }
    if (semaphores.signal) {
        submit.signalSemaphoreInfoCount = 1;
        submit.pSignalSemaphoreInfos = &signal;
    }
    context_.submit(submit, f.fence);
    f.submitted = true;
}

void FrameRing::wait(Frame& f) {
    if (!f.submitted) return;
    check(vkWaitForFences(context_.device(), 1, &f.fence, VK_TRUE, UINT64_MAX), "vkWaitForFences");
    f.submitted = false;
}

}  // namespace ds::vk
