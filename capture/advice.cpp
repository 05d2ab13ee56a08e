#include "capture/advice.h"

#include <algorithm>
#include <cstdio>
#include <vector>

#include "renderer/common/error.h"
#include "renderer/passes/clear_counts.h"
#include "renderer/settings/frame_knobs.h"

namespace ds::capture {
namespace {

// ms over a fragment count, in ns per fragment (0 when nothing was shaded).
double ns_per(double ms, uint64_t fragments) {
    return fragments ? ms * 1e6 / double(fragments) : 0.0;
}

double median(std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

const PassResult* find_pass(const FrameResult& f, const char* name) {
    for (const PassResult& p : f.passes)
        if (p.name == name) return &p;
    return nullptr;
}

// Per-frame GPU ms of the passes the advice compares, gathered over the timed frames.
struct Timings {
    std::vector<double> depth, forward, frame;
    void add(const FrameResult& f) {
        double depth_ms = 0;
        for (const char* name : {"depth_prepass", "depth_resolve"})
            if (const PassResult* p = find_pass(f, name)) depth_ms += p->gpu_ms;
        const PassResult* fwd = find_pass(f, "forward");
        depth.push_back(depth_ms);
        forward.push_back(fwd ? fwd->gpu_ms : 0.0);
        frame.push_back(f.gpu_ms);
    }
};

// The exact counts of one counting frame into `side`.
void take_counts(const FrameResult& f, AdviceSide& side) {
    const PassResult* fwd = find_pass(f, "forward");
    if (!fwd || !fwd->shaded_fragments || !f.covered_pixels)
        throw Error("advice: the counting frame has no forward count or covered pixels");
    side.forward_shaded = *fwd->shaded_fragments;
    side.covered_pixels = *f.covered_pixels;
}

std::string fixed(double v, const char* format = "%.3f") {
    char text[64];
    std::snprintf(text, sizeof text, format, v);
    return text;
}

}  // namespace

Advice advise(const AdviceInput& in) {
    const AdviceSide& on = in.with_prepass;
    const AdviceSide& off = in.without;
    Advice a;
    a.input = in;
    a.overdraw = off.covered_pixels ? double(off.forward_shaded) / double(off.covered_pixels) : 0;
    a.prepass_ms = on.depth_ms - off.depth_ms;
    a.ns_per_fragment_with = ns_per(on.forward_ms, on.forward_shaded);
    a.ns_per_fragment_without = ns_per(off.forward_ms, off.forward_shaded);
    // Fragments the prepass spares forward, priced at forward's cost without the prepass.
    const double saved = double(off.forward_shaded) - double(on.forward_shaded);
    a.predicted_change_ms = a.prepass_ms - a.ns_per_fragment_without * saved * 1e-6;
    a.measured_change_ms = (on.depth_ms + on.forward_ms) - (off.depth_ms + off.forward_ms);
    a.frame_change_ms = on.frame_ms - off.frame_ms;
    // A prepass that spares forward no fragment can only cost: drop it whatever the timing
    // noise says (at a fraction of a millisecond a measured difference can have either sign).
    a.keep = saved > 0 && a.measured_change_ms < 0;
    a.rule_keep = a.overdraw > kRuleOverdraw;
    return a;
}

nlohmann::json advice_json(const Advice& a) {
    const char* rule = a.rule_keep ? kKeep : kDrop;
    return {
        {"overdraw", a.overdraw},
        {"prepass_ms", a.prepass_ms},
        {"forward_ns_per_fragment",
         {{"with_prepass", a.ns_per_fragment_with}, {"without", a.ns_per_fragment_without}}},
        {"shaded_fragments",
         {{"with_prepass", a.input.with_prepass.forward_shaded},
          {"without", a.input.without.forward_shaded}}},
        {"covered_pixels", a.input.without.covered_pixels},
        {"predicted_change_ms", a.predicted_change_ms},
        {"measured_change_ms", a.measured_change_ms},
        {"frame_ms",
         {{"with_prepass", a.input.with_prepass.frame_ms}, {"without", a.input.without.frame_ms}}},
        {"verdict", a.keep ? kKeep : kDrop},
        {"rule_of_thumb",
         {{"overdraw_above_2", a.rule_keep}, {"verdict", rule}, {"agrees", a.agrees()}}},
        {"note",
         "changes are of keeping the prepass (negative: it saves time): measured = (depth_prepass "
         "+ depth_resolve + forward) with it - (depth_resolve + forward) without, GPU medians of "
         "frames without counting; predicted = prepass_ms - forward's ns per fragment without "
         "the prepass x the fragments it saves (exact counts, count_fragments=on); frame_ms also "
         "includes the screen-space passes only the prepass feeds (gtao, ao_*, "
         "contact_shadows). The rule of thumb is seed 003's avg_overdraw > 2.0; its shader-cost "
         "term is not measured by the rule here (forward_ns_per_fragment is the measured cost)"},
    };
}

std::string verdict_line(const Advice& a) {
    const std::string change = a.measured_change_ms < 0
                                   ? "saves " + fixed(-a.measured_change_ms) + " ms"
                                   : "costs " + fixed(a.measured_change_ms) + " ms";
    return std::string(a.keep ? kKeep : kDrop) + ": the prepass " + change + " (predicted " +
           fixed(a.predicted_change_ms, "%+.3f") + " ms); overdraw " + fixed(a.overdraw, "%.2f") +
           ", rule of thumb (overdraw > 2) says " + (a.rule_keep ? kKeep : kDrop) +
           (a.agrees() ? ": agrees" : ": disagrees");
}

AdviceInput measure_advice(const Settings& base, const RenderFrame& render, AdviceRun run) {
    // [0] with the prepass, [1] without; count_fragments only in the counting frame.
    Settings timed[2] = {base, base};
    set_knob(timed[0], knobs::kPrepass, "on");
    set_knob(timed[1], knobs::kPrepass, "off");
    AdviceInput in;
    AdviceSide* sides[2] = {&in.with_prepass, &in.without};
    for (int k = 0; k < 2; ++k) {
        Settings counting = timed[k];
        set_knob(counting, passes::ClearCountsPass::kKnob, "on");
        take_counts(render(counting), *sides[k]);
        set_knob(timed[k], passes::ClearCountsPass::kKnob, "off");
    }
    for (int i = 0; i < run.warmup; ++i)
        for (const Settings& s : timed) render(s);
    // Alternating, so that both configurations see the same machine (frame times on a shared
    // CPU device drift).
    Timings t[2];
    for (int i = 0; i < run.frames; ++i)
        for (int k = 0; k < 2; ++k) t[k].add(render(timed[k]));
    for (int k = 0; k < 2; ++k) {
        sides[k]->depth_ms = median(t[k].depth);
        sides[k]->forward_ms = median(t[k].forward);
        sides[k]->frame_ms = median(t[k].frame);
    }
    return in;
}

}  // namespace ds::capture
