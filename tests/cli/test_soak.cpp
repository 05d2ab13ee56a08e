// bench --soak: the 60-second soak CI runs (every built-in scene, sizes, msaa, prepass and
// diagnostics, validation on: RSS flat after warm-up, no validation message, teardown's leak
// check included), its usage errors, and the rules it judges resident memory by.
#include <array>
#include <set>
#include <tuple>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "app/soak.h"
#include "tests/support/run_process.h"

namespace {

using ds::app::RssSample;
using ds::test::run_depthscope;

constexpr uint64_t kMiB = 1 << 20;

TEST(Soak, SixtySecondsKeepResidentMemoryFlatWithoutValidationMessages) {
    const auto json_path = ds::test::fresh_dir("soak") / "soak.json";
    const auto r = run_depthscope(
        "bench --soak 60 --validate --size 160x90 --json " + json_path.string(), 600);
    std::printf("%s", r.out.c_str());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err.find("validation"), std::string::npos) << r.err;
    EXPECT_NE(r.out.find("resident memory flat after warm-up, no validation messages"),
              std::string::npos)
        << r.out;
    const auto json = nlohmann::json::parse(ds::test::read_file(json_path))["soak"];
    EXPECT_GE(json["cycle_ends"].size(), 2u) << "60 s must hold warm-up and at least one more";
    EXPECT_GE(json["seconds"].get<double>(), 60.0);
    EXPECT_EQ(json["validation_messages"], 0);
    EXPECT_FALSE(json["growing"].get<bool>());
    EXPECT_GE(json["scenes"].size(), 5u);
    const auto& rss = json["rss_mib"];
    EXPECT_GT(rss["start"].get<double>(), 0.0);
    EXPECT_GT(rss["warm"].get<double>(), 0.0);
    EXPECT_GT(rss["end"].get<double>(), 0.0);
}

TEST(Soak, UsageErrorsBeforeAnyFrame) {
    for (const char* args :
         {"bench --soak 0", "bench --soak -5", "bench --soak x", "bench --soak 5 --matrix msaa=1,4",
          "bench --soak 5 --ui", "bench --soak 5 --advise"}) {
        const auto r = run_depthscope(args);
        EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
        EXPECT_EQ(ds::test::count_lines(r.err), 1u) << r.err;
        EXPECT_EQ(r.out.find("soak:"), std::string::npos) << args << ": " << r.out;
    }
}

TEST(SoakRules, GrowthCountsOnlyAboveBothTolerances) {
    const ds::app::RssTolerance tolerance{.mib = 8.0, .percent = 3.0};
    // 300 MiB after warm-up: 8 MiB is 2.7 %, so +10 MiB (3.3 %) grows and +8.5 MiB does not.
    const std::array<RssSample, 3> grows{{{10, 300 * kMiB}, {40, 305 * kMiB}, {70, 310 * kMiB}}};
    const ds::app::RssVerdict v = ds::app::judge_rss(250 * kMiB, grows, tolerance);
    EXPECT_TRUE(v.growing);
    EXPECT_DOUBLE_EQ(v.growth_mib, 10.0);
    EXPECT_NEAR(v.slope_mib_per_min, 10.0, 1e-9);  // 10 MiB per minute
    EXPECT_EQ(v.start, 250 * kMiB);

    const std::array<RssSample, 2> small{{{10, 300 * kMiB}, {70, 300 * kMiB + 17 * kMiB / 2}}};
    EXPECT_FALSE(ds::app::judge_rss(0, small, tolerance).growing) << "above 8 MiB, below 3 %";
    const std::array<RssSample, 2> tiny{{{10, 100 * kMiB}, {70, 107 * kMiB}}};
    EXPECT_FALSE(ds::app::judge_rss(0, tiny, tolerance).growing) << "7 %, but below 8 MiB";
    const std::array<RssSample, 2> shrinks{{{10, 300 * kMiB}, {70, 200 * kMiB}}};
    EXPECT_FALSE(ds::app::judge_rss(0, shrinks, tolerance).growing);
}

