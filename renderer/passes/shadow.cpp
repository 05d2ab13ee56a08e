#include "renderer/passes/shadow.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "renderer/gpu_scene/gpu_scene.h"
#include "renderer/passes/scene_draw.h"
#include "renderer/shader/compiler.h"
#include "renderer/vk/context.h"
#include "renderer/vk/functions.h"

namespace ds::passes {

using graph::Access;
using scene::AlphaMode;

ShadowPass::ShadowPass(const PassServices& services)
    : services_(services),
      no_set_(services.context, {}, "shadow empty set"),
      instrument_(services, kName, no_set_.handle()),
      pipelines_([this](const Variant& v) { return compile(v); },
                 [this](const Variant& v, const ShaderStages& s, const graph::RenderTarget& t) {
                     return create(v, s, t);
                 },
                 [](const Variant& v, const ShaderStages& s) {
                     return describe_pipeline(pipeline_name(v), s, /*alpha_to_coverage=*/false);
                 }) {
    layout_ = vk::PipelineLayout(services.context, instrument_.sets(), {}, "shadow layout");
    pipelines_.info({.mask = false});  // shader errors surface at start-up, not in the first frame
}

void ShadowPass::rebuild_pipelines(vk::DestroyList& retired) {
    pipelines_.rebuild(retired);
    instrument_.rebuild_pipelines(retired);
}

ShaderStages ShadowPass::compile(const Variant& v) const {
    std::vector<shader::Define> vert_defines, defines = {{"ALPHA_MASK", v.mask ? "1" : "0"}};
    if (v.counting) add_count_defines(defines, vert_defines, services_.context, v.count_draws);
    ShaderStages s;
    s.vert = services_.compiler.compile("shadow.vert", shader::Stage::Vertex, vert_defines).spirv;
    if (!v.mask && !v.counting) return s;  // depth only
    s.frag = services_.compiler.compile("shadow.frag", shader::Stage::Fragment, defines).spirv;
    return s;
}

std::string ShadowPass::pipeline_name(const Variant& v) {
    std::string name = v.mask ? "shadow mask" : "shadow opaque";
    if (v.counting) name += " counting";
    return name;
}

void ShadowPass::collect(const FrameCollect& c, std::span<PassResult> own, FrameResult& frame) {
    instrument_.collect(c, own, frame, {});
}

vk::Pipeline ShadowPass::create(const Variant& v, const ShaderStages& s,
                                const graph::RenderTarget& target) const {
    vk::GraphicsPipelineBuilder b =
        scene_pipeline_builder(layout_.handle(), s.vert, s.frag, VertexInputs::PositionUv);
    apply_target(b, target);
    return b.build(services_.context, pipeline_name(v).c_str());
}

std::vector<SettingDef> ShadowPass::knobs() {
    return {bool_knob(kKnob, "passes", true, "directional-light shadow map (PCF in forward)",
                      Invalidates::Nothing)};
}

void ShadowPass::configure(const FrameSetup& setup, FrameOptions& o) {
    o.shadows = knob_value(setup.settings, kKnob);
    if (!o.shadows) set_skipped("shadows=off");
}

void ShadowPass::add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) {
    instrument_.begin_frame(res.shadow_counts, /*queries=*/false, 0);
    if (!in.options.shadows) return;
    const bool counting = res.shadow_counts.valid();
    const bool count_draws = res.shadow_counts.draws.valid();
    const Variant opaque{.mask = false, .counting = counting, .count_draws = count_draws};
    const Variant mask{.mask = true, .counting = counting, .count_draws = count_draws};
    const Draw draw{opaque, mask, pipelines_.info(opaque), pipelines_.info(mask)};
    struct Data {
        FrameInputs in;
    };
    graph.add_pass<Data>(
        kName,
        [&](graph::PassBuilder& b, Data& d) {
            res.shadow_map =
                b.create_image("shadow_map", {.format = services_.preferred_depth_format,
                                              .size = graph::ImageSize::fixed(kSize, kSize),
                                              .semantic = graph::Semantic::ShadowDepth});
            // Stored: forward and transparent sample it after this pass.
            b.depth(res.shadow_map, {.load = graph::Load::Clear, .clear = 1.0f});
            b.read(res.frame_uniforms, Access::UniformRead,
                   graph::Shader::Vertex | graph::Shader::Fragment);
            instrument_.declare(b);
            d = {in};
        },
        [this, draw](graph::PassContext& ctx, const Data& d) { record(ctx, d.in, draw); });
    instrument_.add_measure(graph, in, res,
                            {.vertex = RasterizedCount::Vertex::Shadow,
                             .modes = {AlphaMode::Opaque, AlphaMode::Mask},
                             .decals = scene_groups(in.options.decal_pass),
                             .cull = VK_CULL_MODE_NONE});
}

void ShadowPass::record(graph::PassContext& ctx, const FrameInputs& in, const Draw& draw) {
    VkCommandBuffer cmd = ctx.cmd();
    const VkPipelineLayout layout = layout_.handle();
    instrument_.bind_counts(ctx, in.frame_number, layout);
    set_depth_state(cmd, /*test=*/true, /*write=*/true, VK_COMPARE_OP_LESS);
    bind_geometry(cmd, *in.scene);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 0, 1, &in.frame_set, 0,
                            nullptr);
    const Decals decals = scene_groups(in.options.decal_pass);
    const AlphaMode opaque_modes[] = {AlphaMode::Opaque};
    const AlphaMode mask_modes[] = {AlphaMode::Mask};
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS,
                      pipelines_.get(draw.opaque, ctx.target()));
    instrument_.used(
        draw.opaque_info,
        draw_groups(cmd, *in.scene, layout, opaque_modes, decals, VK_CULL_MODE_NONE).draws);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS,
                      pipelines_.get(draw.mask, ctx.target()));
    instrument_.used(
        draw.mask_info,
        draw_groups(cmd, *in.scene, layout, mask_modes, decals, VK_CULL_MODE_NONE).draws);
}

glm::mat4 ShadowPass::fit_sun(const scene::Bounds& bounds, glm::vec3 to_sun) {
    scene::Bounds b = bounds;
    if (!b.valid()) b = {glm::vec3(-1.0f), glm::vec3(1.0f)};
    const glm::vec3 l = glm::normalize(to_sun);
    const glm::vec3 up = std::abs(l.y) > 0.99f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    const glm::vec3 center = b.center();
    const glm::mat4 view = glm::lookAt(center + l, center, up);
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 corner((i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y,
                               (i & 4) ? b.max.z : b.min.z);
        const glm::vec3 p = glm::vec3(view * glm::vec4(corner, 1.0f));
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    // A margin so geometry on the bounds is never clipped or on the border texels.
    const glm::vec3 pad = 0.01f * (hi - lo) + glm::vec3(0.05f);
    lo -= pad;
    hi += pad;
    // The view looks down -z: distance from the sun is -z, from -hi.z (near) to -lo.z (far).
    const float near = -hi.z, far = -lo.z;
    glm::mat4 p(1.0f);
    p[0][0] = 2.0f / (hi.x - lo.x);
    p[3][0] = -(hi.x + lo.x) / (hi.x - lo.x);
    p[1][1] = 2.0f / (hi.y - lo.y);
    p[3][1] = -(hi.y + lo.y) / (hi.y - lo.y);
    p[2][2] = -1.0f / (far - near);
    p[3][2] = -near / (far - near);
    return p * view;
}

}  // namespace ds::passes
