#include "renderer/passes/compute_kernel.h"

#include <algorithm>
#include <utility>

#include "renderer/common/error.h"
#include "renderer/vk/check.h"
#include "renderer/vk/context.h"

namespace ds::passes {
namespace {

VkDescriptorType descriptor_type(KernelBinding binding) {
    return binding == KernelBinding::Storage ? VK_DESCRIPTOR_TYPE_STORAGE_IMAGE
                                             : VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
}

}  // namespace

ComputeKernel::ComputeKernel(const PassServices& services, std::string shader,
                             std::vector<KernelBinding> bindings, uint32_t push_constant_size,
                             uint32_t dispatches)
    : context_(services.context),
      compiler_(services.compiler),
      shader_(std::move(shader)),
      bindings_(std::move(bindings)),
      push_constant_size_(push_constant_size),
      dispatches_(std::max(dispatches, 1u)) {
    if (services.frame_layout == VK_NULL_HANDLE)
        throw Error("compute pass " + shader_ + ": no frame set layout");
    // The shaders read with texelFetch; a combined image sampler still needs a sampler.
    nearest_ = vk::nearest_clamp_sampler(context_, "screen-space nearest");

    std::vector<VkDescriptorSetLayoutBinding> layout_bindings;
    uint32_t samplers = 0, storage = 0;
    for (uint32_t i = 0; i < bindings_.size(); ++i) {
        layout_bindings.push_back(
            vk::layout_binding(i, descriptor_type(bindings_[i]), VK_SHADER_STAGE_COMPUTE_BIT));
        (bindings_[i] == KernelBinding::Storage ? storage : samplers) += 1;
    }
    set_layout_ = vk::DescriptorSetLayout(context_, layout_bindings, shader_.c_str());

    const uint32_t set_count = vk::FrameRing::kFramesInFlight * dispatches_;
    std::vector<VkDescriptorPoolSize> sizes;
    if (samplers)
        sizes.push_back({VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, samplers * set_count});
    if (storage) sizes.push_back({VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, storage * set_count});
    pool_ = vk::DescriptorPool(context_, set_count, sizes, shader_.c_str());
    sets_.resize(set_count);
    for (VkDescriptorSet& set : sets_) set = pool_.allocate(set_layout_.handle());

    const VkDescriptorSetLayout sets[] = {services.frame_layout, set_layout_.handle()};
    const VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, push_constant_size_};
    layout_ = vk::PipelineLayout(
        context_, sets,
        push_constant_size_ ? std::span(&push, 1) : std::span<const VkPushConstantRange>(),
        shader_.c_str());
}

ComputeKernel::Prepared ComputeKernel::prepare(const std::vector<shader::Define>& defines) const {
    // SPIR-V 1.5 (the compiler's target) states the workgroup size as a literal LocalSize.
    const std::vector<uint32_t> spirv =
        compiler_.compile(shader_, shader::Stage::Compute, defines).spirv;
    return {vk::create_compute_pipeline(context_, layout_.handle(), spirv, shader_.c_str())};
}

void ComputeKernel::install(Prepared prepared, vk::DestroyList& retired) {
    if (pipeline_) retired.defer(std::move(pipeline_));
    pipeline_ = std::move(prepared.pipeline);
}

void ComputeKernel::write_set(VkDescriptorSet set, std::span<const BoundImage> images) const {
    if (images.size() != bindings_.size())
        throw Error("compute pass " + shader_ + ": " + std::to_string(images.size()) +
                    " images for " + std::to_string(bindings_.size()) + " bindings");
    std::vector<VkDescriptorImageInfo> infos(images.size());
    std::vector<VkWriteDescriptorSet> writes(images.size());
    for (uint32_t i = 0; i < images.size(); ++i) {
        const KernelBinding kind = bindings_[i];
        const VkSampler sampler =
            kind == KernelBinding::Storage ? VK_NULL_HANDLE : nearest_.handle();
        infos[i] = {sampler, images[i].view, images[i].layout};
        writes[i] = vk::make<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
        writes[i].dstSet = set;
        writes[i].dstBinding = i;
        writes[i].descriptorCount = 1;
        writes[i].descriptorType = descriptor_type(kind);
        writes[i].pImageInfo = &infos[i];
    }
    vkUpdateDescriptorSets(context_.device(), uint32_t(writes.size()), writes.data(), 0, nullptr);
}

