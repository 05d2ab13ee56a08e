#pragma once
// tune msaa (issue 30): every combination of msaa (the device's counts) x sample_shading x
// alpha_to_coverage (the last two only where msaa > 1, where they mean something), each scored
// against the reference (score.h) and costed (candidate_cost.h); the Pareto front of cost
// against error and the best candidate within a few budgets.
#include <string>
#include <vector>

#include "capture/tune/candidate_cost.h"
#include "capture/tune/reference.h"
#include "capture/tune/score.h"

namespace ds::tune {

struct MsaaCandidate {
    int msaa = 1;
    bool sample_shading = false;
    bool alpha_to_coverage = false;
    std::string label() const;                     // "msaa 4 + sample_shading"
    std::vector<std::string> assignments() const;  // "msaa=4", "sample_shading=on", …
};

struct MsaaRow {
    MsaaCandidate candidate;
    ImageScore score;
    Cost cost;
    bool front = false;  // on the Pareto front of (cost, error)
};

// The best candidate whose cost is at most `budget` times the cheapest one's (0: no limit).
struct Recommendation {
    double budget = 0;
    int row = -1;  // into MsaaTune::rows; -1 when nothing fits
};

struct MsaaTune {
    VkExtent2D size{};
    CostKind cost_kind = CostKind::Fragments;
    uint32_t reference_factor = 0;
    double reference_ms = 0;
    uint64_t reference_bytes = 0, edge_pixels = 0;
    std::vector<MsaaRow> rows;  // candidates in msaa, sample_shading, alpha_to_coverage order
    std::vector<Recommendation> recommendations;
};

inline constexpr double kBudgets[] = {1.5, 2.0, 4.0, 0.0};  // x the cheapest; 0: any

// The candidates for a device's msaa counts.
std::vector<MsaaCandidate> msaa_candidates(const std::vector<int>& msaa_counts);

// Runs the sweep (Renderer::set_scene(scene) done). `settings` are the user's; scored_settings
// and each candidate's knobs are applied over them.
MsaaTune tune_msaa(Renderer& renderer, const scene::Scene& scene, const scene::Camera& camera,
                   const Settings& settings, VkExtent2D size, CostKind kind,
                   const Timing& timing = {});

// Marks the Pareto front (lower cost, lower error) and picks the budgets' recommendations.
void rank(MsaaTune& t);

}  // namespace ds::tune
