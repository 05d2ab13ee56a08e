#pragma once
// What every pass of the seed frame shares: the per-frame uniforms, the settings that shape the
// frame (read once per frame from the registry), the graph handles passes meet through, and
// the services a pass is built with. Passes never include each other (DESIGN.md); they meet
// only here and in graph resources.
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>

#include <vulkan/vulkan.h>
#include <glm/glm.hpp>

#include "renderer/graph/types.h"
#include "renderer/passes/frame_result.h"
#include "renderer/settings/settings.h"

namespace ds {
class GpuScene;
class HostReadback;
namespace scene {
struct Camera;
}
namespace shader {
class Compiler;
}
namespace vk {
class Context;
}
}  // namespace ds

namespace ds::passes {

// std140 twin of FrameUniforms in shaders/common/frame.glsl (set 0, binding 0).
struct FrameUniforms {
    glm::mat4 view_projection{1.0f};  // the one expression both prepass and forward use
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f};
    glm::mat4 inverse_view_projection{1.0f};
    glm::mat4 inverse_projection{1.0f};
    glm::mat4 previous_view_projection{1.0f};         // last frame's, for temporal reprojection
    glm::mat4 sun_view_projection{1.0f};              // world -> shadow map clip space
    glm::vec4 camera_position{0.0f};                  // xyz world
    glm::vec4 sun_direction{0.0f, 1.0f, 0.0f, 0.0f};  // xyz unit, towards the sun
    glm::vec4 sun_radiance{0.0f};                     // rgb colour * intensity
    glm::vec4 sky_ambient{0.0f};                      // rgb hemispherical ambient, above
    glm::vec4 ground_ambient{0.0f};                   // rgb hemispherical ambient, below
    glm::vec4 viewport{0.0f};                         // xy output size in pixels, zw 1 / size
    glm::vec4 depth_params{0.0f};              // x znear, y zfar, z 1 = reverse-Z, w exposure
    glm::vec4 alpha{-1.0f, 0.0f, 0.0f, 0.0f};  // x cutoff (< 0: material's), y 1 alpha_level0
    glm::uvec4 flags{0u};                      // x kFrame* bits, y frame number
};
static_assert(sizeof(FrameUniforms) == 7 * 64 + 9 * 16);

// FrameUniforms::flags.x bits (mirrored in shaders/common/frame.glsl).
inline constexpr uint32_t kFrameShadows = 1u << 0;         // shadow map valid
inline constexpr uint32_t kFrameAO = 1u << 1;              // AO image holds GTAO (else white)
inline constexpr uint32_t kFrameContactShadows = 1u << 2;  // contact image valid (else 1)
inline constexpr uint32_t kFrameReverseZ = 1u << 3;

// Formats of the frame's imported colour targets (FrameTargets creates them).
inline constexpr VkFormat kFinalFormat = VK_FORMAT_R8G8B8A8_SRGB;      // tonemap writes it
inline constexpr VkFormat kHdrFormat = VK_FORMAT_R16G16B16A16_SFLOAT;  // scene colour
// The scene colour's clear: linear radiance behind everything when the sky pass is off.
inline constexpr std::array<float, 4> kHdrBackground = {0.25f, 0.42f, 0.85f, 1.0f};

// render_path=subpass: the render pass prepass (subpass 0) and forward + skybox (subpass 1) form.
inline constexpr const char* kSubpassGroup = "gbuffer_lighting";

// depth_format's choices; the VkFormat each names depends on the device (resolve_depth_format).
enum class DepthChoice : uint8_t { D32f, D24, D16 };

// The options of one frame: the frame-wide knobs (settings/frame_knobs.h), parsed once by
// from(), then the facts that passes own and others read, set by their owner's configure()
// or resolve() (the pass list's order; names and meanings: the registry's help text).
struct FrameOptions {
    bool prepass = true;
    // prepass_mode=gbuffer: the prepass writes normals and roughness too (forward reads them);
    // depth: Z only (opaque pipeline without a fragment stage). Meaningful with the prepass.
    bool gbuffer = true;
    bool depth_equal = true;  // depth_compare=equal (else greater_or_equal; prepass on)
    // render_path=subpass (effective: with the prepass): prepass, forward and skybox are the
    // two subpasses of one render pass (kSubpassGroup); the passes that need neighbours
    // (gtao, contact_shadows) or instrument a pass (counts, surface_id, zfight, ...) are off.
    bool subpass = false;
    std::optional<float> alpha_cutoff;  // none: each material's own
    bool alpha_level0 = false;          // the MASK test samples alpha at level 0 (uniform)
    bool reverse_z = true;
    bool sample_shading = false;                            // effective: also needs msaa > 1
    bool alpha_to_coverage = false;                         // effective: also needs msaa > 1
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;  // msaa
    DepthChoice depth_choice = DepthChoice::D32f;
    // The scene depth's format for depth_choice on this device: the registry cannot know the
    // device, so from() leaves it undefined and the renderer resolves it (resolve_depth_format)
    // before the frame begins.
    VkFormat depth_format = VK_FORMAT_UNDEFINED;
    std::optional<float> znear, zfar;  // none: the scene camera's own