void ComputeKernel::dispatch(VkCommandBuffer cmd, VkDescriptorSet frame_set, uint64_t frame_number,
                             std::span<const BoundImage> images, const void* push_constants,
                             VkExtent2D extent, uint32_t slot) {
    if (!pipeline_) throw Error("compute pass " + shader_ + ": no pipeline (rebuild() first)");
    if (slot >= dispatches_)
        throw Error("compute pass " + shader_ + ": dispatch " + std::to_string(slot) +
                    " of at most " + std::to_string(dispatches_) + " a frame");
    // The sets of frame N are reused by frame N + kFramesInFlight, after N's fence.
    const uint64_t ring = frame_number % vk::FrameRing::kFramesInFlight;
    const VkDescriptorSet set = sets_[size_t(ring) * dispatches_ + slot];
    write_set(set, images);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_.handle());
    const VkDescriptorSet sets[] = {frame_set, set};
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_.handle(), 0, 2, sets, 0,
                            nullptr);
    if (push_constant_size_)
        vkCmdPushConstants(cmd, layout_.handle(), VK_SHADER_STAGE_COMPUTE_BIT, 0,
                           push_constant_size_, push_constants);
    vkCmdDispatch(cmd, group_count(extent.width), group_count(extent.height), 1);
}

graph::ImageHandle add_depth_normals_pass(graph::RenderGraph& graph, const char* pass_name,
                                          const char* image_name, const graph::ImageDesc& desc,
                                          ComputeKernel& kernel, const void* push_constants,
                                          const FrameInputs& in, const FrameResources& res) {
    using graph::Access;
    struct Data {
        graph::ImageHandle depth, normals, out;
    };
    const Data& data = graph.add_pass<Data>(
        {pass_name, graph::PassKind::Compute},
        [&](graph::PassBuilder& b, Data& d) {
            d.out = b.create_image(image_name, desc);
            b.read(res.frame_uniforms, Access::UniformRead);
            d.depth = b.read(res.depth, Access::Sampled);
            d.normals = b.read(res.normals, Access::Sampled);
            b.write(d.out, Access::StorageWrite);
        },
        [&kernel, push_constants, frame_set = in.frame_set, frame = in.frame_number](
            graph::PassContext& ctx, const Data& d) {
            const BoundImage images[] = {{ctx.view(d.depth), ctx.layout(d.depth)},
                                         {ctx.view(d.normals), ctx.layout(d.normals)},
                                         {ctx.view(d.out), ctx.layout(d.out)}};
            kernel.dispatch(ctx.cmd(), frame_set, frame, images, push_constants, ctx.extent(d.out));
        });
    return data.out;
}

VkPipeline LazyComputePipeline::get(VkPipelineLayout layout) {
    if (!pipeline_ || layout != layout_) {
        layout_ = layout;
        vk::DestroyList nothing_in_flight;  // first build: no frame has used it
        build(nothing_in_flight);
    }
    return pipeline_.handle();
}

void LazyComputePipeline::rebuild(vk::DestroyList& retired) {
    if (pipeline_) build(retired);
}

void LazyComputePipeline::build(vk::DestroyList& retired) {
    vk::Pipeline pipeline = vk::create_compute_pipeline(
        services_.context, layout_,
        services_.compiler.compile(shader_, shader::Stage::Compute, defines_).spirv, name_);
    if (pipeline_) retired.defer(std::move(pipeline_));
    pipeline_ = std::move(pipeline);
}

}  // namespace ds::passes
