#pragma once
// tune alpha (issue 30): for each MASK material (by name, as material_alpha_cutoff names it), a
// sweep of its cutoff (and alpha_to_coverage where msaa > 1), each frame's coverage of that
// material compared with the reference's (reference.h) pixel by pixel: a pixel is covered when
// at least half its samples see the material, and the coverage error is the share of the
// material's pixels (covered by it in either frame, by any sample) covered in one frame and not
// the other. The cutoff with the least error is the one that best matches the reference.
#include <string>
#include <vector>

#include "capture/tune/candidate_cost.h"
#include "capture/tune/reference.h"

namespace ds::tune {

struct AlphaPoint {
    float cutoff = 0;
    bool alpha_to_coverage = false;
    double coverage_error = 0;  // mismatched / material_pixels (0 when there are none)
    uint64_t mismatched = 0, material_pixels = 0;
    uint64_t covered = 0;  // pixels the candidate covers
    Cost cost;             // cost.discarded_fragments: the alpha test's discards
};

struct AlphaMaterial {
    std::string name;
    float cutoff = 0.5f;             // what the user's settings give it (the reference's)
    uint64_t reference_covered = 0;  // pixels the reference covers
    std::vector<AlphaPoint> points;  // by cutoff, then alpha_to_coverage
    int best = -1;                   // the least coverage error (ties: nearest `cutoff`)
    int current = -1;                // the point at `cutoff` without alpha_to_coverage
};

struct AlphaTune {
    VkExtent2D size{};
    CostKind cost_kind = CostKind::Fragments;
    int msaa = 1;
    float step = 0.05f;
    uint32_t reference_factor = 0;
    double reference_ms = 0;
    std::vector<AlphaMaterial> materials;
};

struct AlphaSweep {
    std::vector<std::string> materials;  // empty: every MASK material of the scene
    float step = 0.05f;                  // cutoffs step, step*2, … below 1, plus the current one
    CostKind cost_kind = CostKind::Fragments;
    Timing timing;
};

// The MASK materials' names (sorted, once each). Throws UsageError for a name in `wanted` that
// is no MASK material (listing them), or when the scene has none.
std::vector<std::string> masked_material_names(const scene::Scene& scene,
                                               const std::vector<std::string>& wanted);

AlphaTune tune_alpha(Renderer& renderer, const scene::Scene& scene, const scene::Camera& camera,
                     const Settings& settings, VkExtent2D size, const AlphaSweep& sweep);

}  // namespace ds::tune
