#pragma once
// Subpass groups (seed 002): consecutive graphics passes that assign_subpasses() put in one
// group are planned as one VkRenderPass. The pure half, like plan.h: no
// Vulkan calls, so unit tests check it without a device and dump() prints what execute()
// records.
//
// - Attachments: every image a pass of the group attaches (colour, depth, resolve, input), in
//   first-declaration order (so the group's first colour attachment is attachment 0: seed
//   002's "light first"). Each one's layout in a subpass is the plan's layout for that pass;
//   the render pass goes from the first to the last of them itself (initialLayout is the
//   first, finalLayout the last), so the graph's own barriers stop at the group's edges.
// - Load op: CLEAR where the first pass using it declared Load::Clear, LOAD where it holds
//   something (written earlier this frame, or an import / history that arrives with
//   contents), else DONT_CARE (rendering.h's rule). Store op: STORE where anything after the group
//   uses it (a later pass, an import's final state, a history image), else DONT_CARE.
// - Transient: an image the graph owns that nothing outside the group touches lives in tile
//   memory only: TRANSIENT_ATTACHMENT usage (no TRANSFER_SRC: nothing can read it back) and
//   LAZILY_ALLOCATED memory where the device has it.
// - Dependencies: one per pair of subpasses that share an attachment, BY_REGION, with the
//   stages and accesses of both uses (for seed 002's layout exactly the seed's masks).
// - Barriers: a group's passes get no barriers of their own. Those that bring a resource into
//   its first use inside the group are recorded before the render pass begins; those between
//   two subpasses are the dependencies above. A non-attachment resource written by one
//   subpass and used by a later one cannot be synchronised inside a render pass: compile()
//   throws.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "renderer/graph/plan.h"

namespace ds::graph {

struct GroupAttachment {
    uint32_t resource = kNoResource;
    VkAttachmentLoadOp load = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    VkAttachmentStoreOp store = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    VkImageLayout initial = VK_IMAGE_LAYOUT_UNDEFINED;
    VkImageLayout final = VK_IMAGE_LAYOUT_UNDEFINED;
    VkClearValue clear{};
    bool transient = false;  // used by this group only: tile memory
};

struct AttachmentRef {
    uint32_t attachment = 0;  // index into GroupPlan::attachments
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
};

struct SubpassPlan {
    std::vector<uint32_t> passes;  // graph pass indices, in order
    std::vector<AttachmentRef> colors;
    std::vector<AttachmentRef> inputs;    // input_attachment_index = position
    std::vector<AttachmentRef> resolves;  // empty, or one per colour (i-th resolves i-th)
    std::optional<AttachmentRef> depth;
    bool depth_read_only = false;
};

struct SubpassDependency {
    uint32_t src = 0, dst = 0;  // subpass indices
    VkPipelineStageFlags2 src_stages = 0, dst_stages = 0;
    VkAccessFlags2 src_access = 0, dst_access = 0;
    bool by_region = true;
};

struct GroupPlan {
    std::string name;
    uint32_t first_pass = 0, last_pass = 0;  // graph pass indices, inclusive
    VkExtent2D extent{0, 0};
    std::vector<GroupAttachment> attachments;
    std::vector<SubpassPlan> subpasses;
    std::vector<SubpassDependency> dependencies;
    std::vector<Barrier> barriers;  // before the render pass begins
};

// compile()'s first step: sets each pass's PassInfo::group and ::subpass. A pass that asked
// for a render pass of its own (PassBuilder::render_pass) is a group of one, named after it.
// With a `group` name (RenderGraph::plan_subpasses), each run of two or more consecutive
// graphics passes rendering to the same depth image becomes one group (`group`, then
// `group#2`, ...); in it a pass starts the next subpass where it reads an input attachment
// that the current subpass writes, where its depth use (written or read-only) differs, or
// where its colour slots do. Passes plan nothing themselves: the same declarations render
// alone or as subpasses.
void assign_subpasses(std::span<PassInfo> passes, std::span<const ResourceInfo> resources,
                      const std::string& group);

// The groups of `passes` (in pass order), without layouts yet: which resources are
// transient. Throws ds::Error for a malformed group (a group name that comes back after
// another pass, subpass indices that go back or skip, attachments of different sizes, an
// input attachment outside a group, a depth resolve).
std::vector<GroupPlan> find_subpass_groups(std::span<const ResourceInfo> resources,
                                           std::span<const PassInfo> passes);

// Each group attachment's last use in its group, where the store op writes it.
std::vector<StoreWrite> store_writes(std::span<const GroupPlan> groups,
                                     std::span<const PassInfo> passes);

// Completes each group from the frame's barrier plan (layouts, load/store ops, dependencies)
// and moves the barriers of the group's passes to the group (GroupPlan::barriers) or drops
// them (subpass dependencies). Throws ds::Error for an in-group dependency the render pass
// cannot express.
void plan_subpass_groups(std::vector<GroupPlan>& groups, std::span<const ResourceInfo> resources,
                         std::span<const PassInfo> passes, BarrierPlan& plan);

// The group a pass belongs to (index into `groups`), or -1.
int group_of(std::span<const GroupPlan> groups, uint32_t pass);

const char* load_op_name(VkAttachmentLoadOp op);    // "clear", "load", "dont_care"
const char* store_op_name(VkAttachmentStoreOp op);  // "store", "dont_care"

}  // namespace ds::graph
