#include "renderer/passes/pass_util.h"

#include <cstring>

#include "renderer/readback/host_readback.h"
#include "renderer/shader/compiler.h"
#include "renderer/vk/capabilities.h"
#include "renderer/vk/check.h"
#include "renderer/vk/context.h"
#include "renderer/vk/functions.h"

namespace ds::passes {

FrameDescriptorPool::FrameDescriptorPool(vk::Context& context, uint32_t max_sets,
                                         std::span<const VkDescriptorPoolSize> sizes,
                                         const char* name) {
    for (vk::DescriptorPool& pool : pools_)
        pool = vk::DescriptorPool(context, max_sets, sizes, name);
    frames_.fill(UINT64_MAX);
}

VkDescriptorSet FrameDescriptorPool::allocate(uint64_t frame_number, VkDescriptorSetLayout layout) {
    const size_t slot = frame_number % pools_.size();
    if (frames_[slot] != frame_number) {
        pools_[slot].reset_sets();
        frames_[slot] = frame_number;
    }
    return pools_[slot].allocate(layout);
}

ShaderStages compile_fullscreen(shader::Compiler& compiler, const char* fragment) {
    return {compiler.compile("fullscreen.vert", shader::Stage::Vertex).spirv,
            compiler.compile(fragment, shader::Stage::Fragment).spirv};
}

vk::Pipeline create_fullscreen(vk::Context& context, const FullscreenPipeline& p,
                               const ShaderStages& stages) {
    vk::GraphicsPipelineBuilder b;
    b.shader(VK_SHADER_STAGE_VERTEX_BIT, stages.vert)
        .shader(VK_SHADER_STAGE_FRAGMENT_BIT, stages.frag)
        .samples(p.samples)
        .layout(p.layout);
    if (p.color != VK_FORMAT_UNDEFINED) b.color_attachment(p.color);
    if (p.depth != VK_FORMAT_UNDEFINED) b.depth_attachment(p.depth);
    if (p.render_pass) b.render_pass(p.render_pass, p.subpass);
    return b.build(context, p.name);
}

VkRenderingAttachmentInfo attachment(VkImageView view, VkImageLayout layout,
                                     VkAttachmentLoadOp load, VkAttachmentStoreOp store) {
    auto a = vk::make<VkRenderingAttachmentInfo>(VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO);
    a.imageView = view;
    a.imageLayout = layout;
    a.loadOp = load;
    a.storeOp = store;
    return a;
}

VkRenderingAttachmentInfo color_attachment(VkImageView view, VkAttachmentLoadOp load,
                                           std::array<float, 4> clear) {
    VkRenderingAttachmentInfo a = attachment(view, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, load,
                                             VK_ATTACHMENT_STORE_OP_STORE);
    for (size_t i = 0; i < 4; ++i) a.clearValue.color.float32[i] = clear[i];
    return a;
}

VkRenderingAttachmentInfo resolving_color_attachment(VkImageView msaa, VkImageView resolve,
                                                     VkAttachmentLoadOp load,
                                                     VkAttachmentStoreOp store,
                                                     std::array<float, 4> clear) {
    VkRenderingAttachmentInfo a = color_attachment(msaa, load, clear);
    a.storeOp = store;
    a.resolveMode = VK_RESOLVE_MODE_AVERAGE_BIT;
    a.resolveImageView = resolve;
    a.resolveImageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    return a;
}

VkRenderingAttachmentInfo depth_attachment(VkImageView view, VkImageLayout layout,
                                           VkAttachmentLoadOp load, VkAttachmentStoreOp store,
                                           float clear_depth) {
    VkRenderingAttachmentInfo a = attachment(view, layout, load, store);
    a.clearValue.depthStencil = {clear_depth, 0};
    return a;
}

void begin_rendering(VkCommandBuffer cmd, VkExtent2D extent,
                     std::span<const VkRenderingAttachmentInfo> colors,
                     const VkRenderingAttachmentInfo* depth) {
    auto info = vk::make<VkRenderingInfo>(VK_STRUCTURE_TYPE_RENDERING_INFO);
    info.renderArea = {{0, 0}, extent};
    info.layerCount = 1;
    info.colorAttachmentCount = uint32_t(colors.size());
    info.pColorAttachments = colors.data();
    info.pDepthAttachment = depth;
    vk::fn().cmd_begin_rendering(cmd, &info);
    const VkViewport viewport{0.0f, 0.0f, float(extent.width), float(extent.height), 0.0f, 1.0f};
    const VkRect2D scissor{{0, 0}, extent};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
}

void set_depth_state(VkCommandBuffer cmd, bool test, bool write, VkCompareOp compare) {
    vk::fn().cmd_set_depth_test_enable(cmd, test ? VK_TRUE : VK_FALSE);
    vk::fn().cmd_set_depth_write_enable(cmd, write ? VK_TRUE : VK_FALSE);
    vk::fn().cmd_set_depth_compare_op(cmd, compare);
}

void draw_fullscreen_depth(graph::PassContext& ctx, graph::ImageHandle target, VkPipeline pipeline,
                           VkPipelineLayout layout, std::span<const VkDescriptorSet> sets,
                           std::span<const std::byte> push) {
    VkCommandBuffer cmd = ctx.cmd();
    // Every pixel is written, so the old contents are not needed.
    const VkRenderingAttachmentInfo depth =
        depth_attachment(ctx.view(target), ctx.layout(target), VK_ATTACHMENT_LOAD_OP_DONT_CARE,
                         VK_ATTACHMENT_STORE_OP_STORE);
    begin_rendering(cmd, ctx.extent(target), {}, &depth);
    // gl_FragDepth is only written with the test on: ALWAYS passes.
    set_depth_state(cmd, /*test=*/true, /*write=*/true, VK_COMPARE_OP_ALWAYS);
    vk::fn().cmd_set_cull_mode(cmd, VK_CULL_MODE_NONE);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 0, uint32_t(sets.size()),
                            sets.data(), 0, nullptr);
    vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_FRAGMENT_BIT, 0, uint32_t(push.size()),
                       push.data());
    vkCmdDraw(cmd, 3, 1, 0, 0);
    vk::fn().cmd_end_rendering(cmd);
}

