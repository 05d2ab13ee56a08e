#pragma once
// report.json: what was rendered, where, with which settings, and what it cost.
#include <cstdint>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "renderer/scene/scene.h"
#include "renderer/settings/settings.h"

namespace ds::capture {

struct ReportInput {
    std::string device_name;
    std::string driver;
    std::string api_version;
    const scene::Scene* scene = nullptr;
    uint32_t width = 0;
    uint32_t height = 0;
    const Settings* settings = nullptr;
    double gpu_ms = 0.0;
    double cpu_ms = 0.0;
    uint64_t validation_messages = 0;
};

nlohmann::json make_report(const ReportInput& in);
nlohmann::json scene_summary(const scene::Scene& scene);

// Writes pretty JSON; throws ds::Error when the file cannot be written.
void write_json(const std::filesystem::path& path, const nlohmann::json& json);
// The same, through a temporary file renamed into place: PATH is complete or absent.
void write_json_atomically(const std::filesystem::path& path, const nlohmann::json& json);

}  // namespace ds::capture
