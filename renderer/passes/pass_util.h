#pragma once
// What the passes share that is not a pass (a pass never includes another pass): per-frame
// descriptor sets, fail-safe pipeline variants, attachments, and the u32 count images of
// count_fragments=on.
#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <span>
#include <vector>

#include <vulkan/vulkan.h>

#include "renderer/graph/graph.h"
#include "renderer/vk/descriptors.h"
#include "renderer/vk/destroy_list.h"
#include "renderer/vk/frame.h"
#include "renderer/vk/pipeline.h"

namespace ds::vk {
class Context;
}

namespace ds::passes {

// Descriptor sets that live for one frame. A pool per frame in flight, reset when its slot
// comes round again: vk::FrameRing::begin() has waited for that slot's previous frame.
class FrameDescriptorPool {
  public:
    FrameDescriptorPool(vk::Context& context, uint32_t max_sets,
                        std::span<const VkDescriptorPoolSize> sizes, const char* name);
    VkDescriptorSet allocate(uint64_t frame_number, VkDescriptorSetLayout layout);

  private:
    std::array<vk::DescriptorPool, vk::FrameRing::kFramesInFlight> pools_;
    std::array<uint64_t, vk::FrameRing::kFramesInFlight> frames_;
};

// SPIR-V of one pipeline's stages; an empty fragment stage means depth only.
struct ShaderStages {
    std::vector<uint32_t> vert;
    std::vector<uint32_t> frag;
};

// A pass's pipelines by variant key (a few bits of defines and state), each built on first
// use, so a variant no frame asks for (the counting ones, invariant=off) costs nothing.
// rebuild() is fail-safe: every stage of every built variant compiles first (a
// shader::ShaderError leaves the current pipelines in place), then the pipelines are created,
// and only then are the old ones retired.
class PipelineVariants {
  public:
    using Compile = std::function<ShaderStages(uint32_t key)>;
    using Create = std::function<vk::Pipeline(uint32_t key, const ShaderStages& stages)>;

    PipelineVariants(Compile compile, Create create)
        : compile_(std::move(compile)), create_(std::move(create)) {}

    VkPipeline get(uint32_t key);  // throws shader::ShaderError / ds::Error on first build
    void rebuild(vk::DestroyList& retired);

  private:
    Compile compile_;
    Create create_;
    std::map<uint32_t, vk::Pipeline> pipelines_;
};

VkRenderingAttachmentInfo attachment(VkImageView view, VkImageLayout layout,
                                     VkAttachmentLoadOp load, VkAttachmentStoreOp store);
VkRenderingAttachmentInfo color_attachment(VkImageView view, VkAttachmentLoadOp load,
                                           std::array<float, 4> clear = {});
VkRenderingAttachmentInfo depth_attachment(VkImageView view, VkImageLayout layout,
                                           VkAttachmentLoadOp load, VkAttachmentStoreOp store,
                                           float clear_depth = 0.0f);
// Begins dynamic rendering over the whole `extent` and sets viewport and scissor to it.
void begin_rendering(VkCommandBuffer cmd, VkExtent2D extent,
                     std::span<const VkRenderingAttachmentInfo> colors,
                     const VkRenderingAttachmentInfo* depth);
// The dynamic depth state every pipeline declares (pipeline.h), in one call.
void set_depth_state(VkCommandBuffer cmd, bool test, bool write, VkCompareOp compare);

// Pipeline variant key bits for the sample count (bits 8-15; 0 at 1x, so single-sample keys
// are unchanged): pipelines are built per count on first use and kept, so switching msaa
// back and forth costs nothing after the first frame of each.
inline uint32_t samples_key(VkSampleCountFlagBits samples) {
    return samples == VK_SAMPLE_COUNT_1_BIT ? 0u : uint32_t(samples) << 8;
}
inline VkSampleCountFlagBits key_samples(uint32_t key) {
    const uint32_t s = (key >> 8) & 0xffu;
    return s ? VkSampleCountFlagBits(s) : VK_SAMPLE_COUNT_1_BIT;
}
// A colour attachment that resolves (AVERAGE) into `resolve` at the end of the rendering.
VkRenderingAttachmentInfo resolving_color_attachment(VkImageView msaa, VkImageView resolve,
                                                     VkAttachmentLoadOp load,
                                                     VkAttachmentStoreOp store,
                                                     std::array<float, 4> clear = {});

// Count images (shaders/common/count.glsl, set 3): R32_UINT, one per counting pass.
inline constexpr VkFormat kCountFormat = VK_FORMAT_R32_UINT;
inline constexpr uint32_t kCountSet = 3;
vk::DescriptorSetLayout create_count_set_layout(vk::Context& context);
// Declares what clear_counts() and the counting fragment shader do to `counts`.
void declare_counts(graph::PassBuilder& builder, graph::ImageHandle counts);
// Zeroes the image (in the pass's GENERAL layout) and makes the zeros visible to the
// fragment shader's atomics: a dependency inside the pass, which the graph cannot see.
void clear_counts(VkCommandBuffer cmd, VkImage image);
void write_count_set(VkDevice device, VkDescriptorSet set, VkImageView view);

}  // namespace ds::passes
