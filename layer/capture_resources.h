#pragma once
// What one captured submission counts into: host-visible buffers for the per-draw counters
// (DrawCounters, 16 bytes each at an aligned stride) and the per-pixel counters of each pass
// with a depth attachment (PixelCounters: width, height, 2 reserved words, then 4 words per
// pixel: shaded, discarded, rasterized, reserved), the descriptor set that reaches them at the
// layer's slot (both bindings dynamic storage buffers), and a precise occlusion query per draw.
#include <cstdint>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "layer/state.h"

namespace ds::layer {

struct DrawCounters {
    uint32_t shaded, discarded, rasterized, reserved;
};

class CaptureResources {
  public:
    // `pass_pixels`: width x height of each pass's pixel counters (0 x 0: none).
    // `layout`: the counters' set layout (CountingPipelines::set_layout()).
    CaptureResources(DeviceData& d, VkDescriptorSetLayout layout, uint32_t draws,
                     const std::vector<VkExtent2D>& pass_pixels);
    ~CaptureResources();
    CaptureResources(const CaptureResources&) = delete;
    CaptureResources& operator=(const CaptureResources&) = delete;

    bool ok() const { return error_.empty(); }
    const std::string& error() const { return error_; }

    VkDescriptorSet set() const { return set_; }
    VkQueryPool queries() const { return queries_; }
    uint32_t draw_offset(uint32_t draw) const { return uint32_t(draw * draw_stride_); }
    uint32_t pass_offset(uint32_t pass) const { return uint32_t(pass_offsets_[pass]); }
    VkDeviceSize bytes() const { return draw_bytes_ + pixel_bytes_; }

    const DrawCounters& draw(uint32_t i) const;
    // A pass's pixels: 4 words each, row-major.
    const uint32_t* pixels(uint32_t pass) const;

  private:
    bool make_buffer(VkDeviceSize size, VkBuffer& buffer, VkDeviceMemory& memory, void*& mapped);
    bool make_descriptors(VkDeviceSize pixel_range);


    DeviceData& d_;
    std::string error_;
    VkDeviceSize draw_stride_ = 16, draw_bytes_ = 0, pixel_bytes_ = 0;
    std::vector<VkDeviceSize> pass_offsets_;
    VkBuffer draw_buffer_ = VK_NULL_HANDLE, pixel_buffer_ = VK_NULL_HANDLE;
    VkDeviceMemory draw_memory_ = VK_NULL_HANDLE, pixel_memory_ = VK_NULL_HANDLE;
    void *draw_map_ = nullptr, *pixel_map_ = nullptr;
    VkDescriptorSetLayout layout_;
    VkDescriptorPool pool_ = VK_NULL_HANDLE;
    VkDescriptorSet set_ = VK_NULL_HANDLE;
    VkQueryPool queries_ = VK_NULL_HANDLE;
};

}  // namespace ds::layer
