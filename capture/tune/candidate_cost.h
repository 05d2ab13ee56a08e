#pragma once
// What a tuning candidate costs and what it drew: one frame read back (its image, the per-pass
// fragment counts, the surface ids asked for) and, for CostKind::Ms, timed frames whose GPU ms
// are reduced to medians (per frame and per pass) with their spread.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "renderer/renderer.h"
#include "renderer/settings/settings.h"

namespace ds::tune {

// fragments: shaded fragments of the frame's passes (count_fragments; deterministic, so two
// runs agree); ms: the frame's and each pass's GPU ms, medians of `frames` timed frames.
enum class CostKind { Fragments, Ms };
const char* cost_kind_name(CostKind kind);  // "fragments" | "ms"

struct Timing {
    int frames = 5;  // timed frames (CostKind::Ms)
    int warmup = 1;  // frames rendered first, not timed
};

struct Cost {
    // count_fragments, summed over the frame's passes but the shadow map's, whose size follows
    // neither msaa nor the frame: shaded fragments, and those the alpha test discarded.
    uint64_t shaded_fragments = 0;
    uint64_t discarded_fragments = 0;
    double frame_ms = 0, frame_ms_min = 0, frame_ms_max = 0;  // CostKind::Ms: median and spread
    std::vector<std::pair<std::string, double>> pass_ms;      // medians, in frame order
    double value(CostKind kind) const {
        return kind == CostKind::Ms ? frame_ms : double(shaded_fragments);
    }
};

// One candidate's frame: its final image and what it asked to inspect.
struct CandidateFrame {
    FrameResult frame;
    Cost cost;
};

// Renders `settings` once with count_fragments on (the image, the counts and the `inspect`
// images) and, for CostKind::Ms, warm-up and timed frames without read-back or counting.
CandidateFrame render_candidate(Renderer& renderer, const scene::Camera& camera,
                                const Settings& settings, VkExtent2D size, CostKind kind,
                                const Timing& timing, std::vector<InspectRequest> inspect = {});

}  // namespace ds::tune
