#pragma once
// The renderer facade: Settings + Scene + Camera in, pixels and timings out. Inside, every
// frame is a render graph: shadow -> depth_prepass -> gtao -> ao_spatial -> ao_temporal ->
// contact_shadows -> forward -> skybox -> transparent -> tonemap, passes switched off by the
// settings left out.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "renderer/graph/types.h"
#include "renderer/scene/scene.h"
#include "renderer/settings/settings.h"
#include "renderer/view/image.h"  // InspectedImage
#include "renderer/vk/capabilities.h"

namespace ds::vk {
class Context;
}

namespace ds {

struct RendererOptions {
    bool validate = false;  // validation layer (+ synchronization validation) and messenger
    std::string device;     // "" = first suitable, "N" = index, else a name substring
    // The inspector's window: surface instance extensions and VK_KHR_swapchain.
    std::vector<std::string> instance_extensions;
    bool swapchain = false;
};

// One pass of a frame, as measured by the GPU.
struct PassResult {
    std::string name;
    double gpu_ms = 0;  // from two timestamps around the pass
    // Pipeline statistics (0 without the device feature). Lavapipe counts fragment shader
    // invocations per rasterized 4x4 block before the depth test: not what a prepass saves.
    uint64_t vertex_shader_invocations = 0;
    uint64_t fragment_shader_invocations = 0;
    uint64_t clipping_primitives = 0;
    // count_fragments=on (depth_prepass, forward, transparent): fragments that really ran
    // the fragment shader after the depth and alpha tests, summed from a per-pixel u32 image.
    // Exact for shaders without discard (early fragment tests); a pipeline with discard
    // counts after the discard, and its late depth test may still reject the fragment.
    std::optional<uint64_t> shaded_fragments;
    // The graph resources the pass declared, by name, in declaration order.
    std::vector<std::string> reads, writes;
};

// One resource of the frame's graph (the inspector's Resources panel).
struct ResourceSummary {
    std::string name;
    bool is_image = true;
    VkFormat format = VK_FORMAT_UNDEFINED;  // images
    uint32_t width = 0, height = 0, samples = 1;
    graph::Semantic semantic = graph::Semantic::Other;
    graph::Lifetime lifetime = graph::Lifetime::Transient;
    uint64_t bytes = 0;  // buffers
};

// msaa: how the frame was multisampled.
struct MsaaResult {
    uint32_t samples = 1;
    std::string depth_resolve;  // msaa > 1: "native-max" | "native-min" | "shader"; else ""
    // msaa > 1 and read back: pixels whose HDR colour samples are not all equal (after
    // transparent, before the resolve); exact, counted by a compute pass over every sample.
    std::optional<uint64_t> edge_pixels;
    // ReadBack::WithMsaaDepth, msaa > 1 and a D32 depth only: every depth sample (per pixel,
    // `samples` consecutive, row 0 = top) and the resolved depth (one per pixel).
    std::vector<float> depth_samples;
    std::vector<float> resolved_depth;
};

// count_discards=on: fragments that ran the depth prepass's alpha-tested pipeline (the MASK one;
// masked_split=off: the one for all geometry), and how many of them it discarded. Exact
// (shader atomics; helper invocations do not count).
struct DiscardCounts {
    uint64_t invoked = 0;
    uint64_t discarded = 0;
};

struct FrameResult {
    uint32_t width = 0, height = 0;
    std::vector<uint8_t> rgba8;      // final image, sRGB-encoded, tightly packed, top row first;
                                     // empty when the frame was rendered without read-back
    std::vector<PassResult> passes;  // in execution order
    double gpu_ms = 0;               // first pass start to last pass end, from timestamps
    double cpu_ms = 0;               // host time to record and submit the frame (not the wait)
    // Pixels some surface covers: depth differs from "far" after the prepass (or forward).
    // Read back with the image, or with count_fragments=on; none for ReadBack::No otherwise.
    std::optional<uint64_t> covered_pixels;
    std::vector<std::string> skipped;  // "gtao: skipped (prepass off)", in pass order
    MsaaResult msaa;
    std::optional<DiscardCounts> masked_discards;  // count_discards=on with the prepass
    // Every resource of the frame's graph, in creation order (the inspect pass's own target
    // left out).
    std::vector<ResourceSummary> resources;
    // InspectRequest: the image as read; none when the frame has no image of that name (its
    // pass is off) or nothing was asked.
    std::optional<InspectedImage> inspected;
};

// Read back one graph image by name at the end of the frame ("final": the tonemapped image;
// any other: a compute pass "inspect" samples it, so it appears last in FrameResult::passes).
struct InspectRequest {
    std::string resource;  // "" = none
    uint32_t sample = 0;   // multisampled images
};

// Benchmarks skip the copy to host memory; WithMsaaDepth is Yes plus MsaaResult's depth.
// Color reads back the final image only (no covered pixels, no MSAA probe: the inspector).
enum class ReadBack { Yes, No, WithMsaaDepth, Color };

class Renderer {
  public:
    explicit Renderer(const RendererOptions& options);  // context, device, shader compiler
    ~Renderer();  // explicit teardown order, vkDeviceWaitIdle first
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    const vk::DeviceReport& device_report() const;
    // Uploads geometry, materials and textures (+ mips); replaces the previous scene.
    void set_scene(const scene::Scene& scene);
    // Draws one frame at width x height and reads it back (blocks until it is done).
    // Throws ds::Error before set_scene(), for a zero size, or for an msaa sample count the
    // device does not support (the message lists the supported ones); UsageError for a
    // material_alpha_cutoff name that is no MASK material of the scene (before the frame begins).
    FrameResult render(const scene::Camera& camera, const Settings& settings, uint32_t width,
                       uint32_t height, ReadBack read_back = ReadBack::Yes,
                       const InspectRequest& inspect = {});
    // A camera cut: the next frame's temporal passes start over (no history, and its
    // previous_view_projection is its own). set_scene() and a new size imply one.
    void camera_cut();
    // Hot reload: every pass rebuilds its pipelines, fail-safe (throws shader::ShaderError
    // naming file:line and keeps the current pipelines when a shader does not compile).
    void rebuild_pipelines();
    // The last frame's compiled graph as text (passes, resources, barriers); built on demand,
    // so frames that nobody dumps do not pay for the formatting.
    std::string graph_dump() const;
    uint64_t validation_message_count() const;
    VkInstance instance() const;  // for RenderDoc's device pointer
    // The device, for the inspector's presentation layer (ui/), which draws on it.
    vk::Context& context();

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace ds
