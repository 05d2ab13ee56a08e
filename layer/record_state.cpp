// Recording of the commands that set state: pipelines, descriptor sets, buffers, dynamic state.
#include <array>
#include <cstring>

#include "layer/record.h"

namespace ds::layer {

namespace {

VKAPI_ATTR void VKAPI_CALL CmdBindPipeline(VkCommandBuffer cb, VkPipelineBindPoint bp,
                                           VkPipeline p) {
    DeviceData& d = device_of(cb);
    d.t.CmdBindPipeline(cb, bp, p);
    record(d, cb, Op::BindPipeline, BindPipelineArgs{bp, p},
           [bp, p](const DeviceTable& t, VkCommandBuffer c) { t.CmdBindPipeline(c, bp, p); });
}

VKAPI_ATTR void VKAPI_CALL CmdSetViewport(VkCommandBuffer cb, uint32_t first, uint32_t n,
                                          const VkViewport* v) {
    DeviceData& d = device_of(cb);
    d.t.CmdSetViewport(cb, first, n, v);
    record(d, cb, Op::State, {}, [first, v = copy(v, n)](const DeviceTable& t, VkCommandBuffer c) {
        t.CmdSetViewport(c, first, uint32_t(v.size()), v.data());
    });
}

VKAPI_ATTR void VKAPI_CALL CmdSetScissor(VkCommandBuffer cb, uint32_t first, uint32_t n,
                                         const VkRect2D* r) {
    DeviceData& d = device_of(cb);
    d.t.CmdSetScissor(cb, first, n, r);
    record(d, cb, Op::State, {}, [first, r = copy(r, n)](const DeviceTable& t, VkCommandBuffer c) {
        t.CmdSetScissor(c, first, uint32_t(r.size()), r.data());
    });
}

VKAPI_ATTR void VKAPI_CALL CmdSetViewportWithCount(VkCommandBuffer cb, uint32_t n,
                                                   const VkViewport* v) {
    DeviceData& d = device_of(cb);
    d.t.CmdSetViewportWithCount(cb, n, v);
    record(d, cb, Op::State, {}, [v = copy(v, n)](const DeviceTable& t, VkCommandBuffer c) {
        t.CmdSetViewportWithCount(c, uint32_t(v.size()), v.data());
    });
}

VKAPI_ATTR void VKAPI_CALL CmdSetScissorWithCount(VkCommandBuffer cb, uint32_t n,
                                                  const VkRect2D* r) {
    DeviceData& d = device_of(cb);
    d.t.CmdSetScissorWithCount(cb, n, r);
    record(d, cb, Op::State, {}, [r = copy(r, n)](const DeviceTable& t, VkCommandBuffer c) {
        t.CmdSetScissorWithCount(c, uint32_t(r.size()), r.data());
    });
}

VKAPI_ATTR void VKAPI_CALL CmdSetLineWidth(VkCommandBuffer cb, float w) {
    plain_state(cb, &DeviceTable::CmdSetLineWidth, w);
}
VKAPI_ATTR void VKAPI_CALL CmdSetDepthBias(VkCommandBuffer cb, float c, float clamp, float s) {
    plain_state(cb, &DeviceTable::CmdSetDepthBias, c, clamp, s);
}
VKAPI_ATTR void VKAPI_CALL CmdSetBlendConstants(VkCommandBuffer cb, const float k[4]) {
    DeviceData& d = device_of(cb);
    d.t.CmdSetBlendConstants(cb, k);
    std::array<float, 4> v{k[0], k[1], k[2], k[3]};
    record(d, cb, Op::State, {},
           [v](const DeviceTable& t, VkCommandBuffer c) { t.CmdSetBlendConstants(c, v.data()); });
}
VKAPI_ATTR void VKAPI_CALL CmdSetDepthBounds(VkCommandBuffer cb, float lo, float hi) {
    plain_state(cb, &DeviceTable::CmdSetDepthBounds, lo, hi);
}
VKAPI_ATTR void VKAPI_CALL CmdSetStencilCompareMask(VkCommandBuffer cb, VkStencilFaceFlags f,
                                                    uint32_t m) {
    plain_state(cb, &DeviceTable::CmdSetStencilCompareMask, f, m);
}
VKAPI_ATTR void VKAPI_CALL CmdSetStencilWriteMask(VkCommandBuffer cb, VkStencilFaceFlags f,
                                                  uint32_t m) {
    plain_state(cb, &DeviceTable::CmdSetStencilWriteMask, f, m);
}
VKAPI_ATTR void VKAPI_CALL CmdSetStencilReference(VkCommandBuffer cb, VkStencilFaceFlags f,
                                                  uint32_t r) {
    plain_state(cb, &DeviceTable::CmdSetStencilReference, f, r);
}

VKAPI_ATTR void VKAPI_CALL CmdBindDescriptorSets(VkCommandBuffer cb, VkPipelineBindPoint bp,
                                                 VkPipelineLayout layout, uint32_t first,
                                                 uint32_t n, const VkDescriptorSet* sets,
                                                 uint32_t n_offsets, const uint32_t* offsets) {
    DeviceData& d = device_of(cb);
    d.t.CmdBindDescriptorSets(cb, bp, layout, first, n, sets, n_offsets, offsets);
    BindSetsArgs a{bp, layout, first, copy(sets, n), copy(offsets, n_offsets)};
    record(d, cb, Op::BindSets, a, [a](const DeviceTable& t, VkCommandBuffer c) {
        t.CmdBindDescriptorSets(c, a.bind_point, a.layout, a.first_set, uint32_t(a.sets.size()),
                                a.sets.data(), uint32_t(a.dynamic_offsets.size()),
                                data_or_null(a.dynamic_offsets));
    });
}

VKAPI_ATTR void VKAPI_CALL CmdBindIndexBuffer(VkCommandBuffer cb, VkBuffer b, VkDeviceSize o,
                                              VkIndexType type) {
    DeviceData& d = device_of(cb);
    d.t.CmdBindIndexBuffer(cb, b, o, type);
    record(d, cb, Op::State, IndexBufferArgs{b, o, type},
           [b, o, type](const DeviceTable& t, VkCommandBuffer c) {
               t.CmdBindIndexBuffer(c, b, o, type);
           });
}

VKAPI_ATTR void VKAPI_CALL CmdBindVertexBuffers(VkCommandBuffer cb, uint32_t first, uint32_t n,
                                                const VkBuffer* b, const VkDeviceSize* o) {
    DeviceData& d = device_of(cb);
    d.t.CmdBindVertexBuffers(cb, first, n, b, o);
    record(d, cb, Op::State, VertexBuffersArgs{first, copy(b, n), copy(o, n)},
           [first, b = copy(b, n), o = copy(o, n)](const DeviceTable& t, VkCommandBuffer c) {
               t.CmdBindVertexBuffers(c, first, uint32_t(b.size()), b.data(), o.data());
           });
}

VKAPI_ATTR void VKAPI_CALL CmdBindVertexBuffers2(VkCommandBuffer cb, uint32_t first, uint32_t n,
                                                 const VkBuffer* b, const VkDeviceSize* o,
                                                 const VkDeviceSize* sizes,
                                                 const VkDeviceSize* strides) {
    DeviceData& d = device_of(cb);
    d.t.CmdBindVertexBuffers2(cb, first, n, b, o, sizes, strides);
    record(d, cb, Op::State, VertexBuffersArgs{first, copy(b, n), copy(o, n)},
           [first, n, b = copy(b, n), o = copy(o, n), s = copy(sizes, n),
            st = copy(strides, n)](const DeviceTable& t, VkCommandBuffer c) {
               t.CmdBindVertexBuffers2(c, first, n, b.data(), o.data(), data_or_null(s),
                                       data_or_null(st));
           });
}

VKAPI_ATTR void VKAPI_CALL CmdPushConstants(VkCommandBuffer cb, VkPipelineLayout layout,
                                            VkShaderStageFlags stages, uint32_t offset,
                                            uint32_t size, const void* values) {
    DeviceData& d = device_of(cb);
    d.t.CmdPushConstants(cb, layout, stages, offset, size, values);
    std::vector<uint8_t> bytes(size);
    std::memcpy(bytes.data(), values, size);
    record(d, cb, Op::State, {},
           [layout, stages, offset, bytes](const DeviceTable& t, VkCommandBuffer c) {
               t.CmdPushConstants(c, layout, stages, offset, uint32_t(bytes.size()),
                                  bytes.data());
           });
}

VKAPI_ATTR void VKAPI_CALL CmdSetDeviceMask(VkCommandBuffer cb, uint32_t mask) {
    plain_state(cb, &DeviceTable::CmdSetDeviceMask, mask);
}
VKAPI_ATTR void VKAPI_CALL CmdSetCullMode(VkCommandBuffer cb, VkCullModeFlags m) {
    plain_state(cb, &DeviceTable::CmdSetCullMode, m);
}
VKAPI_ATTR void VKAPI_CALL CmdSetFrontFace(VkCommandBuffer cb, VkFrontFace f) {
    plain_state(cb, &DeviceTable::CmdSetFrontFace, f);
}
VKAPI_ATTR void VKAPI_CALL CmdSetPrimitiveTopology(VkCommandBuffer cb, VkPrimitiveTopology p) {
    plain_state(cb, &DeviceTable::CmdSetPrimitiveTopology, p);
}
VKAPI_ATTR void VKAPI_CALL CmdSetDepthCompareOp(VkCommandBuffer cb, VkCompareOp op) {
    DeviceData& d = device_of(cb);
    d.t.CmdSetDepthCompareOp(cb, op);
    record(d, cb, Op::DynamicDepth, DynamicDepthArgs{DynamicDepthArgs::CompareOp, uint32_t(op)},
           [op](const DeviceTable& t, VkCommandBuffer c) { t.CmdSetDepthCompareOp(c, op); });
}
VKAPI_ATTR void VKAPI_CALL CmdSetStencilOp(VkCommandBuffer cb, VkStencilFaceFlags f,
                                           VkStencilOp fail, VkStencilOp pass,
                                           VkStencilOp depth_fail, VkCompareOp op) {
    plain_state(cb, &DeviceTable::CmdSetStencilOp, f, fail, pass, depth_fail, op);
}
VKAPI_ATTR void VKAPI_CALL CmdSetRasterizerDiscardEnable(VkCommandBuffer cb, VkBool32 e) {
    plain_state(cb, &DeviceTable::CmdSetRasterizerDiscardEnable, e);
}
VKAPI_ATTR void VKAPI_CALL CmdSetDepthBiasEnable(VkCommandBuffer cb, VkBool32 e) {
    plain_state(cb, &DeviceTable::CmdSetDepthBiasEnable, e);
}
VKAPI_ATTR void VKAPI_CALL CmdSetPrimitiveRestartEnable(VkCommandBuffer cb, VkBool32 e) {
    plain_state(cb, &DeviceTable::CmdSetPrimitiveRestartEnable, e);
}

// The depth and stencil switches the measurement draw turns off and back on.
template <typename Pfn>
void dynamic_depth(VkCommandBuffer cb, Pfn DeviceTable::*fn, DynamicDepthArgs::Which which,
                   VkBool32 value) {
    DeviceData& d = device_of(cb);
    (d.t.*fn)(cb, value);
    record(d, cb, Op::DynamicDepth, DynamicDepthArgs{which, value},
           [fn, value](const DeviceTable& t, VkCommandBuffer c) { (t.*fn)(c, value); });
}
VKAPI_ATTR void VKAPI_CALL CmdSetDepthTestEnable(VkCommandBuffer cb, VkBool32 e) {
    dynamic_depth(cb, &DeviceTable::CmdSetDepthTestEnable, DynamicDepthArgs::DepthTest, e);
}
VKAPI_ATTR void VKAPI_CALL CmdSetDepthWriteEnable(VkCommandBuffer cb, VkBool32 e) {
    dynamic_depth(cb, &DeviceTable::CmdSetDepthWriteEnable, DynamicDepthArgs::DepthWrite, e);
}
VKAPI_ATTR void VKAPI_CALL CmdSetStencilTestEnable(VkCommandBuffer cb, VkBool32 e) {
    dynamic_depth(cb, &DeviceTable::CmdSetStencilTestEnable, DynamicDepthArgs::StencilTest, e);
}
VKAPI_ATTR void VKAPI_CALL CmdSetDepthBoundsTestEnable(VkCommandBuffer cb, VkBool32 e) {
    dynamic_depth(cb, &DeviceTable::CmdSetDepthBoundsTestEnable,
                  DynamicDepthArgs::DepthBoundsTest, e);
}

}  // namespace

PFN_vkVoidFunction recorded_state_command(const char* name) {
#define DS_X(fn) \
    if (std::strcmp(name, "vk" #fn) == 0) return reinterpret_cast<PFN_vkVoidFunction>(&fn);
    DS_X(CmdBindPipeline)
    DS_X(CmdSetViewport)
    DS_X(CmdSetScissor)
    DS_X(CmdSetViewportWithCount)
    DS_X(CmdSetScissorWithCount)
    DS_X(CmdSetLineWidth)
    DS_X(CmdSetDepthBias)
    DS_X(CmdSetBlendConstants)
    DS_X(CmdSetDepthBounds)
    DS_X(CmdSetStencilCompareMask)
    DS_X(CmdSetStencilWriteMask)
    DS_X(CmdSetStencilReference)
    DS_X(CmdBindDescriptorSets)
    DS_X(CmdBindIndexBuffer)
    DS_X(CmdBindVertexBuffers)
    DS_X(CmdBindVertexBuffers2)
    DS_X(CmdPushConstants)
    DS_X(CmdSetDeviceMask)
    DS_X(CmdSetCullMode)
    DS_X(CmdSetFrontFace)
    DS_X(CmdSetPrimitiveTopology)
    DS_X(CmdSetDepthCompareOp)
    DS_X(CmdSetStencilOp)
    DS_X(CmdSetRasterizerDiscardEnable)
    DS_X(CmdSetDepthBiasEnable)
    DS_X(CmdSetPrimitiveRestartEnable)
    DS_X(CmdSetDepthTestEnable)
    DS_X(CmdSetDepthWriteEnable)
    DS_X(CmdSetStencilTestEnable)
    DS_X(CmdSetDepthBoundsTestEnable)
#undef DS_X
    return nullptr;
}

}  // namespace ds::layer
