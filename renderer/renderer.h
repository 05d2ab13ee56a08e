#pragma once
// The renderer facade: Settings + Scene + Camera in, pixels and timings out. Inside, every
// frame is a render graph declared by the ordered pass list (renderer/frame/frame_passes.cpp):
// shadow -> depth_prepass -> (depth_resolve) -> gtao -> ao_spatial -> ao_temporal ->
// contact_shadows -> forward -> skybox -> transparent -> tonemap, passes switched off by the
// settings left out, then the read-backs the caller asked for (FrameResult, frame_result.h).
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>
#include <nlohmann/json_fwd.hpp>

#include "renderer/common/surface_name.h"
#include "renderer/graph/types.h"
#include "renderer/passes/frame_result.h"
#include "renderer/scene/scene.h"
#include "renderer/settings/settings.h"

namespace ds::vk {
class Context;
struct DeviceReport;  // renderer/vk/capabilities.h, for the few that need the device's facts
}  // namespace ds::vk

namespace ds {

// What a surface_id value names in the current scene (Renderer::describe_surface).
struct SurfaceInfo {
    SurfaceName name;
    uint32_t instance = 0;  // scene instance index
    uint32_t triangle = 0;  // of its mesh
};
// surface id -> what it names (Renderer::describe_surface, or a copy of its answers): what the
// sample view and tune's surface samples take, so that they need no Renderer of their own.
using DescribeSurface = std::function<std::optional<SurfaceInfo>(uint32_t)>;

struct RendererOptions {
    bool validate = false;  // validation layer (+ synchronization validation) and messenger
    std::string device;     // "" = first suitable, "N" = index, else a name substring
    // The inspector's window: surface instance extensions and VK_KHR_swapchain.
    std::vector<std::string> instance_extensions;
    bool swapchain = false;
};

class Renderer {
  public:
    explicit Renderer(const RendererOptions& options);  // context, device, shader compiler
    ~Renderer();  // explicit teardown order, vkDeviceWaitIdle first
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    const vk::DeviceReport& device_report() const;
    // Uploads geometry, materials and textures (+ mips); replaces the previous scene.
    void set_scene(const scene::Scene& scene);
    // Draws one frame as `request` asks (size, read-back, inspected images, pixel history,
    // sample view) and reads it back (blocks until it is done).
    // Throws ds::Error before set_scene(), for a zero size, or for an msaa sample count the
    // device does not support (the message lists the supported ones); UsageError, before the
    // frame begins, for a material_alpha_cutoff name that is no MASK material of the scene, a
    // depth_format the device lacks, or planes (`camera`'s with the znear / zfar knobs) that
    // are not 0 < znear < zfar.
    // `request.pixel`: a PixelHistory (pixel_history.h) for that pixel (ds::Error outside the
    // frame). `request.samples`: MsaaSamples (msaa_samples.h) for that rectangle, clamped to
    // the frame (ds::Error when it starts outside the frame, is empty or larger than
    // MsaaSamplesPass::kMaxPixels); such a frame has surface_id on (with the prepass) whatever
    // the settings say. The first inspected image is FrameResult::inspected, the others
    // FrameResult::overlays.
    FrameResult render(const scene::Camera& camera, const Settings& settings,
                       const RenderRequest& request);
    // A camera cut: the next frame's temporal passes start over (no history, and its
    // previous_view_projection is its own). set_scene() and a new size imply one.
    void camera_cut();
    // Hot reload: every pass rebuilds its pipelines, fail-safe (throws shader::ShaderError
    // naming file:line and keeps the current pipelines when a shader does not compile).
    void rebuild_pipelines();
    // The last frame's compiled graph as text (passes, resources, barriers); built on demand,
    // so frames that nobody dumps do not pay for the formatting.
    std::string graph_dump() const;
    // The same as JSON (graph/dump_json.h): report.json's "graph".
    nlohmann::json graph_json() const;
    // The surface a surface_id texel names in the current scene (its instance's mesh,
    // material and node, and the triangle); none for 0 (nothing drawn) or an unknown id.
    std::optional<SurfaceInfo> describe_surface(uint32_t id) const;
    // Validation messages so far; after shutdown(), every one, teardown's included.
    uint64_t validation_message_count() const;
    // Waits for the device and destroys everything down to the instance now, so that what the
    // validation layer reports at vkDestroyDevice (objects never destroyed) is counted before
    // the caller decides its exit code. Afterwards only validation_message_count() may be
    // called (render() and set_scene() throw); the destructor then does nothing more.
    void shutdown();
    VkInstance instance() const;  // for RenderDoc's device pointer
    // The device, for the inspector's presentation layer (ui/), which draws on it.
    vk::Context& context();

  private:
    struct Impl;
    Impl& live() const;  // throws ds::Error after shutdown()
    std::unique_ptr<Impl> impl_;
    std::shared_ptr<const std::atomic<uint64_t>> validation_;  // outlives the device
};

}  // namespace ds
