#pragma once
// A capture folder read back for `depthscope diff` (issue 13): report.json, final.png and the
// resources report.json lists, all checked before any comparison starts, so that a folder that
// is not a depthscope capture is one line and nothing is written. No Vulkan: plain files only.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace ds::capture {

// 8-bit RGBA, tightly packed, top row first.
struct Rgba8Image {
    uint32_t width = 0, height = 0;
    std::vector<uint8_t> rgba;
};

// One entry of report.json's "resources" (resource_files.h writes them).
struct ResourceRef {
    std::string name;
    std::string format;    // "R8G8B8A8_SRGB" (format::name)
    std::string semantic;  // graph::semantic_name
    uint32_t width = 0, height = 0, samples = 0;
    std::filesystem::path exr;  // the capture folder / exr.file
};

// One entry of report.json's "passes": what diff sets side by side.
struct PassNumbers {
    std::string name;
    std::string kind;  // "frame", "readback", … ("" when the report has none)
    double gpu_ms = 0;
    // The exact counters (count_fragments=on), absent when not counted.
    std::optional<uint64_t> rasterized, shaded, discarded;
};

struct CaptureFolder {
    std::filesystem::path dir;
    nlohmann::json report;
    Rgba8Image final_image;              // final.png, decoded
    bool lists_resources = false;        // report.json has a "resources" array
    std::vector<ResourceRef> resources;  // in report.json's order
    std::vector<PassNumbers> passes;     // in execution order
    std::optional<double> frame_gpu_ms;  // report.json frame.gpu_ms
};

// Reads and checks one capture folder: DIR a folder; report.json a regular file (at most
// 64 MiB) holding a JSON object with "tool": "depthscope"; final.png a PNG (at most 16384 per
// side); "passes" and "resources", when present, arrays of well-formed entries, each listed
// EXR a regular file inside DIR. Throws ds::Error "DIR: …" (or "DIR/FILE: …") naming the
// first fault.
CaptureFolder load_capture(const std::filesystem::path& dir);

// A PNG file as RGBA8 (any PNG colour type and depth; 16-bit is reduced to 8). Throws
// ds::Error "PATH: …" for a missing, oversized or undecodable file.
Rgba8Image read_png_rgba8(const std::filesystem::path& path);

}  // namespace ds::capture
