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
    // RSS growth over the second half of the time after warm-up (all of it with fewer than
    // three samples): a leak keeps growing there, a driver's pool that grew in steps and
    // settled does not.
    double late_growth_mib = 0;
    double heap_growth_mib = 0, heap_growth_percent = 0;  // heap in use, warm-up to end
    bool rss_growing = false;   // RSS above both tolerances and still growing late
    bool heap_growing = false;  // heap in use above both tolerances
    bool growing = false;       // either
};

// `cycle_ends`: the samples at the end of each cycle, the first being the end of warm-up.
// Needs at least one; growth and slope stay 0 with only the warm-up sample.
// Memory grows when the heap in use (this process's own allocations) grew above both
// tolerances, or RSS did and at least half the MiB tolerance of it came in the second half of
// the time: on NVIDIA's driver RSS rises in 4 MiB steps for a minute or two while the heap in
// use stays flat (H200, 2026-12-02), which a tolerance on RSS alone takes for a leak.
RssVerdict judge_rss(uint64_t start, std::span<const RssSample> cycle_ends,
                     const RssTolerance& tolerance = {});

double mib(uint64_t bytes);

}  // namespace ds::app
