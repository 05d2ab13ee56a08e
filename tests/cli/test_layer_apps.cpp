// depthscope's Vulkan layer on applications it does not own: vkcube under Xvfb (live), the
// same vkcube run captured by GFXReconstruct and replayed (gfxrecon-replay), and the
// launcher's refusals.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "tests/support/run_process.h"

namespace ds::test {
namespace {

using nlohmann::json;

// A command under its own X server (xvfb-run picks a free display from 100 on: the window
// tests start at 70 and 80, so a search started together never races for one).
ProcessResult under_xvfb(const std::string& command, int timeout_s = 180) {
    return run_command("xvfb-run -a -n 100 -s '-screen 0 640x480x24' " + command, timeout_s);
}

std::string layer(const std::string& args) {
    return std::string(DS_EXECUTABLE) + " layer " + args;
}

// What must be the same live and replayed: the draws and their counts (not handles or times).
json comparable(const json& report) {
    json draws = json::array();
    for (const json& d : report.at("draws")) {
        json c = d;
        c.erase("pipeline");
        draws.push_back(c);
    }
    json passes = json::array();
    for (const json& p : report.at("passes")) {
        json c = p;
        c.erase("submission");
        c.erase("index");
        if (c.contains("images"))
            for (auto& [kind, image] : c["images"].items()) c["images"][kind] = image.at("total");
        passes.push_back(c);
    }
    return {{"draws", draws},
            {"passes", passes},
            {"not_analysed", report.at("not_analysed")},
            {"zfight", report.value("zfight", json())},
            {"equal_check", report.value("equal_check", json())}};
}

TEST(LayerVkcube, ListsFramesAndCapturesFrameFiveLiveAndReplayed) {
    const auto dir = fresh_dir("layer_vkcube");
    const ProcessResult list = under_xvfb(layer("--list -- vkcube --c 6"));
    ASSERT_EQ(list.exit_code, 0) << list.err;
    EXPECT_NE(list.out.find("render pass 500x500 depth D16_UNORM: 1 draw"), std::string::npos)
        << list.out;
    EXPECT_NE(list.out.find("frames 2-6 (each)"), std::string::npos) << list.out;

    // vkcube --validate (it then labels its draws) captured by GFXReconstruct alone: the loader
    // puts depthscope's layer above GFXReconstruct's whatever VK_INSTANCE_LAYERS' order, so a
    // capture made under both holds the layer's work. Then the same command under the layer,
    // frame 5 (vkcube's frames are deterministic); the validation layer comes after it, vkcube
    // prints each message ("ERROR : VALIDATION - …"), and the layer must add none.
    const auto gfxr = dir / "cube.gfxr";
    const ProcessResult record = under_xvfb(
        "env VK_INSTANCE_LAYERS=VK_LAYER_LUNARG_gfxreconstruct GFXRECON_CAPTURE_FILE=" +
        gfxr.string() + " GFXRECON_CAPTURE_FILE_TIMESTAMP=false vkcube --validate --c 8");
    ASSERT_EQ(record.exit_code, 0) << record.err;
    ASSERT_TRUE(std::filesystem::exists(gfxr)) << record.err;
    // With the Z-fight and EQUAL checks on: a cube has no coplanar surfaces and no EQUAL pass.
    const std::string checks = "--set zfight=on --set equal_check=on ";
    const ProcessResult live =
        under_xvfb(layer("--frame 5 " + checks + "--out " + (dir / "live").string() +
                         " -- vkcube --validate --c 8"));
    ASSERT_EQ(live.exit_code, 0) << live.err;
    EXPECT_EQ((live.out + live.err).find("VALIDATION"), std::string::npos) << live.out << live.err;
    const json a = json::parse(read_file(dir / "live" / "report.json"));
    ASSERT_EQ(a.at("draws").size(), 1u);
    const json& draw = a.at("draws")[0];
    EXPECT_EQ(draw.at("count"), 36);
    EXPECT_GT(draw.at("rasterized").get<uint64_t>(), 10000u);
    // Back faces culled, nothing in front of the cube: every fragment passes and shades.
    EXPECT_EQ(draw.at("shaded"), draw.at("rasterized"));
    EXPECT_EQ(draw.at("samples_passed"), draw.at("rasterized"));
    EXPECT_EQ(a.at("pipelines")[0].at("early_z"), "guaranteed");
    EXPECT_EQ(a.at("zfight").at("pairs").size(), 0u) << a.at("zfight").dump();
    EXPECT_EQ(a.at("zfight").at("pixels"), 0);
    EXPECT_EQ(draw.value("depth_recorded", false), true) << draw.dump();
    EXPECT_EQ(a.at("equal_check").at("holes"), 0);

    const ProcessResult replay =
        under_xvfb(layer("--frame 5 " + checks + "--out " + (dir / "replay").string() +
                         " -- gfxrecon-replay " + gfxr.string()));
    ASSERT_EQ(replay.exit_code, 0) << replay.err;
    const json b = json::parse(read_file(dir / "replay" / "report.json"));
    EXPECT_EQ(comparable(a), comparable(b));
    // diff says so too: the same draws and count images.
    const ProcessResult diff =
        run_depthscope("diff " + (dir / "live").string() + " " + (dir / "replay").string());
    EXPECT_EQ(diff.exit_code, 0) << diff.out << diff.err;
    EXPECT_EQ(diff.out.rfind("same: 1 draws and 4 count images equal", 0), 0u) << diff.out;
    // The inspector opens it read-only (no scene to render again) in a real window.
    const ProcessResult view = under_xvfb(std::string(DS_EXECUTABLE) + " view --capture " +
                                          (dir / "live").string() + " --frames 10");
    EXPECT_EQ(view.exit_code, 0) << view.err;
    EXPECT_NE(view.out.find("layer capture"), std::string::npos) << view.out;
    EXPECT_NE(view.out.find("10 frames"), std::string::npos) << view.out;
}

TEST(LayerLauncher, RefusesBadInputWithOneLine) {
    const auto dir = fresh_dir("layer_bad_input");
    expect_one_error_line(run_depthscope("layer --list"), 2, "app");
    expect_one_error_line(run_depthscope("layer -- vkcube"), 2, "--list or --frame");
    expect_one_error_line(run_depthscope("layer --list --bogus -- vkcube"), 2, "bogus");
    expect_one_error_line(run_depthscope("layer --list -- no-such-app-here"), 1,
                          "no-such-app-here");
    expect_one_error_line(run_depthscope("layer --frame 0 -- vkcube"), 2, "--frame");
    expect_one_error_line(run_depthscope("layer --list --set bogus=on -- vkcube"), 2,
                          "unknown setting 'bogus'");
    expect_one_error_line(run_depthscope("layer --list --set zfight=maybe -- vkcube"), 2,
                          "expects on or off");
    expect_one_error_line(run_depthscope("layer --list --set zfight_steps=2000 -- vkcube"), 2,
                          "from 0 to 1024");
    expect_one_error_line(run_depthscope("layer --list --set zfight_steps=-1 -- vkcube"), 2,
                          "from 0 to 1024");
    // A frame that never comes: the application (depthscope, two submissions) ends first.
    const auto out = dir / "never";
    expect_one_error_line(
        run_depthscope("layer --frame 9 --out " + out.string() + " -- " + DS_EXECUTABLE +
                       " capture --resources none --scene overdraw --size "
                       "64x36 --out " +
                       (dir / "app").string()),
        1, "submission 9 never came");
    EXPECT_FALSE(std::filesystem::exists(out));
    // An unwritable folder: refused before the application runs.
    const ProcessResult r = run_depthscope("layer --frame 1 --out /proc/no/such -- vkcube");
    EXPECT_NE(r.exit_code, 0);
    EXPECT_EQ(count_lines(r.err), 1u) << r.err;
}

}  // namespace
}  // namespace ds::test
