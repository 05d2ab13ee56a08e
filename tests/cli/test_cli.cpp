// The command line as a user meets it: help, listings, usage errors and their exit codes.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "tests/support/run_process.h"

using ds::test::count_lines;
using ds::test::run_depthscope;

TEST(Cli, HelpDescribesEveryCommand) {
    auto r = run_depthscope("--help");
    EXPECT_EQ(r.exit_code, 0);
    for (const char* cmd :
         {"info", "scenes", "cameras", "settings", "capture", "export-scene", "bench"}) {
        EXPECT_NE(r.out.find(cmd), std::string::npos) << cmd;
    }
    EXPECT_NE(r.out.find("Exit codes"), std::string::npos);
    auto c = run_depthscope("capture --help");
    EXPECT_EQ(c.exit_code, 0);
    for (const char* opt : {"--scene", "--size", "--out", "--set", "--validate", "--renderdoc",
                            "--camera", "--look-at"}) {
        EXPECT_NE(c.out.find(opt), std::string::npos) << opt;
    }
}

TEST(Cli, ScenesListsOneLineEach) {
    auto r = run_depthscope("scenes");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(count_lines(r.out), 6u) << r.out;
    for (const char* name : {"atrium", "overdraw", "zfight", "foliage", "edges", "decals"}) {
        EXPECT_NE(r.out.find(name), std::string::npos) << name;
    }
    EXPECT_EQ(r.out.rfind("atrium", 0), 0u) << "the default scene comes first";
}

TEST(Cli, SettingsListsTheRegistry) {
    auto r = run_depthscope("settings");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("overdraw_layers"), std::string::npos);
    EXPECT_NE(r.out.find("1..64"), std::string::npos);
}

// The selected device (lavapipe here, whatever runs the suite elsewhere) with its facts.
TEST(Cli, InfoPrintsTheSelectedDevicesCapabilities) {
    auto r = run_depthscope("info");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_FALSE(ds::test::selected_device_name().empty()) << r.out;
    for (const char* line : {"suitable:             yes", "depth formats:", "D32_SFLOAT",
                             "colour sample counts:", "depth resolve modes:"})
        EXPECT_NE(r.out.find(line), std::string::npos) << line << "\n" << r.out;
}

TEST(Cli, UsageErrorsExitTwoWithOneLine) {
    for (const char* args :
         {"--bogus", "capture --size 12", "capture --size 0x5", "capture --set nope=1",
          "capture --set overdraw_layers=0", "capture --set exposure", "frobnicate"}) {
        auto r = run_depthscope(args);
        EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
        EXPECT_EQ(count_lines(r.err), 1u) << args << "\n" << r.err;
        EXPECT_EQ(r.err.rfind("depthscope: error: ", 0), 0u) << args << "\n" << r.err;
    }
}

TEST(Cli, UnknownSettingNamesTheValidOnes) {
    auto r = run_depthscope("capture --set overdraw_layer=3");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("overdraw_layers"), std::string::npos) << r.err;
}

TEST(Cli, RenderDocWithoutRenderDocIsAClearError) {
    auto dir = ds::test::fresh_dir("renderdoc-missing");
    auto r = run_depthscope("capture --renderdoc --size 32x32 --out " + (dir / "cap").string());
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("RenderDoc is not loaded"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "cap"));
}

TEST(Cli, DeviceByIndexAndNameAndAClearErrorOtherwise) {
    auto dir = ds::test::fresh_dir("device-choice");
    EXPECT_EQ(run_depthscope("capture --device 0 --scene overdraw --size 16x16 --out " +
                             (dir / "a").string())
                  .exit_code,
              0);
    // A substring of the device's name (its first word: "llvmpipe", "NVIDIA").
    const std::string name = ds::test::selected_device_name();
    const std::string word = name.substr(0, name.find(' '));
    ASSERT_FALSE(word.empty());
    EXPECT_EQ(run_depthscope("capture --device " + word + " --scene overdraw --size 16x16 --out " +
                             (dir / "b").string())
                  .exit_code,
              0);
    auto r = run_depthscope("capture --device no-such-gpu --scene overdraw --size 16x16 --out " +
                            (dir / "c").string());
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(count_lines(r.err), 1u) << r.err;
    EXPECT_NE(r.err.find("no device name contains 'no-such-gpu'"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(name), std::string::npos) << "lists the devices: " << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "c"));
}

