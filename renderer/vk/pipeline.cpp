#include "renderer/vk/pipeline.h"

#include <utility>

#include "renderer/vk/check.h"
#include "renderer/vk/context.h"

namespace ds::vk {

PipelineLayout::PipelineLayout(Context& context, std::span<const VkDescriptorSetLayout> sets,
                               std::span<const VkPushConstantRange> push_constants,
                               const char* name)
    : device_(context.device()) {
    auto info = make<VkPipelineLayoutCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO);
    info.setLayoutCount = uint32_t(sets.size());
    info.pSetLayouts = sets.data();
    info.pushConstantRangeCount = uint32_t(push_constants.size());
    info.pPushConstantRanges = push_constants.data();
    check(vkCreatePipelineLayout(device_, &info, nullptr, &layout_), "vkCreatePipelineLayout");
    context.set_name(VK_OBJECT_TYPE_PIPELINE_LAYOUT, layout_, name);
}

PipelineLayout& PipelineLayout::operator=(PipelineLayout&& other) noexcept {
    if (this == &other) return *this;
    reset();
    device_ = std::exchange(other.device_, VK_NULL_HANDLE);
    layout_ = std::exchange(other.layout_, VK_NULL_HANDLE);
    return *this;
}

void PipelineLayout::reset() {
    if (layout_) vkDestroyPipelineLayout(device_, layout_, nullptr);
    layout_ = VK_NULL_HANDLE;
}

Pipeline::Pipeline(const Context& context, VkPipeline pipeline)
    : context_(&context), pipeline_(pipeline) {}

Pipeline& Pipeline::operator=(Pipeline&& other) noexcept {
    if (this == &other) return *this;
    reset();
    context_ = std::exchange(other.context_, nullptr);
    pipeline_ = std::exchange(other.pipeline_, VK_NULL_HANDLE);
    return *this;
}

void Pipeline::reset() {
    if (pipeline_) {
        context_->clear_name(VK_OBJECT_TYPE_PIPELINE, pipeline_);
        vkDestroyPipeline(context_->device(), pipeline_, nullptr);
    }
    pipeline_ = VK_NULL_HANDLE;
}

GraphicsPipelineBuilder& GraphicsPipelineBuilder::shader(VkShaderStageFlagBits stage,
                                                         std::span<const uint32_t> spirv) {
    stages_.push_back({stage, {spirv.begin(), spirv.end()}});
    return *this;
}

GraphicsPipelineBuilder& GraphicsPipelineBuilder::vertex_binding(uint32_t binding,
                                                                 uint32_t stride) {
    bindings_.push_back({binding, stride, VK_VERTEX_INPUT_RATE_VERTEX});
    return *this;
}

GraphicsPipelineBuilder& GraphicsPipelineBuilder::vertex_attribute(uint32_t location,
                                                                   uint32_t binding,
                                                                   VkFormat format,
                                                                   uint32_t offset) {
    attributes_.push_back({location, binding, format, offset});
    return *this;
}

GraphicsPipelineBuilder& GraphicsPipelineBuilder::color_attachment(VkFormat format, Blend blend) {
    color_formats_.push_back(format);
    blends_.push_back(blend);
    return *this;
}

GraphicsPipelineBuilder& GraphicsPipelineBuilder::depth_attachment(VkFormat format) {
    depth_format_ = format;
    return *this;
}

GraphicsPipelineBuilder& GraphicsPipelineBuilder::samples(VkSampleCountFlagBits samples) {
    samples_ = samples;
    return *this;
}

GraphicsPipelineBuilder& GraphicsPipelineBuilder::sample_shading(float min_fraction) {
    min_sample_shading_ = min_fraction;
    return *this;
}

GraphicsPipelineBuilder& GraphicsPipelineBuilder::alpha_to_coverage(bool enable) {
    alpha_to_coverage_ = enable;
    return *this;
}

GraphicsPipelineBuilder& GraphicsPipelineBuilder::front_face(VkFrontFace face) {
    front_face_ = face;
    return *this;
}

GraphicsPipelineBuilder& GraphicsPipelineBuilder::depth_bias(float constant, float slope) {
    depth_bias_constant_ = constant;
    depth_bias_slope_ = slope;
    return *this;
}

