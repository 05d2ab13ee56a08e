#pragma once
// What `depthscope diff` shows of a DiffResult (capture_diff.h): the heat-map PNG of a compared
// image, the one-screen summary and diff.json, which holds everything the summary says.
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "capture/capture_diff.h"

namespace ds::capture {

// RGBA8, top row first: black where nothing differs, else view::heat_color of the pixel's heat
// value (blue for the smallest difference up to white for the image's largest, a NaN or an
// infinity), so every differing pixel is non-black.
std::vector<uint8_t> heat_map_rgba(const ImageDiff& image);

// The heat map's file inside the --out folder: "final.png", or "resources/NAME.png" (NAME the
// resource's file stem, as captures name it).
std::string heat_map_file(const ImageDiff& image);

struct DiffNames {
    std::string a, b;  // the capture folders as given
    std::string out;   // the --out folder, "" without one
};

// final.png's line, the resources most differing first (then those not comparable or in one
// capture only), the pass table (gpu_ms and the exact counters of A and B with B/A) and the
// verdict line, each line ending in '\n'.
std::string diff_summary(const DiffResult& result, const DiffNames& names);

// diff.json's object: the options and rules, every image's counts and largest differences
// (with its heat map's file when `names.out` is set), the lists, the passes and the verdict.
nlohmann::json diff_json(const DiffResult& result, const DiffNames& names);

// 0 when the verdict passes, 1 when final.png differs beyond --max-percent (or cannot be
// compared).
int diff_exit_code(const DiffResult& result);

}  // namespace ds::capture
