#pragma once
// Pieces of `depthscope bench --soak` that need no GPU: the combinations one cycle renders,
// resident-memory sampling and the verdict on it.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "app/bench.h"
#include "app/cli.h"

namespace ds::app {

// What a soak frame measures or reads back besides the frame itself.
enum class SoakProbe : uint8_t {
    None,     // the frame, nothing read back
    Counts,   // count_fragments + count_discards
    Draws,    // count_draws (per-draw occlusion queries and counts)
    ZFight,   // zfight + equal_check + depth_precision
    Pixel,    // pixel history of the centre pixel, everything read back
    Inspect,  // the inspector's read-back of the depth image
};
const char* probe_name(SoakProbe probe);
// The knobs a probe turns on, through the registry like any --set.
std::vector<Assignment> probe_settings(SoakProbe probe);

struct SoakStep {
    size_t scene = 0;  // index into the soak's scene list
    Size size;
    int msaa = 1;
    bool prepass = true;
    SoakProbe probe = SoakProbe::None;
};

// Cycle `cycle` (0 first): each scene once, drawn at every msaa count with the prepass on
// and off; the sizes and the probes rotate over those frames, shifted by one per scene, so
// that with at least as many scenes as probes every cycle renders each msaa x prepass x probe
// combination (and every scene, size and probe) once; the probes shift by one per cycle too,
// so every scene meets every probe over as many cycles as there are probes.
std::vector<SoakStep> soak_cycle(size_t scenes, std::span<const Size> sizes,
                                 std::span<const int> msaa_counts,
                                 std::span<const SoakProbe> probes, size_t cycle);

// Resident memory of this process in bytes (/proc/self/statm); throws ds::Error without it.
uint64_t resident_bytes();

// Bytes malloc has handed out and not had back (glibc's mallinfo2: uordblks + hblkhd): beside
// RSS it tells a leak (this grows) from fragmentation or driver mappings (only RSS does).
uint64_t heap_in_use_bytes();

// RSS at the end of a cycle.
struct RssSample {
    double seconds = 0;  // since the soak's first frame
    uint64_t bytes = 0;
    uint64_t heap_bytes = 0;  // heap_in_use_bytes() then
};

// The tolerance: growth from the end of warm-up to the end counts only when it is above both.
struct RssTolerance {
    double mib = 8.0;
    double percent = 3.0;
};

struct RssVerdict {
    uint64_t start = 0, warm = 0, end = 0;  // before the first frame, after warm-up, at the end
    double growth_mib = 0, growth_percent = 0;
    double slope_mib_per_min = 0;  // least squares over the cycle ends from warm-up on
    bool growing = false;          // growth above both tolerances
};

// `cycle_ends`: the samples at the end of each cycle, the first being the end of warm-up.
// Needs at least one; growth and slope stay 0 with only the warm-up sample.
RssVerdict judge_rss(uint64_t start, std::span<const RssSample> cycle_ends,
                     const RssTolerance& tolerance = {});

double mib(uint64_t bytes);

}  // namespace ds::app