GraphicsPipelineBuilder& GraphicsPipelineBuilder::layout(VkPipelineLayout layout) {
    layout_ = layout;
    return *this;
}

namespace {

VkPipelineColorBlendAttachmentState blend_state(Blend blend) {
    VkPipelineColorBlendAttachmentState s{};
    s.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                       VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
    if (blend == Blend::Alpha) {
        s.blendEnable = VK_TRUE;
        s.srcColorBlendFactor = VK_BLEND_FACTOR_SRC_ALPHA;
        s.dstColorBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
        s.colorBlendOp = VK_BLEND_OP_ADD;
        s.srcAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
        s.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
        s.alphaBlendOp = VK_BLEND_OP_ADD;
    }
    return s;
}

constexpr VkDynamicState kDynamicStates[] = {
    VK_DYNAMIC_STATE_VIEWPORT,           VK_DYNAMIC_STATE_SCISSOR,
    VK_DYNAMIC_STATE_CULL_MODE,          VK_DYNAMIC_STATE_DEPTH_TEST_ENABLE,
    VK_DYNAMIC_STATE_DEPTH_WRITE_ENABLE, VK_DYNAMIC_STATE_DEPTH_COMPARE_OP};

// The state every pipeline of this builder shares: triangles, one dynamic viewport, dynamic
// cull mode and depth test/write/compare op.
struct FixedState {
    VkPipelineInputAssemblyStateCreateInfo assembly = make<VkPipelineInputAssemblyStateCreateInfo>(
        VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO);
    VkPipelineViewportStateCreateInfo viewport = make<VkPipelineViewportStateCreateInfo>(
        VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO);
    VkPipelineRasterizationStateCreateInfo raster = make<VkPipelineRasterizationStateCreateInfo>(
        VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO);
    VkPipelineMultisampleStateCreateInfo multisample = make<VkPipelineMultisampleStateCreateInfo>(
        VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO);
    VkPipelineDepthStencilStateCreateInfo depth = make<VkPipelineDepthStencilStateCreateInfo>(
        VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO);  // all dynamic
    VkPipelineDynamicStateCreateInfo dynamic = make<VkPipelineDynamicStateCreateInfo>(
        VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO);

    FixedState(VkFrontFace front_face, VkSampleCountFlagBits samples) {
        assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
        viewport.viewportCount = 1;
        viewport.scissorCount = 1;
        raster.polygonMode = VK_POLYGON_MODE_FILL;
        raster.frontFace = front_face;
        raster.lineWidth = 1.0f;
        multisample.rasterizationSamples = samples;
        dynamic.dynamicStateCount = uint32_t(std::size(kDynamicStates));
        dynamic.pDynamicStates = kDynamicStates;
    }
};

// Shader modules live only for the vkCreateGraphicsPipelines call.
struct Modules {
    VkDevice device;
    std::vector<VkShaderModule> modules;
    ~Modules() {
        for (VkShaderModule m : modules) vkDestroyShaderModule(device, m, nullptr);
    }
};

}  // namespace

std::vector<VkPipelineShaderStageCreateInfo> GraphicsPipelineBuilder::create_stages(
    VkDevice device, std::vector<VkShaderModule>& modules) const {
    std::vector<VkPipelineShaderStageCreateInfo> stages;
    for (const Stage& s : stages_) {
        auto info = make<VkShaderModuleCreateInfo>(VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO);
        info.codeSize = s.spirv.size() * sizeof(uint32_t);
        info.pCode = s.spirv.data();
        VkShaderModule module = VK_NULL_HANDLE;
        check(vkCreateShaderModule(device, &info, nullptr, &module), "vkCreateShaderModule");
        modules.push_back(module);
        auto stage = make<VkPipelineShaderStageCreateInfo>(
            VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO);
        stage.stage = s.stage;
        stage.module = module;
        stage.pName = "main";
        stages.push_back(stage);
    }
    return stages;
}

GraphicsPipelineBuilder& GraphicsPipelineBuilder::render_pass(VkRenderPass pass, uint32_t subpass) {
    render_pass_ = pass;
    subpass_ = subpass;
    return *this;
}

