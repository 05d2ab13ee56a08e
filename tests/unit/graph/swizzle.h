#pragma once
// A fullscreen-triangle pass for the tests: samples one image (texelFetch at the pixel) and
// writes it with red and blue swapped, so the output proves the pixels went through it.
#include "renderer/shader/compiler.h"
#include "renderer/vk/descriptors.h"
#include "renderer/vk/image.h"
#include "renderer/vk/pipeline.h"
#include "tests/unit/graph/graph_fixture.h"

namespace ds::graph::test {

inline constexpr VkFormat kSwizzleFormat = VK_FORMAT_R8G8B8A8_UNORM;

// Everything the swizzle pass needs that is not a graph resource.
struct Swizzle {
    VkDevice device;
    vk::DescriptorSetLayout set_layout;
    vk::PipelineLayout layout;
    vk::Pipeline pipeline;
    vk::DescriptorPool pool;
    VkDescriptorSet set = VK_NULL_HANDLE;
    vk::Sampler sampler;

    explicit Swizzle(vk::Context& context) : device(context.device()) {
        shader::Compiler compiler(DS_GRAPH_TEST_SHADERS, "");
        const auto vert = compiler.compile("fullscreen.vert", shader::Stage::Vertex).spirv;
        const auto frag = compiler.compile("swizzle.frag", shader::Stage::Fragment).spirv;
        const VkDescriptorSetLayoutBinding binding = vk::layout_binding(
            0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT);
        set_layout = vk::DescriptorSetLayout(context, {&binding, 1}, "swizzle set");
        const VkDescriptorSetLayout sets[] = {set_layout.handle()};
        layout = vk::PipelineLayout(context, sets, {}, "swizzle layout");
        pipeline = vk::GraphicsPipelineBuilder()
                       .shader(VK_SHADER_STAGE_VERTEX_BIT, vert)
                       .shader(VK_SHADER_STAGE_FRAGMENT_BIT, frag)
                       .color_attachment(kSwizzleFormat)
                       .layout(layout.handle())
                       .build(context, "swizzle");
        const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1};
        pool = vk::DescriptorPool(context, 1, {&size, 1}, "swizzle pool");
        set = pool.allocate(set_layout.handle());
        auto info = vk::make<VkSamplerCreateInfo>(VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO);
        info.magFilter = info.minFilter = VK_FILTER_NEAREST;
        info.addressModeU = info.addressModeV = info.addressModeW =
            VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
        sampler = vk::Sampler(context, info, "nearest");
    }

    // A fullscreen triangle into the pass's target (declared cleared to black) that samples
    // `source` in the layout the graph chose.
    void record(const PassContext& ctx, ImageHandle source) const {
        vk::DescriptorWriter writer;  // every earlier frame has finished: the set is free
        writer.image(0, ctx.view(source), sampler.handle(), ctx.layout(source));
        writer.update(device, set);
        VkCommandBuffer cmd = ctx.cmd();
        vk::fn().cmd_set_cull_mode(cmd, VK_CULL_MODE_NONE);
        vk::fn().cmd_set_depth_test_enable(cmd, VK_FALSE);
        vk::fn().cmd_set_depth_write_enable(cmd, VK_FALSE);
        vk::fn().cmd_set_depth_compare_op(cmd, VK_COMPARE_OP_ALWAYS);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline.handle());
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout.handle(), 0, 1, &set,
                                0, nullptr);
        vkCmdDraw(cmd, 3, 1, 0, 0);
    }
};

}  // namespace ds::graph::test
