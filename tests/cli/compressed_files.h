#pragma once
// The compressed and quantized atriums of tests/data/compressed/ (README.md there says how
// each was made) beside a fresh export of the atrium, whose PNG textures they name; shared by
// cli_tests (every file loads) and compressed_tests (what each renders).
#include <filesystem>
#include <string>

namespace ds::test {

// The folder of the current test binary's files: made once, by the first test that asks.
std::filesystem::path compressed_folder();

}  // namespace ds::test
