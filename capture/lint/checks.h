#pragma once
// lint's checks, one per file: each reads the scene (and OVERDRAW the frames it renders) and
// appends findings, or says why it could not check. Shared here: the depth facts of
// NEAR_COPLANAR_FIGHT and DEPTH_RANGE (lint_depth.cpp).
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "capture/lint/lint.h"

namespace ds::lint {

struct Output {
    std::vector<Finding> findings;
    std::vector<diagnose::SkippedDetector> skipped;
    std::vector<std::string> ran;
    std::vector<std::string> images;
    uint32_t frames = 0;
    void skip(std::string check, std::string reason) {
        skipped.push_back({std::move(check), std::move(reason)});
    }
};

void check_surface_pairs(const Input& in, Output& out);  // COPLANAR_OVERLAP, DUPLICATE_INSTANCE,
                                                         // NEAR_COPLANAR_FIGHT
void check_degenerate(const Input& in, Output& out);     // DEGENERATE_TRIANGLE
void check_decals(const Input& in, Output& out);         // DECAL, DECAL_WITHOUT_BASE
void check_alpha_mode(const Input& in, Output& out);     // ALPHA_MODE
void check_overdraw(const Input& in, Output& out);       // OVERDRAW (rendered)
void check_mesh_overdraw(const Input& in, Output& out);  // OVERDRAW (info, per mesh)
void check_depth_range(const Input& in, Output& out);    // DEPTH_RANGE

// Per mesh, the first instance that draws it, or -1 for a mesh no node places (lint_run.cpp).
std::vector<int64_t> first_instances(const scene::Scene& scene);

// --- lint_depth.cpp ---

// The formats a depth fact is given for: d32f reverse-Z, d32f forward-Z, d24, d16 (unorm steps
// do not depend on the direction), each with `planes`' near and far.
std::vector<view::DepthConfig> every_format(const view::DepthConfig& planes);
// The nearest view depth in [znear, zfar] from which one depth step of `c` is at least `gap`
// (scene units): two parallel surfaces `gap` apart, seen head-on, store the same depth from
// there on (the step grows with the distance, in float formats up to its ULP saw-tooth: the
// first depth reached counts). None when the step stays below `gap` up to the far plane or
// `seen_to`, whichever is nearer.
std::optional<double> fight_distance(const view::DepthConfig& c, double gap,
                                     double seen_to = INFINITY);
// The coarsest step of `c` between its planes, over kFightSamples log-spaced depths: at the
// far end for unorm and forward-Z float; for reverse-Z float, whose stored values crowd
// towards 0 at the far plane, below it (the model's step at the plane itself is 0).
double coarsest_step(const view::DepthConfig& c, double seen_to = INFINITY);
// How far the scene reaches from `camera`: the distance to its bounds' farthest corner. Beyond
// it the whole scene is nearer than a fight could start, so a fight distance past it is not
// reported (a far plane of 1e6 around a model 500 units wide would pair every parallel face).
double seen_to(const scene::Scene& scene, const scene::Camera& camera);
// "%.3g" of `v`.
std::string g3(double v);

}  // namespace ds::lint
