#include "renderer/passes/frame.h"

#include <algorithm>
#include <bit>
#include <sstream>
#include <string>

#include "renderer/common/error.h"
#include "renderer/format/format.h"
#include "renderer/scene/scene.h"
#include "renderer/settings/frame_knobs.h"

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
    using namespace knobs;
    FrameOptions o;
    o.prepass = knob_value(s, kPrepass);
    o.gbuffer = knob_value(s, kPrepassMode) == "gbuffer";
    o.depth_equal = knob_value(s, kDepthCompare) == "equal";
    o.alpha_cutoff = knob_value(s, kAlphaCutoff);
    o.alpha_level0 = knob_value(s, kAlphaLevel0);
    o.reverse_z = knob_value(s, kReverseZ);
    // The registry allows 1..8; VkSampleCountFlagBits are the powers of two themselves.
    const int msaa = knob_value(s, kMsaa);
    if (!std::has_single_bit(unsigned(msaa)))
        throw Error("setting msaa: " + std::to_string(msaa) +
                    " is not a power of two (1, 2, 4, 8)");
    o.samples = VkSampleCountFlagBits(msaa);
    // Both act on multisampled targets only; at 1x they would change nothing but the key.
    o.sample_shading = knob_value(s, kSampleShading) && o.msaa();
    o.alpha_to_coverage = knob_value(s, kAlphaToCoverage) && o.msaa();
    o.depth_choice = depth_choice_of(knob_value(s, kDepthFormat));
    // Nothing may run between the subpasses, and a render pass leaves no room for the per-pass
    // instruments (query resets, storage counters read by the next subpass): the passes that
    // cannot run on it say so in their configure().
    o.subpass = knob_value(s, kRenderPath) == "subpass" && o.prepass;
    o.znear = knob_value(s, kZnear);
    o.zfar = knob_value(s, kZfar);
    return o;
}

}  // namespace ds::passes
