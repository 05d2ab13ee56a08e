#pragma once
// triangle_size (triangle_size=on, with the prepass, not on render_path=subpass): one compute
// dispatch (shaders/triangle_size.comp) after the prepass, over its surface_id. Image
// `triangle_size` (R32_SFLOAT, frame size): per pixel the screen-space area in px² of the
// triangle that won the prepass depth test (at msaa > 1 sample 0's winner: surface_id is
// resolved from sample 0), clipped against the near plane only, so the parts outside the
// screen count; 0 where nothing was drawn. The same dispatch counts the covered pixels per
// power-of-two bin of area into a HostReadback buffer: a TriangleSizeResult (report.json
// "triangle_size"). It asks the prepass for surface ids, so it needs what they need:
// gl_PrimitiveID in the prepass's fragment shader, a feature of devices with geometryShader.
// The image is shown on a log heat scale in px² (its graph::Display).
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>
#include <nlohmann/json_fwd.hpp>

#include "renderer/passes/compute_kernel.h"
#include "renderer/passes/frame_pass.h"
#include "renderer/settings/knob.h"
#include "renderer/vk/buffer.h"
#include "renderer/vk/descriptors.h"
#include "renderer/vk/image.h"
#include "renderer/vk/pipeline.h"

namespace ds {

// Covered pixels by the area of the triangle that won them. Bin i counts areas in
// [2^(kMinExponent + i), 2^(kMinExponent + i + 1)) px², except that the first bin starts at 0
// (every area below 2^(kMinExponent + 1), zero included) and the last has no upper bound.
struct TriangleSizeResult {
    static constexpr int kMinExponent = -10;
    static constexpr int kMaxExponent = 30;
    static constexpr size_t kBins = size_t(kMaxExponent - kMinExponent + 1);

    std::array<uint64_t, kBins> bins{};
    uint64_t covered = 0;  // the bins' sum: pixels where surface_id names a surface
    uint64_t under_1 = 0;  // covered by triangles under 1 px² (the bins below 2^0)
    uint64_t under_4 = 0;  // under 4 px² (the bins below 2^2)

    // Bin `bin`'s bounds in px²: lower(0) is 0, upper(kBins - 1) is infinity.
    static double lower(size_t bin);
    static double upper(size_t bin);
    // Fills bins from the shader's u32 counts and sums covered, under_1 and under_4.
    static TriangleSizeResult from_counts(std::span<const uint32_t, kBins> counts);
};

namespace passes {

// report.json's `triangle_size`: covered pixels, those under 1 and 4 px², and the non-empty
// bins, each {from, to, pixels} in px² (the first from 0, the last to null: unbounded).
nlohmann::json triangle_size_json(const TriangleSizeResult& result);
void triangle_size_report(const TriangleSizeResult& result, const FrameResult& frame,
                          nlohmann::json& report);

class TriangleSizePass final : public FramePass {
  public:
    explicit TriangleSizePass(const PassServices& services);

    static constexpr Knob<bool> kKnob{"triangle_size"};
    static std::vector<SettingDef> knobs();

    const char* name() const override { return "triangle_size"; }
    void configure(const FrameSetup& setup, FrameOptions& options) override;
    void add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) override;
    void rebuild_pipelines(vk::DestroyList& retired) override;
    void collect(const FrameCollect& c, std::span<PassResult> own, FrameResult& frame) override;

  private:
    // One per scene instance, in instance order (so in surface base order, which the shader's
    // binary search needs): the instance's surfaces and where its mesh's triangles are.
    struct InstanceRow {
        uint32_t surface_base, triangles, first_index;
        int32_t vertex_offset;
        bool operator==(const InstanceRow&) const = default;
    };
    struct Bound {
        graph::ImageHandle surfaces, sizes;
        graph::BufferHandle histogram;
    };
    void update_rows(const GpuScene& scene);
    void record(graph::PassContext& ctx, const Bound& bound, const GpuScene& scene,
                VkDescriptorSet frame_set);

    PassServices services_;
    vk::Sampler nearest_;
    vk::DescriptorSetLayout set_layout_;
    vk::DescriptorPool pool_;
    // One set (Renderer::render waits for each frame before recording the next, as HostReadback
    // relies on), rewritten every frame: the graph's views change on resize.
    VkDescriptorSet set_ = VK_NULL_HANDLE;
    vk::PipelineLayout layout_;
    LazyComputePipeline pipeline_;   // built by the first frame that measures
    std::vector<InstanceRow> rows_;  // what rows_buffer_ holds
    vk::Buffer rows_buffer_;         // host-visible; rewritten when the scene's rows change
    graph::BufferHandle histogram_;  // this frame's
    bool on_ = false;                // this frame's (configure)
};

}  // namespace passes
}  // namespace ds
