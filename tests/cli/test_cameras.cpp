// Cameras from the command line (issue 27 part 3) through the real executable: `cameras` lists
// a scene's camera nodes (tests/data/cameras.gltf: "Front" and "Side" perspective, "Top"
// orthographic), --camera NAME|INDEX and --look-at EX,EY,EZ:TX,TY,TZ[:FOV] choose the view of
// capture, bench, pixel, replay, view and diagnose, and report.json holds it; a bad choice is
// one error line, exit 2, nothing written. Replays of such captures: tests/render/test_replay.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "tests/support/run_process.h"

namespace ds::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const std::string kCameras = std::string(DS_TEST_DATA) + "/cameras.gltf";

// `capture --scene SCENE --size 64x36 ARGS` into a fresh folder; its report.json.
json capture_report(const std::string& tag, const std::string& scene, const std::string& args) {
    const fs::path dir = fresh_dir(tag) / "cap";
    const ProcessResult r = run_depthscope("capture --validate --scene " + scene +
                                           " --size 64x36 --out " + dir.string() + " " + args);
    EXPECT_EQ(r.exit_code, 0) << args << "\n" << r.err;
    if (r.exit_code != 0) return json::object();
    return json::parse(read_file(dir / "report.json"));
}

std::vector<float> floats(const json& j) {
    std::vector<float> out;
    for (const json& v : j) out.push_back(v.get<float>());
    return out;
}

// The cameras.gltf without its cameras (a scene with none), written into `dir`.
fs::path without_cameras(const fs::path& dir) {
    json g = json::parse(read_file(kCameras));
    g.erase("cameras");
    for (json& node : g["nodes"]) node.erase("camera");
    const fs::path path = dir / "no_cameras.gltf";
    std::ofstream(path) << g.dump();
    return path;
}

TEST(Cameras, ListsEveryCameraNodeWithItsTypeFovAndPlanes) {
    const ProcessResult r = run_depthscope("cameras " + kCameras);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(count_lines(r.out), 4u) << r.out;  // the header and three cameras
    EXPECT_TRUE(std::regex_search(r.out, std::regex("INDEX +NAME +TYPE +YFOV +ZNEAR +ZFAR +NODE")))
        << r.out;
    // Walk order: Front (node 1), Side (node 3, under Parent), Top (node 4).
    EXPECT_TRUE(
        std::regex_search(r.out, std::regex("\\n0 +Front +perspective +45\\.84 +0\\.1 +100 +1\\n")))
        << r.out;
    EXPECT_TRUE(std::regex_search(
        r.out, std::regex("\\n1 +Side +perspective +57\\.30 +0\\.05 +infinite +3\\n")))
        << r.out;
    EXPECT_TRUE(std::regex_search(r.out, std::regex("\\n2 +Top +orthographic +- +0\\.1 +50 +4\\n")))
        << r.out;
}

TEST(Cameras, ListsABuiltinScenesCameraAndSaysWhenThereIsNone) {
    const ProcessResult atrium = run_depthscope("cameras atrium");
    ASSERT_EQ(atrium.exit_code, 0) << atrium.err;
    EXPECT_TRUE(std::regex_search(atrium.out, std::regex("\\n0 +camera +perspective ")))
        << atrium.out;
    const fs::path none = without_cameras(fresh_dir("cameras_none"));
    const ProcessResult r = run_depthscope("cameras " + none.string());
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.out,
              "no_cameras has no camera nodes (its view is framed from the scene's "
              "bounds)\n");
    expect_one_error_line(run_depthscope("cameras no-such-scene"), 1, "no-such-scene");
}

