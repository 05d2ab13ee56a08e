#pragma once
// Staging uploads: copies are collected into one command buffer and submitted once, fenced
// (scene loading). Not for per-frame data: that lives in host-visible buffers.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include <vulkan/vulkan.h>

#include "renderer/vk/buffer.h"
#include "renderer/vk/image.h"

namespace ds::vk {

class Context;

// How a texture's mip chain was filled.
//  Blit: vkCmdBlitImage chain from level 0, when the format supports linear-filtered blits
//        (optimal tiling).
//  Cpu:  every level given by the caller (made on the CPU: scene/alpha_mips.h's box chain
//        where blits are not supported, or alpha_mip_coverage=preserve's chain).
//  None: the image has one level.
enum class MipFill : uint8_t { None, Blit, Cpu };

bool supports_blit_mips(const Context& context, VkFormat format);

class UploadBatch {
  public:
    explicit UploadBatch(Context& context) : context_(context) {}

    // `dst` needs TRANSFER_DST usage.
    void buffer(const Buffer& dst, const void* data, size_t size, VkDeviceSize dst_offset = 0);
    // `levels`: tightly packed texels of a 4-byte-per-texel format, level 0 first, each of
    // its level's size (halved and floored, never below 1). Every level of `dst`: copied as
    // given; level 0 alone: the others are blitted from it, which the format must support
    // (supports_blit_mips; throws otherwise). `dst` needs TRANSFER_DST and SAMPLED
    // (+ TRANSFER_SRC for blits). Ends in SHADER_READ_ONLY_OPTIMAL.
    MipFill texture(const Image& dst, std::span<const uint8_t* const> levels);
    MipFill texture(const Image& dst, const uint8_t* rgba8) {
        return texture(dst, std::span<const uint8_t* const>(&rgba8, 1));
    }
    // Records, submits and waits; frees the staging memory. The batch can be reused.
    void submit();

  private:
    Buffer& stage(const void* data, size_t size);

    Context& context_;
    std::vector<Buffer> staging_;
    std::vector<std::function<void(VkCommandBuffer)>> commands_;
};

// Set-up, outside any frame: clears every texel of `image` (colour or depth, TRANSFER_DST
// usage) to `value`, submits and waits; ends in SHADER_READ_ONLY_OPTIMAL for fragment reads.
// For constant images such as a pass's fallback inputs.
void clear_image_once(Context& context, const Image& image, const VkClearValue& value);

// Records a blit chain from level 0 (in TRANSFER_DST) to every level; ends every level in
// SHADER_READ_ONLY_OPTIMAL.
void record_blit_mips(VkCommandBuffer cmd, const Image& image);

}  // namespace ds::vk
