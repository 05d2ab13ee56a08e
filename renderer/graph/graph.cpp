#include "renderer/graph/graph.h"

#include <algorithm>
#include <ostream>

#include "renderer/common/error.h"
#include "renderer/format/format.h"
#include "renderer/graph/dump.h"
#include "renderer/graph/dump_json.h"
#include "renderer/vk/check.h"
#include "renderer/vk/context.h"
#include "renderer/vk/debug.h"
#include "renderer/vk/destroy_list.h"
#include "renderer/vk/functions.h"
#include "renderer/vk/image.h"

namespace ds::graph {
namespace {

bool same_extent(VkExtent2D a, VkExtent2D b) {
    return a.width == b.width && a.height == b.height;
}

ImageKey image_key(const std::string& name, const ResourceInfo& r) {
    return {name, r.image.format, r.extent, r.image.samples, r.image.mip_levels, r.usage};
}

}  // namespace

RenderGraph::RenderGraph(vk::Context& context)
    : context_(context), cache_(context), profiler_(context), render_passes_(context) {}

RenderGraph::~RenderGraph() = default;

void RenderGraph::begin_frame(VkExtent2D output, vk::DestroyList& retired) {
    if (output.width == 0 || output.height == 0)
        throw Error("render graph: output size " + std::to_string(output.width) + "x" +
                    std::to_string(output.height) + " is empty");
    // Relative images get new keys (so new images); history is lost whatever its size.
    if (!same_extent(output, output_)) cache_.invalidate_history();
    output_ = output;
    retired_ = &retired;
    resources_.clear();
    bindings_.clear();
    passes_.clear();
    records_.clear();
    histories_.clear();
    pass_data_.clear();
    plan_ = BarrierPlan{};
    groups_.clear();
    group_passes_.clear();
    prologues_.clear();
    renderings_.clear();
    targets_.clear();
    subpass_group_.clear();
    phase_ = Phase::Declaring;
}

void RenderGraph::require_declaring(const char* what) const {
    if (phase_ != Phase::Declaring)
        throw Error(std::string("render graph: ") + what +
                    " needs begin_frame() first (and not after compile())");
}

uint32_t RenderGraph::add_resource(ResourceInfo info) {
    require_declaring("declaring a resource");
    const auto same_name = [&](const ResourceInfo& r) { return r.name == info.name; };
    if (std::any_of(resources_.begin(), resources_.end(), same_name))
        throw Error("render graph: resource '" + info.name + "' declared twice in one frame");
    resources_.push_back(std::move(info));
    bindings_.emplace_back();
    return uint32_t(resources_.size() - 1);
}

const ResourceInfo& RenderGraph::resource(uint32_t index, bool image, const char* what) const {
    // The usual cause: a record lambda that copied a handle before setup assigned it.
    if (index >= resources_.size())
        throw Error(std::string("render graph: ") + what +
                    ": invalid handle (captured by value before setup assigned it?)");
    const ResourceInfo& r = resources_[index];
    if (r.is_image != image)
        throw Error(std::string("render graph: ") + what + ": '" + r.name + "' is not " +
                    (image ? "an image" : "a buffer"));
    return r;
}

ImageHandle RenderGraph::import_image(const std::string& name, const ExternalImage& image) {
    if (image.desc.size.is_relative())
        throw Error("render graph: imported image '" + name + "' needs a fixed size");
    ResourceInfo info;
    info.name = name;
    info.lifetime = Lifetime::External;
    info.image = image.desc;
    info.extent = image.desc.size.absolute;
    info.initial = ResourceState::from_external(image.initial);
    info.final = image.final;
    const uint32_t index = add_resource(std::move(info));
    bindings_[index].image = image.image;
    bindings_[index].view = image.view;
    bindings_[index].attachment_view = image.attachment_view;
    return {index};
}

void RenderGraph::bind_import(ImageHandle image, VkImage handle, VkImageView view,
                              VkImageView attachment_view) {
    require_declaring("bind_import");
    if (resource(image.index, true, "bind_import").lifetime != Lifetime::External)
        throw Error("render graph: bind_import on an image the graph owns");
    bindings_[image.index].image = handle;
    bindings_[image.index].view = view;
    bindings_[image.index].attachment_view = attachment_view;
}

BufferHandle RenderGraph::import_buffer(const std::string& name, const ExternalBuffer& buffer) {
    ResourceInfo info;
    info.name = name;
    info.lifetime = Lifetime::External;
    info.is_image = false;
    info.size = buffer.size;
    info.initial = ResourceState::from_external(buffer.initial);
    info.final = buffer.final;
    const uint32_t index = add_resource(std::move(info));
    bindings_[index].buffer = buffer.buffer;
    return {index};
}

void RenderGraph::plan_subpasses(std::string group) {
    require_declaring("plan_subpasses");
    subpass_group_ = std::move(group);
}

PassBuilder RenderGraph::begin_pass(const PassDecl& decl) {
    require_declaring("add_pass");
    PassInfo info;
    info.name = decl.name;
    info.kind = decl.kind;
    info.role = decl.role;
    passes_.push_back(std::move(info));
    records_.emplace_back();
    prologues_.emplace_back();
    return PassBuilder(*this, uint32_t(passes_.size() - 1));
}

void RenderGraph::compile() {
    require_declaring("compile");
    const std::vector<VkFlags> usage = derive_usage(resources_, passes_);
    for (size_t i = 0; i < resources_.size(); ++i) resources_[i].usage = usage[i];
    assign_subpasses(passes_, resources_, subpass_group_);
    groups_ = find_subpass_groups(resources_, passes_);
    // Tile memory only: attachment usages and TRANSIENT (no TRANSFER_SRC, no sampling).
    constexpr VkFlags kAttachmentUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT |
                                         VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT |
                                         VK_IMAGE_USAGE_INPUT_ATTACHMENT_BIT;
    for (const GroupPlan& g : groups_)
        for (const GroupAttachment& a : g.attachments)
            if (a.transient)
                resources_[a.resource].usage = (resources_[a.resource].usage & kAttachmentUsage) |
                                               VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT;
    realize_resources();
    plan_ = plan_barriers(resources_, passes_, store_writes(groups_, passes_));
    plan_subpass_groups(groups_, resources_, passes_, plan_);
    for (const GroupPlan& g : groups_) group_passes_.push_back(render_passes_.get(g, resources_));
    renderings_.resize(passes_.size());
    targets_.resize(passes_.size());
    for (uint32_t i = 0; i < passes_.size(); ++i) {
        if (passes_[i].renders() && passes_[i].group.empty())
            renderings_[i] = plan_rendering(i, resources_, passes_, plan_);
        targets_[i] = render_target(passes_[i], resources_);
        targets_[i].render_pass = render_pass_of(i);
        targets_[i].subpass = passes_[i].subpass;
    }
    phase_ = Phase::Compiled;
}

// Graph-owned resources get their cached images and buffers (new ones where a description
// changed) and start from the state the previous frame left them in.
void RenderGraph::realize_resources() {
    cache_.begin_frame();
    for (size_t i = 0; i < resources_.size(); ++i) {
        ResourceInfo& r = resources_[i];
        Binding& b = bindings_[i];
        if (r.lifetime != Lifetime::Transient) continue;
        if (r.is_image) {
            CachedImage& entry = cache_.image(image_key(r.name, r));
            b.image = entry.image.handle();
            b.view = entry.image.view();
            b.attachment_view = entry.image.attachment_view();
            b.lazily_allocated = entry.image.lazily_allocated();
            r.initial = entry.state.discarded();
            b.persistent = &entry.state;
        } else {
            CachedBuffer& entry = cache_.buffer({r.name, r.size, r.usage, r.memory});
            b.buffer = entry.buffer.handle();
            r.initial = entry.state;
            b.persistent = &entry.state;
        }
    }
    for (HistoryRequest& h : histories_) realize_history(h);
    cache_.retire_unused(*retired_);
}

void RenderGraph::realize_history(HistoryRequest& h) {
    ResourceInfo& previous = resources_[h.previous];
    ResourceInfo& current = resources_[h.current];
    // Both images take both roles in turn, so both get every usage either role needs.
    const VkFlags usage = previous.usage | current.usage;
    previous.usage = current.usage = usage;
    HistoryPair& pair = cache_.history(image_key(h.name, current));
    h.pair = &pair;
    const uint32_t p = pair.previous(), c = pair.current;
    bindings_[h.previous] = {pair.images[p].handle(),
                             pair.images[p].view(),
                             VK_NULL_HANDLE,
                             &pair.states[p],
                             false,
                             pair.images[p].attachment_view()};
    bindings_[h.current] = {pair.images[c].handle(),
                            pair.images[c].view(),
                            VK_NULL_HANDLE,
                            &pair.states[c],
                            false,
                            pair.images[c].attachment_view()};
    previous.history_valid = pair.valid;
    previous.initial = pair.valid ? pair.states[p] : pair.states[p].discarded();
    current.initial = pair.states[c].discarded();
}

void RenderGraph::record_barriers(VkCommandBuffer cmd, std::span<const Barrier> barriers) const {
    if (barriers.empty()) return;
    std::vector<VkImageMemoryBarrier2> images;
    std::vector<VkBufferMemoryBarrier2> buffers;
    for (const Barrier& b : barriers) {
        const ResourceInfo& r = resources_[b.resource];
        if (r.is_image) {
            auto v = vk::make<VkImageMemoryBarrier2>(VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2);
            v.srcStageMask = b.src_stages;
            v.srcAccessMask = b.src_access;
            v.dstStageMask = b.dst_stages;
            v.dstAccessMask = b.dst_access;
            v.oldLayout = b.old_layout;
            v.newLayout = b.new_layout;
            v.srcQueueFamilyIndex = v.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
            v.image = bindings_[b.resource].image;
            v.subresourceRange = {r.aspects(), 0, VK_REMAINING_MIP_LEVELS, 0,
                                  VK_REMAINING_ARRAY_LAYERS};
            images.push_back(v);
        } else {
            auto v = vk::make<VkBufferMemoryBarrier2>(VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2);
            v.srcStageMask = b.src_stages;
            v.srcAccessMask = b.src_access;
            v.dstStageMask = b.dst_stages;
            v.dstAccessMask = b.dst_access;
            v.srcQueueFamilyIndex = v.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
            v.buffer = bindings_[b.resource].buffer;
            v.size = VK_WHOLE_SIZE;
            buffers.push_back(v);
        }
    }
    auto dep = vk::make<VkDependencyInfo>(VK_STRUCTURE_TYPE_DEPENDENCY_INFO);
    dep.imageMemoryBarrierCount = uint32_t(images.size());
    dep.pImageMemoryBarriers = images.data();
    dep.bufferMemoryBarrierCount = uint32_t(buffers.size());
    dep.pBufferMemoryBarriers = buffers.data();
    vk::fn().cmd_pipeline_barrier2(cmd, &dep);
}

uint64_t RenderGraph::execute(VkCommandBuffer cmd) {
    if (phase_ != Phase::Compiled) throw Error("render graph: execute() needs compile() first");
    const uint64_t id = frames_++;
    std::vector<std::string> names;
    for (const PassInfo& p : passes_) names.push_back(p.name);
    profiler_.begin_frame(cmd, id, std::move(names), *retired_);
    // The whole frame under one label, so a tool that sees its commands can find it.
    vk::ScopedLabel frame_label(context_.debug(), cmd, "depthscope frame");
    for (uint32_t i = 0; i < passes_.size();) {
        const int group = group_of(groups_, i);
        if (group >= 0) {
            execute_group(cmd, uint32_t(group));
            i = groups_[size_t(group)].last_pass + 1;
            continue;
        }
        // The barriers sit inside the label, so a capture shows them under their pass.
        vk::ScopedLabel label(context_.debug(), cmd, passes_[i].name.c_str());
        record_barriers(cmd, plan_.passes[i].barriers);
        record_pass(cmd, i);
        ++i;
    }
    record_barriers(cmd, plan_.final_barriers);
    commit_states();
    phase_ = Phase::Executed;
    return id;
}

// A pass outside a subpass group: its prologue, then its rendering (if it renders) around
// its record lambda, inside its timestamps and statistics.
void RenderGraph::record_pass(VkCommandBuffer cmd, uint32_t pass) {
    const bool alone = passes_[pass].group.empty();
    const bool own_rendering = alone && passes_[pass].renders();
    if (alone)
        for (const auto& prologue : prologues_[pass]) prologue(cmd);
    profiler_.begin_pass(cmd, pass);
    if (own_rendering) begin_rendering(cmd, pass);
    PassContext ctx(*this, pass, cmd);
    if (records_[pass]) records_[pass](ctx);
    if (own_rendering) vk::fn().cmd_end_rendering(cmd);
    profiler_.end_pass(cmd, pass);
}

namespace {

VkRenderingAttachmentInfo rendering_attachment(const RenderingAttachment& a, VkImageView view,
                                               VkImageView resolve) {
    auto info = vk::make<VkRenderingAttachmentInfo>(VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO);
    if (a.resource == kNoResource) return info;  // an unused slot
    info.imageView = view;
    info.imageLayout = a.layout;
    info.loadOp = a.load;
    info.storeOp = a.store;
    info.clearValue = a.clear;
    if (a.resolve != kNoResource) {
        info.resolveMode = a.mode;
        info.resolveImageView = resolve;
        info.resolveImageLayout = a.resolve_layout;
    }
    return info;
}

}  // namespace

// vkCmdBeginRendering over the planned attachments; viewport and scissor cover the render
// area (dynamic state in every pipeline).
void RenderGraph::begin_rendering(VkCommandBuffer cmd, uint32_t pass) const {
    const RenderingPlan& r = renderings_[pass];
    auto attachment = [&](const RenderingAttachment& a) {
        const bool unused = a.resource == kNoResource;
        return rendering_attachment(
            a, unused ? VK_NULL_HANDLE : bindings_[a.resource].attached(),
            a.resolve == kNoResource ? VK_NULL_HANDLE : bindings_[a.resolve].attached());
    };
    std::vector<VkRenderingAttachmentInfo> colors;
    for (const RenderingAttachment& a : r.colors) colors.push_back(attachment(a));
    VkRenderingAttachmentInfo depth{};
    if (r.depth) depth = attachment(*r.depth);
    auto info = vk::make<VkRenderingInfo>(VK_STRUCTURE_TYPE_RENDERING_INFO);
    info.renderArea = {{0, 0}, r.extent};
    info.layerCount = 1;
    info.colorAttachmentCount = uint32_t(colors.size());
    info.pColorAttachments = colors.data();
    info.pDepthAttachment = r.depth ? &depth : nullptr;
    vk::fn().cmd_begin_rendering(cmd, &info);
    const VkViewport viewport{0.0f, 0.0f, float(r.extent.width), float(r.extent.height),
                              0.0f, 1.0f};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &info.renderArea);
}

