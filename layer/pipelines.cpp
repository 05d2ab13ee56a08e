#include "layer/pipelines.h"
#include "layer/typed.h"

#include <cstring>

namespace ds::layer {

using CodeOf = std::function<std::shared_ptr<const std::vector<uint32_t>>(VkShaderModule)>;

namespace {

template <typename T>
std::vector<T> copy_array(const T* items, uint32_t count) {
    return items ? std::vector<T>(items, items + count) : std::vector<T>{};
}

// Extension structures of the rasterization state that hold no pointers: copied as bytes.
size_t raster_next_size(VkStructureType type) {
    switch (type) {
        case VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_DEPTH_CLIP_STATE_CREATE_INFO_EXT:
            return sizeof(VkPipelineRasterizationDepthClipStateCreateInfoEXT);
        case VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_LINE_STATE_CREATE_INFO_EXT:
            return sizeof(VkPipelineRasterizationLineStateCreateInfoEXT);
        case VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_PROVOKING_VERTEX_STATE_CREATE_INFO_EXT:
            return sizeof(VkPipelineRasterizationProvokingVertexStateCreateInfoEXT);
        case VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_CONSERVATIVE_STATE_CREATE_INFO_EXT:
            return sizeof(VkPipelineRasterizationConservativeStateCreateInfoEXT);
        default: return 0;
    }
}

bool copy_stages(const VkGraphicsPipelineCreateInfo& in, const CodeOf& code, PipelineRecipe& r,
                 std::string& why) {
    for (uint32_t i = 0; i < in.stageCount; ++i) {
        const VkPipelineShaderStageCreateInfo& s = in.pStages[i];
        if (s.pNext || s.module == VK_NULL_HANDLE) {
            why = "a shader stage given inline or with an extension structure";
            return false;
        }
        StageRecipe st{s.stage, s.module, code(s.module), s.pName ? s.pName : "main", {}, {}, {}};
        if (!st.code) {
            why = "a shader module the layer did not see created";
            return false;
        }
        if (const VkSpecializationInfo* sp = s.pSpecializationInfo) {
            st.spec_entries = copy_array(sp->pMapEntries, sp->mapEntryCount);
            const auto* bytes = static_cast<const uint8_t*>(sp->pData);
            st.spec_data.assign(bytes, bytes + sp->dataSize);
            st.spec.mapEntryCount = sp->mapEntryCount;
            st.spec.dataSize = sp->dataSize;
        }
        r.stages.push_back(std::move(st));
    }
    return true;
}

bool copy_fixed_function(const VkGraphicsPipelineCreateInfo& in, PipelineRecipe& r,
                         std::string& why) {
    if (const auto* v = in.pVertexInputState) {
        if (v->pNext) return (why = "a vertex input extension structure"), false;
        r.bindings = copy_array(v->pVertexBindingDescriptions, v->vertexBindingDescriptionCount);
        r.attributes =
            copy_array(v->pVertexAttributeDescriptions, v->vertexAttributeDescriptionCount);
    }
    if (in.pInputAssemblyState) r.input_assembly = *in.pInputAssemblyState;
    if (in.pTessellationState) {
        if (in.pTessellationState->pNext) return (why = "a tessellation extension structure"), false;
        r.has_tessellation = true;
        r.tessellation = *in.pTessellationState;
    }
    if (const auto* v = in.pViewportState) {
        if (v->pNext) return (why = "a viewport extension structure"), false;
        r.has_viewport = true;
        r.viewport_count = v->viewportCount;
        r.scissor_count = v->scissorCount;
        r.viewports = copy_array(v->pViewports, v->pViewports ? v->viewportCount : 0);
        r.scissors = copy_array(v->pScissors, v->pScissors ? v->scissorCount : 0);
    }
    if (!in.pRasterizationState) return (why = "no rasterization state"), false;
    r.raster = *in.pRasterizationState;
    for (auto* s = static_cast<const VkBaseInStructure*>(r.raster.pNext); s; s = s->pNext) {
        const size_t size = raster_next_size(s->sType);
        if (!size) return (why = "a rasterization extension structure"), false;
        const auto* bytes = reinterpret_cast<const uint8_t*>(s);
        r.raster_next.emplace_back(bytes, bytes + size);
    }
    return true;
}

bool copy_output_state(const VkGraphicsPipelineCreateInfo& in, PipelineRecipe& r,
                       std::string& why) {
    if (const auto* m = in.pMultisampleState) {
        if (m->pNext) return (why = "a multisample extension structure"), false;
        r.has_multisample = true;
        r.multisample = *m;
        r.sample_mask = copy_array(m->pSampleMask, (uint32_t(m->rasterizationSamples) + 31) / 32);
    }
    if (const auto* d = in.pDepthStencilState) {
        if (d->pNext) return (why = "a depth-stencil extension structure"), false;
        r.has_depth_stencil = true;
        r.depth_stencil = *d;
    }
    if (const auto* b = in.pColorBlendState) {
        if (b->pNext) return (why = "a colour blend extension structure"), false;
        r.has_blend = true;
        r.blend = *b;
        r.blend_attachments = copy_array(b->pAttachments, b->attachmentCount);
    }
    if (const auto* d = in.pDynamicState)
        r.dynamic = copy_array(d->pDynamicStates, d->dynamicStateCount);
    return true;
}

bool copy_next(const VkGraphicsPipelineCreateInfo& in, PipelineRecipe& r, std::string& why) {
    for (auto* s = static_cast<const VkBaseInStructure*>(in.pNext); s; s = s->pNext) {
        if (s->sType == VK_STRUCTURE_TYPE_PIPELINE_CREATION_FEEDBACK_CREATE_INFO) continue;
        if (s->sType != VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO) {
            why = s->sType == VK_STRUCTURE_TYPE_PIPELINE_LIBRARY_CREATE_INFO_KHR ||
                          s->sType == VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_LIBRARY_CREATE_INFO_EXT
                      ? "a graphics pipeline library"
                      : "a pipeline extension structure (" + std::to_string(s->sType) + ")";
            return false;
        }
        const auto* ri = reinterpret_cast<const VkPipelineRenderingCreateInfo*>(s);
        r.has_rendering = true;
        r.rendering = *ri;
        r.color_formats = copy_array(ri->pColorAttachmentFormats, ri->colorAttachmentCount);
    }
    return true;
}

}  // namespace

std::unique_ptr<PipelineRecipe> copy_recipe(const VkGraphicsPipelineCreateInfo& in,
                                            const CodeOf& code, std::string& why) {
    if (in.flags & VK_PIPELINE_CREATE_LIBRARY_BIT_KHR) {
        why = "a graphics pipeline library";
        return nullptr;
    }
    auto r = std::make_unique<PipelineRecipe>();
    r->flags = in.flags & ~VkPipelineCreateFlags(VK_PIPELINE_CREATE_DERIVATIVE_BIT);
    r->layout = in.layout;
    r->render_pass = in.renderPass;
    r->subpass = in.subpass;
    if (!copy_stages(in, code, *r, why) || !copy_fixed_function(in, *r, why) ||
        !copy_output_state(in, *r, why) || !copy_next(in, *r, why))
        return nullptr;
    return r;
}

const StageRecipe* PipelineRecipe::fragment() const {
    for (const StageRecipe& s : stages)
        if (s.stage == VK_SHADER_STAGE_FRAGMENT_BIT) return &s;
    return nullptr;
}

bool PipelineRecipe::is_dynamic(VkDynamicState s) const {
    for (VkDynamicState d : dynamic)
        if (d == s) return true;
    return false;
}

// The stage infos and the state structures that point into this recipe.
void PipelineRecipe::build_pointers() {
    Built& b = built;
    b.stages.clear();
    for (StageRecipe& s : stages) {
        auto st = typed<VkPipelineShaderStageCreateInfo>(
            VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO);
        st.stage = s.stage;
        st.module = s.module;
        st.pName = s.entry.c_str();
        if (!s.spec_entries.empty() || !s.spec_data.empty()) {
            s.spec.pMapEntries = s.spec_entries.data();
            s.spec.pData = s.spec_data.data();
            st.pSpecializationInfo = &s.spec;
        }
        b.stages.push_back(st);
    }
    b.vertex_input = typed<VkPipelineVertexInputStateCreateInfo>(
        VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO);
    b.vertex_input.vertexBindingDescriptionCount = uint32_t(bindings.size());
    b.vertex_input.pVertexBindingDescriptions = bindings.data();
    b.vertex_input.vertexAttributeDescriptionCount = uint32_t(attributes.size());
    b.vertex_input.pVertexAttributeDescriptions = attributes.data();
    b.viewport =
        typed<VkPipelineViewportStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO);
    b.viewport.viewportCount = viewport_count;
    b.viewport.pViewports = viewports.empty() ? nullptr : viewports.data();
    b.viewport.scissorCount = scissor_count;
    b.viewport.pScissors = scissors.empty() ? nullptr : scissors.data();
    // The rasterization state's extension structures, chained in this copy.
    raster.pNext = nullptr;
    for (auto it = raster_next.rbegin(); it != raster_next.rend(); ++it) {
        auto* s = reinterpret_cast<VkBaseOutStructure*>(it->data());
        s->pNext = static_cast<VkBaseOutStructure*>(const_cast<void*>(raster.pNext));
        raster.pNext = s;
    }
    multisample.pSampleMask = sample_mask.empty() ? nullptr : sample_mask.data();
    blend.pAttachments = blend_attachments.empty() ? nullptr : blend_attachments.data();
    b.dynamic =
        typed<VkPipelineDynamicStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO);
    b.dynamic.dynamicStateCount = uint32_t(dynamic.size());
    b.dynamic.pDynamicStates = dynamic.data();
    rendering.pColorAttachmentFormats = color_formats.empty() ? nullptr : color_formats.data();
    rendering.pNext = nullptr;
}

const VkGraphicsPipelineCreateInfo& PipelineRecipe::info() {
    build_pointers();
    Built& b = built;
    VkGraphicsPipelineCreateInfo& i = b.info;
    i = typed<VkGraphicsPipelineCreateInfo>(VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO);
    i.pNext = has_rendering ? &rendering : nullptr;
    i.flags = flags;
    i.stageCount = uint32_t(b.stages.size());
    i.pStages = b.stages.data();
    i.pVertexInputState = &b.vertex_input;
    i.pInputAssemblyState = &input_assembly;
    i.pTessellationState = has_tessellation ? &tessellation : nullptr;
    i.pViewportState = has_viewport ? &b.viewport : nullptr;
    i.pRasterizationState = &raster;
    i.pMultisampleState = has_multisample ? &multisample : nullptr;
    i.pDepthStencilState = has_depth_stencil ? &depth_stencil : nullptr;
    i.pColorBlendState = has_blend ? &blend : nullptr;
    i.pDynamicState = dynamic.empty() ? nullptr : &b.dynamic;
    i.layout = layout;
    i.renderPass = render_pass;
    i.subpass = subpass;
    i.basePipelineIndex = -1;
    return i;
}

}  // namespace ds::layer
