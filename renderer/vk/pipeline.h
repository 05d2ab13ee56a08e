#pragma once
// Pipeline layouts and a graphics pipeline builder for dynamic rendering
// (VkPipelineRenderingCreateInfo, no VkRenderPass). Cull mode, depth test, depth write and
// depth compare op are dynamic (extended dynamic state, core in 1.3): one pipeline serves
// one-sided and double-sided groups, prepass (GREATER, writes) and EQUAL passes.
#include <cstdint>
#include <span>
#include <vector>

#include <vulkan/vulkan.h>

namespace ds::vk {

class Context;

class PipelineLayout {
  public:
    PipelineLayout() = default;
    PipelineLayout(Context& context, std::span<const VkDescriptorSetLayout> sets,
                   std::span<const VkPushConstantRange> push_constants = {},
                   const char* name = nullptr);
    ~PipelineLayout() { reset(); }
    PipelineLayout(PipelineLayout&& other) noexcept { *this = std::move(other); }
    PipelineLayout& operator=(PipelineLayout&& other) noexcept;
    PipelineLayout(const PipelineLayout&) = delete;
    PipelineLayout& operator=(const PipelineLayout&) = delete;

    void reset();
    VkPipelineLayout handle() const { return layout_; }

  private:
    VkDevice device_ = VK_NULL_HANDLE;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkRenderPass render_pass_ = VK_NULL_HANDLE;
    uint32_t subpass_ = 0;
};

class Pipeline {
  public:
    Pipeline() = default;
    // `context` (kept) removes the pipeline's debug-utils name before it is destroyed: the
    // validation layer keeps a name until then, and pipelines are rebuilt whenever a knob
    // invalidates them (a soak's probes do every cycle).
    Pipeline(const Context& context, VkPipeline pipeline);
    ~Pipeline() { reset(); }
    Pipeline(Pipeline&& other) noexcept { *this = std::move(other); }
    Pipeline& operator=(Pipeline&& other) noexcept;
    Pipeline(const Pipeline&) = delete;
    Pipeline& operator=(const Pipeline&) = delete;

    void reset();
    explicit operator bool() const { return pipeline_ != VK_NULL_HANDLE; }
    VkPipeline handle() const { return pipeline_; }

  private:
    const Context* context_ = nullptr;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
};

enum class Blend : uint8_t { None, Alpha };

class GraphicsPipelineBuilder {
  public:
    GraphicsPipelineBuilder& shader(VkShaderStageFlagBits stage, std::span<const uint32_t> spirv);
    GraphicsPipelineBuilder& vertex_binding(uint32_t binding, uint32_t stride);
    GraphicsPipelineBuilder& vertex_attribute(uint32_t location, uint32_t binding, VkFormat format,
                                              uint32_t offset);
    GraphicsPipelineBuilder& color_attachment(VkFormat format, Blend blend = Blend::None);
    GraphicsPipelineBuilder& depth_attachment(VkFormat format);
    GraphicsPipelineBuilder& samples(VkSampleCountFlagBits samples);
    // Per-sample shading with minSampleShading (0: off; needs the sampleRateShading feature).
    GraphicsPipelineBuilder& sample_shading(float min_fraction);
    // Colour attachment 0's alpha becomes the coverage mask (multisampled targets).
    GraphicsPipelineBuilder& alpha_to_coverage(bool enable);
    GraphicsPipelineBuilder& front_face(VkFrontFace face);  // default counter-clockwise (glTF)
    // Static depth bias (depthBiasConstantFactor, depthBiasSlopeFactor; no clamp).
    GraphicsPipelineBuilder& depth_bias(float constant, float slope);
    GraphicsPipelineBuilder& layout(VkPipelineLayout layout);
    // For subpass `subpass` of a VkRenderPass (render graph subpass groups) instead of dynamic
    // rendering; the colour attachments must still be listed (their blend states).
    GraphicsPipelineBuilder& render_pass(VkRenderPass pass, uint32_t subpass);

    Pipeline build(Context& context, const char* name = nullptr) const;  // throws ds::Error

  private:
    struct Stage {
        VkShaderStageFlagBits stage;
        std::vector<uint32_t> spirv;
    };
    // Creates one module per stage (appended to `modules`, which the caller destroys).
    std::vector<VkPipelineShaderStageCreateInfo> create_stages(
        VkDevice device, std::vector<VkShaderModule>& modules) const;
    std::vector<Stage> stages_;
    std::vector<VkVertexInputBindingDescription> bindings_;
    std::vector<VkVertexInputAttributeDescription> attributes_;
    std::vector<VkFormat> color_formats_;
    std::vector<Blend> blends_;
    VkFormat depth_format_ = VK_FORMAT_UNDEFINED;
    VkSampleCountFlagBits samples_ = VK_SAMPLE_COUNT_1_BIT;
    float min_sample_shading_ = 0.0f;
    bool alpha_to_coverage_ = false;
    VkFrontFace front_face_ = VK_FRONT_FACE_COUNTER_CLOCKWISE;
    float depth_bias_constant_ = 0.0f, depth_bias_slope_ = 0.0f;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkRenderPass render_pass_ = VK_NULL_HANDLE;
    uint32_t subpass_ = 0;
};

// A compute pipeline from SPIR-V (the module is destroyed once the pipeline exists).
Pipeline create_compute_pipeline(Context& context, VkPipelineLayout layout,
                                 const std::vector<uint32_t>& spirv, const char* name);

}  // namespace ds::vk