void declare_hdr_over_depth(graph::PassBuilder& b, FrameResources& res, bool msaa, bool resolve) {
    if (!msaa) {
        b.read(res.depth, graph::Access::DepthReadOnly);
        b.write(res.hdr, graph::Access::ColorAttachment);
        return;
    }
    b.read(res.msaa_depth, graph::Access::DepthReadOnly);
    b.write(res.msaa_hdr, graph::Access::ColorAttachment);
    if (!resolve) return;
    res.hdr = b.create_image("hdr", {.format = kHdrFormat,
                                     .size = graph::ImageSize::relative(1.0f),
                                     .semantic = graph::Semantic::HdrColor});
    b.write(res.hdr, graph::Access::ResolveDst);
}

void begin_hdr_over_depth(graph::PassContext& ctx, const FrameResources& res, bool msaa,
                          bool resolve) {
    const VkAttachmentLoadOp load = VK_ATTACHMENT_LOAD_OP_LOAD;
    const VkRenderingAttachmentInfo color =
        !msaa     ? color_attachment(ctx.view(res.hdr), load)
        : resolve ? resolving_color_attachment(ctx.view(res.msaa_hdr), ctx.view(res.hdr), load,
                                               VK_ATTACHMENT_STORE_OP_STORE)
                  : color_attachment(ctx.view(res.msaa_hdr), load);
    const graph::ImageHandle depth_image = msaa ? res.msaa_depth : res.depth;
    const VkRenderingAttachmentInfo depth = depth_attachment(
        ctx.view(depth_image), ctx.layout(depth_image), load, VK_ATTACHMENT_STORE_OP_NONE);
    begin_rendering(ctx.cmd(), ctx.extent(msaa ? res.msaa_hdr : res.hdr), {&color, 1}, &depth);
}

vk::DescriptorSetLayout create_count_set_layout(vk::Context& context) {
    const VkDescriptorSetLayoutBinding bindings[] = {
        vk::layout_binding(0, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_SHADER_STAGE_FRAGMENT_BIT),
        vk::layout_binding(1, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_SHADER_STAGE_FRAGMENT_BIT),
        vk::layout_binding(2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_FRAGMENT_BIT),
        vk::layout_binding(3, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_SHADER_STAGE_FRAGMENT_BIT)};
    return vk::DescriptorSetLayout(context, bindings, "count set layout");
}

void add_count_defines(std::vector<shader::Define>& frag, std::vector<shader::Define>& vert,
                       const vk::Context& context, bool per_draw) {
    frag.push_back({"COUNT_FRAGMENTS", "1"});
    if (context.report().fragment_quad_operations) frag.push_back({"COUNT_QUADS", "1"});
    if (!per_draw) return;
    frag.push_back({"COUNT_DRAWS", "1"});
    vert.push_back({"COUNT_DRAWS", "1"});
}

