// Recording of render passes, dynamic rendering, draws, labels, queries and secondary buffers.
#include <array>
#include <cstring>
#include <memory>

#include "layer/record.h"

namespace ds::layer {

namespace {

// A VkRenderPassBeginInfo and its arrays, owned.
struct RenderPassBegin {
    VkRenderPassBeginInfo info{};
    VkRenderPassAttachmentBeginInfo views_info{};
    std::vector<VkClearValue> clears;
    std::vector<VkImageView> views;
};

std::shared_ptr<RenderPassBegin> copy_begin(DeviceData& d, VkCommandBuffer cb,
                                            const VkRenderPassBeginInfo* b) {
    auto out = std::make_shared<RenderPassBegin>();
    out->info = *b;
    out->clears = copy(b->pClearValues, b->clearValueCount);
    out->info.pClearValues = data_or_null(out->clears);
    out->info.pNext = nullptr;
    for (auto* s = static_cast<const VkBaseInStructure*>(b->pNext); s; s = s->pNext) {
        if (s->sType != VK_STRUCTURE_TYPE_RENDER_PASS_ATTACHMENT_BEGIN_INFO) {
            unrecordable(d, cb, "vkCmdBeginRenderPass with a pNext structure of type " +
                                    std::to_string(s->sType));
            continue;
        }
        const auto* a = reinterpret_cast<const VkRenderPassAttachmentBeginInfo*>(s);
        out->views = copy(a->pAttachments, a->attachmentCount);
        out->views_info = *a;
        out->views_info.pNext = nullptr;
        out->views_info.pAttachments = out->views.data();
        out->info.pNext = &out->views_info;
    }
    return out;
}

RenderPassArgs pass_args(const RenderPassBegin& b) {
    return {b.info.renderPass, b.info.framebuffer, b.info.renderArea, b.views};
}

VKAPI_ATTR void VKAPI_CALL CmdBeginRenderPass(VkCommandBuffer cb, const VkRenderPassBeginInfo* b,
                                              VkSubpassContents contents) {
    DeviceData& d = device_of(cb);
    d.t.CmdBeginRenderPass(cb, b, contents);
    auto begin = copy_begin(d, cb, b);
    record(d, cb, Op::BeginRenderPass, pass_args(*begin),
           [begin, contents](const DeviceTable& t, VkCommandBuffer c) {
               t.CmdBeginRenderPass(c, &begin->info, contents);
           });
}

bool plain_subpass_info(DeviceData& d, VkCommandBuffer cb, const void* next, const char* what) {
    if (!next) return true;
    unrecordable(d, cb, std::string(what) + " with a pNext structure");
    return false;
}

VKAPI_ATTR void VKAPI_CALL CmdBeginRenderPass2(VkCommandBuffer cb, const VkRenderPassBeginInfo* b,
                                               const VkSubpassBeginInfo* s) {
    DeviceData& d = device_of(cb);
    d.t.CmdBeginRenderPass2(cb, b, s);
    auto begin = copy_begin(d, cb, b);
    plain_subpass_info(d, cb, s->pNext, "vkCmdBeginRenderPass2's VkSubpassBeginInfo");
    const VkSubpassContents contents = s->contents;
    record(d, cb, Op::BeginRenderPass, pass_args(*begin),
           [begin, contents](const DeviceTable& t, VkCommandBuffer c) {
               VkSubpassBeginInfo si{VK_STRUCTURE_TYPE_SUBPASS_BEGIN_INFO, nullptr, contents};
               t.CmdBeginRenderPass2(c, &begin->info, &si);
           });
}

VKAPI_ATTR void VKAPI_CALL CmdNextSubpass(VkCommandBuffer cb, VkSubpassContents contents) {
    DeviceData& d = device_of(cb);
    d.t.CmdNextSubpass(cb, contents);
    record(d, cb, Op::NextSubpass, {}, [contents](const DeviceTable& t, VkCommandBuffer c) {
        t.CmdNextSubpass(c, contents);
    });
}

VKAPI_ATTR void VKAPI_CALL CmdNextSubpass2(VkCommandBuffer cb, const VkSubpassBeginInfo* b,
                                           const VkSubpassEndInfo* e) {
    DeviceData& d = device_of(cb);
    d.t.CmdNextSubpass2(cb, b, e);
    plain_subpass_info(d, cb, b->pNext, "vkCmdNextSubpass2's VkSubpassBeginInfo");
    plain_subpass_info(d, cb, e->pNext, "vkCmdNextSubpass2's VkSubpassEndInfo");
    const VkSubpassContents contents = b->contents;
    record(d, cb, Op::NextSubpass, {}, [contents](const DeviceTable& t, VkCommandBuffer c) {
        VkSubpassBeginInfo si{VK_STRUCTURE_TYPE_SUBPASS_BEGIN_INFO, nullptr, contents};
        VkSubpassEndInfo ei{VK_STRUCTURE_TYPE_SUBPASS_END_INFO, nullptr};
        t.CmdNextSubpass2(c, &si, &ei);
    });
}

VKAPI_ATTR void VKAPI_CALL CmdEndRenderPass(VkCommandBuffer cb) {
    DeviceData& d = device_of(cb);
    d.t.CmdEndRenderPass(cb);
    record(d, cb, Op::EndRenderPass, {},
           [](const DeviceTable& t, VkCommandBuffer c) { t.CmdEndRenderPass(c); });
}

VKAPI_ATTR void VKAPI_CALL CmdEndRenderPass2(VkCommandBuffer cb, const VkSubpassEndInfo* e) {
    DeviceData& d = device_of(cb);
    d.t.CmdEndRenderPass2(cb, e);
    plain_subpass_info(d, cb, e->pNext, "vkCmdEndRenderPass2's VkSubpassEndInfo");
    record(d, cb, Op::EndRenderPass, {}, [](const DeviceTable& t, VkCommandBuffer c) {
        VkSubpassEndInfo ei{VK_STRUCTURE_TYPE_SUBPASS_END_INFO, nullptr};
        t.CmdEndRenderPass2(c, &ei);
    });
}

// A VkRenderingInfo and its attachments, owned.
struct RenderingBegin {
    VkRenderingInfo info{};
    std::vector<VkRenderingAttachmentInfo> colors;
    VkRenderingAttachmentInfo depth{}, stencil{};
};

VKAPI_ATTR void VKAPI_CALL CmdBeginRendering(VkCommandBuffer cb, const VkRenderingInfo* r) {
    DeviceData& d = device_of(cb);
    d.t.CmdBeginRendering(cb, r);
    auto b = std::make_shared<RenderingBegin>();
    b->info = *r;
    if (r->pNext) unrecordable(d, cb, "vkCmdBeginRendering with a pNext structure");
    b->info.pNext = nullptr;
    b->colors = copy(r->pColorAttachments, r->colorAttachmentCount);
    b->info.pColorAttachments = data_or_null(b->colors);
    RenderingArgs a{r->renderArea, r->layerCount, r->viewMask, VK_NULL_HANDLE, VK_NULL_HANDLE,
                    {}, (r->flags & VK_RENDERING_RESUMING_BIT) != 0,
                    (r->flags & VK_RENDERING_SUSPENDING_BIT) != 0};
    for (const auto& c : b->colors) {
        a.color_views.push_back(c.imageView);
        if (c.pNext) unrecordable(d, cb, "a colour attachment with a pNext structure");
    }
    if (r->pDepthAttachment) {
        b->depth = *r->pDepthAttachment;
        b->info.pDepthAttachment = &b->depth;
        a.depth_view = b->depth.imageView;
    }
    if (r->pStencilAttachment) {
        b->stencil = *r->pStencilAttachment;
        b->info.pStencilAttachment = &b->stencil;
        a.stencil_view = b->stencil.imageView;
    }
    record(d, cb, Op::BeginRendering, a,
           [b](const DeviceTable& t, VkCommandBuffer c) { t.CmdBeginRendering(c, &b->info); });
}

VKAPI_ATTR void VKAPI_CALL CmdEndRendering(VkCommandBuffer cb) {
    DeviceData& d = device_of(cb);
    d.t.CmdEndRendering(cb);
    record(d, cb, Op::EndRendering, {},
           [](const DeviceTable& t, VkCommandBuffer c) { t.CmdEndRendering(c); });
}

template <typename Pfn, typename... Args>
void draw(VkCommandBuffer cb, DrawArgs a, Pfn DeviceTable::*fn, Args... args) {
    DeviceData& d = device_of(cb);
    (d.t.*fn)(cb, args...);
    record(d, cb, Op::Draw, a,
           [fn, args...](const DeviceTable& t, VkCommandBuffer c) { (t.*fn)(c, args...); });
}

VKAPI_ATTR void VKAPI_CALL CmdDraw(VkCommandBuffer cb, uint32_t n, uint32_t inst, uint32_t first,
                                   uint32_t first_inst) {
    draw(cb, {DrawKind::Draw, n, inst, first, 0, first_inst}, &DeviceTable::CmdDraw, n, inst, first, first_inst);
}
VKAPI_ATTR void VKAPI_CALL CmdDrawIndexed(VkCommandBuffer cb, uint32_t n, uint32_t inst,
                                          uint32_t first, int32_t offset, uint32_t first_inst) {
    draw(cb, {DrawKind::Indexed, n, inst, first, offset, first_inst}, &DeviceTable::CmdDrawIndexed, n, inst, first, offset,
         first_inst);
}
VKAPI_ATTR void VKAPI_CALL CmdDrawIndirect(VkCommandBuffer cb, VkBuffer b, VkDeviceSize o,
                                           uint32_t n, uint32_t stride) {
    draw(cb, {DrawKind::Indirect, n, 0, 0, 0, 0, b, o}, &DeviceTable::CmdDrawIndirect, b, o, n, stride);
}
VKAPI_ATTR void VKAPI_CALL CmdDrawIndexedIndirect(VkCommandBuffer cb, VkBuffer b, VkDeviceSize o,
                                                  uint32_t n, uint32_t stride) {
    draw(cb, {DrawKind::IndexedIndirect, n, 0, 0, 0, 0, b, o}, &DeviceTable::CmdDrawIndexedIndirect, b, o, n,
         stride);
}
VKAPI_ATTR void VKAPI_CALL CmdDrawIndirectCount(VkCommandBuffer cb, VkBuffer b, VkDeviceSize o,
                                                VkBuffer cb_buf, VkDeviceSize co, uint32_t n,
                                                uint32_t stride) {
    draw(cb, {DrawKind::IndirectCount, n, 0, 0, 0, 0, b, o}, &DeviceTable::CmdDrawIndirectCount, b, o, cb_buf,
         co, n, stride);
}
VKAPI_ATTR void VKAPI_CALL CmdDrawIndexedIndirectCount(VkCommandBuffer cb, VkBuffer b,
                                                       VkDeviceSize o, VkBuffer cb_buf,
                                                       VkDeviceSize co, uint32_t n,
                                                       uint32_t stride) {
    draw(cb, {DrawKind::IndexedIndirectCount, n, 0, 0, 0, 0, b, o}, &DeviceTable::CmdDrawIndexedIndirectCount, b,
         o, cb_buf, co, n, stride);
}

VKAPI_ATTR void VKAPI_CALL CmdClearAttachments(VkCommandBuffer cb, uint32_t n,
                                               const VkClearAttachment* a, uint32_t nr,
                                               const VkClearRect* r) {
    DeviceData& d = device_of(cb);
    d.t.CmdClearAttachments(cb, n, a, nr, r);
    record(d, cb, Op::Other, {},
           [a = copy(a, n), r = copy(r, nr)](const DeviceTable& t, VkCommandBuffer c) {
               t.CmdClearAttachments(c, uint32_t(a.size()), a.data(), uint32_t(r.size()),
                                     r.data());
           });
}

// A label's name and colour, owned.
struct Label {
    std::string name;
    std::array<float, 4> color;
    VkDebugUtilsLabelEXT info() const {
        return {VK_STRUCTURE_TYPE_DEBUG_UTILS_LABEL_EXT, nullptr, name.c_str(),
                {color[0], color[1], color[2], color[3]}};
    }
};
Label copy_label(const VkDebugUtilsLabelEXT* l) {
    return {l->pLabelName ? l->pLabelName : "",
            {l->color[0], l->color[1], l->color[2], l->color[3]}};
}

VKAPI_ATTR void VKAPI_CALL CmdBeginDebugUtilsLabelEXT(VkCommandBuffer cb,
                                                      const VkDebugUtilsLabelEXT* l) {
    DeviceData& d = device_of(cb);
    d.t.CmdBeginDebugUtilsLabelEXT(cb, l);
    Label label = copy_label(l);
    record(d, cb, Op::BeginLabel, LabelArgs{label.name},
           [label](const DeviceTable& t, VkCommandBuffer c) {
               const VkDebugUtilsLabelEXT info = label.info();
               t.CmdBeginDebugUtilsLabelEXT(c, &info);
           });
}
VKAPI_ATTR void VKAPI_CALL CmdEndDebugUtilsLabelEXT(VkCommandBuffer cb) {
    DeviceData& d = device_of(cb);
    d.t.CmdEndDebugUtilsLabelEXT(cb);
    record(d, cb, Op::EndLabel, {},
           [](const DeviceTable& t, VkCommandBuffer c) { t.CmdEndDebugUtilsLabelEXT(c); });
}
VKAPI_ATTR void VKAPI_CALL CmdInsertDebugUtilsLabelEXT(VkCommandBuffer cb,
                                                       const VkDebugUtilsLabelEXT* l) {
    DeviceData& d = device_of(cb);
    d.t.CmdInsertDebugUtilsLabelEXT(cb, l);
    Label label = copy_label(l);
    record(d, cb, Op::Other, {}, [label](const DeviceTable& t, VkCommandBuffer c) {
        const VkDebugUtilsLabelEXT info = label.info();
        t.CmdInsertDebugUtilsLabelEXT(c, &info);
    });
}

VKAPI_ATTR void VKAPI_CALL CmdBeginQuery(VkCommandBuffer cb, VkQueryPool p, uint32_t q,
                                         VkQueryControlFlags f) {
    DeviceData& d = device_of(cb);
    d.t.CmdBeginQuery(cb, p, q, f);
    record(d, cb, Op::Query, QueryArgs{p, q, true},
           [p, q, f](const DeviceTable& t, VkCommandBuffer c) { t.CmdBeginQuery(c, p, q, f); });
}
VKAPI_ATTR void VKAPI_CALL CmdEndQuery(VkCommandBuffer cb, VkQueryPool p, uint32_t q) {
    DeviceData& d = device_of(cb);
    d.t.CmdEndQuery(cb, p, q);
    record(d, cb, Op::Query, QueryArgs{p, q, false},
           [p, q](const DeviceTable& t, VkCommandBuffer c) { t.CmdEndQuery(c, p, q); });
}

VKAPI_ATTR void VKAPI_CALL CmdExecuteCommands(VkCommandBuffer cb, uint32_t n,
                                              const VkCommandBuffer* s) {
    DeviceData& d = device_of(cb);
    d.t.CmdExecuteCommands(cb, n, s);
    ExecuteArgs a{copy(s, n)};
    record(d, cb, Op::Execute, a, [a](const DeviceTable& t, VkCommandBuffer c) {
        t.CmdExecuteCommands(c, uint32_t(a.secondaries.size()), a.secondaries.data());
    });
}

VKAPI_ATTR void VKAPI_CALL CmdDispatch(VkCommandBuffer cb, uint32_t x, uint32_t y, uint32_t z) {
    plain(cb, &DeviceTable::CmdDispatch, x, y, z);
}
VKAPI_ATTR void VKAPI_CALL CmdDispatchIndirect(VkCommandBuffer cb, VkBuffer b, VkDeviceSize o) {
    plain(cb, &DeviceTable::CmdDispatchIndirect, b, o);
}
VKAPI_ATTR void VKAPI_CALL CmdDispatchBase(VkCommandBuffer cb, uint32_t bx, uint32_t by,
                                           uint32_t bz, uint32_t x, uint32_t y, uint32_t z) {
    plain(cb, &DeviceTable::CmdDispatchBase, bx, by, bz, x, y, z);
}
VKAPI_ATTR void VKAPI_CALL CmdResetQueryPool(VkCommandBuffer cb, VkQueryPool p, uint32_t first,
                                             uint32_t n) {
    plain(cb, &DeviceTable::CmdResetQueryPool, p, first, n);
}
VKAPI_ATTR void VKAPI_CALL CmdWriteTimestamp(VkCommandBuffer cb, VkPipelineStageFlagBits s,
                                             VkQueryPool p, uint32_t q) {
    plain(cb, &DeviceTable::CmdWriteTimestamp, s, p, q);
}
VKAPI_ATTR void VKAPI_CALL CmdWriteTimestamp2(VkCommandBuffer cb, VkPipelineStageFlags2 s,
                                              VkQueryPool p, uint32_t q) {
    plain(cb, &DeviceTable::CmdWriteTimestamp2, s, p, q);
}
VKAPI_ATTR void VKAPI_CALL CmdCopyQueryPoolResults(VkCommandBuffer cb, VkQueryPool p,
                                                   uint32_t first, uint32_t n, VkBuffer b,
                                                   VkDeviceSize o, VkDeviceSize stride,
                                                   VkQueryResultFlags f) {
    plain(cb, &DeviceTable::CmdCopyQueryPoolResults, p, first, n, b, o, stride, f);
}

}  // namespace

PFN_vkVoidFunction recorded_pass_command(const char* name) {
#define DS_X(fn) \
    if (std::strcmp(name, "vk" #fn) == 0) return reinterpret_cast<PFN_vkVoidFunction>(&fn);
    DS_X(CmdBeginRenderPass)
    DS_X(CmdBeginRenderPass2)
    DS_X(CmdNextSubpass)
    DS_X(CmdNextSubpass2)
    DS_X(CmdEndRenderPass)
    DS_X(CmdEndRenderPass2)
    DS_X(CmdBeginRendering)
    DS_X(CmdEndRendering)
    DS_X(CmdDraw)
    DS_X(CmdDrawIndexed)
    DS_X(CmdDrawIndirect)
    DS_X(CmdDrawIndexedIndirect)
    DS_X(CmdDrawIndirectCount)
    DS_X(CmdDrawIndexedIndirectCount)
    DS_X(CmdClearAttachments)
    DS_X(CmdBeginDebugUtilsLabelEXT)
    DS_X(CmdEndDebugUtilsLabelEXT)
    DS_X(CmdInsertDebugUtilsLabelEXT)
    DS_X(CmdBeginQuery)
    DS_X(CmdEndQuery)
    DS_X(CmdExecuteCommands)
    DS_X(CmdDispatch)
    DS_X(CmdDispatchIndirect)
    DS_X(CmdDispatchBase)
    DS_X(CmdResetQueryPool)
    DS_X(CmdWriteTimestamp)
    DS_X(CmdWriteTimestamp2)
    DS_X(CmdCopyQueryPoolResults)
#undef DS_X
    return nullptr;
}

}  // namespace ds::layer
