// The Context is shared by threads (the inspector renders on one, presents on another and
// diagnoses on a third): its queue, one-time submits and memory allocator synchronize
// themselves. Two threads hammer them at once with validation on; the threading check reports
// any unsynchronized VkQueue or command buffer use, and the allocator's tables must survive.
#include <atomic>
#include <thread>

#include <gtest/gtest.h>

#include "renderer/vk/buffer.h"
#include "renderer/vk/context.h"

namespace {

using namespace ds::vk;

TEST(VkThreads, QueueOneTimeSubmitsAndAllocatorAreSafeFromTwoThreads) {
    ContextOptions options;
    options.validate = true;
    Context context(options);
    std::atomic<int> failures{0};
    auto work = [&](int seed) {
        try {
            for (int i = 0; i < 150; ++i) {
                Buffer b(context, {.size = VkDeviceSize(256 * (1 + (i + seed) % 7)),
                                   .usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                   .memory = MemoryUsage::GpuOnly,
                                   .name = "thread buffer"});
                context.submit_once([&](VkCommandBuffer cmd) {
                    vkCmdFillBuffer(cmd, b.handle(), 0, VK_WHOLE_SIZE, uint32_t(i));
                });
                if (i % 10 == seed) context.wait_idle();
            }
        } catch (const std::exception&) {
            ++failures;
        }
    };
    std::thread other(work, 3);
    work(7);
    other.join();
    EXPECT_EQ(failures.load(), 0);
    EXPECT_EQ(context.validation_message_count(), 0u);
    EXPECT_EQ(context.allocator().stats().used_bytes, 0u);
}

}  // namespace
