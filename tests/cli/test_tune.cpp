// depthscope tune and capture --reference through the real executable on the device: msaa on
// the edges scene (edge error falls as samples rise, the front holds both ends, fragments make
// two runs agree), alpha on a MASK texture whose best cutoff is known by construction, the
// reference as a capture resource, and bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "tests/cli/tune_scene.h"
#include "tests/support/run_process.h"

namespace {

using ds::test::run_depthscope;
using nlohmann::json;

json run_json(const std::string& name, const std::string& args, int timeout_s = 300) {
    const auto path = ds::test::fresh_dir("tune_" + name) / "tune.json";
    const auto r =
        run_depthscope("tune " + args + " --validate --json " + path.string(), timeout_s);
    EXPECT_EQ(r.exit_code, 0) << r.err << r.out;
    if (!std::filesystem::exists(path)) return json::object();
    return json::parse(ds::test::read_file(path));
}

TEST(TuneMsaa, EdgeErrorFallsAsSamplesRiseAndTheFrontHoldsBothEnds) {
    const std::string args = "msaa --scene edges --size 160x90 --cost fragments";
    const json a = run_json("msaa_a", args);
    ASSERT_TRUE(a.contains("candidates")) << a.dump();
    EXPECT_GT(a["reference"]["edge_pixels"].get<uint64_t>(), 100u);
    std::vector<std::pair<int, double>> plain;  // msaa alone, in count order
    int highest = 1;
    bool front_has_1 = false, front_has_highest = false;
    for (const json& c : a["candidates"]) highest = std::max(highest, c["msaa"].get<int>());
    for (const json& c : a["candidates"]) {
        if (!c["sample_shading"].get<bool>() && !c["alpha_to_coverage"].get<bool>())
            plain.emplace_back(c["msaa"].get<int>(), c["edge_error"].get<double>());
        if (c["front"].get<bool>()) {
            front_has_1 = front_has_1 || c["msaa"] == 1;
            front_has_highest = front_has_highest || c["msaa"] == highest;
        }
    }
    ASSERT_GE(plain.size(), 2u) << "the device has one msaa count";
    for (size_t i = 1; i < plain.size(); ++i)
        EXPECT_LT(plain[i].second, plain[i - 1].second)
            << "msaa " << plain[i].first << " against " << plain[i - 1].first;
    EXPECT_TRUE(front_has_1);
    EXPECT_TRUE(front_has_highest);
    const json b = run_json("msaa_b", args);
    EXPECT_EQ(a["recommendations"], b["recommendations"]);
    for (size_t i = 0; i < a["candidates"].size() && i < b["candidates"].size(); ++i)
        EXPECT_EQ(a["candidates"][i]["cost"]["shaded_fragments"],
                  b["candidates"][i]["cost"]["shaded_fragments"]);
}

TEST(TuneAlpha, RecommendsTheCutoffKnownByConstruction) {
    const auto dir = ds::test::fresh_dir("tune_alpha_scene");
    const ds::test::TuneScene s = ds::test::write_tune_scene(dir);
    const auto plot = dir / "alpha.png";
    const json t = run_json("alpha_synthetic", "alpha --scene " + s.gltf.string() + " --size " +
                                                   s.size + " --plot " + plot.string());
    ASSERT_EQ(t["materials"].size(), 1u) << t.dump();
    const json& m = t["materials"][0];
    EXPECT_EQ(m["name"], "cards");
    const json& best = m["points"][m["best"].get<size_t>()];
    EXPECT_NEAR(best["cutoff"].get<double>(), s.best_cutoff, 0.05 + 1e-6) << m.dump(1);
    const json& current = m["points"][m["current"].get<size_t>()];
    EXPECT_GT(current["coverage_error"].get<double>(), best["coverage_error"].get<double>() + 0.1);
    const ds::test::Png png = ds::test::read_png(plot);
    EXPECT_EQ(png.width, 800);
    EXPECT_GT(ds::test::distinct_colours(png), 3u);
}

// Seen from far, the grass bushes sample mip levels whose box-filtered alpha lost coverage:
// alpha_mip_coverage=preserve brings the frame's coverage of them closer to the reference's.
TEST(TuneAlpha, PreservedMipCoverageLowersTheFarGrassCoverageError) {
    const std::string args =
        "alpha --scene foliage --size 320x180 --material grass --step 0.25 "
        "--look-at 0,3,40:0,1,0:20 --set alpha_mip_coverage=";
    double error[2] = {0, 0};
    for (int preserve = 0; preserve < 2; ++preserve) {
        const json t = run_json(preserve ? "alpha_preserve" : "alpha_box",
                                args + (preserve ? "preserve" : "box"));
        ASSERT_EQ(t["materials"].size(), 1u) << t.dump();
        const json& m = t["materials"][0];
        EXPECT_GT(m["reference_covered_pixels"].get<uint64_t>(), 100u);
        error[preserve] = m["points"][m["current"].get<size_t>()]["coverage_error"].get<double>();
    }
    EXPECT_LT(error[1], error[0] * 0.8) << "box " << error[0] << ", preserve " << error[1];
}

TEST(TuneCapture, ReferenceIsAResourceAndScoresFinal) {
    const auto dir = ds::test::fresh_dir("tune_capture_reference") / "cap";
    const auto r = run_depthscope(
        "capture --validate --scene edges --size 96x54 --reference --out " + dir.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const json report = json::parse(ds::test::read_file(dir / "report.json"));
    const json& ref = report["reference"];
    EXPECT_EQ(ref["samples_per_pixel"], 16);
    EXPECT_GT(ref["edge_pixels"].get<uint64_t>(), 0u);
    const double ssim = ref["final"]["ssim"].get<double>();
    EXPECT_GT(ssim, 0.5);
    EXPECT_LT(ssim, 1.0);  // aliased edges differ from the reference
    for (const char* f : {"reference.png", "reference.exr", "reference_edges.png"})
        EXPECT_TRUE(std::filesystem::exists(dir / "resources" / f)) << f;
    EXPECT_EQ(ds::test::read_png(dir / "resources" / "reference.png").width, 96);
}

TEST(TuneCli, BadInputIsOneLineAndWritesNothing) {
    const auto dir = ds::test::fresh_dir("tune_bad");
    ds::test::expect_one_error_line(run_depthscope("tune msaa --cost seconds"), 2, "--cost");
    ds::test::expect_one_error_line(run_depthscope("tune alpha --step 0"), 2, "--step");
    ds::test::expect_one_error_line(
        run_depthscope("tune alpha --scene foliage --size 64x36 --material nothing"), 2, "nothing");
    ds::test::expect_one_error_line(run_depthscope("tune alpha --scene overdraw --size 64x36"), 2,
                                    "MASK");
    ds::test::expect_one_error_line(run_depthscope("tune msaa --size 8x8 --scene edges"), 2, "11");
    ds::test::expect_one_error_line(
        run_depthscope("tune msaa --scene edges --json " + (dir / "no" / "t.json").string()), 1,
        "--json");
    ds::test::expect_one_error_line(run_depthscope("tune"), 2, "subcommand");
    EXPECT_TRUE(std::filesystem::is_empty(dir));
}

}  // namespace
