#pragma once
// How an image of semantic Scalar is shown (issue 23: a pass declares how its images are
// shown): the pass that creates it says so beside its format (ImageDesc::display), and the
// viewer (decode, hover readout, legend), the capture's PNG, EXR and report.json entry read
// it from here, never from the image's name. A Scalar image is one value per texel, in r.
// Vulkan-free, like semantic.h, so the view library can read it without the graph.
//
// The shown quantity is the value (Linear) or log10 of it (Log; a value <= 0 has none and is
// black). The range rule picks black..white over the shown quantity when the viewer
// auto-fits (its default, and what a capture's PNG uses):
//   MinMax     the finite min..max over the image; one value only: mid palette
//   ZeroToMax  0..max, so zero is black (Log: log10 v from 0, the values 1..max)
//   Fixed      black..white as declared, in the value's unit (Log: both > 0)
// With nothing to fit (no finite value; Log: none > 0; ZeroToMax: no max above 0) the range
// is 0..1 of the shown quantity (Log: the values 1..10). The palette maps black..white to
// grey 0..255 or to the count heat map (view/heat.h); on the heat map a Linear value at or
// below black is black, as counts are, and a Log value > 0 at or below black takes the first
// colour above black (blue), so only "no value" is black. NaN and infinities are magenta.
#include <cstdint>
#include <string>

namespace ds::graph {

enum class ValueScale : uint8_t { Linear, Log };
enum class Palette : uint8_t { Grey, Heat };
enum class ExrType : uint8_t { Float, Uint };  // Uint: rounded to nearest, negatives 0

struct DisplayRange {
    enum class Rule : uint8_t { MinMax, ZeroToMax, Fixed };
    Rule rule = Rule::MinMax;
    float black = 0.0f, white = 1.0f;  // Fixed only, in the value's unit

    static constexpr DisplayRange min_max() { return {Rule::MinMax, 0.0f, 1.0f}; }
    static constexpr DisplayRange zero_to_max() { return {Rule::ZeroToMax, 0.0f, 1.0f}; }
    static constexpr DisplayRange fixed(float black, float white) {
        return {Rule::Fixed, black, white};
    }
};

// Every member has a default, so a designated initializer names only what differs.
struct Display {
    ValueScale scale = ValueScale::Linear;
    DisplayRange range{};
    Palette palette = Palette::Grey;
    // The value's unit ("px²"): after the viewer's range, on the legend, the PNG's "unit".
    std::string unit{};
    // The text over the viewer's colour bar (Heat); "" shows the image's name there.
    std::string legend{};
    // The hover readout: every "{}" is replaced by the value at 3 significant digits
    // (view::value_text): "triangle {} px²" reads "triangle 0.18 px²".
    std::string hover = "{}";
    // The EXR's one channel ("" writes "Y") and its type.
    std::string exr_channel = "Y";
    ExrType exr_type = ExrType::Float;
};

// Names report.json uses.
inline const char* value_scale_name(ValueScale s) {
    return s == ValueScale::Log ? "log" : "linear";
}
inline const char* palette_name(Palette p) {
    return p == Palette::Heat ? "heat" : "grey";
}
inline const char* range_rule_name(DisplayRange::Rule r) {
    switch (r) {
        case DisplayRange::Rule::ZeroToMax:
            return "zero_to_max";
        case DisplayRange::Rule::Fixed:
            return "fixed";
        case DisplayRange::Rule::MinMax:
            break;
    }
    return "min_max";
}
inline const char* exr_type_name(ExrType t) {
    return t == ExrType::Uint ? "UINT" : "FLOAT";
}

}  // namespace ds::graph
