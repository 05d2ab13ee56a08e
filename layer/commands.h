#pragma once
// What the layer keeps of each command buffer: a copy of every command recorded into it, so
// the captured frame can be recorded again with counting added (capture.h), and what --list
// shows (render passes, draws, labels) is read from the same copy.
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include <vulkan/vulkan.h>

#include "layer/dispatch.h"

namespace ds::layer {

// The application's command as it was recorded, replayed into any command buffer.
using Call = std::function<void(const DeviceTable&, VkCommandBuffer)>;

struct BindPipelineArgs {
    VkPipelineBindPoint bind_point;
    VkPipeline pipeline;
};
struct BindSetsArgs {
    VkPipelineBindPoint bind_point;
    VkPipelineLayout layout;
    uint32_t first_set;
    std::vector<VkDescriptorSet> sets;
    std::vector<uint32_t> dynamic_offsets;
};
struct RenderPassArgs {  // vkCmdBeginRenderPass(2)
    VkRenderPass render_pass;
    VkFramebuffer framebuffer;
    VkRect2D area;
    std::vector<VkImageView> attachments;  // an imageless framebuffer's views
};
struct RenderingArgs {  // vkCmdBeginRendering
    VkRect2D area;
    uint32_t layer_count;
    uint32_t view_mask;
    VkImageView depth_view;
    VkImageView stencil_view;
    std::vector<VkImageView> color_views;
    bool resuming;
    bool suspending;
};
enum class DrawKind : uint8_t { Draw, Indexed, Indirect, IndexedIndirect, IndirectCount, IndexedIndirectCount };
struct DrawArgs {
    DrawKind kind;
    uint32_t count;      // vertices or indices (direct), draws (indirect: the maximum)
    uint32_t instances;  // direct draws
    uint32_t first = 0;  // firstVertex or firstIndex (direct draws)
    int32_t vertex_offset = 0;
    uint32_t first_instance = 0;
    VkBuffer indirect = VK_NULL_HANDLE;  // indirect draws: the buffer and offset
    VkDeviceSize indirect_offset = 0;
    bool indexed() const {
        return kind == DrawKind::Indexed || kind == DrawKind::IndexedIndirect ||
               kind == DrawKind::IndexedIndirectCount;
    }
};
struct VertexBuffersArgs {  // vkCmdBindVertexBuffers(2)
    uint32_t first;
    std::vector<VkBuffer> buffers;
    std::vector<VkDeviceSize> offsets;
};
struct IndexBufferArgs {  // vkCmdBindIndexBuffer
    VkBuffer buffer;
    VkDeviceSize offset;
    VkIndexType type;
};
struct LabelArgs {
    std::string name;
};
struct QueryArgs {
    VkQueryPool pool;
    uint32_t query;
    bool begin;
};
// vkCmdSet{DepthTest,DepthWrite,StencilTest,DepthBoundsTest}Enable, vkCmdSetDepthCompareOp
struct DynamicDepthArgs {
    enum Which : uint8_t { DepthTest, DepthWrite, StencilTest, DepthBoundsTest, CompareOp } which;
    uint32_t value;  // a VkBool32, or a VkCompareOp
};
struct ExecuteArgs {
    std::vector<VkCommandBuffer> secondaries;
};

enum class Op : uint8_t {
    Other,  // replayed as recorded
    State,  // replayed as recorded; sets state only (viewport, buffers, push constants, ...)
    BindPipeline,
    BindSets,
    BeginRenderPass,
    NextSubpass,
    EndRenderPass,
    BeginRendering,
    EndRendering,
    Draw,
    BeginLabel,
    EndLabel,
    Query,
    DynamicDepth,
    Execute,
};

using Payload = std::variant<std::monostate, BindPipelineArgs, BindSetsArgs, RenderPassArgs,
                             RenderingArgs, DrawArgs, LabelArgs, QueryArgs, DynamicDepthArgs,
                             ExecuteArgs, VertexBuffersArgs, IndexBufferArgs>;

struct Command {
    Op op = Op::Other;
    Call call;
    Payload payload;
};

// One command buffer as the layer knows it.
struct CommandBufferState {
    VkDevice device = VK_NULL_HANDLE;
    VkCommandPool pool = VK_NULL_HANDLE;
    VkCommandBufferLevel level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    std::vector<Command> commands;
    // Why the copy is not faithful (a structure the layer cannot copy): the buffer is then
    // submitted as the application recorded it and never replayed.
    std::string unrecordable;
    void reset() {
        commands.clear();
        unrecordable.clear();
    }
};

}  // namespace ds::layer
