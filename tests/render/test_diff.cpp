// `depthscope diff A B` on real captures made by the real executable (issue 13's acceptance):
// a capture against an identical one, prepass on against off, invariance off against on (the
// EQUAL test's holes, which the diff's heat map must show), and input that is no capture.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "capture/exr_file.h"
#include "tests/render/capture_helpers.h"

namespace fs = std::filesystem;

namespace ds::test {
namespace {

nlohmann::json read_json(const fs::path& path) {
    return nlohmann::json::parse(read_file(path), nullptr, false);
}

bool is_black(const Png& png, size_t pixel) {
    return png.rgba[pixel * 4] == 0 && png.rgba[pixel * 4 + 1] == 0 && png.rgba[pixel * 4 + 2] == 0;
}

size_t non_black(const Png& png) {
    size_t n = 0;
    for (size_t p = 0; p < size_t(png.width) * size_t(png.height); ++p)
        n += is_black(png, p) ? 0 : 1;
    return n;
}

// The N of the summary's "final.png WxH: P % (N of M pixels)".
long summary_final_count(const std::string& out) {
    const size_t at = out.find("\nfinal.png ");
    long count = -1;
    if (at == std::string::npos) return count;
    const size_t open = out.find('(', at);
    if (open != std::string::npos) std::sscanf(out.c_str() + open, "(%ld of", &count);
    return count;
}

std::string last_line(const std::string& text) {
    const size_t end = text.find_last_not_of('\n');
    const size_t start = text.rfind('\n', end);
    return text.substr(start == std::string::npos ? 0 : start + 1, end - start);
}

ProcessResult diff(const Capture& a, const Capture& b, const fs::path& out) {
    return run_depthscope("diff " + a.dir.string() + " " + b.dir.string() + " --out " +
                          out.string());
}

// A capture against its replay (the same frame rendered again from report.json alone, on one
// device) differs nowhere: exit 0, 0 %, final.png, every resource and every heat map black.
TEST(Diff, ACaptureAgainstItsReplayIsTheSameEverywhere) {
    const Capture a = capture("diff-same-a", "atrium", "160x90", "--resources all");
    ASSERT_FALSE(a.report.is_null());
    Capture b;
    b.dir = fresh_dir("diff-same-b") / "replay";
    const ProcessResult replayed =
        run_depthscope("replay " + a.dir.string() + " --resources all --out " + b.dir.string());
    ASSERT_EQ(replayed.exit_code, 0) << replayed.err;
    b.report = read_json(b.dir / "report.json");
    ASSERT_FALSE(b.report.is_null());
    const fs::path out = fresh_dir("diff-same") / "out";
    const ProcessResult r = diff(a, b, out);
    ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_EQ(r.err, "");
    EXPECT_EQ(summary_final_count(r.out), 0) << r.out;
    EXPECT_EQ(last_line(r.out).rfind("verdict: same (0.000 % of final.png's pixels", 0), 0u)
        << r.out;

    const nlohmann::json j = read_json(out / "diff.json");
    ASSERT_TRUE(j.is_object());
    EXPECT_EQ(j["final"]["differing"], 0);
    EXPECT_EQ(j["final"]["ssim"], 1.0);  // identical images
    EXPECT_NE(r.out.find("largest 0/255, SSIM 1.0000\n"), std::string::npos) << r.out;
    EXPECT_EQ(j["verdict"]["same"], true);
    ASSERT_EQ(j["resources"].size(), a.report["resources"].size());
    EXPECT_GE(j["resources"].size(), 10u);
    for (const auto& res : j["resources"]) {
        EXPECT_EQ(res["differing"], 0) << res["name"];
        EXPECT_EQ(res["percent"], 0.0) << res["name"];
        const Png heat = read_png(out / res["heat_map"].get<std::string>());
        EXPECT_EQ(heat.width, res["width"].get<int>()) << res["name"];
        EXPECT_EQ(non_black(heat), 0u) << res["name"];
    }
    EXPECT_EQ(non_black(read_png(out / "final.png")), 0u);
    EXPECT_TRUE(j["not_comparable"].empty());
    EXPECT_TRUE(j["only_in_a"].empty());
    EXPECT_TRUE(j["only_in_b"].empty());
    // Every pass has both sides.
    ASSERT_EQ(j["passes"].size(), a.report["passes"].size());
    for (const auto& p : j["passes"]) {
        EXPECT_TRUE(p["a"].is_object()) << p["name"];
        EXPECT_TRUE(p["b"].is_object()) << p["name"];
    }
}

// Seed 004's acceptance as a command: without the gtao and contact shadows that only the
// prepass feeds, the frame with and without the prepass is the same image within 0.1 %.
TEST(Diff, PrepassOnAndOffPassWithinATenthOfAPercent) {
    const std::string common =
        "--set gtao=off --set contact_shadows=off --set count_fragments=on --resources depth,hdr";
    const Capture on = capture("diff-prepass-on", "atrium", "320x180", common);
    const Capture off =
        capture("diff-prepass-off", "atrium", "320x180", common + " --set prepass=off");
    const fs::path out = fresh_dir("diff-prepass") / "out";
    const ProcessResult r = diff(on, off, out);
    ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
    const nlohmann::json j = read_json(out / "diff.json");
    EXPECT_LT(j["final"]["percent"].get<double>(), 0.1);
    EXPECT_EQ(j["final"]["differing"].get<long>(), summary_final_count(r.out));
    // Structurally the same image: SSIM near 1 (0.99988 on lavapipe).
    EXPECT_GT(j["final"]["ssim"].get<double>(), 0.99) << r.out;
    EXPECT_LE(j["final"]["ssim"].get<double>(), 1.0) << r.out;
    EXPECT_EQ(j["resources"].size(), 2u);  // depth and hdr, in both
    // The passes side by side: the prepass in A only, forward's shaded fragments in both, and
    // without the prepass forward shades more (the overdraw the prepass saves).
    bool prepass_a_only = false, forward_more = false;
    for (const auto& p : j["passes"]) {
        if (p["name"] == "depth_prepass") prepass_a_only = p["a"].is_object() && p["b"].is_null();
        if (p["name"] == "forward")
            forward_more = p["b_over_a"]["shaded_fragments"].get<double>() > 1.0;
    }
    EXPECT_TRUE(prepass_a_only) << j["passes"].dump();
    EXPECT_TRUE(forward_more) << j["passes"].dump();
    EXPECT_NE(r.out.find("shaded A"), std::string::npos) << r.out;
}

// Without `invariant`, EQUAL rejects visible fragments (seed 004): the diff fails, and its heat
// map for final.png is non-black exactly on the pixels it counts, each of them a hole that the
// equal_check pass of the capture without invariance found.
TEST(Diff, WithoutInvarianceTheHolesFailAndShowInTheHeatMap) {
    const std::string common = "--set equal_check=on --resources equal_check";
    const Capture on = capture("diff-invariant-on", "atrium", "320x180", common);
    const Capture off =
        capture("diff-invariant-off", "atrium", "320x180", common + " --set invariant=off");
    const fs::path out = fresh_dir("diff-invariant") / "out";
    const ProcessResult r = diff(on, off, out);
    ASSERT_EQ(r.exit_code, 1) << r.out << r.err;
    EXPECT_EQ(r.err, "");
    EXPECT_EQ(last_line(r.out).rfind("verdict: differs (", 0), 0u) << r.out;

    const long counted = summary_final_count(r.out);
    const Png heat = read_png(out / "final.png");
    ASSERT_EQ(heat.width, 320);
    EXPECT_EQ(long(non_black(heat)), counted) << r.out;
    const nlohmann::json j = read_json(out / "diff.json");
    EXPECT_EQ(j["final"]["differing"].get<long>(), counted);
    EXPECT_LT(j["final"]["ssim"].get<double>(), 1.0);  // the holes are structure that differs

    // Each differing pixel is one of the holes (equal_check 1 in the invariance-off capture).
    const capture::ExrImage holes = capture::read_exr(off.dir / "resources/equal_check.exr");
    const capture::ExrChannel* marks = holes.find("count");
    ASSERT_NE(marks, nullptr);
    ASSERT_EQ(marks->uints.size(), size_t(320) * 180);
    long differing_holes = 0;
    for (size_t p = 0; p < marks->uints.size(); ++p) {
        if (is_black(heat, p)) continue;
        EXPECT_EQ(marks->uints[p], 1u) << "pixel " << p % 320 << "," << p / 320;
        differing_holes += marks->uints[p] == 1 ? 1 : 0;
    }
    const long reported_holes = off.report["equal_check"]["holes"].get<long>();
    EXPECT_GT(counted, 1000) << r.out;
    EXPECT_EQ(differing_holes, counted);
    EXPECT_GE(differing_holes, reported_holes * 9 / 10) << "most holes visible";
    std::printf("invariant off: %ld pixels differ, %ld holes, SSIM %.4f\n", counted, reported_holes,
                j["final"]["ssim"].get<double>());
}

// Input that is no capture: one line, exit 2 (diff's "trouble"), nothing on stdout, no --out.
TEST(Diff, WhatIsNoCaptureIsOneLineAndWritesNothing) {
    const Capture good = capture("diff-bad-good", "overdraw", "64x64");
    ASSERT_FALSE(good.report.is_null());
    const fs::path root = fresh_dir("diff-bad");
    const auto copy = [&](const std::string& name) {
        fs::copy(good.dir, root / name, fs::copy_options::recursive);
        return root / name;
    };
    const fs::path corrupt = copy("corrupt");
    std::FILE* f = std::fopen((corrupt / "report.json").c_str(), "w");
    std::fputs("{\"tool\": \"depthscope\", ", f);
    std::fclose(f);
    const fs::path other_tool = copy("other-tool");
    f = std::fopen((other_tool / "report.json").c_str(), "w");
    std::fputs("{\"tool\": \"renderdoc\", \"passes\": []}\n", f);
    std::fclose(f);
    const fs::path no_final = copy("no-final");
    fs::remove(no_final / "final.png");
    const std::string g = good.dir.string();
    const struct {
        std::string a, b, says;
    } cases[] = {
        {g, (root / "missing").string(), "missing: no such capture folder"},
        {g, corrupt.string(), "report.json: is not JSON"},
        {other_tool.string(), g, "is not a depthscope report"},
        {g, other_tool.string(), "is not a depthscope report"},
        {g, no_final.string(), "final.png: no such file"},
        {(good.dir / "final.png").string(), g, "final.png: is not a folder"},
    };
    for (const auto& c : cases) {
        const fs::path out = root / "out";
        const ProcessResult r =
            run_depthscope("diff " + c.a + " " + c.b + " --out " + out.string());
        EXPECT_EQ(r.exit_code, 2) << c.says << "\n" << r.err;
        EXPECT_EQ(count_lines(r.err), 1u) << r.err;
        EXPECT_EQ(r.err.rfind("depthscope: error: ", 0), 0u) << r.err;
        EXPECT_NE(r.err.find(c.says), std::string::npos) << r.err;
        EXPECT_EQ(r.out, "");
        EXPECT_FALSE(fs::exists(out)) << c.says;
    }
    // An existing --out is refused before any work and left as it was; so is a bad option.
    const fs::path taken = copy("taken");
    const ProcessResult r = run_depthscope("diff " + g + " " + g + " --out " + taken.string());
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("exists; diff writes a new folder"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(taken / "diff.json"));
    const ProcessResult usage = run_depthscope("diff " + g + " " + g + " --threshold 256");
    EXPECT_EQ(usage.exit_code, 2) << usage.err;
    EXPECT_EQ(count_lines(usage.err), 1u) << usage.err;
    // Only staging leftovers could remain beside out; there must be none.
    for (const auto& entry : fs::directory_iterator(root))
        EXPECT_EQ(entry.path().filename().string().find("out"), std::string::npos) << entry.path();
}

}  // namespace
}  // namespace ds::test