// The H200's pattern (2026-12-02, 150 s): RSS rose in two 4 MiB steps within the first minute
// after warm-up and stayed flat; the heap in use did not move. Not a leak. The same total
// growth spread evenly is one, and so is heap growth under a flat RSS.
TEST(SoakRules, StepsThatSettleAreNotALeakGrowthThatGoesOnIs) {
    const ds::app::RssTolerance tolerance{.mib = 8.0, .percent = 3.0};
    const uint64_t heap = 48 * kMiB;
    const std::array<RssSample, 6> steps{{{2, 274 * kMiB + kMiB / 2, heap},
                                          {21, 279 * kMiB, heap},
                                          {57, 283 * kMiB + kMiB / 3, heap},
                                          {80, 283 * kMiB + kMiB / 3, heap},
                                          {110, 283 * kMiB + kMiB / 3, heap},
                                          {150, 283 * kMiB + kMiB / 3, heap}}};
    const ds::app::RssVerdict settled = ds::app::judge_rss(210 * kMiB, steps, tolerance);
    EXPECT_GT(settled.growth_mib, 8.0);
    EXPECT_GT(settled.growth_percent, 3.0);
    EXPECT_DOUBLE_EQ(settled.late_growth_mib, 0.0);
    EXPECT_FALSE(settled.growing);

    std::array<RssSample, 6> even = steps;
    for (RssSample& s : even)  // 9 MiB at an even rate over the 148 s
        s.bytes = 274 * kMiB + uint64_t((s.seconds - 2.0) / 148.0 * 9.0 * double(kMiB));
    const ds::app::RssVerdict leak = ds::app::judge_rss(210 * kMiB, even, tolerance);
    EXPECT_GT(leak.late_growth_mib, 4.0);
    EXPECT_TRUE(leak.rss_growing);
    EXPECT_TRUE(leak.growing);

    std::array<RssSample, 6> heap_leak = steps;
    for (size_t i = 0; i < heap_leak.size(); ++i) {
        heap_leak[i].bytes = 274 * kMiB;
        heap_leak[i].heap_bytes = heap + i * 2 * kMiB;  // +10 MiB, 21 %
    }
    const ds::app::RssVerdict own = ds::app::judge_rss(210 * kMiB, heap_leak, tolerance);
    EXPECT_FALSE(own.rss_growing);
    EXPECT_TRUE(own.heap_growing);
    EXPECT_TRUE(own.growing);
}

TEST(SoakRules, EachCycleRendersEveryMsaaPrepassProbeCombinationOnce) {
    using ds::app::SoakProbe;
    const std::array<ds::app::Size, 3> sizes{{{64, 36}, {32, 18}, {25, 13}}};
    const std::array<int, 2> msaa{1, 4};
    const std::array<SoakProbe, 4> probes{SoakProbe::None, SoakProbe::Counts, SoakProbe::Pixel,
                                          SoakProbe::ZFight};
    std::set<std::tuple<size_t, int, bool, SoakProbe>> over_cycles;
    for (size_t c = 0; c < probes.size(); ++c) {
        const auto cycle = ds::app::soak_cycle(5, sizes, msaa, probes, c);
        ASSERT_EQ(cycle.size(), 5u * 2u * 2u);
        std::set<std::tuple<int, bool, SoakProbe>> combinations;
        std::set<uint32_t> widths;
        for (size_t i = 0; i < cycle.size(); ++i) {
            if (i > 0) {
                EXPECT_LE(cycle[i - 1].scene, cycle[i].scene) << "each scene once";
            }
            combinations.insert({cycle[i].msaa, cycle[i].prepass, cycle[i].probe});
            widths.insert(cycle[i].size.width);
            over_cycles.insert({cycle[i].scene, cycle[i].msaa, cycle[i].prepass, cycle[i].probe});
        }
        EXPECT_EQ(combinations.size(), 2u * 2u * probes.size()) << "cycle " << c;
        EXPECT_EQ(widths.size(), sizes.size());
    }
    EXPECT_EQ(over_cycles.size(), 5u * 2u * 2u * probes.size())
        << "every scene x msaa x prepass x probe once over as many cycles as probes";
    EXPECT_EQ(ds::app::probe_settings(SoakProbe::Counts).size(), 2u);
}

TEST(SoakRules, ResidentMemoryIsReadable) {
    EXPECT_GT(ds::app::resident_bytes(), kMiB);
}

}  // namespace