Pipeline GraphicsPipelineBuilder::build(Context& context, const char* name) const {
    VkDevice device = context.device();
    Modules modules{device, {}};
    const std::vector<VkPipelineShaderStageCreateInfo> stages =
        create_stages(device, modules.modules);

    auto vertex = make<VkPipelineVertexInputStateCreateInfo>(
        VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO);
    vertex.vertexBindingDescriptionCount = uint32_t(bindings_.size());
    vertex.pVertexBindingDescriptions = bindings_.data();
    vertex.vertexAttributeDescriptionCount = uint32_t(attributes_.size());
    vertex.pVertexAttributeDescriptions = attributes_.data();
    FixedState fixed(front_face_, samples_);
    fixed.multisample.sampleShadingEnable = min_sample_shading_ > 0.0f ? VK_TRUE : VK_FALSE;
    fixed.multisample.minSampleShading = min_sample_shading_;
    fixed.multisample.alphaToCoverageEnable = alpha_to_coverage_ ? VK_TRUE : VK_FALSE;
    const bool biased = depth_bias_constant_ != 0.0f || depth_bias_slope_ != 0.0f;
    fixed.raster.depthBiasEnable = biased ? VK_TRUE : VK_FALSE;
    fixed.raster.depthBiasConstantFactor = depth_bias_constant_;
    fixed.raster.depthBiasSlopeFactor = depth_bias_slope_;
    std::vector<VkPipelineColorBlendAttachmentState> blends;
    for (Blend b : blends_) blends.push_back(blend_state(b));
    auto blend = make<VkPipelineColorBlendStateCreateInfo>(
        VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO);
    blend.attachmentCount = uint32_t(blends.size());
    blend.pAttachments = blends.data();
    // Depth only: no pass uses stencil, so depth/stencil formats get no stencil attachment.
    auto rendering =
        make<VkPipelineRenderingCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO);
    rendering.colorAttachmentCount = uint32_t(color_formats_.size());
    rendering.pColorAttachmentFormats = color_formats_.data();
    rendering.depthAttachmentFormat = depth_format_;

    auto info = make<VkGraphicsPipelineCreateInfo>(VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO,
                                                   render_pass_ ? nullptr : &rendering);
    info.renderPass = render_pass_;
    info.subpass = subpass_;
    info.stageCount = uint32_t(stages.size());
    info.pStages = stages.data();
    info.pVertexInputState = &vertex;
    info.pInputAssemblyState = &fixed.assembly;
    info.pViewportState = &fixed.viewport;
    info.pRasterizationState = &fixed.raster;
    info.pMultisampleState = &fixed.multisample;
    info.pDepthStencilState = &fixed.depth;
    info.pColorBlendState = &blend;
    info.pDynamicState = &fixed.dynamic;
    info.layout = layout_;
    VkPipeline pipeline = VK_NULL_HANDLE;
    check(vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline),
          "vkCreateGraphicsPipelines");
    context.set_name(VK_OBJECT_TYPE_PIPELINE, pipeline, name);
    return Pipeline(context, pipeline);
}

Pipeline create_compute_pipeline(Context& context, VkPipelineLayout layout,
                                 const std::vector<uint32_t>& spirv, const char* name) {
    VkDevice device = context.device();
    auto module_info = make<VkShaderModuleCreateInfo>(VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO);
    module_info.codeSize = spirv.size() * sizeof(uint32_t);
    module_info.pCode = spirv.data();
    VkShaderModule module = VK_NULL_HANDLE;
    check(vkCreateShaderModule(device, &module_info, nullptr, &module), "vkCreateShaderModule");

    auto info = make<VkComputePipelineCreateInfo>(VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO);
    info.stage =
        make<VkPipelineShaderStageCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO);
    info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    info.stage.module = module;
    info.stage.pName = "main";
    info.layout = layout;
    VkPipeline pipeline = VK_NULL_HANDLE;
    const VkResult result =
        vkCreateComputePipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline);
    vkDestroyShaderModule(device, module, nullptr);  // the pipeline keeps what it needs
    check(result, "vkCreateComputePipelines");
    context.set_name(VK_OBJECT_TYPE_PIPELINE, pipeline, name);
    return Pipeline(context, pipeline);
}

}  // namespace ds::vk
