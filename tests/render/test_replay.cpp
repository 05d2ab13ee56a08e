// replay (issue 13 part 3): a capture rendered again from its report.json alone.
#include <fstream>
#include <sstream>

#include "tests/render/capture_helpers.h"

namespace ds::test {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> builtin_scenes() {
    const ProcessResult r = run_depthscope("scenes");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    std::vector<std::string> names;
    std::istringstream in(r.out);
    for (std::string line; std::getline(in, line);)
        if (!line.empty()) names.push_back(line.substr(0, line.find(' ')));
    return names;
}

ProcessResult replay(const fs::path& dir, const std::string& extra = "") {
    return run_depthscope("replay " + dir.string() + " --validate --resources none " + extra);
}

void expect_identical_replay(const fs::path& dir) {
    const ProcessResult r = replay(dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("final.png is bit-identical to " + dir.string()), std::string::npos)
        << r.out;
    const fs::path again = dir.string() + "-replay";
    EXPECT_EQ(read_file(again / "final.png"), read_file(dir / "final.png"));
    // The replay's own report replays the same frame: same camera, settings and size.
    const auto a = nlohmann::json::parse(read_file(dir / "report.json"));
    const auto b = nlohmann::json::parse(read_file(again / "report.json"));
    EXPECT_EQ(a["replay"], b["replay"]);
    EXPECT_EQ(a["settings"], b["settings"]);
    EXPECT_EQ(a["graph"], b["graph"]);
}

TEST(Replay, EveryBuiltinSceneReplaysBitIdentical) {
    const std::vector<std::string> scenes = builtin_scenes();
    ASSERT_GE(scenes.size(), 5u);
    for (const std::string& scene : scenes) {
        SCOPED_TRACE(scene);
        const Capture c = capture("replay-" + scene, scene, "96x54");
        ASSERT_FALSE(c.report.is_discarded());
        EXPECT_FALSE(c.report["version"].get<std::string>().empty());
        EXPECT_EQ(c.report["replay"]["scene"]["builtin"], scene);
        EXPECT_TRUE(c.report["graph"]["passes"].is_array());
        expect_identical_replay(c.dir);
    }
}

TEST(Replay, AGltfFileReplaysAndAChangedFileIsRefusedWithoutForce) {
    const fs::path dir = fresh_dir("replay-gltf");
    const fs::path gltf = dir / "foliage.gltf";
    ASSERT_EQ(run_depthscope("export-scene foliage " + gltf.string()).exit_code, 0);
    const Capture c = capture("replay-gltf-cap", gltf.string(), "96x54");
    ASSERT_FALSE(c.report.is_discarded());
    EXPECT_EQ(c.report["replay"]["scene"]["file"], fs::absolute(gltf).string());
    EXPECT_EQ(c.report["replay"]["scene"]["sha256"].get<std::string>().size(), 64u);
    expect_identical_replay(c.dir);

    std::ofstream(gltf, std::ios::app) << "\n";  // same scene, another file
    fs::remove_all(c.dir.string() + "-replay");
    const ProcessResult refused = replay(c.dir);
    EXPECT_EQ(refused.exit_code, 1);
    EXPECT_EQ(count_lines(refused.err), 1u) << refused.err;
    EXPECT_NE(refused.err.find("changed since the capture"), std::string::npos) << refused.err;
    EXPECT_FALSE(fs::exists(c.dir.string() + "-replay"));
    const ProcessResult forced = replay(c.dir, "--force");
    EXPECT_EQ(forced.exit_code, 0) << forced.err;
    EXPECT_NE(forced.out.find("bit-identical"), std::string::npos) << forced.out;
}

TEST(Replay, SetOverridesMakeAnABPairFromOneCamera) {
    const Capture c = capture("replay-ab", "atrium", "96x54");
    const fs::path b = fresh_dir("replay-ab-b") / "b";
    const ProcessResult r = replay(c.dir, "--set exposure=4 --out " + b.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("differs from"), std::string::npos) << r.out;
    const auto report = nlohmann::json::parse(read_file(b / "report.json"));
    EXPECT_EQ(report["settings"]["exposure"], "4");
    EXPECT_EQ(report["replay"]["camera"], c.report["replay"]["camera"]);
}

// A view chosen on the command line replays exactly: report.json holds the camera node's or
// the --look-at's camera, and replay renders the same bytes from it (issue 27 part 3).
TEST(Replay, ACaptureFromACameraNodeOrALookAtReplaysBitIdentical) {
    const std::string cameras = std::string(DS_TEST_DATA) + "/cameras.gltf";
    const Capture side = capture("replay-camera", cameras, "96x54", "--camera Side");
    ASSERT_FALSE(side.report.is_discarded());
    EXPECT_EQ(side.report["replay"]["camera"]["position"], nlohmann::json({8.0, 1.0, 0.0}));
    expect_identical_replay(side.dir);
    const Capture look =
        capture("replay-look-at", "atrium", "96x54", "--look-at 0,1.7,-9:0,4,12:70");
    ASSERT_FALSE(look.report.is_discarded());
    const nlohmann::json& c = look.report["replay"]["camera"];
    EXPECT_EQ(c["position"], nlohmann::json({0.0, 1.7f, -9.0}));
    EXPECT_NEAR(c["yfov"].get<double>(), 70.0 * 3.14159265358979 / 180.0, 1e-6);
    expect_identical_replay(look.dir);
}

// replay --camera / --look-at replaces the captured camera: the frame is the one capture
// renders from that view (the same bytes), and its report holds the new camera.
TEST(Replay, CameraOrLookAtOverridesTheCapturedCamera) {
    const std::string cameras = std::string(DS_TEST_DATA) + "/cameras.gltf";
    const Capture base = capture("replay-override", cameras, "96x54");
    const Capture side = capture("replay-override-side", cameras, "96x54", "--camera Side");
    const fs::path out = fresh_dir("replay-override-out") / "r";
    const ProcessResult r = replay(base.dir, "--camera Side --out " + out.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("differs from " + base.dir.string() + " (--camera changed the view)"),
              std::string::npos)
        << r.out;
    EXPECT_EQ(read_file(out / "final.png"), read_file(side.dir / "final.png"));
    const auto report = nlohmann::json::parse(read_file(out / "report.json"));
    EXPECT_EQ(report["replay"]["camera"], side.report["replay"]["camera"]);

    const Capture look =
        capture("replay-override-look", cameras, "96x54", "--look-at 2,3,7:0,0.5,-3");
    const fs::path out2 = fresh_dir("replay-override-out2") / "r";
    ASSERT_EQ(replay(base.dir, "--look-at 2,3,7:0,0.5,-3 --out " + out2.string()).exit_code, 0);
    EXPECT_EQ(read_file(out2 / "final.png"), read_file(look.dir / "final.png"));
    // A bad choice is refused before anything is written.
    const fs::path out3 = fresh_dir("replay-override-out3") / "r";
    const ProcessResult bad = replay(base.dir, "--camera Top --out " + out3.string());
    expect_one_error_line(bad, 2, "is orthographic: not supported");
    EXPECT_FALSE(fs::exists(out3));
}

// Seed 004's acceptance from one capture: replay it without the prepass and diff the pair.
TEST(Replay, ThenDiffShowsWhatChanged) {
    const Capture c = capture("replay-diff", "atrium", "160x90",
                              "--resources all --set gtao=off --set contact_shadows=off");
    const fs::path b = fresh_dir("replay-diff-b") / "b";
    const ProcessResult r =
        run_depthscope("replay " + c.dir.string() + " --set prepass=off --out " + b.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const ProcessResult d = run_depthscope("diff " + c.dir.string() + " " + b.string());
    EXPECT_EQ(d.exit_code, 0) << d.out << d.err;
    EXPECT_NE(d.out.find("depth_prepass"), std::string::npos) << d.out;  // in A only
    EXPECT_NE(d.out.find("final"), std::string::npos) << d.out;
}

TEST(Replay, BadCapturesAreOneLineAndWriteNothing) {
    const Capture c = capture("replay-bad", "overdraw", "32x32");
    const fs::path out = fresh_dir("replay-bad-out") / "r";
    const auto expect_refused = [&](const fs::path& dir, const std::string& why) {
        const ProcessResult r = run_depthscope("replay " + dir.string() + " --out " + out.string());
        EXPECT_EQ(r.exit_code, 1) << why;
        EXPECT_EQ(count_lines(r.err), 1u) << r.err;
        EXPECT_NE(r.err.find(why), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(out));
    };
    expect_refused(fresh_dir("replay-empty"), "report.json: no such file");
    const std::string report = read_file(c.dir / "report.json");
    std::ofstream(c.dir / "report.json") << report.substr(0, report.size() / 2);
    expect_refused(c.dir, "report.json: not JSON");
    auto json = nlohmann::json::parse(report);
    json["version"] = "v0.0.0-other";
    std::ofstream(c.dir / "report.json") << json.dump();
    expect_refused(c.dir, "captured by depthscope 'v0.0.0-other'");
    json.erase("replay");
    std::ofstream(c.dir / "report.json") << json.dump();
    expect_refused(c.dir, "no replay information");
}

// An output folder that cannot be made (under /proc, where not even root creates one) or that
// fills up (a 1 KiB file-size limit; stderr stays a pipe) is one line and leaves nothing, for
// replay and for diff's --out alike.
TEST(Replay, AnUnwritableOrFullOutputIsOneLineAndLeavesNothing) {
    const Capture c = capture("replay-full", "overdraw", "64x64");
    const fs::path base = fresh_dir("replay-full-out");
    const auto expect_failed = [&](const std::string& args, int code, const std::string& why) {
        const ProcessResult r = run_depthscope_under_file_limit(1, args);
        SCOPED_TRACE(args);
        expect_one_error_line(r, code, why);
        EXPECT_TRUE(fs::is_empty(base)) << "left behind in " << base;
    };
    expect_failed("replay " + c.dir.string() + " --out /proc/ds-replay", 1,
                  "/proc/ds-replay: cannot create folder");
    expect_failed("replay " + c.dir.string() + " --out " + (base / "r").string(), 1,
                  "final.png: cannot write: File too large");
    // A B that differs (exposure 2), so diff has pixels to report and a diff.json over 1 KiB.
    const fs::path b = c.dir.string() + "-bright";
    ASSERT_EQ(run_depthscope("replay " + c.dir.string() + " --set exposure=2 --out " + b.string())
                  .exit_code,
              0);
    expect_failed("diff " + c.dir.string() + " " + b.string() + " --out /proc/ds-diff", 2,
                  "/proc/ds-diff: cannot create folder");
    expect_failed("diff " + c.dir.string() + " " + b.string() + " --out " + (base / "d").string(),
                  2, "cannot write: File too large");
}

}  // namespace
}  // namespace ds::test