// By name and by index alike, placed by the node hierarchy (Side: its parent's translation and
// its own rotation, looking down -X); the first perspective camera is the scene's own.
TEST(Cameras, CameraPicksANodeByNameOrIndexAndTheReportHoldsIt) {
    const json by_name = capture_report("camera_by_name", kCameras, "--camera Side");
    const json by_index = capture_report("camera_by_index", kCameras, "--camera 1");
    ASSERT_TRUE(by_name.contains("replay") && by_index.contains("replay"));
    const json& side = by_name["replay"]["camera"];
    EXPECT_EQ(side, by_index["replay"]["camera"]);
    EXPECT_EQ(floats(side["position"]), (std::vector<float>{8, 1, 0}));
    const std::vector<float> forward = floats(side["forward"]);
    EXPECT_NEAR(forward[0], -1.0f, 1e-6f);
    EXPECT_NEAR(forward[2], 0.0f, 1e-6f);
    EXPECT_FLOAT_EQ(side["yfov"].get<float>(), 1.0f);
    EXPECT_FLOAT_EQ(side["znear"].get<float>(), 0.05f);
    EXPECT_GT(side["zfar"].get<float>(), 10.0f);  // no zfar in the file: past the scene

    const json front = capture_report("camera_front", kCameras, "--camera Front");
    const json plain = capture_report("camera_default", kCameras, "");
    ASSERT_TRUE(front.contains("replay") && plain.contains("replay"));
    EXPECT_EQ(front["replay"]["camera"], plain["replay"]["camera"]);
    EXPECT_EQ(floats(front["replay"]["camera"]["position"]), (std::vector<float>{0, 1.5f, 8}));
}

// Eye and target exactly, up +Y, the field of view given or the scene camera's.
TEST(Cameras, LookAtSetsTheViewWithAndWithoutFov) {
    const json plain = capture_report("look_at", kCameras, "--look-at 0,2,6:0,1,0");
    const json wide = capture_report("look_at_fov", kCameras, "--look-at 0,2,6:0,1,0:60");
    ASSERT_TRUE(plain.contains("replay") && wide.contains("replay"));
    const json& c = plain["replay"]["camera"];
    EXPECT_EQ(floats(c["position"]), (std::vector<float>{0, 2, 6}));
    const std::vector<float> f = floats(c["forward"]);
    const float len = std::sqrt(37.0f);
    EXPECT_NEAR(f[0], 0.0f, 1e-6f);
    EXPECT_NEAR(f[1], -1.0f / len, 1e-6f);
    EXPECT_NEAR(f[2], -6.0f / len, 1e-6f);
    EXPECT_GT(floats(c["up"])[1], 0.98f);
    EXPECT_FLOAT_EQ(c["yfov"].get<float>(), 0.8f);  // Front's, the scene camera
    EXPECT_FLOAT_EQ(c["znear"].get<float>(), 0.1f);
    EXPECT_NEAR(wide["replay"]["camera"]["yfov"].get<float>(), 1.0471976f, 1e-6f);
    EXPECT_EQ(wide["replay"]["camera"]["position"], c["position"]);
    // Aspect from --size: the same camera at another size renders at that size.
    EXPECT_EQ(plain["size"]["width"], 64);
    // Two degrees off vertical is a view (one degree is the limit).
    capture_report("look_at_steep", kCameras, "--look-at 0,0,0:0.2,5,0");
}

// The other commands take the same choice: bench and pixel render from it.
TEST(Cameras, BenchAndPixelTakeTheView) {
    const ProcessResult bench = run_depthscope("bench --scene " + kCameras +
                                               " --size 32x18 --frames 1 --warmup 0 --camera Side");
    EXPECT_EQ(bench.exit_code, 0) << bench.err;
    const ProcessResult front =
        run_depthscope("pixel --scene " + kCameras + " --size 64x36 --at 32,30 --camera 0");
    const ProcessResult top_down = run_depthscope("pixel --scene " + kCameras +
                                                  " --size 64x36 --at 32,30 --look-at "
                                                  "0,1.5,8:0,8,-3");
    ASSERT_EQ(front.exit_code, 0) << front.err;
    ASSERT_EQ(top_down.exit_code, 0) << top_down.err;
    EXPECT_NE(front.out, top_down.out);  // the floor there, the sky here
}

