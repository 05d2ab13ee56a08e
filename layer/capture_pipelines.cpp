#include "layer/capture_pipelines.h"

#include <chrono>
#include <optional>
#include <span>

#include "layer/spirv/instrument.h"
#include "layer/typed.h"
#include "renderer/spirv/spirv_facts.h"

namespace ds::layer {

CountingPipelines::CountingPipelines(DeviceData& d) : d_(d) {
    // Draw and pixel counters, depth records per pass (dynamic offsets), the record buffer.
    VkDescriptorSetLayoutBinding bindings[4] = {};
    for (uint32_t i = 0; i < 4; ++i) {
        bindings[i].binding = i;
        bindings[i].descriptorType = i < 3 ? VK_DESCRIPTOR_TYPE_STORAGE_BUFFER_DYNAMIC
                                           : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        bindings[i].descriptorCount = 1;
        bindings[i].stageFlags = VK_SHADER_STAGE_FRAGMENT_BIT;
    }
    auto l = typed<VkDescriptorSetLayoutCreateInfo>(
        VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO);
    l.bindingCount = 4;
    l.pBindings = bindings;
    d.t.CreateDescriptorSetLayout(d.device, &l, nullptr, &set_layout_);
    l.bindingCount = 0;
    d.t.CreateDescriptorSetLayout(d.device, &l, nullptr, &empty_layout_);
}

CountingPipelines::~CountingPipelines() {
    for (auto& [app, p] : pipelines_) {
        if (p.counting && p.counting != app) d_.t.DestroyPipeline(d_.device, p.counting, nullptr);
        for (VkPipeline own : {p.measure, p.depth_record, p.equal})
            if (own) d_.t.DestroyPipeline(d_.device, own, nullptr);
    }
    for (auto& [extent, fb] : framebuffers_) d_.t.DestroyFramebuffer(d_.device, fb, nullptr);
    if (empty_pass_) d_.t.DestroyRenderPass(d_.device, empty_pass_, nullptr);
    for (auto& [app, l] : layouts_) d_.t.DestroyPipelineLayout(d_.device, l.first, nullptr);
    for (VkShaderModule m : modules_) d_.t.DestroyShaderModule(d_.device, m, nullptr);
    d_.t.DestroyDescriptorSetLayout(d_.device, set_layout_, nullptr);
    d_.t.DestroyDescriptorSetLayout(d_.device, empty_layout_, nullptr);
}

VkShaderModule CountingPipelines::module(const std::vector<uint32_t>& code) {
    auto info = typed<VkShaderModuleCreateInfo>(VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO);
    info.codeSize = code.size() * 4;
    info.pCode = code.data();
    VkShaderModule m = VK_NULL_HANDLE;
    if (d_.t.CreateShaderModule(d_.device, &info, nullptr, &m) == VK_SUCCESS)
        modules_.push_back(m);
    return m;
}

VkPipelineLayout CountingPipelines::extended_layout(VkPipelineLayout app, uint32_t& app_sets,
                                                    std::string& why) {
    if (auto it = layouts_.find(app); it != layouts_.end()) {
        app_sets = it->second.second;
        return it->second.first;
    }
    LayoutRecipe recipe;
    {
        std::lock_guard lock(d_.mutex);
        auto it = d_.layouts.find(app);
        if (it == d_.layouts.end()) return (why = "a pipeline layout the layer did not see"), nullptr;
        recipe = it->second;
    }
    if (recipe.sets.size() > d_.counter_set)
        return (why = "the pipeline layout uses the layer's descriptor set slot"), nullptr;
    std::vector<VkDescriptorSetLayout> sets = recipe.sets;
    for (VkDescriptorSetLayout& s : sets)
        if (s == VK_NULL_HANDLE) s = empty_layout_;
    sets.resize(d_.counter_set, empty_layout_);
    sets.push_back(set_layout_);
    auto info = typed<VkPipelineLayoutCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO);
    info.setLayoutCount = uint32_t(sets.size());
    info.pSetLayouts = sets.data();
    info.pushConstantRangeCount = uint32_t(recipe.push_constants.size());
    info.pPushConstantRanges = recipe.push_constants.data();
    VkPipelineLayout layout = VK_NULL_HANDLE;
    if (d_.t.CreatePipelineLayout(d_.device, &info, nullptr, &layout) != VK_SUCCESS)
        return (why = "cannot create the extended pipeline layout"), nullptr;
    app_sets = uint32_t(recipe.sets.size());
    layouts_[app] = {layout, app_sets};
    return layout;
}

const CountingPipeline& CountingPipelines::get(VkPipeline app) {
    if (auto it = pipelines_.find(app); it != pipelines_.end()) return it->second;
    const auto start = std::chrono::steady_clock::now();
    CountingPipeline& p = pipelines_[app];
    std::unique_ptr<PipelineRecipe> copy;
    {
        std::lock_guard lock(d_.mutex);
        auto it = d_.pipelines.find(app);
        if (auto n = d_.names.find(uint64_t(app)); n != d_.names.end()) p.name = n->second;
        if (it == d_.pipelines.end())
            p.why = "a pipeline the layer did not see created";
        else if (!it->second.recipe)
            p.why = it->second.why;
        else
            copy = std::make_unique<PipelineRecipe>(*it->second.recipe);
    }
    if (copy) {
        read_depth_state(p, *copy);
        // The depth checks' copies start from the recipe as the application gave it.
        std::optional<PipelineRecipe> original;
        if (config().settings.depth_records()) original = *copy;
        build(p, std::move(*copy));
        if (original) build_depth(p, *original);
    }
    build_ms_ += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() -
                                                           start).count();
    return p;
}

}  // namespace ds::layer
