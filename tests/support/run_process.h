#pragma once
// Test helpers that run the real depthscope executable and read what it wrote.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace ds::test {

struct ProcessResult {
    int exit_code = -1;
    std::string out;  // stdout
    std::string err;  // stderr
};

// Runs `depthscope ARGS` (a shell word list) with a time limit in seconds. A capture writes
// only what its test asks for: `capture …` without `--resources` runs as `capture --resources
// none …` (every graph image as PNG and EXR costs seconds, a minute under ASan; the
// resources are tested where they are asked for, tests/render/test_capture_resources.cpp).
ProcessResult run_depthscope(const std::string& args, int timeout_s = 120);
// Runs a shell command line (/bin/sh) with a time limit, its output captured the same way
// (`bash -c 'ulimit -f 8; exec ...'`; DS_EXECUTABLE names depthscope).
ProcessResult run_command(const std::string& command, int timeout_s = 120);
// `depthscope ARGS` under a file-size limit of `kib` KiB (`ulimit -f`; stderr stays a pipe, so
// the error line still comes through).
ProcessResult run_depthscope_under_file_limit(int kib, const std::string& args);
// The name of the device depthscope selects by default ("llvmpipe (LLVM 15.0.6, 256 bits)" here,
// "NVIDIA H200" there), read from `depthscope info`; tests stay device-independent with it.
std::string selected_device_name();

// A fresh empty folder under the build tree, removed by the caller when wanted.
std::filesystem::path fresh_dir(const std::string& name);

struct Png {
    int width = 0;
    int height = 0;
    std::vector<uint8_t> rgba;
};
Png read_png(const std::filesystem::path& path);  // fails the test on error (width 0)
std::string read_file(const std::filesystem::path& path);

size_t count_lines(const std::string& text);
// A refusal as users see it: exit `code`, one stderr line "depthscope: error: ..." that
// mentions `mention`.
void expect_one_error_line(const ProcessResult& r, int code, const std::string& mention);
// Number of distinct RGB colours (a blank image has 1).
size_t distinct_colours(const Png& png);
// Pixels whose channels differ by more than `tolerance` in any channel.
size_t differing_pixels(const Png& a, const Png& b, int tolerance);

}  // namespace ds::test