std::vector<graph::ImageHandle> count_images(const FrameResources& res) {
    std::vector<graph::ImageHandle> out;
    for (const CountImages* c : res.all_counts())
        for (graph::ImageHandle h : {c->shaded, c->discarded, c->rasterized, c->quads})
            if (h.valid()) out.push_back(h);
    return out;
}

void declare_counts(graph::PassBuilder& builder, const CountImages& counts) {
    builder.write(counts.shaded, graph::Access::StorageReadWrite, graph::Shader::Fragment);
    builder.write(counts.discarded, graph::Access::StorageReadWrite, graph::Shader::Fragment);
    if (counts.quads.valid())
        builder.write(counts.quads, graph::Access::StorageReadWrite, graph::Shader::Fragment);
    if (counts.draws.valid())
        builder.write(counts.draws, graph::Access::StorageReadWrite, graph::Shader::Fragment);
}

void write_count_set(const graph::PassContext& ctx, VkDevice device, VkDescriptorSet set,
                     const CountImages& counts) {
    vk::DescriptorWriter writer;
    writer.storage_image(0, ctx.view(counts.shaded)).storage_image(1, ctx.view(counts.discarded));
    if (counts.draws.valid())
        writer.buffer(2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, ctx.buffer(counts.draws));
    if (counts.quads.valid()) writer.storage_image(3, ctx.view(counts.quads));
    writer.update(device, set);
}

void collect_counts(const HostReadback& readback, const CountImages& counts, PassResult& out) {
    out.shaded_fragments = readback.u32_sum(counts.shaded);
    out.discarded_fragments = readback.u32_sum(counts.discarded);
    out.rasterized_fragments = readback.u32_sum(counts.rasterized);
    if (counts.quads.valid()) out.quads = readback.u32_sum(counts.quads);
    if (!counts.draws.valid()) return;
    const std::span<const std::byte> bytes = readback.buffer_bytes(counts.draws);
    out.draw_shaded.resize(bytes.size() / sizeof(uint32_t));
    for (size_t i = 0; i < out.draw_shaded.size(); ++i) {
        uint32_t v;
        std::memcpy(&v, bytes.data() + i * sizeof v, sizeof v);
        out.draw_shaded[i] = v;
    }
    out.draw_shaded_in_view = counts.in_view;
}

ReadbackSet make_readback_set(vk::Context& context, uint32_t samplers, uint32_t push_size,
                              const std::string& name) {
    std::vector<VkDescriptorSetLayoutBinding> bindings;
    for (uint32_t i = 0; i < samplers; ++i)
        bindings.push_back(vk::layout_binding(i, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                                              VK_SHADER_STAGE_COMPUTE_BIT));
    bindings.push_back(vk::layout_binding(samplers, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                                          VK_SHADER_STAGE_COMPUTE_BIT));
    ReadbackSet r;
    r.set_layout = vk::DescriptorSetLayout(context, bindings, (name + " set").c_str());
    const VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, samplers},
                                          {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1}};
    r.pool = vk::DescriptorPool(context, 1, sizes, name.c_str());
    r.set = r.pool.allocate(r.set_layout.handle());
    const VkDescriptorSetLayout sets[] = {r.set_layout.handle()};
    const VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, push_size};
    r.layout = vk::PipelineLayout(context, sets, {&push, 1}, (name + " layout").c_str());
    return r;
}

std::string off_or_without_prepass(bool on, const FrameOptions& options, const char* knob) {
    if (!on) return std::string(knob) + "=off";
    if (options.subpass) return subpass_path_reason();
    return "prepass off";
}

std::string subpass_path_reason() {
    return "render_path=subpass: nothing runs between the subpasses, and tile memory holds no "
           "neighbours";
}

VkResolveModeFlagBits native_depth_resolve(const vk::DeviceReport& report, const FrameOptions& o) {
    const VkResolveModeFlagBits mode =
        o.reverse_z ? VK_RESOLVE_MODE_MAX_BIT : VK_RESOLVE_MODE_MIN_BIT;
    if (o.subpass) return VK_RESOLVE_MODE_NONE;
    return (report.depth_resolve_modes & mode) ? mode : VK_RESOLVE_MODE_NONE;
}

const char* depth_resolve_name(const vk::DeviceReport& report, const FrameOptions& o) {
    if (!native_depth_resolve(report, o)) return "shader";
    return o.reverse_z ? "native-max" : "native-min";
}

}  // namespace ds::passes
