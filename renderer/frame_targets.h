#pragma once
// The images a frame hands to the graph from outside, because they are read back after it:
// the final image (tonemap writes it; the caller gets its pixels), the scene depth (covered
// pixels), and with count_fragments=on the three count images. Each is imported with a final
// TRANSFER_SRC state; after graph.execute() record_read_back() copies them to host buffers.
// With msaa > 1 also the multisampled depth and HDR colour, left sampleable after the graph
// so MsaaProbe can read every sample (a multisampled image cannot be copied to a buffer).
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include <vulkan/vulkan.h>

#include "renderer/graph/graph.h"
#include "renderer/passes/frame.h"
#include "renderer/vk/buffer.h"
#include "renderer/vk/destroy_list.h"
#include "renderer/vk/image.h"

namespace ds::vk {
class Context;
}

namespace ds {

enum class CountImage : uint8_t { Prepass, Forward, Transparent };

class FrameTargets {
  public:
    FrameTargets(vk::Context& context, VkFormat final_format, VkFormat depth_format,
                 VkFormat hdr_format);

    // (Re)creates what this frame needs at `size` and `samples`; replaced images go to
    // `retired` (an earlier frame may still use them).
    void ensure(VkExtent2D size, bool counts, VkSampleCountFlagBits samples,
                vk::DestroyList& retired);
    // Imports the final image, the depth and, with counting on, a count image for each
    // counting pass that runs. Fills res.final_image, res.depth and res.*_counts.
    void import(graph::RenderGraph& graph, const passes::FrameOptions& options,
                passes::FrameResources& res);
    // After graph.execute(): copies what is wanted to the read-back buffers and makes the
    // copies visible to the host.
    void record_read_back(VkCommandBuffer cmd, bool image, bool depth) const;

    // After the frame's fence.
    std::vector<uint8_t> rgba8() const;                         // tightly packed, top row first
    uint64_t covered_pixels(float far_depth) const;             // depth texels != far
    std::optional<uint64_t> count_sum(CountImage which) const;  // none unless imported

    // msaa > 1: the multisampled images (sampleable after the graph); null otherwise.
    const vk::Image& msaa_depth() const { return msaa_depth_; }
    const vk::Image& msaa_hdr() const { return msaa_hdr_; }
    // D32 only: the resolved depth as floats, row 0 = top (empty for other formats).
    std::vector<float> depth_floats() const;

    // Releases everything (teardown, device idle).
    void reset();

  private:
    struct Target {
        vk::Image image;
        vk::Buffer readback;
    };
    Target make_target(VkFormat format, VkImageUsageFlags usage, uint32_t bytes_per_texel,
                       const char* name) const;
    void copy(VkCommandBuffer cmd, const Target& target) const;
    void ensure_msaa(VkSampleCountFlagBits samples, vk::DestroyList& retired);

    vk::Context& context_;
    VkFormat final_format_;
    VkFormat depth_format_;
    VkFormat hdr_format_;
    VkSampleCountFlagBits samples_ = VK_SAMPLE_COUNT_1_BIT;
    VkExtent2D size_{0, 0};
    Target final_;
    Target depth_;
    std::array<Target, 3> counts_;   // by CountImage; empty until count_fragments=on
    std::array<bool, 3> counted_{};  // imported this frame
    vk::Image msaa_depth_;           // msaa > 1 only
    vk::Image msaa_hdr_;
};

}  // namespace ds
