#pragma once
// shadow: the sun's shadow map, first in the frame. A fixed-size D32 image rendered with an
// orthographic projection along the sun that fit_sun() fits around the scene bounds; depth
// runs 0 (towards the sun) to 1 with LESS, whatever the scene's depth convention. Cull none:
// single-sided walls still cast shadows from behind. Opaque groups use a depth-only pipeline,
// MASK groups an alpha-tested one after them. Forward and transparent sample it with PCF
// (shaders/common/lighting.glsl).
#include <cstdint>

#include <vulkan/vulkan.h>
#include <glm/glm.hpp>

#include "renderer/graph/graph.h"
#include "renderer/passes/frame.h"
#include "renderer/passes/frame_pass.h"
#include "renderer/passes/geometry_instrument.h"
#include "renderer/passes/pass_util.h"
#include "renderer/scene/scene.h"
#include "renderer/settings/knob.h"
#include "renderer/vk/destroy_list.h"
#include "renderer/vk/pipeline.h"

namespace ds::passes {

class ShadowPass final : public FramePass {
  public:
    static constexpr const char* kName = "shadow";
    // 2048^2 costs lavapipe a few ms at most (the atrium: ~40 m across, 2 cm texels).
    static constexpr uint32_t kSize = kShadowMapSize;

    explicit ShadowPass(const PassServices& services);

    // Fail-safe: all stages compile first; on an error the current pipelines stay.
    const char* name() const override { return kName; }
    void rebuild_pipelines(vk::DestroyList& retired) override;
    static constexpr Knob<bool> kKnob{"shadows"};
    static std::vector<SettingDef> knobs();
    void configure(const FrameSetup& setup, FrameOptions& options) override;
    // Creates res.shadow_map and draws into it.
    void add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) override;
    // Its two pipelines and their draws.
    void collect(const FrameCollect& c, std::span<PassResult> own, FrameResult& frame) override;

    // World -> shadow clip space: looking along -to_sun, x/y/depth spanning the bounds
    // (a little padded), depth 0 nearest the sun.
    static glm::mat4 fit_sun(const scene::Bounds& bounds, glm::vec3 to_sun);

  private:
    struct Variant {
        bool mask = false;  // MASK materials: the alpha test (a fragment shader); else depth only
        bool counting = false;     // COUNT_FRAGMENTS=1 (opaque too then has a fragment shader)
        bool count_draws = false;  // COUNT_DRAWS=1 (with counting)
        bool operator==(const Variant&) const = default;
        size_t hash() const { return hash_fields(mask, counting, count_draws); }
    };
    struct Draw {
        Variant opaque, mask;  // their pipelines are made for the target when recorded
        PipelineInfo opaque_info, mask_info;
    };
    ShaderStages compile(const Variant& variant) const;
    vk::Pipeline create(const Variant& variant, const ShaderStages& stages,
                        const graph::RenderTarget& target) const;
    static std::string pipeline_name(const Variant& variant);
    void record(graph::PassContext& ctx, const FrameInputs& in, const Draw& draw);

    PassServices services_;
    vk::DescriptorSetLayout no_set_;  // set 2: the count set is set 3 in every counting shader
    GeometryInstrument instrument_;
    vk::PipelineLayout layout_;
    PipelineVariants<Variant> pipelines_;
};

}  // namespace ds::passes
