#include "capture/tune/candidate_cost.h"

#include <algorithm>

namespace ds::tune {
namespace {

double median(std::vector<double> v) {
    if (v.empty()) return 0;
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

void time_frames(Renderer& renderer, const scene::Camera& camera, const Settings& settings,
                 VkExtent2D size, const Timing& timing, Cost& cost) {
    Settings timed = settings;
    timed.set("count_fragments", "off");
    const RenderRequest request{
        .width = size.width, .height = size.height, .read_back = ReadBack::No};
    for (int i = 0; i < timing.warmup; ++i) renderer.render(camera, timed, request);
    std::vector<double> frames;
    std::vector<std::pair<std::string, std::vector<double>>> passes;
    for (int i = 0; i < timing.frames; ++i) {
        const FrameResult f = renderer.render(camera, timed, request);
        frames.push_back(f.gpu_ms);
        for (size_t p = 0; p < f.passes.size(); ++p) {
            if (p >= passes.size()) passes.push_back({f.passes[p].name, {}});
            if (passes[p].first == f.passes[p].name) passes[p].second.push_back(f.passes[p].gpu_ms);
        }
    }
    cost.frame_ms = median(frames);
    cost.frame_ms_min = frames.empty() ? 0 : *std::min_element(frames.begin(), frames.end());
    cost.frame_ms_max = frames.empty() ? 0 : *std::max_element(frames.begin(), frames.end());
    for (auto& [name, ms] : passes) cost.pass_ms.emplace_back(name, median(ms));
}

}  // namespace

const char* cost_kind_name(CostKind kind) {
    return kind == CostKind::Ms ? "ms" : "fragments";
}

CandidateFrame render_candidate(Renderer& renderer, const scene::Camera& camera,
                                const Settings& settings, VkExtent2D size, CostKind kind,
                                const Timing& timing, std::vector<InspectRequest> inspect) {
    Settings counted = settings;
    counted.set("count_fragments", "on");
    RenderRequest request{.width = size.width, .height = size.height, .read_back = ReadBack::Color};
    request.inspect = std::move(inspect);
    CandidateFrame c{renderer.render(camera, counted, request), {}};
    for (const PassResult& p : c.frame.passes) {
        if (p.name.rfind("shadow", 0) == 0) continue;  // the shadow map follows no knob here
        c.cost.shaded_fragments += p.shaded_fragments.value_or(0);
        c.cost.discarded_fragments += p.discarded_fragments.value_or(0);
    }
    if (kind == CostKind::Ms) time_frames(renderer, camera, settings, size, timing, c.cost);
    return c;
}

}  // namespace ds::tune
