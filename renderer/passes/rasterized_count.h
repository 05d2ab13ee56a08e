#pragma once
// count_fragments=on: a geometry pass's rasterized fragments, its depth complexity (part of
// each counting pass, not a frame pass of its own). Right after the pass, its own selection of
// draw groups is drawn again with the depth test off, no attachments and a fragment shader
// that only counts (shaders/count_rasterized.frag) into CountImages::rasterized, at the pass's
// sample count, with the same vertex shader, so coverage is the pass's own. The graph pass,
// "<pass>_rasterized", has the Measure role: the frame's pass list and timings keep it apart.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "renderer/graph/graph.h"
#include "renderer/passes/frame.h"
#include "renderer/passes/pass_util.h"
#include "renderer/passes/scene_draw.h"
#include "renderer/vk/descriptors.h"
#include "renderer/vk/pipeline.h"

namespace ds::passes {

class RasterizedCount {
  public:
    // The vertex shader the pass draws with: the shared scene one (shaders/common/
    // scene_vertex.glsl), forward's invariant=off experiment, or the shadow map's.
    enum class Vertex : uint8_t { Scene, SceneNonInvariant, Shadow };
    // What the pass draws: its vertex shader, sample count and selection (scene_draw.h).
    struct Selection {
        Vertex vertex = Vertex::Scene;
        VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
        std::vector<scene::AlphaMode> modes;
        Decals decals = Decals::Include;
        static constexpr VkCullModeFlags kEachGroup = VK_CULL_MODE_FLAG_BITS_MAX_ENUM;
        VkCullModeFlags cull = kEachGroup;  // or every group's
    };

    RasterizedCount(const PassServices& services, const char* pass);

    // Adds the measurement pass when `counts` is valid (count_fragments=on and the pass
    // runs): call right after the pass's own graph pass, whose result comes back first.
    void add(graph::RenderGraph& graph, const FrameInputs& in, const FrameResources& res,
             const CountImages& counts, Selection selection);
    void rebuild_pipelines(vk::DestroyList& retired) { pipelines_.rebuild(retired); }

  private:
    struct Variant {
        Vertex vertex = Vertex::Scene;
        VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
        bool operator==(const Variant&) const = default;
        size_t hash() const { return hash_fields(int(vertex), int(samples)); }
    };
    ShaderStages compile(const Variant& v) const;
    vk::Pipeline create(const Variant& v, const ShaderStages& s,
                        const graph::RenderTarget& target) const;
    void record(graph::PassContext& ctx, const FrameInputs& in, graph::ImageHandle counts,
                const Selection& selection);

    PassServices services_;
    std::string name_;
    vk::DescriptorSetLayout set_layout_;
    vk::PipelineLayout layout_;
    FrameDescriptorPool sets_;
    PipelineVariants<Variant> pipelines_;
};

}  // namespace ds::passes
