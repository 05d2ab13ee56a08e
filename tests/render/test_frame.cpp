// The seed frame through the real executable: pass order, validation over the settings that
// change the frame's structure, exact shaded-fragment counts, prepass on/off equivalence.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "tests/render/capture_helpers.h"

using namespace ds::test;

namespace {

const std::vector<std::string> kAllPasses = {
    "shadow",  "depth_prepass", "gtao",   "ao_spatial",  "ao_temporal", "contact_shadows",
    "forward", "skybox",        "decals", "transparent", "tonemap"};

// Without the prepass, gtao and contact shadows have no input and are skipped.
const std::vector<std::string> kPassesWithoutPrepass = {"shadow", "forward",     "skybox",
                                                        "decals", "transparent", "tonemap"};

// The frame's own passes (kind "frame": no clear or read-back), in execution order.
std::vector<std::string> pass_names(const nlohmann::json& passes) {
    std::vector<std::string> names;
    for (const auto& p : passes)
        if (p["kind"] == "frame") names.push_back(p["name"].get<std::string>());
    return names;
}

nlohmann::json find_pass(const nlohmann::json& report, const std::string& name) {
    for (const auto& p : report["passes"]) {
        if (p["name"] == name) return p;
    }
    ADD_FAILURE() << "no pass " << name;
    return {};
}

}  // namespace

// 16 combinations in one process, validation on: any message makes the exit code 3.
TEST(Frame, EveryStructuralCombinationIsValidationClean) {
    const auto json_path = fresh_dir("frame-matrix") / "bench.json";
    auto r = run_depthscope(
        "bench --validate --scene atrium --size 320x180 --frames 1 --warmup 0 "
        "--matrix prepass=on,off --matrix depth_compare=equal,greater_or_equal "
        "--matrix masked_split=on,off --matrix reverse_z=on,off --json " +
            json_path.string(),
        600);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    auto json = nlohmann::json::parse(read_file(json_path));
    ASSERT_EQ(json["runs"].size(), 16u);
    for (const auto& run : json["runs"]) {
        const auto names = pass_names(run["passes"]);
        if (run["settings"]["prepass"] == "on") {
            EXPECT_EQ(names, kAllPasses) << run["settings"].dump();
        } else {
            // Without the prepass, gtao and contact shadows have no input and are skipped.
            EXPECT_EQ(names, kPassesWithoutPrepass) << run["settings"].dump();
        }
    }
}

// Depth knobs: every depth format (lavapipe has all three) x reverse_z x prepass x msaa 1/4
// in one process, validation on, each run with the frame's passes in order; at 4x the shader
// depth resolve (where the device has no native one) follows the pass that wrote the depth.
TEST(Frame, EveryDepthCombinationIsValidationClean) {
    const auto json_path = fresh_dir("frame-depth-matrix") / "bench.json";
    auto r = run_depthscope(
        "bench --validate --scene atrium --size 160x90 --frames 1 --warmup 0 "
        "--matrix depth_format=d32f,d24,d16 --matrix reverse_z=on,off --matrix prepass=on,off "
        "--matrix msaa=1,4 --json " +
            json_path.string(),
        600);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    auto json = nlohmann::json::parse(read_file(json_path));
    ASSERT_EQ(json["runs"].size(), 24u);
    std::set<std::string> seen;
    for (const auto& run : json["runs"]) {
        const auto& s = run["settings"];
        seen.insert(s["depth_format"].get<std::string>() + s["reverse_z"].get<std::string>() +
                    s["prepass"].get<std::string>() + s["msaa"].get<std::string>());
        std::vector<std::string> names = pass_names(run["passes"]);
        const bool prepass = s["prepass"] == "on";
        const auto resolve = std::find(names.begin(), names.end(), "depth_resolve");
        if (resolve != names.end()) {
            EXPECT_EQ(s["msaa"], "4") << s.dump();
            ASSERT_NE(resolve, names.begin());
            // Without the prepass the depth resolves after the last pass that draws into it.
            EXPECT_EQ(*(resolve - 1), prepass ? "depth_prepass" : "transparent") << s.dump();
            names.erase(resolve);
        }
        EXPECT_EQ(names, prepass ? kAllPasses : kPassesWithoutPrepass) << s.dump();
    }
    EXPECT_EQ(seen.size(), 24u);
}

