#include "app/soak.h"

#include <algorithm>

#include <malloc.h>
#include <unistd.h>
#include <cstdio>

#include "renderer/common/error.h"
#include "renderer/passes/clear_counts.h"
#include "renderer/passes/depth_precision.h"
#include "renderer/passes/depth_prepass.h"
#include "renderer/passes/draw_counts.h"
#include "renderer/passes/equal_check.h"
#include "renderer/passes/zfight.h"

namespace ds::app {

const char* probe_name(SoakProbe probe) {
    switch (probe) {
        case SoakProbe::None:
            return "none";
        case SoakProbe::Counts:
            return passes::ClearCountsPass::kKnob.name;
        case SoakProbe::Draws:
            return passes::DrawCountsPass::kKnob.name;
        case SoakProbe::ZFight:
            return passes::ZfightPass::kKnob.name;
        case SoakProbe::Pixel:
            return "pixel-history";
        case SoakProbe::Inspect:
            return "inspect";
    }
    return "?";
}

std::vector<Assignment> probe_settings(SoakProbe probe) {
    switch (probe) {
        case SoakProbe::Counts:
            return {{passes::ClearCountsPass::kKnob.name, "on"},
                    {passes::DepthPrepass::kCountDiscards.name, "on"}};
        case SoakProbe::Draws:
            return {{passes::DrawCountsPass::kKnob.name, "on"}};
        case SoakProbe::ZFight:
            return {{passes::ZfightPass::kKnob.name, "on"},
                    {passes::EqualCheckPass::kKnob.name, "on"},
                    {passes::DepthPrecisionPass::kKnob.name, "on"}};
        default:
            return {};
    }
}

std::vector<SoakStep> soak_cycle(size_t scenes, std::span<const Size> sizes,
                                 std::span<const int> msaa_counts,
                                 std::span<const SoakProbe> probes, size_t cycle) {
    std::vector<SoakStep> steps;
    for (size_t scene = 0; scene < scenes; ++scene) {
        size_t k = scene;
        for (const int msaa : msaa_counts)
            for (const bool prepass : {true, false}) {
                steps.push_back({.scene = scene,
                                 .size = sizes[k % sizes.size()],
                                 .msaa = msaa,
                                 .prepass = prepass,
                                 .probe = probes[(k + cycle) % probes.size()]});
                ++k;
            }
    }
    return steps;
}

uint64_t resident_bytes() {
    std::FILE* f = std::fopen("/proc/self/statm", "r");
    unsigned long long size = 0, resident = 0;
    const bool ok = f && std::fscanf(f, "%llu %llu", &size, &resident) == 2;
    if (f) std::fclose(f);
    if (!ok) throw Error("soak: cannot read /proc/self/statm (resident memory)");
    return resident * uint64_t(sysconf(_SC_PAGESIZE));
}

uint64_t heap_in_use_bytes() {
    const struct mallinfo2 info = mallinfo2();
    return uint64_t(info.uordblks) + uint64_t(info.hblkhd);
}

double mib(uint64_t bytes) {
    return double(bytes) / double(1 << 20);
}

RssVerdict judge_rss(uint64_t start, std::span<const RssSample> ends,
                     const RssTolerance& tolerance) {
    RssVerdict v;
    v.start = start;
    if (ends.empty()) return v;
    v.warm = ends.front().bytes;
    v.end = ends.back().bytes;
    v.growth_mib = mib(v.end) - mib(v.warm);
    v.growth_percent = v.warm ? 100.0 * v.growth_mib / mib(v.warm) : 0.0;
    v.late_growth_mib = v.growth_mib;
    if (ends.size() >= 3) {
        const double middle = (ends.front().seconds + ends.back().seconds) / 2.0;
        const auto mid = std::find_if(ends.begin(), ends.end(),
                                      [&](const RssSample& s) { return s.seconds >= middle; });
        v.late_growth_mib = mib(v.end) - mib(mid->bytes);
    }
    const uint64_t heap_warm = ends.front().heap_bytes;
    v.heap_growth_mib = mib(ends.back().heap_bytes) - mib(heap_warm);
    v.heap_growth_percent = heap_warm ? 100.0 * v.heap_growth_mib / mib(heap_warm) : 0.0;
    v.rss_growing = v.growth_mib > tolerance.mib && v.growth_percent > tolerance.percent &&
                    v.late_growth_mib > tolerance.mib / 2.0;
    v.heap_growing = v.heap_growth_mib > tolerance.mib && v.heap_growth_percent > tolerance.percent;
    v.growing = v.rss_growing || v.heap_growing;
    if (ends.size() < 2) return v;
    double st = 0, sm = 0, stt = 0, stm = 0;
    for (const RssSample& s : ends) {
        const double t = s.seconds / 60.0, m = mib(s.bytes);
        st += t;
        sm += m;
        stt += t * t;
        stm += t * m;
    }
    const double n = double(ends.size());
    const double denominator = n * stt - st * st;
    if (denominator > 0) v.slope_mib_per_min = (n * stm - st * sm) / denominator;
    return v;
}

}  // namespace ds::app
