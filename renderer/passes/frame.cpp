#include "renderer/passes/frame.h"

#include <algorithm>
#include <bit>
#include <sstream>
#include <string>

#include "renderer/common/error.h"
#include "renderer/format/format.h"
#include "renderer/scene/scene.h"

namespace ds::passes {
namespace {

constexpr DepthChoice kDepthChoices[] = {DepthChoice::D32f, DepthChoice::D24, DepthChoice::D16};

// The formats a choice may be, in preference order: d32f D32_SFLOAT, else D32_SFLOAT_S8_UINT;
// d24 the common D24_UNORM_S8_UINT, else X8_D24_UNORM_PACK32 (a stencil is left unused).
std::span<const VkFormat> depth_candidates(DepthChoice choice) {
    static constexpr VkFormat d32f[] = {VK_FORMAT_D32_SFLOAT, VK_FORMAT_D32_SFLOAT_S8_UINT};
    static constexpr VkFormat d24[] = {VK_FORMAT_D24_UNORM_S8_UINT, VK_FORMAT_X8_D24_UNORM_PACK32};
    static constexpr VkFormat d16[] = {VK_FORMAT_D16_UNORM};
    switch (choice) {
        case DepthChoice::D32f:
            return d32f;
        case DepthChoice::D24:
            return d24;
        case DepthChoice::D16:
            break;
    }
    return d16;
}

VkFormat first_supported(DepthChoice choice, std::span<const VkFormat> supported) {
    for (VkFormat f : depth_candidates(choice))
        if (std::find(supported.begin(), supported.end(), f) != supported.end()) return f;
    return VK_FORMAT_UNDEFINED;
}

DepthChoice depth_choice_of(const std::string& name) {
    for (DepthChoice c : kDepthChoices)
        if (name == depth_choice_name(c)) return c;
    throw UsageError("setting depth_format: '" + name + "' is not d32f|d24|d16");
}

// A plane knob: "scene" keeps the camera's.
std::optional<float> plane(const Settings& s, const char* name) {
    if (s.get(name) == "scene") return std::nullopt;
    return s.get_float(name);
}

// "znear=0.5", or "zfar=200 (the scene camera's)" when the knob is at "scene".
std::string plane_text(const char* name, const std::optional<float>& knob, float value) {
    std::ostringstream out;
    out.precision(7);  // as the registry writes numbers
    out << name << "=" << value << (knob ? "" : " (the scene camera's)");
    return out.str();
}

}  // namespace

const char* depth_choice_name(DepthChoice choice) {
    switch (choice) {
        case DepthChoice::D32f:
            return "d32f";
        case DepthChoice::D24:
            return "d24";
        case DepthChoice::D16:
            break;
    }
    return "d16";
}

VkFormat resolve_depth_format(DepthChoice choice, std::span<const VkFormat> supported,
                              const std::string& device) {
    if (const VkFormat f = first_supported(choice, supported)) return f;
    std::string offered;
    for (DepthChoice c : kDepthChoices) {
        const VkFormat f = first_supported(c, supported);
        if (!f) continue;
        offered += std::string(offered.empty() ? "" : ", ") + depth_choice_name(c) + " (" +
                   format::name(f) + ")";
    }
    throw UsageError("depth_format=" + std::string(depth_choice_name(choice)) + ": " + device +
                     " does not support it as a sampled depth attachment; supported: " +
                     (offered.empty() ? "none" : offered));
}

scene::Camera effective_camera(const scene::Camera& camera, const FrameOptions& options) {
    scene::Camera c = camera;
    if (options.znear) c.znear = *options.znear;
    if (options.zfar) c.zfar = *options.zfar;
    if (!(c.znear > 0.0f))
        throw UsageError(plane_text("znear", options.znear, c.znear) +
                         ": the near plane must be above 0");
    if (!(c.znear < c.zfar))
        throw UsageError(plane_text("znear", options.znear, c.znear) + " must be below " +
                         plane_text("zfar", options.zfar, c.zfar));
    return c;
}

FrameOptions FrameOptions::from(const Settings& s) {
    FrameOptions o;
    o.prepass = s.get_bool("prepass");
    o.gbuffer = s.get("prepass_mode") == "gbuffer";
    o.depth_equal = s.get("depth_compare") == "equal";
    o.masked_split = s.get_bool("masked_split");
    o.prepass_sort = s.get_bool("prepass_sort");
    if (s.get("alpha_cutoff") != "material") o.alpha_cutoff = s.get_float("alpha_cutoff");
    o.shadows = s.get_bool("shadows");
    // GTAO and contact shadows read the prepass depth (and normals): no prepass, no effect.
    o.gtao = s.get_bool("gtao") && o.prepass;
    o.contact_shadows = s.get_bool("contact_shadows") && o.prepass;
    o.sky = s.get_bool("sky");
    o.decal_pass = s.get_bool("decal_pass");  // the renderer clears it for a scene without
    o.invariant = s.get_bool("invariant");
    o.reverse_z = s.get_bool("reverse_z");
    // equal_check reads forward's per-pixel counts and names the surfaces that won.
    o.equal_check =
        s.get_bool("equal_check") && o.prepass && o.depth_equal && s.get_int("msaa") == 1;
    // count_draws counts per draw in the counting shaders and names pixels by surface_id.
    o.count_draws = s.get_bool("count_draws");
    o.count_fragments = s.get_bool("count_fragments") || o.equal_check || o.count_draws;
    // The registry allows 1..8; VkSampleCountFlagBits are the powers of two themselves.
    const int msaa = s.get_int("msaa");
    if (!std::has_single_bit(unsigned(msaa)))
        throw Error("setting msaa: " + std::to_string(msaa) +
                    " is not a power of two (1, 2, 4, 8)");
    o.samples = VkSampleCountFlagBits(msaa);
    o.count_discards = s.get_bool("count_discards");
    // Both act on multisampled targets only; at 1x they would change nothing but the key.
    o.sample_shading = s.get_bool("sample_shading") && o.msaa();
    o.alpha_to_coverage = s.get_bool("alpha_to_coverage") && o.msaa();
    // Both diagnostics compare against the prepass's depth and winner; the detector compares
    // at pixel centres, which a multisampled depth (stored at sample positions) is not.
    o.zfight = s.get_bool("zfight") && o.prepass && !o.msaa();
    o.zfight_steps = uint32_t(s.get_int("zfight_steps"));
    o.depth_precision = (s.get_bool("depth_precision") || o.zfight) && o.prepass;
    o.hiz = s.get_bool("hiz") && o.prepass;  // built from the prepass's depth
    o.surface_id =
        (s.get_bool("surface_id") || o.zfight || o.equal_check || o.count_draws) && o.prepass;
    o.depth_choice = depth_choice_of(s.get("depth_format"));
    o.subpass = s.get("render_path") == "subpass" && o.prepass;
    if (o.subpass) {
        // Nothing may run between the subpasses, and a render pass leaves no room for the
        // per-pass instruments (query resets, storage counters read by the next subpass).
        o.gtao = o.contact_shadows = false;
        o.equal_check = o.count_draws = o.count_fragments = o.count_discards = false;
        o.zfight = o.depth_precision = o.surface_id = false;
        o.hiz = false;  // its place is between the subpasses
    }
    o.znear = plane(s, "znear");
    o.zfar = plane(s, "zfar");
    return o;
}

}  // namespace ds::passes