// One render pass: its barriers first, then each subpass's passes in their own labels (and
// timestamps and statistics, which may sit inside a subpass).
void RenderGraph::execute_group(VkCommandBuffer cmd, uint32_t index) {
    const GroupPlan& g = groups_[index];
    vk::ScopedLabel label(context_.debug(), cmd, g.name.c_str());
    record_barriers(cmd, g.barriers);
    for (uint32_t p = g.first_pass; p <= g.last_pass; ++p)
        for (const auto& prologue : prologues_[p]) prologue(cmd);
    std::vector<VkImageView> views;
    for (const GroupAttachment& a : g.attachments)
        views.push_back(bindings_[a.resource].attached());
    render_passes_.begin(cmd, group_passes_[index], g, views, *retired_);
    for (uint32_t s = 0; s < g.subpasses.size(); ++s) {
        if (s > 0) {
            auto begin = vk::make<VkSubpassBeginInfo>(VK_STRUCTURE_TYPE_SUBPASS_BEGIN_INFO);
            begin.contents = VK_SUBPASS_CONTENTS_INLINE;
            const auto end = vk::make<VkSubpassEndInfo>(VK_STRUCTURE_TYPE_SUBPASS_END_INFO);
            vkCmdNextSubpass2(cmd, &begin, &end);
        }
        for (uint32_t p : g.subpasses[s].passes) {
            vk::ScopedLabel pass_label(context_.debug(), cmd, passes_[p].name.c_str());
            record_pass(cmd, p);
        }
    }
    const auto end = vk::make<VkSubpassEndInfo>(VK_STRUCTURE_TYPE_SUBPASS_END_INFO);
    vkCmdEndRenderPass2(cmd, &end);
}

