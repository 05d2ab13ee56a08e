#pragma once
// What the layer keeps of shader modules, descriptor set and pipeline layouts, and graphics
// pipelines, so that it can build counting copies of the application's pipelines when a
// capture is armed: each pipeline's create info is copied whole at creation (its "recipe"),
// or the reason it cannot be is noted (not_analysed in the report).
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

namespace ds::layer {

struct StageRecipe {
    VkShaderStageFlagBits stage;
    VkShaderModule module;  // the application's (it may be destroyed by now: use `code`)
    std::shared_ptr<const std::vector<uint32_t>> code;
    std::string entry;
    std::vector<VkSpecializationMapEntry> spec_entries;
    std::vector<uint8_t> spec_data;
    VkSpecializationInfo spec{};
};

// A VkGraphicsPipelineCreateInfo and everything it points to, owned; info() rebuilds the
// pointers into this copy.
struct PipelineRecipe {
    VkPipelineCreateFlags flags = 0;
    std::vector<StageRecipe> stages;
    std::vector<VkVertexInputBindingDescription> bindings;
    std::vector<VkVertexInputAttributeDescription> attributes;
    VkPipelineInputAssemblyStateCreateInfo input_assembly{};
    bool has_tessellation = false;
    VkPipelineTessellationStateCreateInfo tessellation{};
    bool has_viewport = false;
    std::vector<VkViewport> viewports;
    std::vector<VkRect2D> scissors;
    uint32_t viewport_count = 0, scissor_count = 0;
    VkPipelineRasterizationStateCreateInfo raster{};
    std::vector<std::vector<uint8_t>> raster_next;  // pointer-free extension structures
    bool has_multisample = false;
    VkPipelineMultisampleStateCreateInfo multisample{};
    std::vector<VkSampleMask> sample_mask;
    bool has_depth_stencil = false;
    VkPipelineDepthStencilStateCreateInfo depth_stencil{};
    bool has_blend = false;
    VkPipelineColorBlendStateCreateInfo blend{};
    std::vector<VkPipelineColorBlendAttachmentState> blend_attachments;
    std::vector<VkDynamicState> dynamic;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VkRenderPass render_pass = VK_NULL_HANDLE;
    uint32_t subpass = 0;
    bool has_rendering = false;
    VkPipelineRenderingCreateInfo rendering{};
    std::vector<VkFormat> color_formats;

    // Filled by info(): the structures that point into this recipe.
    struct Built {
        std::vector<VkPipelineShaderStageCreateInfo> stages;
        VkPipelineVertexInputStateCreateInfo vertex_input{};
        VkPipelineViewportStateCreateInfo viewport{};
        VkPipelineDynamicStateCreateInfo dynamic{};
        VkGraphicsPipelineCreateInfo info{};
    } built;

    const StageRecipe* fragment() const;
    bool is_dynamic(VkDynamicState s) const;
    const VkGraphicsPipelineCreateInfo& info();

  private:
    void build_pointers();
};

// Copies `in`; returns null with `why` set when the layer cannot (an unknown extension
// structure, a pipeline library, a module given inline).
// `code` gives each stage's module's SPIR-V (null: unknown module).
std::unique_ptr<PipelineRecipe> copy_recipe(
    const VkGraphicsPipelineCreateInfo& in,
    const std::function<std::shared_ptr<const std::vector<uint32_t>>(VkShaderModule)>& code,
    std::string& why);

struct LayoutRecipe {
    std::vector<VkDescriptorSetLayout> sets;
    std::vector<VkPushConstantRange> push_constants;
};

struct PipelineRecord {
    std::unique_ptr<PipelineRecipe> recipe;  // null: not analysable (why)
    std::string why;
    std::string name;  // the application's debug-utils object name, if any
};

}  // namespace ds::layer
