#include "renderer/passes/lighting_set.h"

#include <array>

#include "renderer/vk/barrier.h"
#include "renderer/vk/check.h"
#include "renderer/vk/context.h"

namespace ds::passes {
namespace {

enum Binding : uint32_t {
    kShadowMap = 0,
    kNormals = 1,
    kRoughness = 2,
    kAO = 3,
    kContact = 4,
    kBindingCount = 5
};

constexpr uint32_t kSetsPerFrame = 2;  // a pass writes one per frame; one spare

VkSamplerCreateInfo sampler_info(VkFilter filter, VkSamplerAddressMode address) {
    auto info = vk::make<VkSamplerCreateInfo>(VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO);
    info.magFilter = info.minFilter = filter;
    info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    info.addressModeU = info.addressModeV = info.addressModeW = address;
    info.borderColor = VK_BORDER_COLOR_FLOAT_OPAQUE_WHITE;
    info.maxLod = 0.0f;
    return info;
}

vk::DescriptorSetLayout create_layout(vk::Context& context) {
    std::array<VkDescriptorSetLayoutBinding, kBindingCount> bindings{};
    for (uint32_t i = 0; i < kBindingCount; ++i)
        bindings[i] = vk::layout_binding(i, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                                         VK_SHADER_STAGE_FRAGMENT_BIT);
    return vk::DescriptorSetLayout(context, bindings, "lighting set layout");
}

constexpr uint32_t kImagesPerFrame = kSetsPerFrame * kBindingCount;
const VkDescriptorPoolSize kPoolSizes[] = {
    {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kImagesPerFrame}};

}  // namespace

LightingSet::LightingSet(vk::Context& context, VkFormat shadow_format)
    : context_(context),
      layout_(create_layout(context)),
      pool_(context, kSetsPerFrame, kPoolSizes, "lighting sets") {
    // Hardware 2x2 PCF per tap where the depth format filters linearly.
    const bool linear = (context.format_properties(shadow_format).optimalTilingFeatures &
                         VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT) != 0;
    VkSamplerCreateInfo shadow = sampler_info(linear ? VK_FILTER_LINEAR : VK_FILTER_NEAREST,
                                              VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_BORDER);
    shadow.compareEnable = VK_TRUE;
    shadow.compareOp = VK_COMPARE_OP_LESS_OR_EQUAL;
    shadow_sampler_ = vk::Sampler(context, shadow, "shadow compare sampler");
    linear_ = vk::Sampler(
        context, sampler_info(VK_FILTER_LINEAR, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE), "linear");
    nearest_ = vk::nearest_clamp_sampler(context, "nearest");
    create_fallbacks(shadow_format);
}

void LightingSet::create_fallbacks(VkFormat shadow_format) {
    const VkImageUsageFlags usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    white_ = vk::Image(context_, {1, 1, 1, VK_FORMAT_R8G8B8A8_UNORM, usage, VK_SAMPLE_COUNT_1_BIT,
                                  "fallback white"});
    lit_shadow_ = vk::Image(
        context_, {1, 1, 1, shadow_format, usage, VK_SAMPLE_COUNT_1_BIT, "fallback shadow map"});
    context_.submit_once([&](VkCommandBuffer cmd) {
        vk::ImageBarrier to_dst[] = {{.image = white_.handle(),
                                      .new_layout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                                      .dst_stage = VK_PIPELINE_STAGE_2_CLEAR_BIT,
                                      .dst_access = VK_ACCESS_2_TRANSFER_WRITE_BIT},
                                     {.image = lit_shadow_.handle(),
                                      .aspect = lit_shadow_.aspect(),
                                      .new_layout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                                      .dst_stage = VK_PIPELINE_STAGE_2_CLEAR_BIT,
                                      .dst_access = VK_ACCESS_2_TRANSFER_WRITE_BIT}};
        vk::image_barriers(cmd, to_dst);
        const VkClearColorValue one{{1.0f, 1.0f, 1.0f, 1.0f}};
        const VkImageSubresourceRange color{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        vkCmdClearColorImage(cmd, white_.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &one, 1,
                             &color);
        const VkClearDepthStencilValue far{1.0f, 0};
        const VkImageSubresourceRange depth{lit_shadow_.aspect(), 0, 1, 0, 1};
        vkCmdClearDepthStencilImage(cmd, lit_shadow_.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                                    &far, 1, &depth);
        vk::ImageBarrier to_read[2] = {to_dst[0], to_dst[1]};
        for (vk::ImageBarrier& b : to_read) {
            b.old_layout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
            b.new_layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
            b.src_stage = VK_PIPELINE_STAGE_2_CLEAR_BIT;
            b.src_access = VK_ACCESS_2_TRANSFER_WRITE_BIT;
            b.dst_stage = VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
            b.dst_access = VK_ACCESS_2_SHADER_SAMPLED_READ_BIT;
        }
        vk::image_barriers(cmd, to_read);
    });
}

void LightingSet::declare(graph::PassBuilder& builder, const LightingInputs& in) {
    for (graph::ImageHandle h :
         {in.shadow_map, in.normals, in.roughness, in.ao, in.contact_shadows}) {
        if (h.valid()) builder.read(h, graph::Access::Sampled, graph::Shader::Fragment);
    }
}

VkDescriptorSet LightingSet::write(const graph::PassContext& ctx, uint64_t frame_number,
                                   const LightingInputs& in) {
    const VkDescriptorSet set = pool_.allocate(frame_number, layout_.handle());
    vk::DescriptorWriter writer;
    auto bind = [&](uint32_t binding, graph::ImageHandle h, const vk::Image& fallback,
                    VkSampler sampler) {
        if (h.valid())
            writer.image(binding, ctx.view(h), sampler, ctx.layout(h));
        else
            writer.image(binding, fallback.view(), sampler);
    };
    bind(kShadowMap, in.shadow_map, lit_shadow_, shadow_sampler_.handle());
    bind(kNormals, in.normals, white_, nearest_.handle());
    bind(kRoughness, in.roughness, white_, nearest_.handle());
    bind(kAO, in.ao, white_, linear_.handle());
    bind(kContact, in.contact_shadows, white_, linear_.handle());
    writer.update(context_.device(), set);
    return set;
}

}  // namespace ds::passes
