#pragma once
// Host-visible buffers for read-back, as graph resources (DESIGN decision 5: the graph plans
// every barrier). A read-back pass declares a copy of a graph image into one of them
// (declare_copy + record_copy), or a shader writes one directly (import_storage); each is
// imported with the final state "host read", so the graph's last barrier makes the data
// visible to the host. After the frame's fence anyone can read this frame's data by the
// graph handle it came from. Buffers are kept across frames by name and replaced when their
// size changes; Renderer::render waits for each frame, so one buffer per name suffices.
#include <cstddef>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "renderer/graph/graph.h"
#include "renderer/vk/buffer.h"
#include "renderer/vk/destroy_list.h"

namespace ds::vk {
class Context;
}

namespace ds {

class HostReadback {
  public:
    explicit HostReadback(vk::Context& context) : context_(context) {}

    // Forgets last frame's entries; replaced buffers go to `retired`.
    void begin_frame(vk::DestroyList& retired);

    // A transfer pass `name` copying each of `images` (single-sample, colour or depth) into a
    // host buffer "readback_<image name>": the whole image, tightly packed, row 0 = top (depth
    // aspect only), with the read-back role.
    void add_copy_pass(graph::RenderGraph& graph, const std::string& name,
                       std::vector<graph::ImageHandle> images);
    // A host buffer a shader writes (declare the write in the pass). Its first `zeroed`
    // bytes are zero when the frame starts (written by the host before the submit).
    graph::BufferHandle import_storage(graph::RenderGraph& graph, const std::string& name,
                                       VkDeviceSize bytes, VkDeviceSize zeroed = 0);

    // After the fence: this frame's bytes of a copied image or an imported storage buffer;
    // empty when it was not read back this frame.
    std::span<const std::byte> image_bytes(graph::ImageHandle image) const;
    std::span<const std::byte> buffer_bytes(graph::BufferHandle buffer) const;
    // A copied R32_UINT image's texels summed; none when it was not copied this frame.
    std::optional<uint64_t> u32_sum(graph::ImageHandle image) const;

    // Lets the buffer `name` go (retired with the last frame's destroy list): a read-back that
    // will not come back soon, such as msaa_probe's after msaa goes back to 1.
    void release(const std::string& name);

    void reset();  // teardown (device idle)

  private:
    graph::BufferHandle declare_copy(graph::RenderGraph& graph, graph::PassBuilder& builder,
                                     graph::ImageHandle image);
    void record_copy(graph::PassContext& ctx, graph::ImageHandle image,
                     graph::BufferHandle buffer) const;
    vk::Buffer& buffer(const std::string& name, VkDeviceSize bytes, VkBufferUsageFlags usage);
    std::span<const std::byte> bytes_of(uint32_t resource) const;

    vk::Context& context_;
    vk::DestroyList* retired_ = nullptr;
    std::map<std::string, vk::Buffer> buffers_;
    struct Entry {
        const vk::Buffer* buffer = nullptr;
        VkDeviceSize bytes = 0;
    };
    std::map<uint32_t, Entry> frame_;  // by graph resource index: the image or the buffer
};

}  // namespace ds
