#include "tests/support/run_process.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>

#include <stb/stb_image.h>

namespace fs = std::filesystem;

namespace ds::test {

std::string read_file(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

fs::path fresh_dir(const std::string& name) {
    fs::path dir = fs::path(DS_TEST_WORK_DIR) / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

ProcessResult run_depthscope(const std::string& args, int timeout_s) {
    const std::string capture = "capture ";
    if (args.rfind(capture, 0) == 0 && args.find("--resources") == std::string::npos)
        return run_command(DS_EXECUTABLE " capture --resources none " + args.substr(capture.size()),
                           timeout_s);
    return run_command(DS_EXECUTABLE " " + args, timeout_s);
}

ProcessResult run_depthscope_under_file_limit(int kib, const std::string& args) {
    return run_command("bash -c 'ulimit -f " + std::to_string(kib) + "; exec " DS_EXECUTABLE " " +
                       args + "'");
}

ProcessResult run_command(const std::string& command, int timeout_s) {
    static int counter = 0;
    const fs::path io = fs::path(DS_TEST_WORK_DIR) /
                        ("io-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    const std::string cmd = "timeout " + std::to_string(timeout_s) + " " + command + " >" +
                            io.string() + ".out 2>" + io.string() + ".err";
    const int status = std::system(cmd.c_str());
    ProcessResult r;
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    r.out = read_file(io.string() + ".out");
    r.err = read_file(io.string() + ".err");
    fs::remove(io.string() + ".out");
    fs::remove(io.string() + ".err");
    // A sanitizer report in the child fails the test even where the test expects a nonzero exit
    // (the sanitizer stage: ./dev test --sanitize, tests/sanitize/env.sh).
    for (const char* mark :
         {"ERROR: AddressSanitizer", "ERROR: LeakSanitizer", "AddressSanitizer:DEADLYSIGNAL",
          ": runtime error: ", "SUMMARY: UndefinedBehaviorSanitizer"}) {
        if (r.err.find(mark) != std::string::npos) {
            ADD_FAILURE() << command << ": sanitizer report\n" << r.err;
            break;
        }
    }
    return r;
}

Png read_png(const fs::path& path) {
    Png png;
    int comp = 0;
    uint8_t* data = stbi_load(path.c_str(), &png.width, &png.height, &comp, 4);
    if (!data) {
        ADD_FAILURE() << "cannot read " << path;
        png.width = png.height = 0;
        return png;
    }
    png.rgba.assign(data, data + size_t(png.width) * png.height * 4);
    stbi_image_free(data);
    return png;
}

size_t count_lines(const std::string& text) {
    size_t n = 0;
    for (char c : text) n += c == '\n';
    if (!text.empty() && text.back() != '\n') ++n;
    return n;
}

size_t distinct_colours(const Png& png) {
    std::set<uint32_t> colours;
    for (size_t i = 0; i + 3 < png.rgba.size(); i += 4) {
        colours.insert(png.rgba[i] | png.rgba[i + 1] << 8 | png.rgba[i + 2] << 16);
    }
    return colours.size();
}

size_t differing_pixels(const Png& a, const Png& b, int tolerance) {
    if (a.width != b.width || a.height != b.height) return size_t(-1);
    size_t n = 0;
    for (size_t i = 0; i < a.rgba.size(); i += 4) {
        for (int c = 0; c < 4; ++c) {
            if (std::abs(int(a.rgba[i + c]) - int(b.rgba[i + c])) > tolerance) {
                ++n;
                break;
            }
        }
    }
    return n;
}

std::string selected_device_name() {
    const ProcessResult r = run_depthscope("info");
    const std::string marker = "[selected] device ";
    const size_t at = r.out.find(marker);
    if (r.exit_code != 0 || at == std::string::npos) return {};
    const size_t name = r.out.find(": ", at) + 2;
    return r.out.substr(name, r.out.find('\n', name) - name);
}

void expect_one_error_line(const ProcessResult& r, int code, const std::string& mention) {
    EXPECT_EQ(r.exit_code, code) << r.err;
    EXPECT_EQ(count_lines(r.err), 1u) << r.err;
    EXPECT_EQ(r.err.rfind("depthscope: error: ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(mention), std::string::npos) << mention << "\n" << r.err;
}

}  // namespace ds::test
