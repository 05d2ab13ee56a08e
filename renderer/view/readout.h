#pragma once
// The view library's per-texel readout: one texel of an InspectedImage as a graphics engineer
// reads it (linear depth, decoded normal, counts...), for the inspector's hover line. Pure
// functions: no Vulkan calls, no ImGui.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "renderer/view/image.h"

namespace ds::view {

struct Readout {
    uint32_t x = 0, y = 0;
    std::array<float, 4> raw{};  // the texel as read
    uint32_t channels = 4;       // meaningful channels of the format
    std::string raw_text;        // "0.0123400" / "(0.512, 0.998, 0.497, 1.000)" / "17"
    // "linear depth 12.345 (scene units)", "sky (far plane)", "normal (0.02, 1.00, -0.01)",
    // "roughness 0.500", "AO 0.830", "17 fragments", "linear rgb (...), luminance 0.5", a
    // Scalar's Display::hover with its value ("triangle 0.18 px²"), ...
    std::string decoded_text;
    std::optional<float> linear_depth;           // perspective depth semantics, not sky
    std::optional<std::array<float, 3>> normal;  // EncodedNormal, normalised (none if zero)
    bool sky = false;                            // perspective depth at the far value
};
// The texel at (x, y), row 0 = top; none outside the image (or for malformed texel data).
// UnormScalar is labelled from the image name: "roughness" (name contains "rough"), "shadow"
// (contains "shadow"), else "value". Other has raw_text only.
std::optional<Readout> readout(const InspectedImage& image, uint32_t x, uint32_t y);
// A length in scene units (metres) at a readable scale: "0.37 mm", "12.4 m", "3.1 um".
std::string length_text(float metres);
// A value at 3 significant digits, as printf's %.3g (trailing zeros dropped, exponent form
// below 1e-4) but without an exponent from 1000 up to 1e6: "0.18", "2", "0.000123",
// "1230", "1.23e+06", "1e-05"; "nan", "inf", "-inf".
std::string value_text(float value);
// `format` with every "{}" replaced by value_text(value): a Scalar's Display::hover.
std::string hover_text(std::string_view format, float value);

}  // namespace ds::view
