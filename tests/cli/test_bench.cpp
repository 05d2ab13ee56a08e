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
