#pragma once
// `depthscope lint` (issue 31): a scene's content problems before anyone flies a camera, as
// findings in glTF-Validator's report shape (capture/diagnose/finding.h: code, severity 0 error
// .. 3 hint, message, pointer into the glTF; depthscope's magnitude, surfaces and fix). Each
// check is a file of capture/lint/ and reads the scene on the CPU, except OVERDRAW, which
// renders the scene's views exactly (count_fragments) when a renderer is given.
//
// Codes: COPLANAR_OVERLAP, DUPLICATE_INSTANCE, NEAR_COPLANAR_FIGHT (check_surface_pairs.cpp),
// DEGENERATE_TRIANGLE (check_degenerate.cpp), DECAL, DECAL_WITHOUT_BASE (check_decals.cpp),
// ALPHA_MODE (check_alpha_mode.cpp), OVERDRAW (check_overdraw.cpp: rendered; per mesh with
// meshoptimizer, check_mesh_overdraw.cpp), DEPTH_RANGE (check_depth_range.cpp).
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "capture/diagnose/finding.h"
#include "renderer/scene/scene.h"
#include "renderer/settings/settings.h"
#include "renderer/view/precision.h"

namespace ds {
class Renderer;
}

namespace ds::lint {

using diagnose::Finding;
using diagnose::FindingSurface;
using diagnose::Severity;

// The numbers the checks compare with; a --config file's "thresholds" may set each.
struct Thresholds {
    double overdraw = 4.0;              // OVERDRAW: rasterized fragments per covered pixel
    double mesh_overdraw = 2.0;         // OVERDRAW (info): meshopt_analyzeOverdraw's ratio
    double min_steps_per_unit = 100.0;  // DEPTH_RANGE: depth steps per scene unit at the far plane
    double coverage_drop = 0.5;         // ALPHA_MODE: a MASK texture's coverage fall at a mip
};

// A view the scene is looked at from: a camera node of the file, the "fit inside" position
// when it has none, or the one --camera / --look-at chose.
struct View {
    std::string name;     // "camera 0 (Main)", "fit inside", "--look-at"
    std::string pointer;  // "/nodes/N" for a camera node, else ""
    scene::Camera camera;
};

// The depth a view is stored in: the user's depth_format and reverse_z, and the planes the
// renderer uses for it (the znear / zfar knobs, else the camera's).
view::DepthConfig depth_config(const Settings& settings, const scene::Camera& camera);
// "d32f reverse-Z", "d24", "d16": the format as messages name it.
std::string depth_name(const view::DepthConfig& c);

struct Input {
    const scene::Scene& scene;
    const Settings& settings;
    std::vector<View>
        views;  // the first one sets the depth range (NEAR_COPLANAR_FIGHT, DEPTH_RANGE)
    Thresholds thresholds;
    uint32_t width = 640, height = 360;  // OVERDRAW's render size
    Renderer* renderer = nullptr;        // none: OVERDRAW's rendered part is skipped
    std::filesystem::path images;        // OVERDRAW's worst views as PNG here; "" none
};

// One scene's lint: every finding, ranked (diagnose::rank), the checks that ran and those that
// could not, and the images written.
struct Report {
    std::string scene, source;
    std::vector<View> views;
    std::vector<std::pair<std::string, std::string>> settings;  // as the user set them
    view::DepthConfig depth;                                    // the first view's
    std::vector<Finding> findings;
    std::vector<std::string> checks;
    std::vector<diagnose::SkippedDetector> skipped;
    std::vector<std::string> images;  // file names under Input::images
    bool truncated = false;           // max-issues dropped some (lint_config.h)
    uint32_t frames = 0;              // frames rendered
};

Report lint_scene(const Input& in);

}  // namespace ds::lint
