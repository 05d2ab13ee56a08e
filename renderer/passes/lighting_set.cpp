#include "renderer/passes/lighting_set.h"

#include <array>

#include "renderer/vk/check.h"
#include "renderer/vk/context.h"
#include "renderer/vk/upload.h"

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
const VkDescriptorPoolSize kLightingSetPoolSizes[] = {
    {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kImagesPerFrame}};

}  // namespace

LightingSet::LightingSet(vk::Context& context, VkFormat shadow_format)
    : context_(context),
      layout_(create_layout(context)),
      pool_(context, kSetsPerFrame, kLightingSetPoolSizes, "lighting sets") {
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
    VkClearValue one{};
    one.color = {{1.0f, 1.0f, 1.0f, 1.0f}};
    vk::clear_image_once(context_, white_, one);
    VkClearValue far{};
    far.depthStencil = {1.0f, 0};
    vk::clear_image_once(context_, lit_shadow_, far);
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
