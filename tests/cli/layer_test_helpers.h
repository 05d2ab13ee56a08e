#pragma once
// What the layer's CLI tests share (test_layer.cpp, test_layer_depth.cpp).
#include <filesystem>

#include <nlohmann/json.hpp>

#include "tests/support/run_process.h"

namespace ds::test {

inline constexpr const char* kLayerTestSize = "--size 320x180";

inline nlohmann::json read_report(const std::filesystem::path& dir) {
    return nlohmann::json::parse(read_file(dir / "report.json"));
}

}  // namespace ds::test
