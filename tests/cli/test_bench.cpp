// bench: one run per matrix combination, per-pass statistics, JSON shape. Counts, never times.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tests/support/run_process.h"

using ds::test::run_depthscope;

TEST(Bench, MatrixRunsEveryCombinationInOrder) {
    const auto json_path = ds::test::fresh_dir("bench") / "bench.json";
    auto r = run_depthscope(
        "bench --validate --scene overdraw --size 64x64 --frames 3 --warmup 1 "
        "--matrix exposure=1,2 --matrix sun_elevation=30,60 --json " +
        json_path.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("run 4: exposure=2 sun_elevation=60"), std::string::npos) << r.out;
    auto json = nlohmann::json::parse(ds::test::read_file(json_path));
    ASSERT_EQ(json["runs"].size(), 4u);
    EXPECT_EQ(json["frames"], 3);
    // The first knob varies slowest.
    EXPECT_EQ(json["runs"][0]["settings"]["exposure"], "1");
    EXPECT_EQ(json["runs"][0]["settings"]["sun_elevation"], "30");
    EXPECT_EQ(json["runs"][1]["settings"]["sun_elevation"], "60");
    EXPECT_EQ(json["runs"][2]["settings"]["exposure"], "2");
    for (const auto& run : json["runs"]) {
        const auto& frame = run["frame_ms"];
        EXPECT_LE(frame["min"].get<double>(), frame["median"].get<double>());
        EXPECT_LE(frame["median"].get<double>(), frame["max"].get<double>());
        ASSERT_FALSE(run["passes"].empty());
        EXPECT_EQ(run["passes"].back()["name"], "tonemap");
    }
}

TEST(Bench, BadMatrixIsAUsageErrorBeforeAnyFrame) {
    for (const char* spec : {"nope=1,2", "exposure=", "exposure", "exposure=1,,2", "exposure=0"}) {
        auto r = run_depthscope(std::string("bench --scene overdraw --matrix ") + spec);
        EXPECT_EQ(r.exit_code, 2) << spec << "\n" << r.err;
        EXPECT_EQ(ds::test::count_lines(r.err), 1u) << r.err;
        EXPECT_TRUE(r.out.empty()) << "nothing rendered for " << spec << ": " << r.out;
    }
}

TEST(Bench, UiDrawsTheInspectorEveryFrameBesideThePlainFrame) {
    const auto json_path = ds::test::fresh_dir("bench_ui") / "bench.json";
    auto r = run_depthscope(
        "bench --validate --ui --scene edges --size 320x180 --frames 2 "
        "--warmup 1 --matrix msaa=1,4 --json " +
        json_path.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("run 4: msaa=4 + inspector"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("the UI costs"), std::string::npos) << r.out;
    auto json = nlohmann::json::parse(ds::test::read_file(json_path));
    ASSERT_EQ(json["runs"].size(), 4u);  // per combination: plain, then with the inspector
    for (size_t i = 0; i < 4; ++i) {
        const auto& run = json["runs"][i];
        EXPECT_EQ(run["ui"].get<bool>(), i % 2 == 1);
        bool ui_row = false;
        for (const auto& p : run["passes"]) ui_row = ui_row || p["name"] == "ui";
        EXPECT_EQ(ui_row, i % 2 == 1) << run.dump();
    }
    EXPECT_EQ(json["runs"][3]["settings"]["msaa"], "4");
}

// prepass_mode (issue 14) through the real executable: bench's matrix and JSON settings echo,
// capture's report.json, the settings listing and a refused value.
TEST(Bench, PrepassModeMatrixCaptureListingAndRefusal) {
    const auto dir = ds::test::fresh_dir("bench_prepass_mode");
    const auto json_path = dir / "bench.json";
    auto r = run_depthscope(
        "bench --validate --scene atrium --size 64x36 --frames 2 --warmup 1 "
        "--matrix prepass_mode=gbuffer,depth --set gtao=off --json " +
        json_path.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("run 2: prepass_mode=depth"), std::string::npos) << r.out;
    auto json = nlohmann::json::parse(ds::test::read_file(json_path));
    ASSERT_EQ(json["runs"].size(), 2u);
    EXPECT_EQ(json["runs"][0]["settings"]["prepass_mode"], "gbuffer");
    EXPECT_EQ(json["runs"][1]["settings"]["prepass_mode"], "depth");
    for (const auto& p : json["runs"][1]["passes"]) {
        if (p["name"] != "depth_prepass") continue;
        EXPECT_EQ(p["pipelines"][0]["name"], "depth_prepass opaque z-only");
        EXPECT_EQ(p["pipelines"][0]["fragment_stage"], false);
    }

    auto capture = run_depthscope("capture --validate --resources none --scene atrium --size "
                                  "64x36 --set prepass_mode=depth --out " +
                                  (dir / "cap").string());
    ASSERT_EQ(capture.exit_code, 0) << capture.err;
    const auto report = nlohmann::json::parse(ds::test::read_file(dir / "cap" / "report.json"));
    EXPECT_EQ(report["settings"]["prepass_mode"], "depth");

    auto listing = run_depthscope("settings");
    ASSERT_EQ(listing.exit_code, 0) << listing.err;
    const size_t row = listing.out.find("\nprepass_mode ");
    ASSERT_NE(row, std::string::npos) << listing.out;
    const std::string line = listing.out.substr(row + 1, listing.out.find('\n', row + 1) - row - 1);
    EXPECT_NE(line.find("gbuffer|depth"), std::string::npos) << line;

    auto bad = run_depthscope("capture --set prepass_mode=zonly --out " + (dir / "bad").string());
    EXPECT_EQ(bad.exit_code, 2) << bad.err;
    EXPECT_EQ(ds::test::count_lines(bad.err), 1u) << bad.err;
    EXPECT_EQ(bad.err.rfind("depthscope: error: ", 0), 0u) << bad.err;
    EXPECT_NE(bad.err.find("gbuffer|depth"), std::string::npos) << bad.err;
}