TEST(Frame, ReportListsPassesWithStatsAndCoverage) {
    Capture c = capture("frame-report", "atrium", "320x180");
    ASSERT_FALSE(c.report.is_discarded());
    EXPECT_EQ(pass_names(c.report["passes"]), kAllPasses);
    for (const auto& p : c.report["passes"]) {
        EXPECT_GE(p["gpu_ms"].get<double>(), 0.0) << p.dump();
        for (const char* k :
             {"vertex_shader_invocations", "fragment_shader_invocations", "clipping_primitives"}) {
            EXPECT_TRUE(p["stats"].contains(k)) << p.dump();
        }
        EXPECT_FALSE(p.contains("shaded_fragments")) << "only with count_fragments=on";
    }
    EXPECT_GT(find_pass(c.report, "forward")["stats"]["vertex_shader_invocations"].get<double>(),
              0.0);
    const auto covered = c.report["coverage"]["covered_pixels"].get<int64_t>();
    EXPECT_GT(covered, 320 * 180 / 2) << "the atrium view is mostly geometry";
    EXPECT_LT(covered, 320 * 180) << "and shows some sky";
}

// Prepass on: EQUAL keeps exactly the visible fragment per pixel. Off: the atrium's authored
// (not front-to-back) order makes forward shade every layer.
TEST(Frame, ShadedFragmentsShowWhatThePrepassSaves) {
    Capture on = capture("count-on", "atrium", "320x180", "--set count_fragments=on");
    Capture off =
        capture("count-off", "atrium", "320x180", "--set count_fragments=on --set prepass=off");
    const double covered_on = on.report["coverage"]["covered_pixels"].get<double>();
    const double covered_off = off.report["coverage"]["covered_pixels"].get<double>();
    const double fwd_on = find_pass(on.report, "forward")["shaded_fragments"].get<double>();
    const double fwd_off = find_pass(off.report, "forward")["shaded_fragments"].get<double>();
    EXPECT_LE(fwd_on, 1.02 * covered_on);
    EXPECT_GE(fwd_on, 0.98 * covered_on) << "EQUAL must not reject visible fragments";
    EXPECT_GE(fwd_off, 2.0 * covered_off);
    EXPECT_TRUE(find_pass(on.report, "depth_prepass").contains("shaded_fragments"));
    EXPECT_TRUE(find_pass(on.report, "transparent").contains("shaded_fragments"));
}

// The exact numbers the overdraw scene's geometry implies: N view-filling quads drawn back to
// front, so without a prepass every quad is shaded at every pixel; with it, one per pixel.
TEST(Frame, OverdrawCountsMatchTheGeometry) {
    const int w = 96, h = 64, layers = 5;
    const std::string size = std::to_string(w) + "x" + std::to_string(h);
    const std::string common =
        "--set count_fragments=on --set overdraw_layers=" + std::to_string(layers);
    Capture sorted = capture("overdraw-sorted", "overdraw", size, common);
    Capture authored =
        capture("overdraw-authored", "overdraw", size, common + " --set prepass_sort=off");
    Capture off = capture("overdraw-off", "overdraw", size, common + " --set prepass=off");
    const int64_t pixels = int64_t(w) * h;
    EXPECT_EQ(sorted.report["coverage"]["covered_pixels"].get<int64_t>(), pixels);
    // Front to back, the nearest quad hides the rest before their shader runs.
    EXPECT_EQ(find_pass(sorted.report, "depth_prepass")["shaded_fragments"].get<int64_t>(), pixels);
    // Authored back to front, every layer passes the depth test in turn.
    EXPECT_EQ(find_pass(authored.report, "depth_prepass")["shaded_fragments"].get<int64_t>(),
              layers * pixels);
    for (const Capture* c : {&sorted, &authored}) {
        EXPECT_EQ(find_pass(c->report, "forward")["shaded_fragments"].get<int64_t>(), pixels);
    }
    EXPECT_EQ(find_pass(off.report, "forward")["shaded_fragments"].get<int64_t>(), layers * pixels);
}

TEST(Frame, PrepassOnAndOffGiveTheSameImage) {
    const std::string common = "--set gtao=off --set contact_shadows=off";
    Capture on = capture("same-on", "atrium", "320x180", common);
    Capture off = capture("same-off", "atrium", "320x180", common + " --set prepass=off");
    ASSERT_GT(on.image.width, 0);
    const size_t total = size_t(on.image.width) * on.image.height;
    EXPECT_LT(differing_pixels(on.image, off.image, 8), total / 1000);
}

TEST(Frame, WithoutInvarianceEqualRejectsVisibleFragments) {
    Capture c = capture("invariant-off", "atrium", "320x180",
                        "--set count_fragments=on --set invariant=off");
    const double covered = c.report["coverage"]["covered_pixels"].get<double>();
    const double shaded = find_pass(c.report, "forward")["shaded_fragments"].get<double>();
    EXPECT_LT(shaded, 0.95 * covered) << "shaded " << shaded << " of " << covered;
}

