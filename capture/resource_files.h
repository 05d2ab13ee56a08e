#pragma once
// A capture's files for one graph image (docs/reference/frame.md): resources/NAME.png, sample 0
// decoded by its semantic exactly as the inspector's viewer shows it by default (view::decode,
// auto-fit, linear depth; the range it used goes into report.json), and resources/NAME.exr,
// the raw values of every sample through OpenEXR, in channels named by meaning:
//   depth (reverse-Z, forward-Z, shadow)  Z           stored depth, FLOAT
//   encoded normals                       X, Y, Z     decoded: stored * 2 - 1, FLOAT
//   [0, 1] scalars, AO                    Y           one channel (more: R, G, B, A), FLOAT
//   HDR and LDR colour                    R, G, B, A  as stored (LDR: the UNORM value), FLOAT
//   counts                                count       UINT
//   surface ids                           id          UINT
//   depth steps                           step, distance (scene units), FLOAT
//   Scalar (graph/display.h)              the Display's exr_channel ("" : Y), FLOAT or UINT
//   anything else                         R, G, B, A  by the format's channels; UINT if integer
// A multisampled image has one layer per sample: "sample0.Z", "sample1.Z", …; a single-sample
// image has no layer prefix. Integer values come through the inspect pass as floats, exact up
// to 2^24 (per-pixel counts and the surface ids of scenes below 16.7 M triangles).
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "capture/exr_file.h"
#include "renderer/passes/frame_result.h"
#include "renderer/view/image.h"

namespace ds::capture {

// The channels of one read sample, each name prefixed with `layer` ("" or "sample1.").
std::vector<ExrChannel> exr_channels(const InspectedImage& image, const std::string& layer);

// The EXR of an image from its samples, in sample order (one: no layer prefix).
ExrImage exr_image(std::span<const InspectedImage> samples);

// Writes `dir`/NAME.png and `dir`/NAME.exr for one graph image (`samples`: every sample of it
// as read, in order) and returns report.json's entry for it, with the graph's format, size and
// semantic (a Scalar image's entry has its Display too, as "display"); paths in the entry are
// relative to the capture folder, `dir` being its resources/ folder. Throws ds::Error.
nlohmann::json write_resource_files(const std::filesystem::path& dir, const ResourceSummary& image,
                                    std::span<const InspectedImage> samples);

// A resource name as a file name: letters, digits, '_', '-' and '.' kept, others '_'.
std::string file_stem(const std::string& resource_name);

}  // namespace ds::capture