// One error line, exit 2, and no output: --out's folder, --json's file, a replay's folder.
void expect_refused(const std::string& args, const std::string& mention) {
    const fs::path dir = fresh_dir("cameras_refused");
    const std::string out = (dir / "out").string();
    for (const std::string& command :
         {"capture --scene " + kCameras + " --size 32x18 --out " + out,
          "bench --scene " + kCameras + " --size 32x18 --frames 1 --warmup 0 --json " + out,
          "pixel --scene " + kCameras + " --size 32x18 --at 1,1 --json " + out,
          "diagnose --scene " + kCameras + " --size 32x18 --json " + out}) {
        SCOPED_TRACE(command + " " + args);
        expect_one_error_line(run_depthscope(command + " " + args), 2, mention);
        EXPECT_TRUE(fs::is_empty(dir)) << "left behind in " << dir;
    }
    // The inspector refuses before it opens a window (none here).
    const ProcessResult view = run_command(
        "env DEPTHSCOPE_CONFIG_DIR=" + (dir / "config").string() + " DISPLAY= " + DS_EXECUTABLE +
        " view --scene " + kCameras + " --frames 1 " + args);
    expect_one_error_line(view, 2, mention);
    EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST(Cameras, AnOrthographicOrUnknownCameraIsAUsageErrorAndWritesNothing) {
    expect_refused("--camera Top",
                   "--camera 'Top': camera 2 'Top' of cameras is orthographic: not supported "
                   "(the renderer is perspective only)");
    expect_refused("--camera 2", "is orthographic: not supported");
    expect_refused("--camera Back",
                   "--camera 'Back': cameras has no camera node of that name (its cameras: 0 "
                   "'Front', 1 'Side')");
    expect_refused("--camera 3", "cameras has no camera node 3 (its cameras: 0 'Front', 1 'Side')");
    expect_refused("--camera front", "no camera node of that name");  // exact match only
    expect_refused("--camera ''", "--camera expects a camera node's name or index");
    expect_refused("--camera Side --look-at 0,1,5:0,1,0", "excludes");
    const fs::path dir = fresh_dir("cameras_none_refused");
    const fs::path none = without_cameras(dir);
    const ProcessResult r = run_depthscope("capture --scene " + none.string() +
                                           " --camera 0 --out " + (dir / "out").string());
    expect_one_error_line(r, 2, "no_cameras has no camera node 0 (it has no camera nodes)");
    EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST(Cameras, ABadLookAtIsAUsageErrorAndWritesNothing) {
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"1,2,3", "--look-at expects EX,EY,EZ:TX,TY,TZ[:FOV]"},
        {"1,2:0,0,0", "--look-at expects"},
        {"1,2,x:0,0,0", "--look-at expects"},
        {"1,2,3:0,0,0:60:2", "--look-at expects"},
        {"1,2,3:0,0,nan", "--look-at expects"},
        {"1,2,3:1,2,3", "the eye and the point it looks at are the same"},
        {"1,2,3:1,2,3:60", "the eye and the point it looks at are the same"},
        {"0,0,0:0,5,0", "within 1 degree of straight up or down"},
        {"0,9,0:0.01,0,0", "within 1 degree of straight up or down"},
        {"0,0,0:0,0,-1:9.9", "FOV expects a vertical field of view in degrees, 10..120"},
        {"0,0,0:0,0,-1:121", "FOV expects"},
        {"0,0,0:0,0,-1:", "FOV expects"},
        {"0,0,0:0,0,-1:wide", "FOV expects"},
        {"-3e38,0,0:3e38,0,0", "give no direction (too far apart)"},
    };
    for (const auto& [value, mention] : cases) expect_refused("--look-at " + value, mention);
}

// diagnose's capture-folder camera is --camera-of now; it excludes the other two.
TEST(Cameras, DiagnoseTakesACaptureFoldersCameraAsCameraOf) {
    const fs::path dir = fresh_dir("cameras_camera_of");
    const fs::path cap = dir / "cap";
    ASSERT_EQ(run_depthscope("capture --scene " + kCameras + " --size 32x18 --camera Side --out " +
                             cap.string())
                  .exit_code,
              0);
    const fs::path json_path = dir / "diagnosis.json";
    const ProcessResult r =
        run_depthscope("diagnose --scene " + kCameras + " --size 32x18 " + "--camera-of " +
                           cap.string() + " --json " + json_path.string(),
                       300);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const json d = json::parse(read_file(json_path));
    const json report = json::parse(read_file(cap / "report.json"));
    EXPECT_EQ(floats(d["camera"]["position"]), floats(report["replay"]["camera"]["position"]));
    expect_one_error_line(run_depthscope("diagnose --scene " + kCameras + " --camera-of " +
                                         cap.string() + " --camera Side"),
                          2, "excludes");
    expect_one_error_line(run_depthscope("diagnose --scene " + kCameras + " --camera-of " +
                                         cap.string() + " --look-at 0,1,5:0,1,0"),
                          2, "excludes");
}

}  // namespace
}  // namespace ds::test
