// view --capture DIR (issue 13 part 6): a folder that cannot be opened is one line and exit 1
// (2 for a usage error) before any window, whatever the display; nothing on stdout. The
// session itself (settings over the saved ones, F12 there) is tests/cli/inspector_window.sh's.
#include <gtest/gtest.h>

#include <fstream>

#include <nlohmann/json.hpp>

#include "tests/support/run_process.h"

namespace ds::test {
namespace {

namespace fs = std::filesystem;

// A capture to break copies of: edges at 64x36, no resources. ctest runs each test as its own
// process, side by side, so each has its own folder (a shared one is wiped under the others).
class ViewCapture : public ::testing::Test {
  protected:
    void SetUp() override {
        root_ = fresh_dir(std::string("view_capture_") +
                          ::testing::UnitTest::GetInstance()->current_test_info()->name());
        const ProcessResult r = run_depthscope(
            "capture --scene edges --size 64x36 --resources "
            "none --set exposure=2 --out " +
            (root_ / "good").string());
        ASSERT_EQ(r.exit_code, 0) << r.err;
    }
    // A copy of the good capture named `name`, with report.json edited by `edit`.
    static fs::path broken(const std::string& name,
                           const std::function<void(nlohmann::json&)>& edit = {}) {
        const fs::path dir = root_ / name;
        fs::remove_all(dir);
        fs::copy(root_ / "good", dir, fs::copy_options::recursive);
        if (edit) {
            nlohmann::json report = nlohmann::json::parse(read_file(dir / "report.json"));
            edit(report);
            std::ofstream(dir / "report.json") << report.dump();
        }
        return dir;
    }
    // `view --capture DIR ARGS` without a display: refused before the window would open.
    static void expect_refused(const std::string& args, int code, const std::string& why) {
        const ProcessResult r =
            run_command("env -u DISPLAY -u WAYLAND_DISPLAY DEPTHSCOPE_CONFIG_DIR=" +
                        (root_ / "config").string() + " " DS_EXECUTABLE " view --frames 1 " + args);
        SCOPED_TRACE(args);
        expect_one_error_line(r, code, why);
        EXPECT_EQ(r.out, "");
    }
    static inline fs::path root_;
};

TEST_F(ViewCapture, FoldersThatAreNoCaptureAreOneLineBeforeAnyWindow) {
    expect_refused("--capture " + (root_ / "missing").string(), 1,
                   "report.json: no such file (not a capture folder?)");
    const fs::path corrupt = broken("corrupt");
    std::ofstream(corrupt / "report.json") << "{\"tool\": ";
    expect_refused("--capture " + corrupt.string(), 1, "report.json: not JSON");
    expect_refused("--capture " + broken("other", [](auto& j) { j["tool"] = "other"; }).string(), 1,
                   "not a depthscope report");
    expect_refused("--capture " + broken("old", [](auto& j) { j.erase("replay"); }).string(), 1,
                   "no replay information");
    const fs::path no_png = broken("no_png");
    fs::remove(no_png / "final.png");
    expect_refused("--capture " + no_png.string(), 1, "final.png: no such file");
    const fs::path small = broken("small", [](auto& j) { j["size"]["width"] = 32; });
    expect_refused("--capture " + small.string(), 1,
                   "final.png: 64x36, but report.json says 32x36");
    const fs::path bad_png = broken("bad_png");
    std::ofstream(bad_png / "final.png") << "not a png";
    expect_refused("--capture " + bad_png.string(), 1, "final.png: is not a PNG");
}

TEST_F(ViewCapture, AnotherVersionOrSettingAreRefusedAndTheSceneCannotBeNamedToo) {
    expect_refused(
        "--capture " + broken("version", [](auto& j) { j["version"] = "v0.0-old"; }).string(), 1,
        "captured by depthscope 'v0.0-old'");
    expect_refused(
        "--capture " +
            broken("setting", [](auto& j) { j["settings"]["exposure"] = "banana"; }).string(),
        1, "report.json: settings: ");
    expect_refused("--capture " + (root_ / "good").string() + " --scene atrium", 2,
                   "--scene with --capture");
    expect_refused("--capture " + (root_ / "good").string() + " --set exposure=banana", 2,
                   "exposure");
    expect_refused("--capture ''", 2, "--capture expects a path");
    expect_refused("--force", 2, "--force requires --capture");
}

TEST_F(ViewCapture, AChangedSceneFileIsRefusedWithoutForce) {
    const fs::path gltf = root_ / "edges.gltf";
    ASSERT_EQ(run_depthscope("export-scene edges " + gltf.string()).exit_code, 0);
    const fs::path dir = root_ / "from_file";
    const ProcessResult r = run_depthscope("capture --scene " + gltf.string() +
                                           " --size 32x18 --resources none --out " + dir.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::ofstream(gltf, std::ios::app) << "\n";
    expect_refused("--capture " + dir.string(), 1, "changed since the capture");
    // With --force it gets as far as the window, which this command has no display for.
    expect_refused("--capture " + dir.string() + " --force", 1, "cannot open a window");
}

}  // namespace
}  // namespace ds::test
