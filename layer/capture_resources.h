#pragma once
// What one captured submission counts into: host-visible buffers for the per-draw counters
// (DrawCounters, 16 bytes each at an aligned stride) and the per-pixel counters of each pass
// with a depth attachment (PixelCounters: width, height, 2 reserved words, then 4 words per
// pixel: shaded, discarded, rasterized, reserved), the descriptor set that reaches them at the
// layer's slot (both bindings dynamic storage buffers), and a precise occlusion query per draw.
// With zfight or equal_check on, also the depth records of each pass with a depth attachment
// (binding 2, dynamic: ZPixels, a 4-word header {width, height, params, mode} then 2 words per
// pixel: nearest depth, EQUAL survivors) and one record buffer (binding 3: {count, capacity,
// 0, 0} then 4-word records, record 0 scratch) that layer/spirv/survival.h writes.
#include <cstdint>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "layer/state.h"

namespace ds::layer {

struct DrawCounters {
    uint32_t shaded, discarded, rasterized, draw_id;  // draw_id: set by the layer (its slot)
};

// ZPixels.mode: what the survival shader does (layer/spirv/survival.h).
enum class DepthMode : uint32_t { NearestMin = 1, NearestMax = 2, Record = 3, CountEqual = 4 };

class CaptureResources {
  public:
    // `pass_pixels`: width x height of each pass's pixel counters (0 x 0: none).
    // `layout`: the counters' set layout (CountingPipelines::set_layout()).
    // `depth_pixels`: the same for the depth records (0 x 0: none); `records`: their capacity.
    CaptureResources(DeviceData& d, VkDescriptorSetLayout layout, uint32_t draws,
                     const std::vector<VkExtent2D>& pass_pixels,
                     const std::vector<VkExtent2D>& depth_pixels, uint32_t records);
    ~CaptureResources();
    CaptureResources(const CaptureResources&) = delete;
    CaptureResources& operator=(const CaptureResources&) = delete;

    bool ok() const { return error_.empty(); }
    const std::string& error() const { return error_; }

    VkDescriptorSet set() const { return set_; }
    VkQueryPool queries() const { return queries_; }
    uint32_t draw_offset(uint32_t draw) const { return uint32_t(draw * draw_stride_); }
    uint32_t pass_offset(uint32_t pass) const { return uint32_t(pass_offsets_[pass]); }
    uint32_t depth_offset(uint32_t pass) const { return uint32_t(depth_offsets_[pass]); }
    VkDeviceSize bytes() const { return draw_bytes_ + pixel_bytes_ + depth_bytes_ + record_bytes_; }
    VkBuffer depth_buffer() const { return depth_buffer_; }
    VkDeviceSize depth_record_bytes() const { return depth_bytes_ + record_bytes_; }

    // Host side, before the submission: a draw's id, a pass's depth header and first words.
    void set_draw_id(uint32_t draw, uint32_t id);
    void init_depth_pass(uint32_t pass, uint32_t params, DepthMode nearest);
    // A pass's depth words (2 per pixel), and the records (count may exceed capacity).
    const uint32_t* depth_words(uint32_t pass) const;
    uint32_t record_count() const;
    uint32_t record_capacity() const { return record_capacity_; }
    const uint32_t* records() const;  // record 1 first

    const DrawCounters& draw(uint32_t i) const;
    // A pass's pixels: 4 words each, row-major.
    const uint32_t* pixels(uint32_t pass) const;

  private:
    bool make_buffer(VkDeviceSize size, VkBuffer& buffer, VkDeviceMemory& memory, void*& mapped);
    bool make_descriptors(VkDeviceSize pixel_range, VkDeviceSize depth_range);
    VkDeviceSize layout_depth(const std::vector<VkExtent2D>& depth_pixels, VkDeviceSize align);


    DeviceData& d_;
    std::string error_;
    VkDeviceSize draw_stride_ = 16, draw_bytes_ = 0, pixel_bytes_ = 0;
    std::vector<VkDeviceSize> pass_offsets_, depth_offsets_;
    std::vector<VkExtent2D> depth_pixels_;
    VkDeviceSize depth_bytes_ = 0, record_bytes_ = 0;
    uint32_t record_capacity_ = 0;
    VkBuffer depth_buffer_ = VK_NULL_HANDLE, record_buffer_ = VK_NULL_HANDLE;
    VkDeviceMemory depth_memory_ = VK_NULL_HANDLE, record_memory_ = VK_NULL_HANDLE;
    void *depth_map_ = nullptr, *record_map_ = nullptr;
    VkBuffer draw_buffer_ = VK_NULL_HANDLE, pixel_buffer_ = VK_NULL_HANDLE;
    VkDeviceMemory draw_memory_ = VK_NULL_HANDLE, pixel_memory_ = VK_NULL_HANDLE;
    void *draw_map_ = nullptr, *pixel_map_ = nullptr;
    VkDescriptorSetLayout layout_;
    VkDescriptorPool pool_ = VK_NULL_HANDLE;
    VkDescriptorSet set_ = VK_NULL_HANDLE;
    VkQueryPool queries_ = VK_NULL_HANDLE;
};

}  // namespace ds::layer
