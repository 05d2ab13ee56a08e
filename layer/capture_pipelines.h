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
};

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

  private:
    VkShaderModule module(const std::vector<uint32_t>& code);
    VkPipelineLayout extended_layout(VkPipelineLayout app, uint32_t& app_sets, std::string& why);
    void build(CountingPipeline& p, PipelineRecipe recipe_copy);
    void build_measure(CountingPipeline& p, PipelineRecipe& r);

    DeviceData& d_;
    VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
    VkDescriptorSetLayout empty_layout_ = VK_NULL_HANDLE;
    std::vector<VkShaderModule> modules_;
    std::map<VkPipelineLayout, std::pair<VkPipelineLayout, uint32_t>> layouts_;
    std::map<VkPipeline, CountingPipeline> pipelines_;
    double build_ms_ = 0;
};

}  // namespace ds::layer
