#pragma once
// Diagnose's findings (issue 24 point 5) in the shape a scene lint will reuse: glTF-Validator's
// message (code, severity 0 error .. 3 hint, message, pointer) plus depthscope's own fields
// (magnitude with its unit, the surfaces named, the fix, the detector) and, for the inspector,
// the pixels a finding covers. A Diagnosis is every finding of one view, ranked, with the
// detectors that did not run and why. Plain data: no Vulkan.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "renderer/scene/scene.h"

namespace ds::diagnose {

// glTF-Validator's numbers. Error: a visible artefact; warning: wasted work; info: advice.
enum class Severity : int { Error = 0, Warning = 1, Info = 2, Hint = 3 };
const char* severity_name(Severity s);  // "error", "warning", "info", "hint"

struct Magnitude {
    double value = 0;
    std::string unit;  // "px", "fragments", "draws", "x" (a ratio), "ms", "scene units"
};

// A surface a finding names: an instance of the scene, as reports name it.
struct FindingSurface {
    std::string mesh, material, node;
    std::string pointer;  // JSON pointer of its glTF node ("/nodes/3"); "" when not known
};

struct Finding {
    std::string code;  // UPPER_SNAKE: ZFIGHT, EQUAL_HOLES, EARLY_Z_LOST, ...
    Severity severity = Severity::Info;
    std::string message;  // one line
    std::string pointer;  // the first named surface's pointer, or ""
    Magnitude magnitude;
    std::vector<FindingSurface> surfaces;
    std::string fix;       // what to change, one line
    std::string detector;  // the check that found it: zfight, equal_check, early_z, ...
    // Named numbers beside the magnitude (lint's fight distance per depth format); JSON
    // "values" {name: number} when there are any.
    std::vector<std::pair<std::string, double>> values;
    // The pixels it covers at the render size, y * width + x (row 0 = top), ascending, each
    // once; empty when it covers none (a draw nothing of which shows). Not in the JSON.
    std::vector<uint32_t> pixels;
};

struct SkippedDetector {
    std::string detector, reason;
};

// One view diagnosed: where it ran, what was found (ranked: severity, then magnitude), what
// was not checked and why, and what it cost in frames.
struct Diagnosis {
    std::string scene;         // Scene::name
    std::string scene_source;  // Scene::source
    scene::Camera camera;
    uint32_t width = 0, height = 0;
    std::vector<std::pair<std::string, std::string>> settings;  // every knob, as the user set it
    std::vector<std::string> measurement_knobs;                 // what diagnose turned on
    std::vector<std::string> detectors;                         // the detectors that ran
    std::vector<Finding> findings;
    std::vector<SkippedDetector> skipped;
    uint32_t frames = 0;  // frames rendered, the advisor's included

    size_t count(Severity s) const;
    // A finding at `level` or more severe (a lower number).
    bool has_at_least(Severity level) const;
};

// Sorts by severity (errors first), then magnitude (largest first), then code and message.
void rank(std::vector<Finding>& findings);

// Pixel indices sorted ascending without repeats.
void normalise_pixels(std::vector<uint32_t>& pixels);

}  // namespace ds::diagnose
