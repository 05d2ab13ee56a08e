#pragma once
// Graph-owned images and buffers that persist across frames, so a frame allocates nothing
// unless a description changed (for relative images: the output size). Each entry keeps the
// state its last frame left it in: the first barrier of the next frame waits for that.
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "renderer/graph/plan.h"
#include "renderer/vk/buffer.h"
#include "renderer/vk/destroy_list.h"
#include "renderer/vk/image.h"

namespace ds::vk {
class Context;
}

namespace ds::graph {

struct ImageKey {
    std::string name;
    VkFormat format = VK_FORMAT_UNDEFINED;
    VkExtent2D extent{0, 0};
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
    uint32_t mip_levels = 1;
    VkImageUsageFlags usage = 0;
    bool operator==(const ImageKey& o) const;
};

struct BufferKey {
    std::string name;
    VkDeviceSize size = 0;
    VkBufferUsageFlags usage = 0;
    vk::MemoryUsage memory = vk::MemoryUsage::GpuOnly;
    bool operator==(const BufferKey& o) const = default;
};

struct CachedImage {
    ImageKey key;
    vk::Image image;
    ResourceState state;
    bool used = false;
};

struct CachedBuffer {
    BufferKey key;
    vk::Buffer buffer;
    ResourceState state;
    bool used = false;
};

// Two images that swap roles every frame: one is written ("current"), the other holds the
// previous frame's contents ("previous").
struct HistoryPair {
    ImageKey key;
    std::array<vk::Image, 2> images;
    std::array<ResourceState, 2> states;
    uint32_t current = 0;  // index written this frame
    bool valid = false;    // images[current ^ 1] holds last frame's contents
    bool used = false;
    uint32_t previous() const { return current ^ 1u; }
};

class ResourceCache {
  public:
    explicit ResourceCache(vk::Context& context) : context_(context) {}

    void begin_frame();  // marks every entry unused
    // The entry with this exact key (created when there is none), marked used. References
    // stay valid until the entry is retired.
    CachedImage& image(const ImageKey& key);
    CachedBuffer& buffer(const BufferKey& key);
    HistoryPair& history(const ImageKey& key);  // a new pair starts invalid
    // Entries no pass used since begin_frame() (replaced, resized, switched off) go to
    // `retired`: an earlier frame may still use them.
    void retire_unused(vk::DestroyList& retired);
    void invalidate_history();  // camera cut, resize: no pair holds a usable previous frame

    uint64_t images_created() const { return images_created_; }
    uint64_t buffers_created() const { return buffers_created_; }

  private:
    vk::Image create_image(const ImageKey& key, const std::string& name);

    vk::Context& context_;
    std::vector<std::unique_ptr<CachedImage>> images_;
    std::vector<std::unique_ptr<CachedBuffer>> buffers_;
    std::vector<std::unique_ptr<HistoryPair>> histories_;
    uint64_t images_created_ = 0;
    uint64_t buffers_created_ = 0;
};

}  // namespace ds::graph
