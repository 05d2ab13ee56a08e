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

void apply_target(vk::GraphicsPipelineBuilder& b, const graph::RenderTarget& target,
                  vk::Blend blend) {
    for (size_t i = 0; i < target.colors.size(); ++i)
        b.color_attachment(target.colors[i], i == 0 ? blend : vk::Blend::None);
    if (target.depth != VK_FORMAT_UNDEFINED) b.depth_attachment(target.depth);
    if (target.render_pass) b.render_pass(target.render_pass, target.subpass);
}

vk::Pipeline create_fullscreen(vk::Context& context, const FullscreenPipeline& p,
                               const ShaderStages& stages, const graph::RenderTarget& target) {
    vk::GraphicsPipelineBuilder b;
    b.shader(VK_SHADER_STAGE_VERTEX_BIT, stages.vert)
        .shader(VK_SHADER_STAGE_FRAGMENT_BIT, stages.frag)
        .samples(p.samples)
        .layout(p.layout);
    apply_target(b, target);
    return b.build(context, p.name);
}

void set_depth_state(VkCommandBuffer cmd, bool test, bool write, VkCompareOp compare) {
    vk::fn().cmd_set_depth_test_enable(cmd, test ? VK_TRUE : VK_FALSE);
    vk::fn().cmd_set_depth_write_enable(cmd, write ? VK_TRUE : VK_FALSE);
    vk::fn().cmd_set_depth_compare_op(cmd, compare);
}

void declare_fullscreen_depth(graph::PassBuilder& b, graph::ImageHandle target) {
    b.depth(target, {.load = graph::Load::DontCare});  // every pixel is written
}

void draw_fullscreen_depth(VkCommandBuffer cmd, VkPipeline pipeline, VkPipelineLayout layout,
                           std::span<const VkDescriptorSet> sets, std::span<const std::byte> push) {
    // gl_FragDepth is only written with the test on: ALWAYS passes.
    set_depth_state(cmd, /*test=*/true, /*write=*/true, VK_COMPARE_OP_ALWAYS);
    vk::fn().cmd_set_cull_mode(cmd, VK_CULL_MODE_NONE);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 0, uint32_t(sets.size()),
                            sets.data(), 0, nullptr);
    vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_FRAGMENT_BIT, 0, uint32_t(push.size()),
                       push.data());
    vkCmdDraw(cmd, 3, 1, 0, 0);
}

void declare_hdr_over_depth(graph::PassBuilder& b, FrameResources& res, bool msaa, bool resolve) {
    b.depth(msaa ? res.msaa_depth : res.depth, {.read_only = true});
    b.color(msaa ? res.msaa_hdr : res.hdr);
    if (!msaa || !resolve) return;
    res.hdr = b.create_image("hdr", {.format = kHdrFormat,
                                     .size = graph::ImageSize::relative(1.0f),
                                     .semantic = graph::Semantic::HdrColor});
    b.resolve(res.msaa_hdr, res.hdr);
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
