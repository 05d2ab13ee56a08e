#include "layer/capture_resources.h"
#include "layer/typed.h"

#include <algorithm>
#include <cstring>

namespace ds::layer {

namespace {

VkDeviceSize align(VkDeviceSize v, VkDeviceSize a) { return (v + a - 1) / a * a; }

constexpr VkDeviceSize kPixelHeader = 16;
constexpr VkDeviceSize kRecordBytes = 16;

}  // namespace

CaptureResources::CaptureResources(DeviceData& d, VkDescriptorSetLayout layout, uint32_t draws,
                                   const std::vector<VkExtent2D>& pass_pixels,
                                   const std::vector<VkExtent2D>& depth_pixels, uint32_t records)
    : d_(d), depth_pixels_(depth_pixels), record_capacity_(records), layout_(layout) {
    const VkDeviceSize a = std::max<VkDeviceSize>(
        16, d.properties.limits.minStorageBufferOffsetAlignment);
    draw_stride_ = a;
    draw_bytes_ = std::max<VkDeviceSize>(1, draws) * a;
    VkDeviceSize largest = kPixelHeader;
    for (const VkExtent2D& e : pass_pixels) {
        pass_offsets_.push_back(pixel_bytes_);
        const VkDeviceSize size = kPixelHeader + VkDeviceSize(e.width) * e.height * 16;
        largest = std::max(largest, size);
        pixel_bytes_ = align(pixel_bytes_ + size, a);
    }
    // The last pass's binding reads `largest` bytes from its offset.
    pixel_bytes_ = std::max<VkDeviceSize>(pixel_bytes_, 1) + largest;
    const VkDeviceSize depth_range = layout_depth(depth_pixels, a);
    record_bytes_ = kRecordBytes * (2 + VkDeviceSize(records));  // header, scratch, records
    if (!make_buffer(draw_bytes_, draw_buffer_, draw_memory_, draw_map_) ||
        !make_buffer(pixel_bytes_, pixel_buffer_, pixel_memory_, pixel_map_) ||
        !make_buffer(depth_bytes_, depth_buffer_, depth_memory_, depth_map_) ||
        !make_buffer(record_bytes_, record_buffer_, record_memory_, record_map_) ||
        !make_descriptors(largest, depth_range))
        return;
    std::memset(draw_map_, 0, draw_bytes_);
    std::memset(pixel_map_, 0, pixel_bytes_);
    std::memset(depth_map_, 0, depth_bytes_);
    // The records are read up to the count the shaders leave: only the header and the scratch
    // record need values (hundreds of MiB with a large shadow map).
    std::memset(record_map_, 0, std::min<VkDeviceSize>(record_bytes_, 32));
    static_cast<uint32_t*>(record_map_)[1] = records;
    for (size_t p = 0; p < pass_pixels.size(); ++p) {
        auto* header = reinterpret_cast<uint32_t*>(static_cast<uint8_t*>(pixel_map_) +
                                                   pass_offsets_[p]);
        header[0] = pass_pixels[p].width;
        header[1] = pass_pixels[p].height;
    }
    auto q = typed<VkQueryPoolCreateInfo>(VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO);
    q.queryType = VK_QUERY_TYPE_OCCLUSION;
    q.queryCount = std::max<uint32_t>(1, draws);
    if (d.t.CreateQueryPool(d.device, &q, nullptr, &queries_) != VK_SUCCESS)
        error_ = "cannot create the occlusion query pool";
}

bool CaptureResources::make_buffer(VkDeviceSize size, VkBuffer& buffer, VkDeviceMemory& memory,
                                   void*& mapped) {
    auto b = typed<VkBufferCreateInfo>(VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO);
    b.size = size;
    b.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    if (d_.t.CreateBuffer(d_.device, &b, nullptr, &buffer) != VK_SUCCESS)
        return (error_ = "cannot create a counter buffer"), false;
    VkMemoryRequirements req;
    d_.t.GetBufferMemoryRequirements(d_.device, buffer, &req);
    // Host-coherent, and cached where the device has such a type: the host reads the counters
    // and records back (hundreds of MiB with the depth checks; uncached reads crawl).
    const VkMemoryPropertyFlags want =
        VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    uint32_t type = UINT32_MAX;
    for (const VkMemoryPropertyFlags flags : {want | VK_MEMORY_PROPERTY_HOST_CACHED_BIT, want})
        for (uint32_t i = 0; i < d_.memory.memoryTypeCount && type == UINT32_MAX; ++i)
            if ((req.memoryTypeBits & (1u << i)) &&
                (d_.memory.memoryTypes[i].propertyFlags & flags) == flags)
                type = i;
    if (type == UINT32_MAX) return (error_ = "no host-visible memory for the counters"), false;
    auto m = typed<VkMemoryAllocateInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO);
    m.allocationSize = req.size;
    m.memoryTypeIndex = type;
    if (d_.t.AllocateMemory(d_.device, &m, nullptr, &memory) != VK_SUCCESS)
        return (error_ = "out of memory for the counters (" + std::to_string(size) + " bytes)"),
               false;
    d_.t.BindBufferMemory(d_.device, buffer, memory, 0);
    if (d_.t.MapMemory(d_.device, memory, 0, VK_WHOLE_SIZE, 0, &mapped) != VK_SUCCESS)
        return (error_ = "cannot map the counters"), false;
    return true;
}