TEST(Frame, DumpGraphPrintsPassesResourcesAndBarriers) {
    auto dir = fresh_dir("dump-graph") / "cap";
    auto r = run_depthscope("capture --validate --dump-graph --scene atrium --size 160x90 --out " +
                            dir.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (const auto& name : kAllPasses) EXPECT_NE(r.out.find(name), std::string::npos) << name;
    for (const char* text : {"D32_SFLOAT", "A2B10G10R10", "R8_UNORM", "R16G16B16A16_SFLOAT",
                             "SHADER_READ_ONLY_OPTIMAL", "DEPTH"}) {
        EXPECT_NE(r.out.find(text), std::string::npos) << text << "\n" << r.out;
    }
}

// Read-back, clears and the shader depth resolve are graph passes: dumped with their role and
// barriers (the last ones make the host buffers visible to the host), reported with a kind
// and a GPU time.
TEST(Frame, ReadBackClearsAndTheShaderResolveArePassesOfTheGraph) {
    auto dir = fresh_dir("dump-readback") / "cap";
    auto r = run_depthscope(
        "capture --validate --dump-graph --scene atrium --size 160x90 --set msaa=4 "
        "--set count_fragments=on --out " +
        dir.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (const char* text :
         {"clear_counts (transfer, clear)", "readback_final (transfer, readback)",
          "readback_depth (transfer, readback)", "readback_counts (transfer, readback)",
          "msaa_probe (compute, readback)", "read depth: transfer src [TRANSFER_SRC_OPTIMAL]",
          "barrier readback_final: buffer, COPY|BLIT|RESOLVE|CLEAR/TRANSFER_WRITE -> "
          "HOST/HOST_READ"})
        EXPECT_NE(r.out.find(text), std::string::npos) << text << "\n" << r.out;
    const auto report = nlohmann::json::parse(read_file(dir / "report.json"));
    std::vector<std::string> readback;
    for (const auto& p : report["passes"]) {
        ASSERT_TRUE(p.contains("kind")) << p.dump();
        EXPECT_TRUE(p.contains("gpu_ms")) << p.dump();
        if (p["kind"] == "readback") readback.push_back(p["name"]);
    }
    EXPECT_EQ(readback, (std::vector<std::string>{"readback_final", "readback_depth",
                                                  "readback_counts", "msaa_probe"}));
    EXPECT_EQ(find_pass(report, "clear_counts")["kind"], "clear");
    // Lavapipe has no MAX depth resolve: the shader one is its own pass after the prepass.
    if (report["msaa"]["depth_resolve"] == "shader") {
        const auto names = pass_names(report["passes"]);
        ASSERT_GE(names.size(), 3u);
        EXPECT_EQ(names[1], "depth_prepass");
        EXPECT_EQ(names[2], "depth_resolve");
        EXPECT_NE(r.out.find("read msaa_depth: sampled (fragment) [SHADER_READ_ONLY_OPTIMAL]"),
                  std::string::npos);
    }
}

// zfight=on through the real executable: report.json names the fighting pairs of the zfight
// scene (each coplanar pair's two quads) and the dump shows the pass; off, no zfight at all.
TEST(Frame, ZfightReportNamesThePairs) {
    Capture on = capture("zfight-on", "zfight", "320x180", "--set zfight=on");
    ASSERT_TRUE(on.report.contains("zfight")) << on.report.dump();
    const auto& z = on.report["zfight"];
    EXPECT_EQ(z["steps"], 4);
    EXPECT_GT(z["pixels"].get<int>(), 0);
    ASSERT_FALSE(z["pairs"].empty());
    for (const auto& p : z["pairs"]) {
        for (const char* k : {"mesh", "material", "node"}) {
            EXPECT_TRUE(p["a"].contains(k)) << p.dump();
            EXPECT_TRUE(p["b"].contains(k)) << p.dump();
        }
        EXPECT_GT(p["pixels"].get<int>(), 0);
    }
    EXPECT_EQ(find_pass(on.report, "zfight")["kind"], "frame");
    Capture off = capture("zfight-off", "zfight", "320x180");
    EXPECT_FALSE(off.report.contains("zfight"));
}

// Every diagnostic of one frame at once through the real executable, validation on (the
// sanitizer stage's pass over them, tests/sanitize/tests.txt): each reaches report.json, and
// the pixel history replays the same frame. Foliage: cut-outs to discard, and no near-ties
// (an empty zfight record list, which once made a memcpy from null).
TEST(Frame, EveryDiagnosticAtOnce) {
    const std::string all =
        "--set count_fragments=on --set count_discards=on --set count_draws=on --set zfight=on "
        "--set equal_check=on --set depth_precision=on";
    Capture c = capture("every-diagnostic", "foliage", "160x90", all);
    for (const char* key : {"coverage", "masked_discards", "draws", "zfight", "equal_check"})
        EXPECT_TRUE(c.report.contains(key)) << key;
    for (const char* pass : {"depth_precision", "zfight", "equal_check"})
        EXPECT_EQ(find_pass(c.report, pass)["kind"], "frame") << pass;
    auto r = run_depthscope("pixel --validate --scene foliage --size 160x90 --at 80,45 " + all);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_FALSE(r.out.empty());
}
