// bench --advise and capture --advise on the overdraw scene: the overdraw comes from exact
// counts (8 view-filling layers: 8; one layer: 1), and the verdict is robust there (8 layers:
// forward shades 8 times the pixels without the prepass; 1 layer: the prepass saves nothing,
// so it can only cost). Times are never asserted.
#include <gtest/gtest.h>

#include <filesystem>

#include <nlohmann/json.hpp>

#include "tests/support/run_process.h"

using ds::test::run_depthscope;

namespace {

constexpr const char* kBench =
    "bench --advise --validate --scene overdraw --size 320x180 --frames 5 --warmup 1";

nlohmann::json bench_advice(const std::string& name, const std::string& extra) {
    const auto json_path = ds::test::fresh_dir(name) / "bench.json";
    auto r = run_depthscope(std::string(kBench) + extra + " --json " + json_path.string());
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("verdict: "), std::string::npos) << r.out;
    const auto json = nlohmann::json::parse(ds::test::read_file(json_path));
    EXPECT_EQ(json["runs"].size(), 1u);
    return json["runs"][0]["advice"];
}

}  // namespace

TEST(Advise, EightLayersOverdrawEightAndTheVerdictKeepsThePrepass) {
    const auto advice = bench_advice("advise8", "");
    ASSERT_TRUE(advice.is_object()) << advice.dump();
    EXPECT_DOUBLE_EQ(advice["overdraw"].get<double>(), 8.0);
    EXPECT_EQ(advice["covered_pixels"], 320 * 180);
    EXPECT_EQ(advice["shaded_fragments"]["without"], 8 * 320 * 180);
    EXPECT_EQ(advice["shaded_fragments"]["with_prepass"], 320 * 180);
    EXPECT_EQ(advice["verdict"], "keep the prepass");
    EXPECT_EQ(advice["rule_of_thumb"]["overdraw_above_2"], true);
    EXPECT_EQ(advice["rule_of_thumb"]["agrees"], true);
    EXPECT_GT(advice["forward_ns_per_fragment"]["without"].get<double>(), 0.0);
}

TEST(Advise, OneLayerOverdrawOneAndTheVerdictDropsIt) {
    const auto advice = bench_advice("advise1", " --set overdraw_layers=1");
    ASSERT_TRUE(advice.is_object()) << advice.dump();
    EXPECT_DOUBLE_EQ(advice["overdraw"].get<double>(), 1.0);
    EXPECT_EQ(advice["verdict"], "drop it");
    EXPECT_EQ(advice["rule_of_thumb"]["verdict"], "drop it");
    // Nothing to save: the prediction is the prepass's own cost.
    EXPECT_DOUBLE_EQ(advice["predicted_change_ms"].get<double>(),
                     advice["prepass_ms"].get<double>());
}

TEST(Advise, AMatrixOverThePrepassIsAUsageError) {
    auto r = run_depthscope(std::string(kBench) + " --matrix prepass=on,off");
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(ds::test::count_lines(r.err), 1u) << r.err;
    EXPECT_NE(r.err.find("prepass"), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
}

TEST(Advise, CaptureWritesTheAdviceIntoTheReportAndKeepsItsFrame) {
    const auto dir = ds::test::fresh_dir("advise_capture") / "cap";
    auto r = run_depthscope("capture --advise --validate --scene overdraw --size 320x180 --out " +
                            dir.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    ASSERT_TRUE(std::filesystem::exists(dir / "final.png"));
    const auto report = nlohmann::json::parse(ds::test::read_file(dir / "report.json"));
    ASSERT_TRUE(report.contains("advice")) << report.dump();
    EXPECT_DOUBLE_EQ(report["advice"]["overdraw"].get<double>(), 8.0);
    EXPECT_EQ(report["advice"]["verdict"], "keep the prepass");
    EXPECT_EQ(report["settings"]["prepass"], "on");  // the frame the settings asked for
    // Without --advise there is none.
    const auto plain = ds::test::fresh_dir("advise_capture_plain") / "cap";
    ASSERT_EQ(
        run_depthscope("capture --scene overdraw --size 32x32 --out " + plain.string()).exit_code,
        0);
    EXPECT_FALSE(
        nlohmann::json::parse(ds::test::read_file(plain / "report.json")).contains("advice"));
}
