#pragma once
// The pure half of compile(): declared passes and resources in, image layouts and
// synchronization2 barriers out. No Vulkan calls, so unit tests check it without a device,
// and dump() prints exactly what execute() records.
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "renderer/graph/access.h"
#include "renderer/graph/types.h"

namespace ds::graph {

struct StageAccess {
    VkPipelineStageFlags2 stages = VK_PIPELINE_STAGE_2_NONE;
    VkAccessFlags2 access = VK_ACCESS_2_NONE;
};

// What earlier users of a resource left behind: all the next barrier needs to know.
struct ResourceState {
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
    // The last write: its stages and accesses. After a layout transition for a read, the
    // stages are that barrier's destination (later barriers chain through them) and the
    // accesses are none (a transition's writes are made available automatically).
    VkPipelineStageFlags2 write_stages = VK_PIPELINE_STAGE_2_NONE;
    VkAccessFlags2 write_access = VK_ACCESS_2_NONE;
    VkPipelineStageFlags2 read_stages = VK_PIPELINE_STAGE_2_NONE;  // reads since that write
    std::vector<StageAccess> visible;  // where that write has been made visible already

    static ResourceState from_external(const ExternalState& state);
    // The same stages with contents discarded: how a transient starts the next frame (its
    // layout is UNDEFINED again, but the previous frame's accesses must still finish first).
    ResourceState discarded() const;
};

enum class HistoryRole : uint8_t { None, Previous, Current };

struct ResourceInfo {
    std::string name;
    Lifetime lifetime = Lifetime::Transient;
    bool is_image = true;
    ImageDesc image;                                    // images
    VkExtent2D extent{0, 0};                            // images: the resolved size
    VkDeviceSize size = 0;                              // buffers
    vk::MemoryUsage memory = vk::MemoryUsage::GpuOnly;  // graph-owned buffers
    VkFlags usage = 0;  // derived from the accesses (VkImage/VkBufferUsageFlags)
    HistoryRole history = HistoryRole::None;
    bool history_valid = false;  // Previous: holds last frame's contents
    ResourceState initial;
    std::optional<ExternalState> final;  // externals only

    bool depth() const;  // a depth/stencil format
    // The aspects the graph plans and transitions: every aspect of the format. A depth-stencil
    // image's stencil moves with its depth: its sampled view names depth alone, but every
    // rendering attaches a view of both (Binding::attachment_view), so a render pass's own
    // transitions move both aspects as the graph's barriers do (one layout, per image).
    VkImageAspectFlags aspects() const;
    bool multisampled() const { return is_image && image.samples != VK_SAMPLE_COUNT_1_BIT; }
};

struct AccessInfo {
    uint32_t resource = kNoResource;
    Access access = Access::Sampled;
    Shader shader = Shader::Default;
};

// One attachment of a graphics pass, in declaration order (PassBuilder::color, unused_color,
// depth, resolve, input): what the graph begins the rendering or the subpass with.
struct AttachmentDecl {
    enum class Kind : uint8_t { Color, UnusedColor, Depth, Resolve, Input };
    Kind kind = Kind::Color;
    uint32_t resource = kNoResource;        // UnusedColor: none
    VkFormat format = VK_FORMAT_UNDEFINED;  // UnusedColor: the slot's (pipelines see it)
    Load load = Load::Keep;
    VkClearValue clear{};
    bool read_only = false;  // Depth
    // Resolve: the attachment (resource) this one resolves, and how.
    uint32_t resolves = kNoResource;
    VkResolveModeFlagBits mode = VK_RESOLVE_MODE_NONE;
};

struct PassInfo {
    std::string name;
    PassKind kind = PassKind::Graphics;
    std::vector<AccessInfo> accesses;  // in declaration order
    PassRole role = PassRole::Frame;
    std::vector<AttachmentDecl> attachments;  // graphics passes that render
    VkExtent2D render_area{0, 0};  // rendering without attachments (PassBuilder::render_area)
    bool render_pass = false;      // a render pass of its own (PassBuilder::render_pass)
    // A subpass of a render pass (graph/subpass.h), as compile() planned it: consecutive passes
    // with the same group form one VkRenderPass; passes with the same index share a subpass.
    // Empty: on its own.
    std::string group;
    uint32_t subpass = 0;

    // Whether the graph begins a rendering (or a subpass) for it.
    bool renders() const { return !attachments.empty() || render_area.width != 0; }
};

struct Barrier {
    uint32_t resource = kNoResource;
    bool is_image = true;
    VkImageLayout old_layout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkImageLayout new_layout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkPipelineStageFlags2 src_stages = VK_PIPELINE_STAGE_2_NONE;
    VkAccessFlags2 src_access = VK_ACCESS_2_NONE;
    VkPipelineStageFlags2 dst_stages = VK_PIPELINE_STAGE_2_NONE;
    VkAccessFlags2 dst_access = VK_ACCESS_2_NONE;
};

// One resource as one pass uses it: all its accesses merged into one layout and one set of
// stages and accesses.
struct PassUse {
    uint32_t resource = kNoResource;
    Use use;
};

struct PassPlan {
    std::vector<Barrier> barriers;  // recorded as one vkCmdPipelineBarrier2 before the pass
    std::vector<PassUse> uses;      // per resource, in first-declaration order
};

struct BarrierPlan {
    std::vector<PassPlan> passes;
    std::vector<Barrier> final_barriers;    // after the last pass: externals' final states
    std::vector<ResourceState> end_states;  // per resource, after the final barriers
};

// A pass's accesses merged per resource. Sampled + depth read-only share the read-only depth
// layout; any other mix of layouts falls back to GENERAL (valid for all of them).
std::vector<PassUse> merge_uses(const PassInfo& pass, std::span<const ResourceInfo> resources);

// A render pass's store op writes each attachment after the last subpass that uses it
// (STORE and DONT_CARE alike): the plan counts that write into the resource's use there.
struct StoreWrite {
    uint32_t pass = kNoResource;
    uint32_t resource = kNoResource;
};

// Passes run in the given order (no reordering, no culling). A barrier is emitted for
// read-after-write, write-after-read, write-after-write and any layout change; none for a
// read after a read in the same layout that the last write is already visible to.
BarrierPlan plan_barriers(std::span<const ResourceInfo> resources, std::span<const PassInfo> passes,
                          std::span<const StoreWrite> store_writes = {});

// Usage flags of each resource from every access, plus TRANSFER_SRC (the capture layer can
// read any resource back).
std::vector<VkFlags> derive_usage(std::span<const ResourceInfo> resources,
                                  std::span<const PassInfo> passes);

}  // namespace ds::graph