// A region per pass of header + 2 words per pixel (passes without: none, offset 0); the binding
// reads the largest region from each offset.
VkDeviceSize CaptureResources::layout_depth(const std::vector<VkExtent2D>& depth_pixels,
                                            VkDeviceSize a) {
    VkDeviceSize largest = kPixelHeader + 8;
    for (const VkExtent2D& e : depth_pixels) {
        const VkDeviceSize size = kPixelHeader + VkDeviceSize(e.width) * e.height * 8;
        depth_offsets_.push_back(e.width ? depth_bytes_ : 0);
        if (!e.width) continue;
        largest = std::max(largest, size);
        depth_bytes_ = align(depth_bytes_ + size, a);
    }
    depth_bytes_ += largest;
    return largest;
}

bool CaptureResources::make_descriptors(VkDeviceSize pixel_range, VkDeviceSize depth_range) {
    const VkDescriptorPoolSize sizes[2] = {{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER_DYNAMIC, 3},
                                           {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1}};
    auto p = typed<VkDescriptorPoolCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO);
    p.maxSets = 1;
    p.poolSizeCount = 2;
    p.pPoolSizes = sizes;
    if (d_.t.CreateDescriptorPool(d_.device, &p, nullptr, &pool_) != VK_SUCCESS)
        return (error_ = "cannot create the counters' descriptor set"), false;
    auto a = typed<VkDescriptorSetAllocateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO);
    a.descriptorPool = pool_;
    a.descriptorSetCount = 1;
    a.pSetLayouts = &layout_;
    if (d_.t.AllocateDescriptorSets(d_.device, &a, &set_) != VK_SUCCESS)
        return (error_ = "cannot allocate the counters' descriptor set"), false;
    const VkDescriptorBufferInfo infos[4] = {{draw_buffer_, 0, sizeof(DrawCounters)},
                                             {pixel_buffer_, 0, pixel_range},
                                             {depth_buffer_, 0, depth_range},
                                             {record_buffer_, 0, VK_WHOLE_SIZE}};
    VkWriteDescriptorSet w[4] = {};
    for (uint32_t i = 0; i < 4; ++i) {
        w[i].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
        w[i].dstSet = set_;
        w[i].dstBinding = i;
        w[i].descriptorCount = 1;
        w[i].descriptorType = i < 3 ? VK_DESCRIPTOR_TYPE_STORAGE_BUFFER_DYNAMIC
                                    : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        w[i].pBufferInfo = &infos[i];
    }
    d_.t.UpdateDescriptorSets(d_.device, 4, w, 0, nullptr);
    return true;
}

void CaptureResources::set_draw_id(uint32_t draw, uint32_t id) {
    reinterpret_cast<DrawCounters*>(static_cast<uint8_t*>(draw_map_) + draw * draw_stride_)
        ->draw_id = id;
}

void CaptureResources::init_depth_pass(uint32_t pass, uint32_t params, DepthMode nearest) {
    const VkExtent2D e = depth_pixels_[pass];
    auto* h = reinterpret_cast<uint32_t*>(static_cast<uint8_t*>(depth_map_) + depth_offsets_[pass]);
    h[0] = e.width;
    h[1] = e.height;
    h[2] = params;
    h[3] = uint32_t(DepthMode::CountEqual);  // during the pass: its EQUAL re-draws count
    const uint32_t far = nearest == DepthMode::NearestMin ? UINT32_MAX : 0;
    for (size_t i = 0; i < size_t(e.width) * e.height; ++i) h[4 + 2 * i] = far;
}

const uint32_t* CaptureResources::depth_words(uint32_t pass) const {
    return reinterpret_cast<const uint32_t*>(static_cast<const uint8_t*>(depth_map_) +
                                             depth_offsets_[pass] + kPixelHeader);
}

uint32_t CaptureResources::record_count() const {
    return static_cast<const uint32_t*>(record_map_)[0];
}

const uint32_t* CaptureResources::records() const {
    return static_cast<const uint32_t*>(record_map_) + 8;
}

const DrawCounters& CaptureResources::draw(uint32_t i) const {
    return *reinterpret_cast<const DrawCounters*>(static_cast<const uint8_t*>(draw_map_) +
                                                  i * draw_stride_);
}

const uint32_t* CaptureResources::pixels(uint32_t pass) const {
    return reinterpret_cast<const uint32_t*>(static_cast<const uint8_t*>(pixel_map_) +
                                             pass_offsets_[pass] + kPixelHeader);
}

CaptureResources::~CaptureResources() {
    const auto& t = d_.t;
    if (queries_) t.DestroyQueryPool(d_.device, queries_, nullptr);
    if (pool_) t.DestroyDescriptorPool(d_.device, pool_, nullptr);
    for (auto [buffer, memory] :
         {std::pair{draw_buffer_, draw_memory_}, std::pair{pixel_buffer_, pixel_memory_},
          std::pair{depth_buffer_, depth_memory_}, std::pair{record_buffer_, record_memory_}}) {
        if (buffer) t.DestroyBuffer(d_.device, buffer, nullptr);
        if (memory) t.FreeMemory(d_.device, memory, nullptr);
    }
}

}  // namespace ds::layer