    // Set by the pass that owns them (configure), read by others.
    bool shadows = true;  // ShadowPass: the shadow map exists
    bool gtao = true;     // GtaoPass: gtao runs (ao_spatial and ao_temporal follow it)
    std::optional<std::string> gtao_skipped;  // GtaoPass: why not, for the passes that follow
    bool contact_shadows = true;              // ContactShadowsPass
    bool sky = true;                          // SkyboxPass
    bool decal_pass = true;    // DecalsPass: decal groups are drawn by it, not by the others
    bool count_draws = false;  // DrawCountsPass: per-draw counts and occlusion queries
    bool zfight = false;       // ZfightPass (clear_counts creates and clears its image)
    // What passes ask of the passes that provide it (configure), and the providers' decisions
    // (resolve): per-pixel counts in every geometry pass (ClearCountsPass), the prepass's
    // winning surface per pixel (DepthPrepass), the depth step per pixel (DepthPrecisionPass).
    // surface_id_samples: at msaa > 1 with surface ids, the prepass STOREs every sample of
    // res.msaa_surface_id for a later pass (zfight), not only the SAMPLE_ZERO resolve.
    struct Requests {
        bool counts = false, surface_id = false, depth_precision = false;
        bool surface_id_samples = false;
    } requests;
    bool count_fragments = false;
    bool surface_id = false;
    bool depth_precision = false;

    static FrameOptions from(const Settings& settings);
    // The depth test that keeps the nearer fragment, and the clear value for "far".
    VkCompareOp closer() const { return reverse_z ? VK_COMPARE_OP_GREATER : VK_COMPARE_OP_LESS; }
    VkCompareOp closer_or_equal() const {
        return reverse_z ? VK_COMPARE_OP_GREATER_OR_EQUAL : VK_COMPARE_OP_LESS_OR_EQUAL;
    }
    float far_depth() const { return reverse_z ? 0.0f : 1.0f; }
    bool msaa() const { return samples != VK_SAMPLE_COUNT_1_BIT; }
    // The prepass writes normals and roughness (prepass on, prepass_mode=gbuffer).
    bool gbuffer_prepass() const { return prepass && gbuffer; }
    // prepass_mode=depth with the prepass on: forward shades from its own normals, and the
    // screen-space passes read normals reconstructed from depth.
    bool depth_only_prepass() const { return prepass && !gbuffer; }
};

// depth_format's name for `choice` ("d32f", "d24", "d16").
const char* depth_choice_name(DepthChoice choice);
// The format `choice` names among the device's `supported` depth formats: d32f D32_SFLOAT (or
// D32_SFLOAT_S8_UINT), d24 D24_UNORM_S8_UINT or X8_D24_UNORM_PACK32, d16 D16_UNORM, the first
// that `supported` holds. Throws UsageError naming `device` and the choices it supports.
VkFormat resolve_depth_format(DepthChoice choice, std::span<const VkFormat> supported,
                              const std::string& device);
// The camera the frame renders with: `camera` with the options' znear / zfar where set. Throws
// UsageError unless 0 < znear < zfar (the planes as combined, so a knob is checked against the
// scene camera's other plane).
scene::Camera effective_camera(const scene::Camera& camera, const FrameOptions& options);

// The shadow map's size (square); its count images have it too.
inline constexpr uint32_t kShadowMapSize = 2048;

// count_fragments=on: one pass's per-pixel u32 counts (clear_counts creates and zeroes them,
// readback_counts copies them): the fragments that ran its fragment shader (shaded; counted
// on entry), those its alpha test then discarded, and those its draws rasterized (a
// measurement draw with the depth test off: depth complexity). `quads` (half size, one texel
// per 2x2 quad) counts the quads that ran with at least one live lane, where the device has
// quad subgroup operations in fragment shaders; invalid elsewhere.
// count_draws=on adds `draws`: a host buffer of one u32 per scene draw group (GpuScene
// draw_groups order), the shaded fragments of each, binding 2 of the count set. in_view:
// the pass draws the camera's view (not the shadow map's), so shaded - visible is waste.
struct CountImages {
    graph::ImageHandle shaded, discarded, rasterized, quads;
    graph::BufferHandle draws;
    bool in_view = true;
    bool valid() const { return shaded.valid(); }
};