VkRenderPass RenderGraph::render_pass_of(uint32_t pass) const {
    const int group = group_of(groups_, pass);
    return group < 0 ? VK_NULL_HANDLE : group_passes_[size_t(group)];
}

bool RenderGraph::lazily_allocated(ImageHandle image) const {
    resource(image.index, true, "lazily_allocated()");
    return bindings_[image.index].lazily_allocated;
}

// What this frame leaves behind is where the next one starts; history pairs swap roles once
// `current` was written.
void RenderGraph::commit_states() {
    for (size_t i = 0; i < resources_.size(); ++i)
        if (bindings_[i].persistent) *bindings_[i].persistent = plan_.end_states[i];
    for (const HistoryRequest& h : histories_) {
        const bool written = std::any_of(passes_.begin(), passes_.end(), [&](const PassInfo& p) {
            return std::any_of(p.accesses.begin(), p.accesses.end(), [&](const AccessInfo& a) {
                return a.resource == h.current && is_write(a.access);
            });
        });
        if (!written) continue;
        h.pair->current = h.pair->previous();
        h.pair->valid = true;
    }
}

std::vector<PassResult> RenderGraph::collect(uint64_t id) const {
    return profiler_.collect(id);
}

void RenderGraph::invalidate_history() {
    cache_.invalidate_history();
}

std::string RenderGraph::dump() const {
    return dump_graph(output_, resources_, passes_, plan_, groups_, renderings_);
}

nlohmann::json RenderGraph::dump_json() const {
    return graph_json(output_, resources_, passes_, plan_, groups_);
}

ImageHandle RenderGraph::find_image(std::string_view name) const {
    for (uint32_t i = 0; i < resources_.size(); ++i)
        if (resources_[i].is_image && resources_[i].name == name) return {i};
    return {};
}

VkImage RenderGraph::image(ImageHandle h) const {
    resource(h.index, true, "image()");
    return bindings_[h.index].image;
}

VkImageView RenderGraph::view(ImageHandle h) const {
    resource(h.index, true, "view()");
    return bindings_[h.index].view;
}

VkBuffer RenderGraph::buffer(BufferHandle h) const {
    resource(h.index, false, "buffer()");
    return bindings_[h.index].buffer;
}

std::ostream& operator<<(std::ostream& out, const RenderGraph& graph) {
    return out << graph.dump();
}

}  // namespace ds::graph
