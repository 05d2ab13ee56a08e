#pragma once
// The counting copies of the application's graphics pipelines, built when a frame is
// captured: `counting` is the application's pipeline with its fragment shader instrumented
// (layer/spirv/instrument.h) and a layout extended to the layer's descriptor set slot;
// `measure` draws the same geometry with the depth and stencil tests off, no colour written,
// and a fragment shader generated to count what it rasterizes (layer/spirv/measure.h). A pipeline without a fragment shader counts as its
// own `counting` copy (it shades nothing).
#include <map>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "layer/state.h"

namespace ds::layer {

struct CountingPipeline {
    VkPipeline counting = VK_NULL_HANDLE;
    VkPipeline measure = VK_NULL_HANDLE;
    VkPipelineLayout layout = VK_NULL_HANDLE;  // the application's sets, empty ones, the layer's
    uint32_t app_sets = 0;
    std::string why;  // not empty: not analysable
    std::string name;
    bool has_fragment = false;
    bool early_tests_added = false;
    uint32_t discard_sites = 0;
    std::string early_z;  // ds::spirv::early_z_verdict of the application's shader
    // Depth and stencil switches the application sets dynamically (restored after `measure`).
    bool dynamic_depth_test = false, dynamic_depth_write = false;
    bool dynamic_stencil_test = false, dynamic_depth_bounds = false;
    std::vector<uint32_t> instrumented;   // the rewritten fragment SPIR-V (for spirv-val)
    std::vector<uint32_t> measure_spirv;  // the measurement draw's fragment shader

    // Depth state as created (dynamic values are the recorder's) and the vertex bindings read.
    bool depth_test = false, depth_write = false;
    VkCompareOp compare_op = VK_COMPARE_OP_ALWAYS;
    bool dynamic_compare_op = false;
    uint32_t samples = 1;  // rasterizationSamples
    std::vector<uint32_t> vertex_bindings;
    // zfight / equal_check (capture_pipelines_depth.cpp): `depth_record` re-draws in the
    // layer's attachment-less pass, `equal` in the application's pass; a reason when absent.
    VkPipeline depth_record = VK_NULL_HANDLE, equal = VK_NULL_HANDLE;
    std::string depth_record_why, equal_why;
    bool instance_known = false;            // the vertex stage hands gl_InstanceIndex on
    std::vector<uint32_t> survival_spirv;   // depth_record's fragment shader (for spirv-val)
};

// The last stage before rasterization (geometry, else tessellation evaluation, else vertex).
const StageRecipe* last_geometry_stage(const PipelineRecipe& r);
// The depth state and vertex bindings `p` keeps of its recipe (capture_pipelines_depth.cpp).
void read_depth_state(CountingPipeline& p, const PipelineRecipe& r);
// A copy's colour writes masked, blending, alpha to coverage and alpha to one off.
void mask_colour_and_coverage(PipelineRecipe& r);

class CountingPipelines {
  public:
    explicit CountingPipelines(DeviceData& d);
    ~CountingPipelines();
    CountingPipelines(const CountingPipelines&) = delete;
    CountingPipelines& operator=(const CountingPipelines&) = delete;

    VkDescriptorSetLayout set_layout() const { return set_layout_; }
    // Built on first use; `why` says what stops it.
    const CountingPipeline& get(VkPipeline app);
    const std::map<VkPipeline, CountingPipeline>& all() const { return pipelines_; }
    double build_ms() const { return build_ms_; }
    // The layer's attachment-less render pass and a framebuffer of `extent` for it.
    VkRenderPass empty_pass();
    VkFramebuffer framebuffer(VkExtent2D extent);

  private:
    VkShaderModule module(const std::vector<uint32_t>& code);
    VkPipelineLayout extended_layout(VkPipelineLayout app, uint32_t& app_sets, std::string& why);
    void build(CountingPipeline& p, PipelineRecipe recipe_copy);
    void build_measure(CountingPipeline& p, PipelineRecipe& r);
    void build_depth(CountingPipeline& p, const PipelineRecipe& r);  // zfight / equal_check on
    void build_depth_record(CountingPipeline& p, PipelineRecipe r);
    void build_equal(CountingPipeline& p, PipelineRecipe r);
    std::vector<uint32_t> survival(CountingPipeline& p, PipelineRecipe& r, bool early_tests,
                                   uint32_t instance_location, std::string& why);

    DeviceData& d_;
    VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
    VkDescriptorSetLayout empty_layout_ = VK_NULL_HANDLE;
    std::vector<VkShaderModule> modules_;
    std::map<VkPipelineLayout, std::pair<VkPipelineLayout, uint32_t>> layouts_;
    std::map<VkPipeline, CountingPipeline> pipelines_;
    double build_ms_ = 0;
    VkRenderPass empty_pass_ = VK_NULL_HANDLE;
    std::map<std::pair<uint32_t, uint32_t>, VkFramebuffer> framebuffers_;
};

}  // namespace ds::layer