// material_alpha_cutoff: bad syntax fails while parsing settings, a name that is no MASK
// material of the scene when rendering; both are one usage-error line and leave no capture
// folder. A good value reaches report.json in canonical form, and `settings` lists the knob.
// report.json labels the device's fragment-shader statistic with what it counts there; on
// lavapipe: once per rasterized 4x4 block, before the depth test.
TEST(Cli, ReportSaysWhatTheFragmentStatisticMeansOnThisDevice) {
    const auto dir = ds::test::fresh_dir("counters-note");
    auto r =
        run_depthscope("capture --scene overdraw --size 64x36 --out " + (dir / "out").string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto json = nlohmann::json::parse(ds::test::read_file(dir / "out" / "report.json"));
    const std::string stats = json["counters"]["stats"];
    if (json["device"]["name"].get<std::string>().find("llvmpipe") != std::string::npos) {
        EXPECT_NE(stats.find("once per rasterized 4x4 block, before the depth test"),
                  std::string::npos)
            << stats;
    }
    EXPECT_EQ(stats.find("not described"), std::string::npos) << stats;
}

TEST(Cli, MaterialAlphaCutoffErrorsAndReport) {
    auto dir = ds::test::fresh_dir("material-alpha-cutoff");
    const struct {
        const char* set;
        const char* mention;
    } bad[] = {
        {"material_alpha_cutoff=bogus=0.5",
         "material_alpha_cutoff: no masked material \"bogus\" in foliage (masked: alpha_ramp, "
         "alpha_ramp_leaf, grass)"},
        {"material_alpha_cutoff=ground=0.5", "no masked material \"ground\""},
        {"material_alpha_cutoff=alpha_ramp", "'alpha_ramp' is not NAME=V"},
        {"material_alpha_cutoff=alpha_ramp=2", "alpha_ramp: 2 is out of range 0..1"},
    };
    for (const auto& b : bad) {
        const auto out = dir / "bad";
        auto r = run_depthscope("capture --scene foliage --size 32x32 --out " + out.string() +
                                " --set " + b.set);
        EXPECT_EQ(r.exit_code, 2) << b.set << "\n" << r.err;
        EXPECT_EQ(count_lines(r.err), 1u) << b.set << "\n" << r.err;
        EXPECT_EQ(r.err.rfind("depthscope: error: ", 0), 0u) << r.err;
        EXPECT_NE(r.err.find(b.mention), std::string::npos) << r.err;
        EXPECT_FALSE(std::filesystem::exists(out)) << b.set;
    }
    for (const auto& entry : std::filesystem::directory_iterator(dir))
        ADD_FAILURE() << "left behind: " << entry.path();

    const auto good = dir / "good";
    auto r =
        run_depthscope("capture --scene foliage --size 32x32 --out " + good.string() +
                       " --set \"material_alpha_cutoff= alpha_ramp_leaf=0.70, alpha_ramp=0.3\"");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto report =
        nlohmann::json::parse(ds::test::read_file(good / "report.json"), nullptr, false);
    ASSERT_FALSE(report.is_discarded());
    EXPECT_EQ(report["settings"]["material_alpha_cutoff"], "alpha_ramp=0.3,alpha_ramp_leaf=0.7");

    auto listing = run_depthscope("settings");
    ASSERT_EQ(listing.exit_code, 0) << listing.err;
    const size_t row = listing.out.find("\nmaterial_alpha_cutoff ");
    ASSERT_NE(row, std::string::npos) << listing.out;
    const std::string line = listing.out.substr(row + 1, listing.out.find('\n', row + 1) - row - 1);
    EXPECT_NE(line.find(" map "), std::string::npos) << line;
    EXPECT_NE(line.find("NAME=0..1,..."), std::string::npos) << line;
}

// capture --ui: the inspector drawn offscreen over the frame, every panel populated.
TEST(Cli, CaptureUiDrawsTheInspectorWithTheElevenPasses) {
    const auto dir = ds::test::fresh_dir("capture_ui");
    auto r = run_depthscope("capture --ui --validate --scene atrium --size 1280x720 --out " +
                            (dir / "out").string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto png = ds::test::read_png(dir / "out" / "final.png");
    EXPECT_EQ(png.width, 1280u);
    EXPECT_EQ(png.height, 720u);
    // The report is the frame the viewer showed: smaller than the UI, eleven passes with
    // timings (the atrium's decals have their pass).
    auto json = nlohmann::json::parse(ds::test::read_file(dir / "out" / "report.json"));
    EXPECT_LT(json["size"]["width"].get<unsigned>(), 1280u);
    const auto frame_passes = std::count_if(json["passes"].begin(), json["passes"].end(),
                                            [](const auto& p) { return p["kind"] == "frame"; });
    ASSERT_EQ(frame_passes, 11);
    for (const auto& p : json["passes"]) EXPECT_GT(p["gpu_ms"].get<double>(), 0.0) << p.dump();
    // A plain capture of the same size differs almost everywhere: panels are drawn over it.
    auto plain =
        run_depthscope("capture --scene atrium --size 1280x720 --out " + (dir / "plain").string());
    ASSERT_EQ(plain.exit_code, 0) << plain.err;
    const auto plain_png = ds::test::read_png(dir / "plain" / "final.png");
    EXPECT_GT(ds::test::differing_pixels(png, plain_png, 8), size_t(1280 * 720 / 2));
    // Any resource can be the one shown.
    auto other = run_depthscope("capture --ui --scene edges --size 640x360 --view normals --out " +
                                (dir / "normals").string());
    EXPECT_EQ(other.exit_code, 0) << other.err;
    // One that this frame does not have is a usage error, and nothing is written.
    auto bad = run_depthscope(
        "capture --ui --scene edges --size 320x180 --view forward_counts "
        "--out " +
        (dir / "bad").string());
    EXPECT_EQ(bad.exit_code, 2) << bad.err;
    EXPECT_EQ(ds::test::count_lines(bad.err), 1u) << bad.err;
    EXPECT_NE(bad.err.find("depthscope: error: --view forward_counts"), std::string::npos);
    EXPECT_FALSE(std::filesystem::exists(dir / "bad"));
}

// The inspector's options live at the top level too; before another command they are refused.
TEST(Cli, InspectorOptionsBeforeACommandAreRefused) {
    for (const char* args : {"--size 64x48 capture", "--set exposure=2 capture --set prepass=on",
                             "--frames 2 bench", "--scene edges capture"}) {
        auto r = run_depthscope(args);
        EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
        EXPECT_EQ(ds::test::count_lines(r.err), 1u) << r.err;
        EXPECT_NE(r.err.find("put options after the command"), std::string::npos) << r.err;
    }
}
