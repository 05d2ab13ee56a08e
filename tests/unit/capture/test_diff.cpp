// `depthscope diff`'s rules on made-up images and EXR files (capture_diff.h), its report
// (diff_report.h) and the checks a capture folder passes before anything is compared
// (capture_folder.h). No device: real captures are diffed in tests/render/test_diff.cpp.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

#include "capture/capture_diff.h"
#include "capture/diff_report.h"
#include "capture/exr_file.h"
#include "capture/image_writer.h"
#include "renderer/common/error.h"

namespace fs = std::filesystem;

namespace ds::capture {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

fs::path temp_dir(const std::string& name) {
    const fs::path dir =
        fs::temp_directory_path() / ("ds-diff-" + name + "-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

void write_text(const fs::path& path, const std::string& text) {
    std::ofstream(path) << text;
}

Rgba8Image grey_image(uint32_t w, uint32_t h, uint8_t v) {
    return {w, h, std::vector<uint8_t>(size_t(w) * h * 4, v)};
}

// A one-row EXR with one channel, and its report entry.
ResourceRef one_channel_resource(const fs::path& dir, const std::string& name,
                                 const std::string& format, ExrChannel channel) {
    const uint32_t w = uint32_t(channel.is_uint ? channel.uints.size() : channel.floats.size());
    ExrImage exr{w, 1, {std::move(channel)}};
    const fs::path path = dir / (name + ".exr");
    write_exr(path, exr);
    return {name, format, "Other", w, 1, 1, path};
}

const ImageDiff& find_image(const DiffResult& r, const std::string& name) {
    for (const ImageDiff& d : r.resources)
        if (d.name == name) return d;
    throw std::runtime_error("no resource " + name);
}

TEST(DiffRules, FinalPngDiffersAtTheThresholdInAnyChannel) {
    Rgba8Image a = grey_image(4, 1, 100), b = a;
    b.rgba[0 * 4 + 0] = 107;  // R by 7: below 8
    b.rgba[1 * 4 + 1] = 108;  // G by 8: differs
    b.rgba[2 * 4 + 3] = 0;    // A by 100: differs, the largest
    const ImageDiff d = diff_final(a, b, 8);
    EXPECT_EQ(d.differing, 2u);
    EXPECT_DOUBLE_EQ(d.percent(), 50.0);
    ASSERT_EQ(d.rules.size(), 1u);
    EXPECT_EQ(d.rules[0].largest, 100);
    EXPECT_EQ(d.heat[0], 0.0f);
    EXPECT_FLOAT_EQ(d.heat[1], 0.08f);  // 8 of the largest 100
    EXPECT_FLOAT_EQ(d.heat[2], 1.0f);
    EXPECT_EQ(d.heat[3], 0.0f);
    EXPECT_EQ(diff_final(a, b, 1).differing, 3u);
    EXPECT_EQ(diff_final(a, a, 1).differing, 0u);
}

TEST(DiffRules, EachChannelByItsRule) {
    const fs::path da = temp_dir("rules-a"), db = temp_dir("rules-b");
    CaptureFolder a, b;
    a.final_image = b.final_image = grey_image(2, 2, 50);
    a.lists_resources = b.lists_resources = true;
    // 8-bit: codes 10 -> 17 (7, below 8), 10 -> 18 (8), 0 -> 255.
    a.resources.push_back(one_channel_resource(
        da, "rough", "R8_UNORM", {"Y", false, {10 / 255.f, 10 / 255.f, 0.f, 0.5f}, {}}));
    b.resources.push_back(one_channel_resource(
        db, "rough", "R8_UNORM", {"Y", false, {17 / 255.f, 18 / 255.f, 1.f, 0.5f}, {}}));
    // float: 0.09 % (same), 0.11 % (differs), below the 1e-6 floor, NaN = NaN, inf = inf,
    // NaN against a number (differs, infinitely).
    a.resources.push_back(one_channel_resource(
        da, "depth", "D32_SFLOAT", {"Z", false, {1.f, 1.f, 0.f, kNaN, kInf, 0.5f}, {}}));
    b.resources.push_back(one_channel_resource(
        db, "depth", "D32_SFLOAT", {"Z", false, {1.0009f, 1.0011f, 5e-7f, kNaN, kInf, kNaN}, {}}));
    // uint: any difference.
    a.resources.push_back(
        one_channel_resource(da, "counts", "R32_UINT", {"count", true, {}, {3, 3, 0}}));
    b.resources.push_back(
        one_channel_resource(db, "counts", "R32_UINT", {"count", true, {}, {3, 4, 0}}));
    int seen = 0;
    const DiffResult r = diff_captures(a, b, {}, [&](const ImageDiff&) { ++seen; });
    EXPECT_EQ(seen, 4);  // final.png and the three resources
    ASSERT_TRUE(r.final_image);
    EXPECT_EQ(r.final_image->differing, 0u);
    EXPECT_TRUE(r.passed());

    const ImageDiff& rough = find_image(r, "rough");
    EXPECT_EQ(rough.differing, 2u);
    EXPECT_EQ(rough.rules.at(0).rule, DiffRule::Bytes8);
    EXPECT_EQ(rough.rules.at(0).largest, 255);
    const ImageDiff& depth = find_image(r, "depth");
    EXPECT_EQ(depth.differing, 2u);  // 1.0011 and NaN against 0.5
    EXPECT_EQ(depth.rules.at(0).rule, DiffRule::Float);
    EXPECT_TRUE(std::isinf(depth.rules.at(0).largest));
    const ImageDiff& counts = find_image(r, "counts");
    EXPECT_EQ(counts.differing, 1u);
    EXPECT_EQ(counts.rules.at(0).largest, 1);
    // Sorted by % differing: rough 50 %, depth 33 %, counts 33 % (A's order among equals).
    EXPECT_EQ(r.resources[0].name, "rough");
    EXPECT_EQ(r.resources[1].name, "depth");
    fs::remove_all(da);
    fs::remove_all(db);
}

TEST(DiffRules, WhatCannotBeCompared) {
    const ResourceRef base{"depth", "D32_SFLOAT", "ReverseZDepth", 160, 90, 1, {}};
    EXPECT_EQ(why_not_comparable(base, base), "");
    ResourceRef other = base;
    other.width = 80;
    EXPECT_EQ(why_not_comparable(base, other), "size 160x90 vs 80x90");
    other = base;
    other.format = "D16_UNORM";
    EXPECT_EQ(why_not_comparable(base, other), "format D32_SFLOAT vs D16_UNORM");
    other = base;
    other.samples = 4;
    EXPECT_EQ(why_not_comparable(base, other), "samples 1 vs 4");

    CaptureFolder a, b;
    a.final_image = grey_image(2, 2, 0);
    b.final_image = grey_image(4, 2, 0);
    const DiffResult r = diff_captures(a, b, {}, {});
    EXPECT_FALSE(r.final_image);
    EXPECT_EQ(r.final_not_comparable, "size 2x2 vs 4x2");
    EXPECT_FALSE(r.passed());
    EXPECT_EQ(diff_exit_code(r), 1);
}

TEST(DiffRules, EightBitFormats) {
    for (const char* f : {"R8_UNORM", "R8G8_UNORM", "R8G8B8A8_SRGB", "B8G8R8A8_UNORM"})
        EXPECT_TRUE(is_unorm8(f)) << f;
    for (const char* f : {"A2B10G10R10_UNORM_PACK32", "R8_UINT", "R16_SFLOAT", "D16_UNORM",
                          "S8_UINT", "R8G8B8A8_SNORM", "", "UNORM"})
        EXPECT_FALSE(is_unorm8(f)) << f;
}

TEST(DiffRules, PassesMatchByNameInAsOrderThenBOnly) {
    const std::vector<PassNumbers> a{{"shadow", "frame", 1, {}, 10, {}},
                                     {"depth_prepass", "frame", 2, {}, {}, {}},
                                     {"blit", "frame", 3, {}, {}, {}},
                                     {"blit", "frame", 4, {}, {}, {}}};
    const std::vector<PassNumbers> b{{"blit", "frame", 5, {}, {}, {}},
                                     {"shadow", "frame", 6, {}, 20, {}},
                                     {"forward", "frame", 7, {}, {}, {}}};
    const std::vector<PassRow> rows = match_passes(a, b);
    ASSERT_EQ(rows.size(), 5u);
    EXPECT_EQ(rows[0].name, "shadow");
    EXPECT_EQ(rows[0].b->shaded, 20u);
    EXPECT_FALSE(rows[1].b);             // depth_prepass: A only
    EXPECT_EQ(rows[2].b->gpu_ms, 5);     // the first blit meets B's first
    EXPECT_FALSE(rows[3].b);             // A's second blit has no partner
    EXPECT_EQ(rows[4].name, "forward");  // B only, after A's passes
    EXPECT_FALSE(rows[4].a);
}

TEST(DiffReport, HeatMapIsBlackExactlyWhereNothingDiffers) {
    Rgba8Image a = grey_image(8, 8, 0), b = a;
    for (size_t p = 0; p < 64; p += 3) b.rgba[p * 4] = uint8_t(p * 4);  // 0, 12, 24, …
    const ImageDiff d = diff_final(a, b, 8);
    const std::vector<uint8_t> rgba = heat_map_rgba(d);
    size_t non_black = 0;
    for (size_t p = 0; p < 64; ++p) {
        const bool black = rgba[p * 4] == 0 && rgba[p * 4 + 1] == 0 && rgba[p * 4 + 2] == 0;
        EXPECT_EQ(!black, d.heat[p] > 0) << p;
        EXPECT_EQ(rgba[p * 4 + 3], 255);
        non_black += black ? 0 : 1;
    }
    EXPECT_EQ(non_black, d.differing);
    EXPECT_EQ(d.differing, 21u);  // every third pixel but the first (0 against 0)
}

TEST(DiffReport, SummaryAndJsonSayTheSame) {
    Rgba8Image a = grey_image(10, 10, 0), b = a;
    b.rgba[0] = 9;
    CaptureFolder ca, cb;
    ca.final_image = a;
    cb.final_image = b;
    ca.passes = {{"forward", "frame", 2.0, 100, 50, 0}};
    cb.passes = {{"forward", "frame", 3.0, 100, 75, 0}};
    ca.frame_gpu_ms = 4.0;
    cb.frame_gpu_ms = 6.0;
    const DiffResult r = diff_captures(ca, cb, {8, 0.5}, {});
    const DiffNames names{"A", "B", "OUT"};
    const std::string text = diff_summary(r, names);
    EXPECT_NE(text.find("final.png 10x10: 1.000 % (1 of 100 pixels), largest 9/255, SSIM n/a "
                        "(under 11 pixels on a side)\n"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("resources: none listed"), std::string::npos) << text;
    EXPECT_NE(text.find("forward"), std::string::npos);
    EXPECT_NE(text.find("1.50"), std::string::npos) << text;  // gpu_ms and shaded B/A
    EXPECT_EQ(text.substr(text.rfind("verdict: ")),
              "verdict: differs (1.000 % of final.png's "
              "pixels differ by >= 8/255; more than 0.5 %)\n");
    EXPECT_EQ(diff_exit_code(r), 1);

    const nlohmann::json j = diff_json(r, names);
    EXPECT_EQ(j["tool"], "depthscope");
    EXPECT_EQ(j["final"]["differing"], 1);
    EXPECT_EQ(j["final"]["heat_map"], "final.png");
    EXPECT_TRUE(j["final"]["ssim"].is_null());  // 10x10: under SSIM's window
    EXPECT_EQ(j["passes"][0]["b_over_a"]["shaded_fragments"], 1.5);
    EXPECT_TRUE(j["passes"][0]["b_over_a"]["discarded_fragments"].is_null());  // 0 / 0
    EXPECT_EQ(j["frame"]["gpu_ms"]["b_over_a"], 1.5);
    EXPECT_EQ(j["verdict"]["same"], false);
    EXPECT_EQ(j["verdict"]["exit_code"], 1);
    EXPECT_EQ(diff_exit_code(diff_captures(ca, cb, {8, 1.0}, {})), 0);  // 1 % allowed
}

// final.png's SSIM (renderer/metrics/ssim.h) beside its pixel counts: 1 for equal images, less
// where they differ, in the summary and diff.json.
TEST(DiffReport, FinalSsim) {
    CaptureFolder ca, cb;
    ca.final_image = grey_image(16, 12, 100);
    for (size_t p = 0; p < ca.final_image.rgba.size(); ++p)
        ca.final_image.rgba[p] = uint8_t((p * 37) % 251);
    cb.final_image = ca.final_image;
    EXPECT_EQ(final_ssim(ca.final_image, cb.final_image), 1.0);
    const DiffResult same = diff_captures(ca, cb, {}, {});
    ASSERT_TRUE(same.final_image);
    EXPECT_EQ(same.final_image->ssim, 1.0);
    EXPECT_NE(diff_summary(same, {"A", "B", ""}).find("largest 0/255, SSIM 1.0000\n"),
              std::string::npos)
        << diff_summary(same, {"A", "B", ""});

    for (size_t p = 0; p < cb.final_image.rgba.size(); p += 8) cb.final_image.rgba[p] ^= 0x40;
    const DiffResult r = diff_captures(ca, cb, {}, {});
    ASSERT_TRUE(r.final_image && r.final_image->ssim);
    const double s = *r.final_image->ssim;
    EXPECT_LT(s, 0.99);
    EXPECT_GT(s, -1.0);
    char expected[32];
    std::snprintf(expected, sizeof expected, "SSIM %.4f\n", s);
    EXPECT_NE(diff_summary(r, {"A", "B", ""}).find(expected), std::string::npos);
    EXPECT_EQ(diff_json(r, {"A", "B", ""})["final"]["ssim"], s);
    EXPECT_FALSE(diff_final(ca.final_image, cb.final_image, 8).ssim);  // the compare view's
}

// A folder that is no capture is refused with one line naming the file and the fault.
TEST(CaptureFolder, RefusesWhatIsNotACapture) {
    const fs::path dir = temp_dir("folder");
    const auto message = [](const fs::path& d) {
        try {
            load_capture(d);
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("(no error)");
    };
    EXPECT_EQ(message(dir / "none"), (dir / "none").string() + ": no such capture folder");
    write_text(dir / "file", "x");
    EXPECT_EQ(message(dir / "file"), (dir / "file").string() + ": is not a folder");
    EXPECT_EQ(message(dir), (dir / "report.json").string() + ": no such file");
    write_text(dir / "report.json", "{\"tool\": ");
    EXPECT_EQ(message(dir), (dir / "report.json").string() + ": is not JSON");
    write_text(dir / "report.json", "{\"tool\": \"renderdoc\"}");
    EXPECT_NE(message(dir).find("is not a depthscope report"), std::string::npos);
    write_text(dir / "report.json", "{\"tool\": \"depthscope\"}");
    EXPECT_EQ(message(dir), (dir / "final.png").string() + ": no such file");
    write_text(dir / "final.png", "not a png");
    EXPECT_EQ(message(dir), (dir / "final.png").string() + ": is not a PNG");
    // A header and no image data: refused before stb decodes (scene/image_checks.h).
    const std::string ihdr("\0\0\0\x0dIHDR\0\0\0\x02\0\0\0\x02\x08\x06\0\0\0\0\0\0\0", 25);
    const std::string iend("\0\0\0\0IEND\0\0\0\0", 12);
    write_text(dir / "final.png", "\x89PNG\r\n\x1a\n" + ihdr + iend);
    EXPECT_EQ(message(dir),
              (dir / "final.png").string() + ": PNG has no image data (no IDAT bytes)");
    write_png_rgba8(dir / "final.png.new", 2, 2, std::vector<uint8_t>(16, 7));
    fs::rename(dir / "final.png.new", dir / "final.png");
    EXPECT_EQ(message(dir), "(no error)");

    const std::string entry = R"({"name": "d", "format": "D32_SFLOAT", "semantic": "Other",
        "width": 2, "height": 2, "samples": 1, "exr": {"file": )";
    write_text(dir / "report.json",
               R"({"tool": "depthscope", "resources": [)" + entry + R"("../x.exr"}}]})");
    EXPECT_NE(message(dir).find("resources[0].exr.file '../x.exr' leaves the capture folder"),
              std::string::npos)
        << message(dir);
    write_text(dir / "report.json",
               R"({"tool": "depthscope", "resources": [)" + entry + R"("resources/d.exr"}}]})");
    EXPECT_EQ(message(dir),
              (dir / "resources/d.exr").string() + ": no such file (listed in report.json)");
    write_text(dir / "report.json", R"({"tool": "depthscope", "resources": [{"name": "d"}]})");
    EXPECT_NE(message(dir).find("resources[0].format is missing"), std::string::npos);
    write_text(dir / "report.json", R"({"tool": "depthscope", "passes": [{"name": 3}]})");
    EXPECT_NE(message(dir).find("passes[0].name is not a string"), std::string::npos);
    fs::remove_all(dir);
}

}  // namespace
}  // namespace ds::capture
