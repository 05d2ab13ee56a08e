#include "renderer/passes/depth_resolve.h"

#include "renderer/shader/compiler.h"
#include "renderer/vk/barrier.h"
#include "renderer/vk/capabilities.h"
#include "renderer/vk/check.h"
#include "renderer/vk/context.h"
#include "renderer/vk/functions.h"

namespace ds::passes {
namespace {

const VkDescriptorPoolSize kPoolSizes[] = {{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1}};
constexpr VkPipelineStageFlags2 kDepthTests =
    VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
constexpr VkAccessFlags2 kDepthAccess =
    VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;

}  // namespace

VkResolveModeFlagBits native_depth_resolve(const vk::DeviceReport& report, bool reverse_z) {
    const VkResolveModeFlagBits mode =
        reverse_z ? VK_RESOLVE_MODE_MAX_BIT : VK_RESOLVE_MODE_MIN_BIT;
    return (report.depth_resolve_modes & mode) ? mode : VK_RESOLVE_MODE_NONE;
}

const char* depth_resolve_name(const vk::DeviceReport& report, bool reverse_z) {
    if (!native_depth_resolve(report, reverse_z)) return "shader";
    return reverse_z ? "native-max" : "native-min";
}

DepthResolve::DepthResolve(const PassServices& services)
    : services_(services),
      nearest_(vk::nearest_clamp_sampler(services.context, "depth resolve nearest")),
      sets_(services.context, 1, kPoolSizes, "depth resolve sets"),
      pipelines_([this](uint32_t key) { return compile(key); },
                 [this](uint32_t key, const ShaderStages& s) { return create(key, s); }) {
    const VkDescriptorSetLayoutBinding binding = vk::layout_binding(
        0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT);
    set_layout_ = vk::DescriptorSetLayout(services.context, {&binding, 1}, "depth resolve set");
    const VkDescriptorSetLayout sets[] = {services.frame_layout, set_layout_.handle()};
    const VkPushConstantRange push{VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(int32_t)};
    layout_ = vk::PipelineLayout(services.context, sets, {&push, 1}, "depth resolve layout");
}

ShaderStages DepthResolve::compile(uint32_t) const {
    return {services_.compiler.compile("fullscreen.vert", shader::Stage::Vertex).spirv,
            services_.compiler.compile("depth_resolve.frag", shader::Stage::Fragment).spirv};
}

vk::Pipeline DepthResolve::create(uint32_t, const ShaderStages& s) const {
    vk::GraphicsPipelineBuilder b;
    return b.shader(VK_SHADER_STAGE_VERTEX_BIT, s.vert)
        .shader(VK_SHADER_STAGE_FRAGMENT_BIT, s.frag)
        .depth_attachment(services_.depth_format)
        .layout(layout_.handle())
        .build(services_.context, "depth resolve");
}

void DepthResolve::transition(VkCommandBuffer cmd, VkImage image, bool to_sampled) const {
    vk::ImageBarrier b{.image = image, .aspect = vk::aspect_flags(services_.depth_format)};
    if (to_sampled) {
        b.old_layout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
        b.new_layout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL;
        b.src_stage = kDepthTests;
        b.src_access = VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
        b.dst_stage = VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
        b.dst_access = VK_ACCESS_2_SHADER_SAMPLED_READ_BIT;
    } else {
        b.old_layout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL;
        b.new_layout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
        b.src_stage = VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
        b.src_access = VK_ACCESS_2_NONE;
        b.dst_stage = kDepthTests;
        b.dst_access = kDepthAccess;
    }
    vk::image_barrier(cmd, b);
}

void DepthResolve::record(VkCommandBuffer cmd, const FrameInputs& in, const Target& t) {
    const VkPipeline pipeline = pipelines_.get(0);
    transition(cmd, t.msaa_image, /*to_sampled=*/true);
    const VkDescriptorSet set = sets_.allocate(in.frame_number, set_layout_.handle());
    vk::DescriptorWriter writer;
    writer.image(0, t.msaa_view, nearest_.handle(),
                 VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL);
    writer.update(services_.context.device(), set);

    // Every pixel is written, so the old contents are not needed.
    const VkRenderingAttachmentInfo depth =
        depth_attachment(t.depth_view, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
                         VK_ATTACHMENT_LOAD_OP_DONT_CARE, VK_ATTACHMENT_STORE_OP_STORE);
    begin_rendering(cmd, t.extent, {}, &depth);
    // gl_FragDepth is only written with the test on: ALWAYS passes.
    set_depth_state(cmd, /*test=*/true, /*write=*/true, VK_COMPARE_OP_ALWAYS);
    vk::fn().cmd_set_cull_mode(cmd, VK_CULL_MODE_NONE);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
    const VkDescriptorSet sets[] = {in.frame_set, set};
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_.handle(), 0, 2, sets, 0,
                            nullptr);
    const int32_t samples = int32_t(t.samples);
    vkCmdPushConstants(cmd, layout_.handle(), VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof samples,
                       &samples);
    vkCmdDraw(cmd, 3, 1, 0, 0);
    vk::fn().cmd_end_rendering(cmd);
    transition(cmd, t.msaa_image, /*to_sampled=*/false);
}

}  // namespace ds::passes
