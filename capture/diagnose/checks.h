#pragma once
// Diagnose's checks, one per file (check_zfight.cpp, check_equal.cpp, ...): each reads what
// the frames measured and appends findings, or says why it could not check. They are pure:
// no Vulkan, no renderer; the frames come from capture/diagnose/diagnose_run.cpp.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "capture/advice.h"
#include "capture/diagnose/finding.h"
#include "renderer/common/surface_name.h"
#include "renderer/passes/frame_result.h"
#include "renderer/scene/scene.h"
#include "renderer/settings/settings.h"

namespace ds {
struct ZfightResult;
}

namespace ds::diagnose {

struct CheckInput {
    const scene::Scene& scene;
    const Settings& settings;     // the user's, without the measurement knobs
    const FrameResult& measured;  // the measuring frame: the user's settings + measurement knobs
    // A frame of the user's settings alone (the advisor's first uncounted frame of it),
    // whose pipelines carry the early-Z verdicts without the counting variants; null when
    // none was rendered (then the measuring frame's are used: it counts nothing either).
    const FrameResult* plain = nullptr;
    const capture::Advice* advice = nullptr;  // the prepass advisor's, when it ran
    std::string advice_skipped;               // why it did not
    uint32_t width = 0, height = 0;
};

struct CheckOutput {
    std::vector<Finding> findings;
    std::vector<SkippedDetector> skipped;
    std::vector<std::string> ran;
    void skip(std::string detector, std::string reason) {
        skipped.push_back({std::move(detector), std::move(reason)});
    }
};

void check_zfight(const CheckInput& in, CheckOutput& out);  // ZFIGHT
void check_decals(const CheckInput& in,
                  CheckOutput& out);  // DECAL_ZFIGHT, DECAL_PASS_OFF, DECAL_BURIED
void check_equal(const CheckInput& in, CheckOutput& out);           // EQUAL_HOLES, EQUAL_TIES
void check_early_z(const CheckInput& in, CheckOutput& out);         // EARLY_Z_LOST
void check_draws(const CheckInput& in, CheckOutput& out);           // OCCLUDED_DRAW, WASTED_...
void check_advice(const CheckInput& in, CheckOutput& out);          // OVERDRAW, PREPASS_COST
void check_precision(const CheckInput& in, CheckOutput& out);       // DEPTH_PRECISION
void check_alpha_coverage(const CheckInput& in, CheckOutput& out);  // ALPHA_COVERAGE

// ALPHA_COVERAGE's findings for every MASK material whose uploaded chain loses more than
// `max_drop` (0..1) of level 0's coverage at a level of at least 16 texels a side (lint's
// ALPHA_MODE reuses them); whether the scene has a MASK material with a base colour texture.
std::vector<Finding> alpha_coverage_findings(const scene::Scene& scene, const Settings& settings,
                                             double max_drop);
bool has_masked_texture(const scene::Scene& scene);

// --- shared by the checks (check_util.cpp) ---

// A scene instance as a finding names it, with its glTF node's pointer.
FindingSurface surface_of(const scene::Scene& scene, uint32_t instance);
// The first instance a report's name stands for, as above; without a pointer when none.
FindingSurface surface_named(const scene::Scene& scene, const SurfaceName& name);
// The instances drawn with material `material` (at most `max`), as surface_of names them.
std::vector<FindingSurface> material_surfaces(const scene::Scene& scene, uint32_t material,
                                              size_t max);
// How a message names a surface: its node, or "mesh (material)" when the node is unnamed.
std::string label(const FindingSurface& s);
// A draw group (instances first .. first + count - 1): its instances' surfaces (at most
// `max`), and how a message names it: its one instance's label, or "mesh M (N instances)".
std::vector<FindingSurface> group_surfaces(const scene::Scene& scene, uint32_t first,
                                           uint32_t count, size_t max);
std::string group_label(const scene::Scene& scene, uint32_t first, uint32_t count);
// The reason the frame gives for leaving `pass` out ("prepass off"), or why the subpass path
// turned `knob` off; none when neither says.
std::optional<std::string> frame_skip_reason(const FrameResult& frame, std::string_view pass,
                                             std::string_view knob);
const PassResult* pass_named(const FrameResult& frame, std::string_view name);
// Per Z-fight pair (ZfightResult::pairs order), the pixels it fights in.
std::vector<std::vector<uint32_t>> pair_pixels(const ZfightResult& z);
// Whether instances named `a` and `b` are a classified overlay and its base (Scene::decals).
bool is_decal_pair(const scene::Scene& scene, const SurfaceName& a, const SurfaceName& b);
// "d32f reverse-Z", from the user's settings.
std::string depth_label(const Settings& settings);
// Pixels of an inspected image whose first channel equals `value` (within 0.5).
std::vector<uint32_t> pixels_where(const InspectedImage& image, float value);

}  // namespace ds::diagnose
