// The prepass advisor's model on made-up numbers: the overdraw, the costs per fragment, the
// predicted and measured changes, the verdict and seed 003's rule beside it. No device.
#include <gtest/gtest.h>

#include "capture/advice.h"

namespace ds::capture {
namespace {

// 1000 covered pixels; without the prepass forward shades `layers` per pixel at 10 ns each.
AdviceInput made_up(double layers, double prepass_ms, double forward_on_ms) {
    AdviceInput in;
    in.without = {.forward_shaded = uint64_t(1000 * layers),
                  .covered_pixels = 1000,
                  .depth_ms = 0.0,
                  .forward_ms = layers * 1000 * 10e-6,
                  .frame_ms = 5.0};
    in.with_prepass = {.forward_shaded = 1000,
                       .covered_pixels = 1000,
                       .depth_ms = prepass_ms,
                       .forward_ms = forward_on_ms,
                       .frame_ms = 6.0};
    return in;
}

TEST(Advice, HighOverdrawKeepsThePrepassAndTheRuleAgrees) {
    // 8 layers: forward costs 0.08 ms without, 0.01 with; the prepass 0.02.
    const Advice a = advise(made_up(8, 0.02, 0.01));
    EXPECT_DOUBLE_EQ(a.overdraw, 8.0);
    EXPECT_DOUBLE_EQ(a.prepass_ms, 0.02);
    EXPECT_NEAR(a.ns_per_fragment_without, 10.0, 1e-9);
    EXPECT_NEAR(a.ns_per_fragment_with, 10.0, 1e-9);
    EXPECT_NEAR(a.predicted_change_ms, 0.02 - 7000 * 10e-6, 1e-12);  // -0.05
    EXPECT_NEAR(a.measured_change_ms, 0.02 + 0.01 - 0.08, 1e-12);
    EXPECT_NEAR(a.frame_change_ms, 1.0, 1e-12);
    EXPECT_TRUE(a.keep);
    EXPECT_TRUE(a.rule_keep);
    EXPECT_TRUE(a.agrees());
    const nlohmann::json j = advice_json(a);
    EXPECT_EQ(j["verdict"], "keep the prepass");
    EXPECT_EQ(j["rule_of_thumb"]["verdict"], "keep the prepass");
    EXPECT_EQ(j["rule_of_thumb"]["overdraw_above_2"], true);
    EXPECT_EQ(j["rule_of_thumb"]["agrees"], true);
    for (const char* key : {"overdraw", "prepass_ms", "forward_ns_per_fragment",
                            "predicted_change_ms", "measured_change_ms", "frame_ms", "note"})
        EXPECT_TRUE(j.contains(key)) << key;
    EXPECT_DOUBLE_EQ(j["frame_ms"]["without"].get<double>(), 5.0);
    EXPECT_NE(verdict_line(a).find("keep the prepass: the prepass saves 0.050 ms"),
              std::string::npos)
        << verdict_line(a);
}

TEST(Advice, NoOverdrawDropsItAndTheRuleAgrees) {
    const Advice a = advise(made_up(1, 0.02, 0.01));
    EXPECT_DOUBLE_EQ(a.overdraw, 1.0);
    EXPECT_NEAR(a.predicted_change_ms, 0.02, 1e-12);  // nothing saved: the prepass only costs
    EXPECT_NEAR(a.measured_change_ms, 0.02, 1e-12);
    EXPECT_FALSE(a.keep);
    EXPECT_FALSE(a.rule_keep);
    EXPECT_TRUE(a.agrees());
    EXPECT_EQ(advice_json(a)["verdict"], "drop it");
}

TEST(Advice, CheapShadingDropsItWhereTheRuleWouldKeepIt) {
    // 3 layers, but the prepass costs more than forward's hidden layers did.
    const Advice a = advise(made_up(3, 0.05, 0.01));
    EXPECT_DOUBLE_EQ(a.overdraw, 3.0);
    EXPECT_NEAR(a.measured_change_ms, 0.05 + 0.01 - 0.03, 1e-12);
    EXPECT_FALSE(a.keep);
    EXPECT_TRUE(a.rule_keep);
    EXPECT_FALSE(a.agrees());
    const nlohmann::json j = advice_json(a);
    EXPECT_EQ(j["verdict"], "drop it");
    EXPECT_EQ(j["rule_of_thumb"]["verdict"], "keep the prepass");
    EXPECT_EQ(j["rule_of_thumb"]["agrees"], false);
    EXPECT_NE(verdict_line(a).find("disagrees"), std::string::npos);
}

TEST(Advice, ExpensiveShadingKeepsItWhereTheRuleWouldDropIt) {
    // 1.5 layers at 10 ns, a nearly free prepass: it pays below the rule's threshold.
    const Advice a = advise(made_up(1.5, 0.001, 0.01));
    EXPECT_DOUBLE_EQ(a.overdraw, 1.5);
    EXPECT_LT(a.predicted_change_ms, 0);
    EXPECT_TRUE(a.keep);
    EXPECT_FALSE(a.rule_keep);
    EXPECT_FALSE(a.agrees());
}

TEST(Advice, TheResolveThatRunsEitherWayIsNoPrepassCost) {
    AdviceInput in = made_up(8, 0.03, 0.01);
    in.without.depth_ms = 0.01;  // depth_resolve after forward, msaa > 1 without the prepass
    const Advice a = advise(in);
    EXPECT_NEAR(a.prepass_ms, 0.02, 1e-12);
    EXPECT_NEAR(a.measured_change_ms, (0.03 + 0.01) - (0.01 + 0.08), 1e-12);
}

TEST(Advice, MeasuresBothConfigurationsCountingOnlyOnce) {
    Settings base;
    base.set("count_fragments", "on");  // the timed frames must not count anyway
    int counted = 0, timed = 0;
    const RenderFrame render = [&](const Settings& s) {
        const bool prepass = s.get("prepass") == "on";
        const bool counting = s.get("count_fragments") == "on";
        (counting ? counted : timed)++;
        FrameResult f;
        f.gpu_ms = prepass ? 3.0 : 2.0;
        f.passes.resize(prepass ? 2 : 1);
        PassResult& fwd = f.passes.back();
        fwd.name = "forward";
        fwd.gpu_ms = counting ? 100.0 : (prepass ? 0.5 : 2.0);
        if (counting) {
            fwd.shaded_fragments = prepass ? 10 : 40;
            f.covered_pixels = 10;
        }
        if (prepass) {
            f.passes[0].name = "depth_prepass";
            f.passes[0].gpu_ms = 0.25;
        }
        return f;
    };
    const AdviceInput in = measure_advice(base, render, {.frames = 3, .warmup = 2});
    EXPECT_EQ(counted, 2);
    EXPECT_EQ(timed, 2 * (3 + 2));
    EXPECT_EQ(in.without.forward_shaded, 40u);
    EXPECT_EQ(in.with_prepass.forward_shaded, 10u);
    EXPECT_DOUBLE_EQ(in.with_prepass.depth_ms, 0.25);
    EXPECT_DOUBLE_EQ(in.with_prepass.forward_ms, 0.5);
    EXPECT_DOUBLE_EQ(in.without.forward_ms, 2.0);
    EXPECT_DOUBLE_EQ(in.without.frame_ms, 2.0);
    EXPECT_DOUBLE_EQ(advise(in).overdraw, 4.0);
}

}  // namespace
}  // namespace ds::capture
