#include "layer/summary.h"

namespace ds::layer {

namespace {

struct Walker {
    DeviceData& device;
    std::vector<PassSummary> passes;
    std::vector<std::string> labels;
    const RenderPassInfo* render_pass = nullptr;
    std::vector<VkImageView> attachments;  // the render pass instance's views
    bool in_pass = false;

    std::string label() const { return labels.empty() ? "" : labels.back(); }

    void subpass(uint32_t index, VkRect2D area) {
        PassSummary p;
        p.subpass = index;
        p.label = label();
        p.width = area.extent.width;
        p.height = area.extent.height;
        p.x = uint32_t(area.offset.x);
        p.y = uint32_t(area.offset.y);
        if (render_pass && index < render_pass->subpasses.size()) {
            p.view_mask = render_pass->subpasses[index].view_mask;
            const uint32_t depth = render_pass->subpasses[index].depth_attachment;
            if (depth != VK_ATTACHMENT_UNUSED && depth < render_pass->formats.size()) {
                p.depth_format = render_pass->formats[depth];
                p.samples = render_pass->samples[depth];
                if (depth < attachments.size()) p.depth_image = image_of(attachments[depth]);
            }
        }
        passes.push_back(p);
        in_pass = true;
    }

    // Under device.mutex.
    VkImage image_of(VkImageView view) const {
        auto it = device.views.find(view);
        return it == device.views.end() ? VK_NULL_HANDLE : it->second.image;
    }

    void begin_render_pass(const RenderPassArgs& a) {
        std::lock_guard lock(device.mutex);
        auto it = device.render_passes.find(a.render_pass);
        render_pass = it == device.render_passes.end() ? nullptr : &it->second;
        attachments = a.attachments;
        if (auto fb = device.framebuffers.find(a.framebuffer);
            attachments.empty() && fb != device.framebuffers.end())
            attachments = fb->second.views;
        subpass(0, a.area);
    }

    void begin_rendering(const RenderingArgs& a) {
        if (a.resuming && !passes.empty() && passes.back().dynamic) {
            in_pass = true;
            return;
        }
        PassSummary p;
        p.dynamic = true;
        p.label = label();
        p.width = a.area.extent.width;
        p.height = a.area.extent.height;
        p.x = uint32_t(a.area.offset.x);
        p.y = uint32_t(a.area.offset.y);
        p.view_mask = a.view_mask;
        if (a.depth_view != VK_NULL_HANDLE) {
            std::lock_guard lock(device.mutex);
            auto it = device.views.find(a.depth_view);
            if (it != device.views.end()) {
                p.depth_format = it->second.format;
                p.depth_image = it->second.image;
            }
        }
        passes.push_back(p);
        in_pass = true;
    }

    void step(const Command& c) {
        switch (c.op) {
            case Op::BeginRenderPass: begin_render_pass(std::get<RenderPassArgs>(c.payload)); break;
            case Op::NextSubpass:
                if (!passes.empty()) {
                    const PassSummary last = passes.back();
                    std::lock_guard lock(device.mutex);
                    subpass(last.subpass + 1,
                            {{int32_t(last.x), int32_t(last.y)}, {last.width, last.height}});
                }
                break;
            case Op::BeginRendering: begin_rendering(std::get<RenderingArgs>(c.payload)); break;
            case Op::EndRenderPass:
            case Op::EndRendering: in_pass = false; break;
            case Op::Draw:
                if (in_pass && !passes.empty()) ++passes.back().draws;
                break;
            case Op::BeginLabel: labels.push_back(std::get<LabelArgs>(c.payload).name); break;
            case Op::EndLabel:
                if (!labels.empty()) labels.pop_back();
                break;
            default: break;
        }
    }
};

}  // namespace

std::vector<PassSummary> summarize(DeviceData& device, const CommandBufferState& cb) {
    Walker w{device, {}, {}, nullptr, {}, false};
    for (const Command& c : cb.commands) w.step(c);
    return w.passes;
}

}  // namespace ds::layer
