#pragma once
// The prepass advisor (issue 11 part 5): from frames with the prepass and without it (same
// camera, same settings otherwise), the overdraw, what the prepass costs, what forward pays per
// shaded fragment, the predicted and the measured frame-time change of keeping the prepass and
// a verdict, beside seed 003's rule of thumb (avg_overdraw > 2.0). Pure: no Vulkan; the frames
// come from a callback, so bench, capture and the inspector share one procedure.
#include <cstdint>
#include <functional>
#include <string>

#include <nlohmann/json.hpp>

#include "renderer/passes/frame_result.h"
#include "renderer/settings/settings.h"

namespace ds::capture {

// One configuration (prepass on or off): exact counts from a counting frame
// (count_fragments=on) and GPU medians over frames without counting (counting costs time).
struct AdviceSide {
    uint64_t forward_shaded = 0;  // forward's shaded_fragments
    uint64_t covered_pixels = 0;
    double depth_ms = 0;    // depth_prepass + depth_resolve (each where the frame has it)
    double forward_ms = 0;  // forward
    double frame_ms = 0;    // the whole frame
};

struct AdviceInput {
    AdviceSide with_prepass, without;
};

struct Advice {
    AdviceInput input;
    double overdraw = 0;                 // forward shaded without the prepass / covered pixels
    double prepass_ms = 0;               // depth ms with the prepass minus without
    double ns_per_fragment_with = 0;     // forward ms / forward shaded, with the prepass
    double ns_per_fragment_without = 0;  // the same without
    double predicted_change_ms = 0;      // prepass - ns/fragment (off) x fragments saved
    double measured_change_ms = 0;       // (depth + forward) on - (depth + forward) off
    double frame_change_ms = 0;          // whole frame on - off (+ the prepass-fed passes)
    bool keep = false;       // it spares forward fragments and the measured change is < 0
    bool rule_keep = false;  // overdraw > 2.0
    bool agrees() const { return keep == rule_keep; }
};

inline constexpr const char* kKeep = "keep the prepass";
inline constexpr const char* kDrop = "drop it";
inline constexpr double kRuleOverdraw = 2.0;  // seed 003: avg_overdraw > 2.0

Advice advise(const AdviceInput& in);

// report.json's and bench --json's `advice` object.
nlohmann::json advice_json(const Advice& a);
// "keep the prepass: it saves 1.23 ms (predicted 1.10 ms); overdraw 8.00 ..." (one line).
std::string verdict_line(const Advice& a);

// Renders one frame of `settings` (the caller's renderer, camera and size).
using RenderFrame = std::function<FrameResult(const Settings&)>;
struct AdviceRun {
    int frames = 5;  // timed frames per configuration (alternating, after the warm-up)
    int warmup = 1;
};
// The two configurations of `base` (prepass=on / off), each counted once and timed
// `run.frames` times; throws what the renderer throws.
AdviceInput measure_advice(const Settings& base, const RenderFrame& render, AdviceRun run);

}  // namespace ds::capture
