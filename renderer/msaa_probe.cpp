#include "renderer/msaa_probe.h"

#include <cstring>

#include "renderer/passes/compute_kernel.h"
#include "renderer/shader/compiler.h"
#include "renderer/vk/barrier.h"
#include "renderer/vk/check.h"
#include "renderer/vk/context.h"

namespace ds {
namespace {

constexpr VkDeviceSize kHeaderBytes = 16;  // edge_pixels + padding (std430 array alignment)

struct Push {
    uint32_t width, height;
    int32_t samples, copy_depth;
};

}  // namespace

MsaaProbe::MsaaProbe(vk::Context& context, shader::Compiler& compiler) : context_(context) {
    nearest_ = vk::nearest_clamp_sampler(context, "msaa probe nearest");
    const VkDescriptorSetLayoutBinding bindings[] = {
        vk::layout_binding(0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                           VK_SHADER_STAGE_COMPUTE_BIT),
        vk::layout_binding(1, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                           VK_SHADER_STAGE_COMPUTE_BIT),
        vk::layout_binding(2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT)};
    set_layout_ = vk::DescriptorSetLayout(context, bindings, "msaa probe set");
    const VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 2},
                                          {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1}};
    pool_ = vk::DescriptorPool(context, 1, sizes, "msaa probe");
    set_ = pool_.allocate(set_layout_.handle());
    const VkDescriptorSetLayout sets[] = {set_layout_.handle()};
    const VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(Push)};
    layout_ = vk::PipelineLayout(context, sets, {&push, 1}, "msaa probe layout");
    pipeline_ = vk::create_compute_pipeline(
        context, layout_.handle(),
        compiler.compile("msaa_probe.comp", shader::Stage::Compute).spirv, "msaa probe");
}

void MsaaProbe::record(VkCommandBuffer cmd, const vk::Image& depth, const vk::Image& color,
                       bool copy_depth) {
    const uint32_t width = depth.width(), height = depth.height();
    const int32_t samples = int32_t(depth.samples());
    const VkDeviceSize values = VkDeviceSize(width) * height * uint32_t(samples);
    const VkDeviceSize bytes = kHeaderBytes + values * sizeof(float);
    if (!buffer_ || buffer_.size() < bytes)
        buffer_ = vk::Buffer(
            context_, {bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                       vk::MemoryUsage::Readback, "msaa probe"});
    depth_values_ = copy_depth ? values : 0;
    vk::DescriptorWriter writer;
    writer
        .image(0, depth.view(), nearest_.handle(), VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL)
        .image(1, color.view(), nearest_.handle(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL)
        .buffer(2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, buffer_.handle());
    writer.update(context_.device(), set_);

    vkCmdFillBuffer(cmd, buffer_.handle(), 0, kHeaderBytes, 0);
    vk::memory_barrier(cmd, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                       VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                       VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_.handle());
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_.handle(), 0, 1, &set_, 0,
                            nullptr);
    const Push push{width, height, samples, copy_depth ? 1 : 0};
    vkCmdPushConstants(cmd, layout_.handle(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push, &push);
    vkCmdDispatch(cmd, passes::group_count(width), passes::group_count(height), 1);
    vk::memory_barrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                       VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_HOST_BIT,
                       VK_ACCESS_2_HOST_READ_BIT);
}

uint64_t MsaaProbe::edge_pixels() const {
    buffer_.invalidate();
    uint32_t edges = 0;
    std::memcpy(&edges, buffer_.mapped(), sizeof edges);
    return edges;
}

std::vector<float> MsaaProbe::depth_samples() const {
    std::vector<float> out(depth_values_);
    if (out.empty()) return out;
    buffer_.invalidate();
    std::memcpy(out.data(), buffer_.mapped() + kHeaderBytes, out.size() * sizeof(float));
    return out;
}

}  // namespace ds
