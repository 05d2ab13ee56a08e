// Building one pipeline's counting and measurement copies from its recipe.
#include "layer/capture_pipelines.h"
#include "layer/spirv/instrument.h"
#include "layer/spirv/measure.h"
#include "layer/typed.h"
#include "renderer/common/error.h"
#include "renderer/spirv/spirv_facts.h"

namespace ds::layer {

namespace {

bool alpha_to_coverage(const PipelineRecipe& r) {
    return r.has_multisample && r.multisample.alphaToCoverageEnable;
}

}  // namespace

void CountingPipelines::build(CountingPipeline& p, PipelineRecipe r) {
    VkPipelineLayout layout = extended_layout(r.layout, p.app_sets, p.why);
    if (!layout) return;
    p.layout = layout;
    p.dynamic_depth_test = r.is_dynamic(VK_DYNAMIC_STATE_DEPTH_TEST_ENABLE);
    p.dynamic_depth_write = r.is_dynamic(VK_DYNAMIC_STATE_DEPTH_WRITE_ENABLE);
    p.dynamic_stencil_test = r.is_dynamic(VK_DYNAMIC_STATE_STENCIL_TEST_ENABLE);
    p.dynamic_depth_bounds = r.is_dynamic(VK_DYNAMIC_STATE_DEPTH_BOUNDS_TEST_ENABLE);
    // The pipeline's own modules may be gone: each stage gets the layer's copy.
    for (StageRecipe& s : r.stages) {
        if (s.stage != VK_SHADER_STAGE_FRAGMENT_BIT) {
            s.module = module(*s.code);
            continue;
        }
        p.has_fragment = true;
        try {
            p.early_z = spirv::early_z_verdict(*s.code, alpha_to_coverage(r));
            InstrumentResult done =
                instrument_fragment(*s.code, s.entry, CounterBindings{d_.counter_set, 0, 1},
                                    alpha_to_coverage(r));
            p.early_tests_added = done.early_fragment_tests_added;
            p.discard_sites = done.discard_sites;
            p.instrumented = std::move(done.spirv);
        } catch (const Error& e) {
            p.why = std::string("its fragment shader: ") + e.what();
            return;
        }
        s.module = module(p.instrumented);
    }
    if (!p.has_fragment) p.early_z = "guaranteed";
    build_measure(p, r);
    if (!p.has_fragment) return;  // it shades nothing: the application's pipeline counts as is
    r.layout = layout;
    if (d_.t.CreateGraphicsPipelines(d_.device, VK_NULL_HANDLE, 1, &r.info(), nullptr,
                                     &p.counting) != VK_SUCCESS)
        p.why = "the counting copy of the pipeline failed to build";
}

void mask_colour_and_coverage(PipelineRecipe& r) {
    for (auto& a : r.blend_attachments) {
        a.blendEnable = VK_FALSE;
        a.colorWriteMask = 0;
    }
    if (r.has_multisample) {
        r.multisample.alphaToCoverageEnable = VK_FALSE;
        r.multisample.alphaToOneEnable = VK_FALSE;
    }
}

// The measurement shader mirrors its outputs.
const StageRecipe* last_geometry_stage(const PipelineRecipe& r) {
    for (VkShaderStageFlagBits stage :
         {VK_SHADER_STAGE_GEOMETRY_BIT, VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT,
          VK_SHADER_STAGE_VERTEX_BIT})
        for (const StageRecipe& s : r.stages)
            if (s.stage == stage) return &s;
    return nullptr;
}

void CountingPipelines::build_measure(CountingPipeline& p, PipelineRecipe& original) {
    PipelineRecipe r = original;
    std::erase_if(r.stages, [](const StageRecipe& s) {
        return s.stage == VK_SHADER_STAGE_FRAGMENT_BIT;
    });
    const StageRecipe* last = last_geometry_stage(r);
    if (!last) {
        p.why = "no vertex stage (mesh shaders are not analysed)";
        return;
    }
    StageRecipe frag = *last;  // its specialization constants size the mirrored arrays
    frag.stage = VK_SHADER_STAGE_FRAGMENT_BIT;
    frag.entry = "main";
    try {
        p.measure_spirv = measurement_fragment(*last->code, last->entry,
                                               CounterBindings{d_.counter_set, 0, 1});
    } catch (const Error& e) {
        p.why = std::string("the measurement shader: ") + e.what();
        return;
    }
    frag.module = module(p.measure_spirv);
    frag.code = nullptr;
    r.stages.push_back(frag);
    r.layout = p.layout;
    if (r.has_depth_stencil) {
        r.depth_stencil.depthTestEnable = VK_FALSE;
        r.depth_stencil.depthWriteEnable = VK_FALSE;
        r.depth_stencil.stencilTestEnable = VK_FALSE;
        r.depth_stencil.depthBoundsTestEnable = VK_FALSE;
    }
    mask_colour_and_coverage(r);
    if (r.has_multisample) {
        r.multisample.sampleShadingEnable = VK_FALSE;
        r.sample_mask.clear();
    }
    if (d_.t.CreateGraphicsPipelines(d_.device, VK_NULL_HANDLE, 1, &r.info(), nullptr,
                                     &p.measure) != VK_SUCCESS)
        p.why = "the measurement copy of the pipeline failed to build";
}

}  // namespace ds::layer
