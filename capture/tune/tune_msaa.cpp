#include "capture/tune/tune_msaa.h"

#include "renderer/device_info.h"

namespace ds::tune {

std::string MsaaCandidate::label() const {
    std::string s = "msaa " + std::to_string(msaa);
    if (sample_shading) s += " + sample_shading";
    if (alpha_to_coverage) s += " + alpha_to_coverage";
    return s;
}

std::vector<std::string> MsaaCandidate::assignments() const {
    return {"msaa=" + std::to_string(msaa),
            std::string("sample_shading=") + (sample_shading ? "on" : "off"),
            std::string("alpha_to_coverage=") + (alpha_to_coverage ? "on" : "off")};
}

std::vector<MsaaCandidate> msaa_candidates(const std::vector<int>& msaa_counts) {
    std::vector<MsaaCandidate> out;
    for (int n : msaa_counts) {
        if (n <= 1) {
            out.push_back({1, false, false});
            continue;
        }
        for (bool shading : {false, true})
            for (bool coverage : {false, true}) out.push_back({n, shading, coverage});
    }
    return out;
}

void rank(MsaaTune& t) {
    const size_t n = t.rows.size();
    double cheapest = 0;
    for (size_t i = 0; i < n; ++i) {
        const double ci = t.rows[i].cost.value(t.cost_kind), ei = t.rows[i].score.error();
        if (i == 0 || ci < cheapest) cheapest = ci;
        bool dominated = false;
        for (size_t j = 0; j < n && !dominated; ++j) {
            const double cj = t.rows[j].cost.value(t.cost_kind), ej = t.rows[j].score.error();
            dominated = j != i && cj <= ci && ej <= ei && (cj < ci || ej < ei);
        }
        t.rows[i].front = !dominated;
    }
    t.recommendations.clear();
    for (double budget : kBudgets) {
        Recommendation r{budget, -1};
        for (size_t i = 0; i < n; ++i) {
            const MsaaRow& row = t.rows[i];
            if (budget > 0 && row.cost.value(t.cost_kind) > budget * cheapest) continue;
            if (r.row < 0 || row.score.error() < t.rows[size_t(r.row)].score.error() ||
                (row.score.error() == t.rows[size_t(r.row)].score.error() &&
                 row.cost.value(t.cost_kind) < t.rows[size_t(r.row)].cost.value(t.cost_kind)))
                r.row = int(i);
        }
        t.recommendations.push_back(r);
    }
}

MsaaTune tune_msaa(Renderer& renderer, const scene::Scene& scene, const scene::Camera& camera,
                   const Settings& settings, VkExtent2D size, CostKind kind, const Timing& timing) {
    const Reference ref = render_reference(renderer, scene, camera, settings, size);
    MsaaTune t;
    t.size = size;
    t.cost_kind = kind;
    t.reference_factor = ref.factor;
    t.reference_ms = ref.ms;
    t.reference_bytes = ref.readback_bytes;
    for (uint8_t e : ref.edges) t.edge_pixels += e;
    const Settings base = scored_settings(settings);
    for (const MsaaCandidate& c : msaa_candidates(device_info(renderer).msaa_counts)) {
        Settings s = base;
        for (const std::string& a : c.assignments()) s.apply(a);
        CandidateFrame f = render_candidate(renderer, camera, s, size, kind, timing);
        t.rows.push_back({c, score_against(f.frame.rgba8, ref), std::move(f.cost), false});
    }
    rank(t);
    return t;
}

}  // namespace ds::tune
