#pragma once
// `depthscope diff A B` (issue 13): two capture folders compared image by image and pass by
// pass; the verdict is seed 004's acceptance ("% of pixels that differ by >= 8/255") as a
// command. No Vulkan: it reads the captures' files (capture_folder.h, read_exr).
//
// When a pixel differs (a pixel differs when any channel of any sample layer differs):
//  - final.png: its RGBA8 bytes; a channel differs by >= threshold (of 255; default 8), the
//    rule of renderer/metrics/threshold.h. Its SSIM is reported beside (metrics/ssim.h).
//  - a resource: the values of its EXR, channel by channel, by the channel's rule:
//      8-bit   the format is 8 bits per channel UNORM or SRGB (R8_UNORM, R8G8B8A8_SRGB,
//              B8G8R8A8_UNORM, …): the stored 8-bit codes, round(v * 255) of the EXR's
//              values (which hold the stored UNORM value, SRGB formats' too), differ by
//              >= threshold — the rule final.png gets, so the `final` resource agrees with it;
//      uint    a UINT channel (counts, surface ids): any difference;
//      float   everything else (depth, decoded normals, half and float colour, AO, steps):
//              |a - b| > max(kFloatRelative * max(|a|, |b|), kFloatAbsolute); a NaN against
//              a number, or an infinity against anything else, differs; NaN against NaN and
//              equal infinities do not.
//  - a resource is compared only when both captures list it with the same size, format,
//    samples, semantic and EXR channels (names and types); otherwise it is "not comparable"
//    with the reason. final.png of two sizes is not comparable, and fails the verdict.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "capture/capture_folder.h"

namespace ds::capture {

inline constexpr double kFloatRelative = 1e-3;
inline constexpr double kFloatAbsolute = 1e-6;

struct DiffOptions {
    int threshold = 8;         // of 255, for 8-bit data (1..255)
    double max_percent = 0.1;  // final.png's differing pixels (%) that still pass
};

enum class DiffRule { Bytes8, Uint, Float };
const char* diff_rule_name(DiffRule rule);  // "8-bit", "uint", "float"

// The largest difference of one rule's channels over an image: 8-bit in steps of 1/255, uint
// in counts, float |a - b| and |a - b| / max(|a|, |b|). Infinite where a NaN or an infinity
// made a pixel differ.
struct RuleLargest {
    DiffRule rule = DiffRule::Float;
    double largest = 0;
    double largest_relative = 0;  // float only
};

struct ImageDiff {
    std::string name;    // "final.png", or the resource's name
    std::string format;  // "RGBA8" for final.png
    std::string semantic;
    uint32_t width = 0, height = 0, samples = 1;
    uint64_t differing = 0;          // pixels over the threshold
    std::vector<RuleLargest> rules;  // one per rule its channels use
    // Per pixel, top row first: 0 where nothing differs, else in (0, 1] the largest difference
    // there over the image's largest of the same rule (1 for a NaN or infinity). Heat maps
    // are made from it; emptied once on_image (diff_captures) has seen it.
    std::vector<float> heat;
    // final.png only: the mean SSIM of the two images' luma (renderer/metrics/ssim.h); absent
    // for a resource, and for an image under 11 pixels on a side.
    std::optional<double> ssim;

    uint64_t pixels() const { return uint64_t(width) * height; }
    double percent() const { return pixels() ? 100.0 * double(differing) / double(pixels()) : 0; }
};

// One pass, matched by name (the n-th of a name in A with the n-th in B).
struct PassRow {
    std::string name;
    std::optional<PassNumbers> a, b;
};

struct NotComparable {
    std::string name;
    std::string why;
};

struct DiffResult {
    DiffOptions options;
    std::optional<ImageDiff> final_image;  // absent when the sizes differ
    std::string final_not_comparable;      // why, then
    std::vector<ImageDiff> resources;      // most differing first (ties: A's order)
    std::vector<NotComparable> not_comparable;
    std::vector<std::string> only_in_a, only_in_b;
    bool a_lists_resources = false, b_lists_resources = false;
    std::vector<PassRow> passes;  // A's order, then B-only passes in B's order
    std::optional<double> frame_ms_a, frame_ms_b;

    // final.png comparable and at most options.max_percent of its pixels differ.
    bool passed() const;
};

// Compares two loaded captures. `on_image` (may be empty) sees every compared image with its
// heat values, final.png first, then each resource in A's order; a throw from it stops the
// comparison. Throws ds::Error for an EXR that cannot be read or does not match its entry.
DiffResult diff_captures(const CaptureFolder& a, const CaptureFolder& b, const DiffOptions& options,
                         const std::function<void(const ImageDiff&)>& on_image);

// The parts, for tests.
ImageDiff diff_final(const Rgba8Image& a, const Rgba8Image& b, int threshold);
// The mean SSIM of two images of one size (their luma; metrics/ssim.h); none under 11 pixels
// on a side. diff_captures fills final.png's ImageDiff::ssim with it (diff_final does not: the
// inspector's compare view calls that on every frame).
std::optional<double> final_ssim(const Rgba8Image& a, const Rgba8Image& b);
// Why two entries of one name cannot be compared ("" when they can).
std::string why_not_comparable(const ResourceRef& a, const ResourceRef& b);
std::vector<PassRow> match_passes(const std::vector<PassNumbers>& a,
                                  const std::vector<PassNumbers>& b);
// Is a format (format::name) 8 bits per channel UNORM or SRGB ("R8_UNORM", "B8G8R8A8_SRGB").
bool is_unorm8(const std::string& format_name);

}  // namespace ds::capture
