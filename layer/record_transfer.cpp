// Recording of transfers, clears, events and barriers.
#include <cstring>
#include <memory>

#include "layer/record.h"

namespace ds::layer {

namespace {

// Copies of structures whose pNext the layer does not follow: any pNext marks the buffer
// unrecordable (the copy then is never replayed).
template <typename T>
std::vector<T> copy_plain(DeviceData& d, VkCommandBuffer cb, const T* items, uint32_t n,
                          const char* what) {
    std::vector<T> out = copy(items, n);
    for (T& item : out)
        if (item.pNext) {
            unrecordable(d, cb, std::string(what) + " with a pNext structure");
            item.pNext = nullptr;
        }
    return out;
}

VKAPI_ATTR void VKAPI_CALL CmdCopyBuffer(VkCommandBuffer cb, VkBuffer s, VkBuffer t_,
                                         uint32_t n, const VkBufferCopy* r) {
    DeviceData& d = device_of(cb);
    d.t.CmdCopyBuffer(cb, s, t_, n, r);
    record(d, cb, Op::Other, {}, [s, t_, r = copy(r, n)](const DeviceTable& t, VkCommandBuffer c) {
        t.CmdCopyBuffer(c, s, t_, uint32_t(r.size()), r.data());
    });
}

VKAPI_ATTR void VKAPI_CALL CmdCopyImage(VkCommandBuffer cb, VkImage s, VkImageLayout sl,
                                        VkImage t_, VkImageLayout tl, uint32_t n,
                                        const VkImageCopy* r) {
    DeviceData& d = device_of(cb);
    d.t.CmdCopyImage(cb, s, sl, t_, tl, n, r);
    record(d, cb, Op::Other, {},
           [s, sl, t_, tl, r = copy(r, n)](const DeviceTable& t, VkCommandBuffer c) {
               t.CmdCopyImage(c, s, sl, t_, tl, uint32_t(r.size()), r.data());
           });
}

VKAPI_ATTR void VKAPI_CALL CmdBlitImage(VkCommandBuffer cb, VkImage s, VkImageLayout sl,
                                        VkImage t_, VkImageLayout tl, uint32_t n,
                                        const VkImageBlit* r, VkFilter f) {
    DeviceData& d = device_of(cb);
    d.t.CmdBlitImage(cb, s, sl, t_, tl, n, r, f);
    record(d, cb, Op::Other, {},
           [s, sl, t_, tl, r = copy(r, n), f](const DeviceTable& t, VkCommandBuffer c) {
               t.CmdBlitImage(c, s, sl, t_, tl, uint32_t(r.size()), r.data(), f);
           });
}

VKAPI_ATTR void VKAPI_CALL CmdResolveImage(VkCommandBuffer cb, VkImage s, VkImageLayout sl,
                                           VkImage t_, VkImageLayout tl, uint32_t n,
                                           const VkImageResolve* r) {
    DeviceData& d = device_of(cb);
    d.t.CmdResolveImage(cb, s, sl, t_, tl, n, r);
    record(d, cb, Op::Other, {},
           [s, sl, t_, tl, r = copy(r, n)](const DeviceTable& t, VkCommandBuffer c) {
               t.CmdResolveImage(c, s, sl, t_, tl, uint32_t(r.size()), r.data());
           });
}

VKAPI_ATTR void VKAPI_CALL CmdCopyBufferToImage(VkCommandBuffer cb, VkBuffer s, VkImage t_,
                                                VkImageLayout tl, uint32_t n,
                                                const VkBufferImageCopy* r) {
    DeviceData& d = device_of(cb);
    d.t.CmdCopyBufferToImage(cb, s, t_, tl, n, r);
    record(d, cb, Op::Other, {},
           [s, t_, tl, r = copy(r, n)](const DeviceTable& t, VkCommandBuffer c) {
               t.CmdCopyBufferToImage(c, s, t_, tl, uint32_t(r.size()), r.data());
           });
}

VKAPI_ATTR void VKAPI_CALL CmdCopyImageToBuffer(VkCommandBuffer cb, VkImage s, VkImageLayout sl,
                                                VkBuffer t_, uint32_t n,
                                                const VkBufferImageCopy* r) {
    DeviceData& d = device_of(cb);
    d.t.CmdCopyImageToBuffer(cb, s, sl, t_, n, r);
    record(d, cb, Op::Other, {},
           [s, sl, t_, r = copy(r, n)](const DeviceTable& t, VkCommandBuffer c) {
               t.CmdCopyImageToBuffer(c, s, sl, t_, uint32_t(r.size()), r.data());
           });
}

VKAPI_ATTR void VKAPI_CALL CmdUpdateBuffer(VkCommandBuffer cb, VkBuffer b, VkDeviceSize o,
                                           VkDeviceSize size, const void* data) {
    DeviceData& d = device_of(cb);
    d.t.CmdUpdateBuffer(cb, b, o, size, data);
    std::vector<uint8_t> bytes(size);
    std::memcpy(bytes.data(), data, size);
    record(d, cb, Op::Other, {}, [b, o, bytes](const DeviceTable& t, VkCommandBuffer c) {
        t.CmdUpdateBuffer(c, b, o, bytes.size(), bytes.data());
    });
}

VKAPI_ATTR void VKAPI_CALL CmdFillBuffer(VkCommandBuffer cb, VkBuffer b, VkDeviceSize o,
                                         VkDeviceSize size, uint32_t v) {
    plain(cb, &DeviceTable::CmdFillBuffer, b, o, size, v);
}

VKAPI_ATTR void VKAPI_CALL CmdClearColorImage(VkCommandBuffer cb, VkImage i, VkImageLayout l,
                                              const VkClearColorValue* v, uint32_t n,
                                              const VkImageSubresourceRange* r) {
    DeviceData& d = device_of(cb);
    d.t.CmdClearColorImage(cb, i, l, v, n, r);
    record(d, cb, Op::Other, {},
           [i, l, v = *v, r = copy(r, n)](const DeviceTable& t, VkCommandBuffer c) {
               t.CmdClearColorImage(c, i, l, &v, uint32_t(r.size()), r.data());
           });
}

VKAPI_ATTR void VKAPI_CALL CmdClearDepthStencilImage(VkCommandBuffer cb, VkImage i,
                                                     VkImageLayout l,
                                                     const VkClearDepthStencilValue* v,
                                                     uint32_t n,
                                                     const VkImageSubresourceRange* r) {
    DeviceData& d = device_of(cb);
    d.t.CmdClearDepthStencilImage(cb, i, l, v, n, r);
    record(d, cb, Op::Other, {},
           [i, l, v = *v, r = copy(r, n)](const DeviceTable& t, VkCommandBuffer c) {
               t.CmdClearDepthStencilImage(c, i, l, &v, uint32_t(r.size()), r.data());
           });
}

VKAPI_ATTR void VKAPI_CALL CmdSetEvent(VkCommandBuffer cb, VkEvent e, VkPipelineStageFlags s) {
    plain(cb, &DeviceTable::CmdSetEvent, e, s);
}
VKAPI_ATTR void VKAPI_CALL CmdResetEvent(VkCommandBuffer cb, VkEvent e, VkPipelineStageFlags s) {
    plain(cb, &DeviceTable::CmdResetEvent, e, s);
}

// The barrier arrays of vkCmdPipelineBarrier and vkCmdWaitEvents, owned.
struct Barriers {
    std::vector<VkMemoryBarrier> memory;
    std::vector<VkBufferMemoryBarrier> buffers;
    std::vector<VkImageMemoryBarrier> images;
};

std::shared_ptr<Barriers> copy_barriers(DeviceData& d, VkCommandBuffer cb, uint32_t nm,
                                        const VkMemoryBarrier* m, uint32_t nb,
                                        const VkBufferMemoryBarrier* b, uint32_t ni,
                                        const VkImageMemoryBarrier* i) {
    auto out = std::make_shared<Barriers>();
    out->memory = copy_plain(d, cb, m, nm, "a memory barrier");
    out->buffers = copy_plain(d, cb, b, nb, "a buffer barrier");
    out->images = copy_plain(d, cb, i, ni, "an image barrier");
    return out;
}

VKAPI_ATTR void VKAPI_CALL CmdPipelineBarrier(VkCommandBuffer cb, VkPipelineStageFlags src,
                                              VkPipelineStageFlags dst, VkDependencyFlags f,
                                              uint32_t nm, const VkMemoryBarrier* m, uint32_t nb,
                                              const VkBufferMemoryBarrier* b, uint32_t ni,
                                              const VkImageMemoryBarrier* i) {
    DeviceData& d = device_of(cb);
    d.t.CmdPipelineBarrier(cb, src, dst, f, nm, m, nb, b, ni, i);
    auto x = copy_barriers(d, cb, nm, m, nb, b, ni, i);
    record(d, cb, Op::Other, {}, [src, dst, f, x](const DeviceTable& t, VkCommandBuffer c) {
        t.CmdPipelineBarrier(c, src, dst, f, uint32_t(x->memory.size()),
                             data_or_null(x->memory), uint32_t(x->buffers.size()),
                             data_or_null(x->buffers), uint32_t(x->images.size()),
                             data_or_null(x->images));
    });
}

VKAPI_ATTR void VKAPI_CALL CmdWaitEvents(VkCommandBuffer cb, uint32_t ne, const VkEvent* e,
                                         VkPipelineStageFlags src, VkPipelineStageFlags dst,
                                         uint32_t nm, const VkMemoryBarrier* m, uint32_t nb,
                                         const VkBufferMemoryBarrier* b, uint32_t ni,
                                         const VkImageMemoryBarrier* i) {
    DeviceData& d = device_of(cb);
    d.t.CmdWaitEvents(cb, ne, e, src, dst, nm, m, nb, b, ni, i);
    auto x = copy_barriers(d, cb, nm, m, nb, b, ni, i);
    record(d, cb, Op::Other, {},
           [e = copy(e, ne), src, dst, x](const DeviceTable& t, VkCommandBuffer c) {
               t.CmdWaitEvents(c, uint32_t(e.size()), e.data(), src, dst,
                               uint32_t(x->memory.size()), data_or_null(x->memory),
                               uint32_t(x->buffers.size()), data_or_null(x->buffers),
                               uint32_t(x->images.size()), data_or_null(x->images));
           });
}

// A VkDependencyInfo and its arrays, owned.
struct Dependency {
    VkDependencyInfo info{};
    std::vector<VkMemoryBarrier2> memory;
    std::vector<VkBufferMemoryBarrier2> buffers;
    std::vector<VkImageMemoryBarrier2> images;
};

std::shared_ptr<Dependency> copy_dependency(DeviceData& d, VkCommandBuffer cb,
                                            const VkDependencyInfo* in) {
    auto out = std::make_shared<Dependency>();
    out->info = *in;
    if (in->pNext) unrecordable(d, cb, "a VkDependencyInfo with a pNext structure");
    out->info.pNext = nullptr;
    out->memory = copy_plain(d, cb, in->pMemoryBarriers, in->memoryBarrierCount, "a barrier");
    out->buffers = copy_plain(d, cb, in->pBufferMemoryBarriers, in->bufferMemoryBarrierCount,
                              "a buffer barrier");
    out->images = copy_plain(d, cb, in->pImageMemoryBarriers, in->imageMemoryBarrierCount,
                             "an image barrier");
    out->info.pMemoryBarriers = data_or_null(out->memory);
    out->info.pBufferMemoryBarriers = data_or_null(out->buffers);
    out->info.pImageMemoryBarriers = data_or_null(out->images);
    return out;
}

VKAPI_ATTR void VKAPI_CALL CmdPipelineBarrier2(VkCommandBuffer cb, const VkDependencyInfo* in) {
    DeviceData& d = device_of(cb);
    d.t.CmdPipelineBarrier2(cb, in);
    auto x = copy_dependency(d, cb, in);
    record(d, cb, Op::Other, {},
           [x](const DeviceTable& t, VkCommandBuffer c) { t.CmdPipelineBarrier2(c, &x->info); });
}

VKAPI_ATTR void VKAPI_CALL CmdSetEvent2(VkCommandBuffer cb, VkEvent e, const VkDependencyInfo* in) {
    DeviceData& d = device_of(cb);
    d.t.CmdSetEvent2(cb, e, in);
    auto x = copy_dependency(d, cb, in);
    record(d, cb, Op::Other, {},
           [e, x](const DeviceTable& t, VkCommandBuffer c) { t.CmdSetEvent2(c, e, &x->info); });
}

VKAPI_ATTR void VKAPI_CALL CmdResetEvent2(VkCommandBuffer cb, VkEvent e, VkPipelineStageFlags2 s) {
    plain(cb, &DeviceTable::CmdResetEvent2, e, s);
}

VKAPI_ATTR void VKAPI_CALL CmdWaitEvents2(VkCommandBuffer cb, uint32_t n, const VkEvent* e,
                                          const VkDependencyInfo* in) {
    DeviceData& d = device_of(cb);
    d.t.CmdWaitEvents2(cb, n, e, in);
    std::vector<std::shared_ptr<Dependency>> deps;
    for (uint32_t k = 0; k < n; ++k) deps.push_back(copy_dependency(d, cb, &in[k]));
    record(d, cb, Op::Other, {},
           [e = copy(e, n), deps](const DeviceTable& t, VkCommandBuffer c) {
               std::vector<VkDependencyInfo> infos;
               for (const auto& x : deps) infos.push_back(x->info);
               t.CmdWaitEvents2(c, uint32_t(e.size()), e.data(), infos.data());
           });
}

// vkCmdCopy*2 / Blit2 / Resolve2: an info structure with a pRegions array.
template <typename Info, typename Region, typename Pfn>
void copy2(VkCommandBuffer cb, const Info* in, Pfn DeviceTable::*fn, const char* what) {
    DeviceData& d = device_of(cb);
    (d.t.*fn)(cb, in);
    struct Owned {
        Info info;
        std::vector<Region> regions;
    };
    auto x = std::make_shared<Owned>();
    x->info = *in;
    if (in->pNext) unrecordable(d, cb, std::string(what) + " with a pNext structure");
    x->info.pNext = nullptr;
    x->regions = copy_plain(d, cb, in->pRegions, in->regionCount, what);
    x->info.pRegions = x->regions.data();
    record(d, cb, Op::Other, {},
           [x, fn](const DeviceTable& t, VkCommandBuffer c) { (t.*fn)(c, &x->info); });
}

VKAPI_ATTR void VKAPI_CALL CmdCopyBuffer2(VkCommandBuffer cb, const VkCopyBufferInfo2* in) {
    copy2<VkCopyBufferInfo2, VkBufferCopy2>(cb, in, &DeviceTable::CmdCopyBuffer2, "CopyBuffer2");
}
VKAPI_ATTR void VKAPI_CALL CmdCopyImage2(VkCommandBuffer cb, const VkCopyImageInfo2* in) {
    copy2<VkCopyImageInfo2, VkImageCopy2>(cb, in, &DeviceTable::CmdCopyImage2, "CopyImage2");
}
VKAPI_ATTR void VKAPI_CALL CmdCopyBufferToImage2(VkCommandBuffer cb,
                                                 const VkCopyBufferToImageInfo2* in) {
    copy2<VkCopyBufferToImageInfo2, VkBufferImageCopy2>(
        cb, in, &DeviceTable::CmdCopyBufferToImage2, "CopyBufferToImage2");
}
VKAPI_ATTR void VKAPI_CALL CmdCopyImageToBuffer2(VkCommandBuffer cb,
                                                 const VkCopyImageToBufferInfo2* in) {
    copy2<VkCopyImageToBufferInfo2, VkBufferImageCopy2>(
        cb, in, &DeviceTable::CmdCopyImageToBuffer2, "CopyImageToBuffer2");
}
VKAPI_ATTR void VKAPI_CALL CmdBlitImage2(VkCommandBuffer cb, const VkBlitImageInfo2* in) {
    copy2<VkBlitImageInfo2, VkImageBlit2>(cb, in, &DeviceTable::CmdBlitImage2, "BlitImage2");
}
VKAPI_ATTR void VKAPI_CALL CmdResolveImage2(VkCommandBuffer cb, const VkResolveImageInfo2* in) {
    copy2<VkResolveImageInfo2, VkImageResolve2>(cb, in, &DeviceTable::CmdResolveImage2,
                                                "ResolveImage2");
}

}  // namespace

PFN_vkVoidFunction recorded_transfer_command(const char* name) {
#define DS_X(fn) \
    if (std::strcmp(name, "vk" #fn) == 0) return reinterpret_cast<PFN_vkVoidFunction>(&fn);
    DS_X(CmdCopyBuffer)
    DS_X(CmdCopyImage)
    DS_X(CmdBlitImage)
    DS_X(CmdResolveImage)
    DS_X(CmdCopyBufferToImage)
    DS_X(CmdCopyImageToBuffer)
    DS_X(CmdUpdateBuffer)
    DS_X(CmdFillBuffer)
    DS_X(CmdClearColorImage)
    DS_X(CmdClearDepthStencilImage)
    DS_X(CmdSetEvent)
    DS_X(CmdResetEvent)
    DS_X(CmdPipelineBarrier)
    DS_X(CmdWaitEvents)
    DS_X(CmdPipelineBarrier2)
    DS_X(CmdSetEvent2)
    DS_X(CmdResetEvent2)
    DS_X(CmdWaitEvents2)
    DS_X(CmdCopyBuffer2)
    DS_X(CmdCopyImage2)
    DS_X(CmdCopyBufferToImage2)
    DS_X(CmdCopyImageToBuffer2)
    DS_X(CmdBlitImage2)
    DS_X(CmdResolveImage2)
#undef DS_X
    return nullptr;
}

}  // namespace ds::layer