// Graph handles the passes of one frame meet through; a pass fills what it writes.
struct FrameResources {
    graph::BufferHandle frame_uniforms;  // FrameUniforms (imported)
    graph::ImageHandle shadow_map;       // PassServices::preferred_depth_format, absolute size
    graph::ImageHandle depth;            // FrameOptions::depth_format; reverse-Z unless off
    // World normals, n * 0.5 + 0.5: the G-buffer prepass's "normals" (A2B10G10R10), or with
    // prepass_mode=depth normals_from_depth's "depth_normals" (RGBA8, from depth).
    graph::ImageHandle normals;
    graph::ImageHandle roughness;        // R8; the G-buffer prepass only
    graph::ImageHandle ao_raw;           // gtao output
    graph::ImageHandle ao_filtered;      // ao_spatial output
    graph::ImageHandle ao;               // ao_temporal output (what forward reads)
    graph::ImageHandle contact_shadows;  // R8, 1 = lit
    graph::ImageHandle hdr;              // R16G16B16A16_SFLOAT scene colour
    // msaa > 1 only (imported, so they can be probed after the graph): the multisampled
    // depth the prepass stores and forward, skybox and transparent load, and the
    // multisampled HDR colour that transparent resolves into hdr.
    graph::ImageHandle msaa_depth;
    graph::ImageHandle msaa_hdr;
    // msaa > 1 with surface_id: the prepass's per-sample surface ids (a transient, STOREd only
    // when the frame has a SampleQuery, msaa_samples reads it, or when requested: zfight).
    graph::ImageHandle msaa_surface_id;
    graph::ImageHandle final_image;  // R8G8B8A8_SRGB (imported; tonemap writes it)
    // With count_fragments=on: each counting pass's CountImages (those that run).
    CountImages shadow_counts;  // kShadowMapSize square
    CountImages prepass_counts;
    CountImages forward_counts;
    CountImages decal_counts;  // decal_pass (effective) only
    CountImages transparent_counts;
    // Every counting pass's images, in pass order (invalid ones included).
    std::array<const CountImages*, 5> all_counts() const {
        return {&shadow_counts, &prepass_counts, &forward_counts, &decal_counts,
                &transparent_counts};
    }
    // Diagnostics (off: invalid). surface_id: R32_UINT, the prepass's winning surface per
    // pixel (gpu_scene.h SurfaceTable; 0 = none); zfight: R32_UINT competitors per pixel (at
    // msaa > 1 competing samples, summed over the pixel's samples).
    graph::ImageHandle surface_id;
    graph::ImageHandle zfight;
    graph::ImageHandle equal_check;      // R32_UINT: 0 ok, 1 hole, 2 shaded more than once
    graph::ImageHandle depth_precision;  // RGBA32F: step and distance along the ray
};

// Built once per Renderer; what a pass needs to create pipelines and record.
struct PassServices {
    vk::Context& context;
    shader::Compiler& compiler;
    VkDescriptorSetLayout frame_layout;     // set 0: FrameUniforms + instances
    VkDescriptorSetLayout material_layout;  // set 1: one per material (gpu_scene.h)
    // The device's first depth format (vk::DeviceReport::depth_format): the shadow map's, and
    // the scene depth pipelines are warmed up with (what d32f gives where the device has it).
    // A frame's scene depth is FrameOptions::depth_format: passes that attach it follow that.
    VkFormat preferred_depth_format;
    HostReadback& readback;  // host buffers the read-back passes copy into
};

// Per-frame inputs beyond the graph handles.
struct FrameInputs {
    const GpuScene* scene = nullptr;
    VkDescriptorSet frame_set = VK_NULL_HANDLE;  // set 0 for this frame
    FrameOptions options;
    glm::vec3 camera_position{0.0f};
    uint64_t frame_number = 0;
    ReadBack read_back = ReadBack::Yes;   // what the caller reads back after the fence
    std::vector<InspectRequest> inspect;  // resources to read back through the inspect pass
    std::optional<PixelQuery> pixel;      // pixel history: the geometry passes replay for it
    std::optional<SampleQuery> samples;   // the sample view: msaa_samples reads these pixels
};

}  // namespace ds::passes
