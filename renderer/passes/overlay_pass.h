#pragma once
// What the transparent and decals passes are, once (a pass never includes another pass):
// surfaces drawn over forward's HDR image against the read-only scene depth, closer-or-equal,
// lit without prepass inputs (LightingSet with the shadow map, AO and contact shadows; their
// own normals; shaders/transparent.*), in steps, each with its own pipeline. A subclass says
// whether it runs, its steps (ALPHA_MODE, blending), how a step draws, its count images and what
// its measurement draws; this class declares the pass, records it, replays it for pixel history
// and collects it (GeometryInstrument). The pipeline layout is {frame, material, lighting,
// count}.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "renderer/graph/graph.h"
#include "renderer/passes/frame.h"
#include "renderer/passes/frame_pass.h"
#include "renderer/passes/geometry_instrument.h"
#include "renderer/passes/lighting_set.h"
#include "renderer/passes/pass_util.h"
#include "renderer/scene/scene.h"
#include "renderer/vk/pipeline.h"

namespace ds::passes {

class OverlayPass : public FramePass {
  public:
    const char* name() const override { return name_.c_str(); }
    void rebuild_pipelines(vk::DestroyList& retired) override;
    // Reads res.depth (read-only attachment), res.shadow_map, res.ao, res.contact_shadows where
    // valid; draws into res.hdr (msaa > 1: res.msaa_hdr). Counts into counts(res) when valid.
    void add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) override;
    // shaded_fragments from counts(res); the pixel history's fragments.
    void collect(const FrameCollect& c, std::span<PassResult> own, FrameResult& frame) override;

  protected:
    // One step of the pass: its materials' ALPHA_MODE (none: the shader's BLEND path), whether
    // it blends, and its depth bias towards the camera (steps of the depth format; slope in
    // pixels' depth slopes).
    struct Step {
        std::optional<scene::AlphaMode> mode;
        bool blend = false;
        float bias_steps = 0.0f, bias_slope = 0.0f;
    };
    // `resolve`: at msaa > 1 the rendering ends by resolving res.msaa_hdr into res.hdr, which
    // the pass creates (the last pass that draws multisampled).
    OverlayPass(const PassServices& services, const char* name, bool resolve);

    virtual bool runs(const FrameOptions& o) const = 0;
    virtual const CountImages& counts(const FrameResources& res) const = 0;
    virtual std::vector<Step> steps() const = 0;
    // Draws step `step` (its pipeline is bound): the scene's draws for it, with `hooks`.
    virtual DrawCounts draw(VkCommandBuffer cmd, const FrameInputs& in, VkPipelineLayout layout,
                            const Step& step, DrawHooks hooks) const = 0;
    // What the measurement draw covers (count_fragments=on).
    virtual RasterizedCount::Selection measured(const FrameInputs& in) const = 0;

  private:
    struct Variant {
        int8_t step = 0;
        bool counting = false;  // COUNT_FRAGMENTS=1
        bool reverse_z = true;  // the bias's direction
        bool history = false;   // PIXEL_HISTORY=1: the replay's
        VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
        bool count_draws = false;  // COUNT_DRAWS=1 (with counting)
        bool operator==(const Variant&) const = default;
        size_t hash() const {
            return hash_fields(int(step), counting, reverse_z, history, int(samples), count_draws);
        }
    };
    ShaderStages compile(const Variant& variant) const;
    vk::Pipeline create(const Variant& variant, const ShaderStages& stages,
                        const graph::RenderTarget& target) const;
    std::string pipeline_name(const Variant& variant) const;
    // Binds what every step shares and draws the steps with `variants`' pipelines (the frame's
    // or the replay's), logged to `log`.
    void draw_steps(graph::PassContext& ctx, const FrameInputs& in, VkPipelineLayout layout,
                    const std::vector<Variant>& variants, const LightingInputs& lighting,
                    DrawLog* log);
    void add_history(graph::RenderGraph& graph, const FrameInputs& in, const FrameResources& res,
                     const std::vector<Variant>& frame_variants, const LightingInputs& lighting);

    PassServices services_;
    std::string name_;
    bool resolve_;
    LightingSet lighting_;
    GeometryInstrument instrument_;
    vk::PipelineLayout layout_;
    PipelineVariants<Variant> pipelines_;
};

}  // namespace ds::passes
