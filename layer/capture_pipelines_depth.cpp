// The Z-fight and EQUAL re-draw pipelines of an application's pipeline (zfight, equal_check):
// its stages with the fragment shader rewritten by layer/spirv/survival.h.
//   depth_record: the vertex stage hands gl_InstanceIndex on (instance_output.h); drawn in the
//     layer's attachment-less render pass, one sample, no tests, no colour (depth_records.h).
//   equal: drawn right after the counted draw in the application's pass, with its depth test,
//     no depth or stencil writes, no colour, early fragment tests: its survivors are the
//     fragments that pass the EQUAL test and are not discarded.
#include "layer/capture_pipelines.h"
#include "layer/spirv/instance_output.h"
#include "layer/spirv/measure.h"
#include "layer/spirv/survival.h"
#include "layer/typed.h"
#include "renderer/common/error.h"
#include "renderer/spirv/spirv_facts.h"

namespace ds::layer {

namespace {

const StageRecipe* fragment_stage(const PipelineRecipe& r) {
    for (const StageRecipe& s : r.stages)
        if (s.stage == VK_SHADER_STAGE_FRAGMENT_BIT) return &s;
    return nullptr;
}

bool equal_capable(const CountingPipeline& p) {
    if (p.dynamic_compare_op) return true;
    return p.compare_op == VK_COMPARE_OP_EQUAL || p.compare_op == VK_COMPARE_OP_LESS_OR_EQUAL ||
           p.compare_op == VK_COMPARE_OP_GREATER_OR_EQUAL;
}

}  // namespace

void read_depth_state(CountingPipeline& p, const PipelineRecipe& r) {
    p.depth_test = r.has_depth_stencil && r.depth_stencil.depthTestEnable;
    p.depth_write = r.has_depth_stencil && r.depth_stencil.depthWriteEnable;
    p.compare_op = r.has_depth_stencil ? r.depth_stencil.depthCompareOp : VK_COMPARE_OP_ALWAYS;
    p.dynamic_compare_op = r.is_dynamic(VK_DYNAMIC_STATE_DEPTH_COMPARE_OP);
    p.samples = r.has_multisample ? uint32_t(r.multisample.rasterizationSamples) : 1;
    for (const VkVertexInputBindingDescription& b : r.bindings)
        p.vertex_bindings.push_back(b.binding);
}

void CountingPipelines::build_depth(CountingPipeline& p, const PipelineRecipe& r) {
    const LayerSettings& s = config().settings;
    if (!p.why.empty()) return;
    if (const StageRecipe* fs = fragment_stage(r);
        fs && spirv::read_fragment_facts(*fs->code).writes_depth) {
        p.depth_record_why = p.equal_why = "its fragment shader writes gl_FragDepth";
        return;
    }
    if (p.depth_write || p.dynamic_depth_write) build_depth_record(p, r);
    if (s.equal_check && (p.depth_test || p.dynamic_depth_test) && equal_capable(p))
        build_equal(p, r);
}

// The fragment stage the re-draws use: the application's, or one that does nothing, rewritten.
std::vector<uint32_t> CountingPipelines::survival(CountingPipeline& p, PipelineRecipe& r,
                                                  bool early_tests, uint32_t instance_location,
                                                  std::string& why) {
    const StageRecipe* fs = fragment_stage(r);
    StageRecipe frag = fs ? *fs : *last_geometry_stage(r);
    std::erase_if(r.stages,
                  [](const StageRecipe& s) { return s.stage == VK_SHADER_STAGE_FRAGMENT_BIT; });
    std::vector<uint32_t> code;
    try {
        if (fs && reads_input_attachments(*fs->code)) {
            why = "its fragment shader reads input attachments";
            return {};
        }
        const std::vector<uint32_t> source =
            fs ? *fs->code : passthrough_fragment(*frag.code, frag.entry);
        code = survival_fragment(source, fs ? frag.entry : "main",
                                 SurvivalBindings{d_.counter_set, 0, 2, 3},
                                 SurvivalOptions{instance_location, early_tests});
    } catch (const Error& e) {
        why = std::string("the survival shader: ") + e.what();
        return {};
    }
    frag.stage = VK_SHADER_STAGE_FRAGMENT_BIT;
    if (!fs) frag.entry = "main";
    frag.module = module(code);
    frag.code = nullptr;
    r.stages.push_back(frag);
    r.layout = p.layout;
    return code;
}

void CountingPipelines::build_depth_record(CountingPipeline& p, PipelineRecipe r) {
    // The vertex stage (when it is the last before rasterization) hands the instance on; the
    // fragment stage is made first, from the stages as they were.
    const StageRecipe* last = last_geometry_stage(r);
    std::shared_ptr<const std::vector<uint32_t>> vertex;
    uint32_t location = UINT32_MAX;
    if (last && last->stage == VK_SHADER_STAGE_VERTEX_BIT) {
        try {
            InstanceOutput io = add_instance_output(*last->code, last->entry);
            location = io.location;
            vertex = std::make_shared<const std::vector<uint32_t>>(std::move(io.spirv));
        } catch (const Error& e) {
            p.depth_record_why = std::string("its vertex shader: ") + e.what();
            return;
        }
    }
    p.instance_known = location != UINT32_MAX;
    p.survival_spirv = survival(p, r, false, location, p.depth_record_why);
    if (p.survival_spirv.empty()) return;
    for (StageRecipe& s : r.stages) {
        if (s.stage == VK_SHADER_STAGE_FRAGMENT_BIT) continue;
        if (s.stage == VK_SHADER_STAGE_VERTEX_BIT && vertex) s.code = vertex;
        s.module = module(*s.code);
    }
    r.render_pass = empty_pass();
    r.subpass = 0;
    r.has_rendering = false;
    r.color_formats.clear();
    r.flags &= ~VkPipelineCreateFlags(VK_PIPELINE_CREATE_DERIVATIVE_BIT);
    if (r.has_depth_stencil) {
        r.depth_stencil.depthTestEnable = r.depth_stencil.depthWriteEnable = VK_FALSE;
        r.depth_stencil.stencilTestEnable = r.depth_stencil.depthBoundsTestEnable = VK_FALSE;
    }
    r.has_blend = false;
    r.blend_attachments.clear();
    r.has_multisample = true;
    r.multisample = typed<VkPipelineMultisampleStateCreateInfo>(
        VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO);
    r.multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
    r.sample_mask.clear();
    if (d_.t.CreateGraphicsPipelines(d_.device, VK_NULL_HANDLE, 1, &r.info(), nullptr,
                                     &p.depth_record) != VK_SUCCESS)
        p.depth_record_why = "the depth record copy of the pipeline failed to build";
}

void CountingPipelines::build_equal(CountingPipeline& p, PipelineRecipe r) {
    if (r.is_dynamic(VK_DYNAMIC_STATE_STENCIL_OP) ||
        r.is_dynamic(VK_DYNAMIC_STATE_STENCIL_WRITE_MASK)) {
        p.equal_why = "its stencil writes are dynamic state";
        return;
    }
    for (StageRecipe& s : r.stages)
        if (s.stage != VK_SHADER_STAGE_FRAGMENT_BIT) s.module = module(*s.code);
    if (survival(p, r, true, UINT32_MAX, p.equal_why).empty()) return;
    r.depth_stencil.depthWriteEnable = VK_FALSE;
    for (VkStencilOpState* st : {&r.depth_stencil.front, &r.depth_stencil.back}) {
        st->failOp = st->passOp = st->depthFailOp = VK_STENCIL_OP_KEEP;
        st->writeMask = 0;
    }
    mask_colour_and_coverage(r);
    r.flags &= ~VkPipelineCreateFlags(VK_PIPELINE_CREATE_DERIVATIVE_BIT);
    if (d_.t.CreateGraphicsPipelines(d_.device, VK_NULL_HANDLE, 1, &r.info(), nullptr,
                                     &p.equal) != VK_SUCCESS)
        p.equal_why = "the EQUAL check copy of the pipeline failed to build";
}

VkRenderPass CountingPipelines::empty_pass() {
    if (empty_pass_) return empty_pass_;
    VkSubpassDescription sub{};
    sub.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    auto info = typed<VkRenderPassCreateInfo>(VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO);
    info.subpassCount = 1;
    info.pSubpasses = &sub;
    d_.t.CreateRenderPass(d_.device, &info, nullptr, &empty_pass_);
    return empty_pass_;
}

VkFramebuffer CountingPipelines::framebuffer(VkExtent2D e) {
    VkFramebuffer& fb = framebuffers_[{e.width, e.height}];
    if (fb) return fb;
    auto info = typed<VkFramebufferCreateInfo>(VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO);
    info.renderPass = empty_pass();
    info.width = e.width;
    info.height = e.height;
    info.layers = 1;
    d_.t.CreateFramebuffer(d_.device, &info, nullptr, &fb);
    return fb;
}

}  // namespace ds::layer
