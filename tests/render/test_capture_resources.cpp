// capture --resources (issue 13 part 1): every graph image as resources/NAME.png and NAME.exr,
// read back by OpenEXR's own tool (exrheader), by OpenEXR through read_exr and by a second,
// independent reader (tinyexr), which must agree on channels and values.
#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <regex>
#include <sstream>

#include <tinyexr.h>

#include "capture/exr_file.h"
#include "tests/render/capture_helpers.h"

namespace ds::test {
namespace {

namespace fs = std::filesystem;

// The images a --dump-graph lists: "  NAME: image FORMAT WxH ..." under "resources:".
std::map<std::string, std::string> dumped_images(const std::string& dump) {
    std::map<std::string, std::string> images;
    const std::regex line(R"(^  ([^ :]+): image ([A-Z0-9_]+) )");
    std::istringstream in(dump);
    for (std::string s; std::getline(in, s);) {
        if (s == "passes:") break;
        std::smatch m;
        if (std::regex_search(s, m, line)) images[m[1]] = m[2];
    }
    return images;
}

// exrheader's channel list: NAME -> "32-bit floating-point" / "32-bit unsigned integer".
std::map<std::string, std::string> exrheader_channels(const fs::path& exr) {
    const ProcessResult r = run_command("exrheader " + exr.string());
    EXPECT_EQ(r.exit_code, 0) << "exrheader (package openexr) on " << exr << ": " << r.err;
    std::map<std::string, std::string> channels;
    const std::regex line(R"(^    ([^,]+), (32-bit [a-z -]+), sampling 1 1$)");
    std::istringstream in(r.out);
    for (std::string s; std::getline(in, s);) {
        std::smatch m;
        if (std::regex_match(s, m, line)) channels[m[1]] = m[2];
    }
    return channels;
}

// Every channel through tinyexr, as floats (UINT widened: exact below 2^24).
std::map<std::string, std::vector<float>> tinyexr_channels(const fs::path& exr) {
    std::map<std::string, std::vector<float>> out;
    EXRVersion version;
    EXRHeader header;
    EXRImage image;
    InitEXRHeader(&header);
    InitEXRImage(&image);
    const char* err = nullptr;
    if (ParseEXRVersionFromFile(&version, exr.c_str()) != TINYEXR_SUCCESS ||
        ParseEXRHeaderFromFile(&header, &version, exr.c_str(), &err) != TINYEXR_SUCCESS ||
        LoadEXRImageFromFile(&image, &header, exr.c_str(), &err) != TINYEXR_SUCCESS) {
        ADD_FAILURE() << "tinyexr cannot read " << exr << ": " << (err ? err : "?");
        if (err) FreeEXRErrorMessage(err);
        FreeEXRHeader(&header);
        return out;
    }
    const size_t texels = size_t(image.width) * size_t(image.height);
    for (int c = 0; c < header.num_channels; ++c) {
        std::vector<float>& values = out[header.channels[c].name];
        values.resize(texels);
        for (size_t i = 0; i < texels; ++i) {
            if (header.pixel_types[c] == TINYEXR_PIXELTYPE_UINT)
                values[i] = float(reinterpret_cast<const uint32_t*>(image.images[c])[i]);
            else
                values[i] = reinterpret_cast<const float*>(image.images[c])[i];
        }
    }
    FreeEXRImage(&image);
    FreeEXRHeader(&header);
    return out;
}

TEST(CaptureResources, AtriumWritesAPngAndAnExrForEveryImageTheGraphLists) {
    Capture c = capture("resources-atrium", "atrium", "160x90", "--resources all --dump-graph");
    ASSERT_FALSE(c.report.is_discarded());
    const ProcessResult dump = run_depthscope(
        "capture --scene atrium --size 160x90 --resources "
        "none --dump-graph --out " +
        (fresh_dir("resources-atrium-dump") / "c").string());
    ASSERT_EQ(dump.exit_code, 0) << dump.err;
    const std::map<std::string, std::string> images = dumped_images(dump.out);
    ASSERT_GE(images.size(), 10u) << dump.out;
    std::map<std::string, nlohmann::json> listed;
    for (const auto& r : c.report["resources"]) listed[r["name"]] = r;
    EXPECT_EQ(listed.size(), images.size());
    for (const auto& [name, format] : images) {
        SCOPED_TRACE(name);
        ASSERT_TRUE(listed.count(name));
        const nlohmann::json& r = listed[name];
        EXPECT_EQ(r["format"], format);
        const Png png = read_png(c.dir / r["png"]["file"].get<std::string>());
        EXPECT_EQ(png.width, r["width"].get<int>());
        const fs::path exr = c.dir / r["exr"]["file"].get<std::string>();
        const capture::ExrImage openexr = capture::read_exr(exr);
        EXPECT_EQ(openexr.width, r["width"].get<uint32_t>());
        const std::map<std::string, std::string> header = exrheader_channels(exr);
        const auto second = tinyexr_channels(exr);
        ASSERT_EQ(header.size(), openexr.channels.size());
        ASSERT_EQ(second.size(), openexr.channels.size());
        for (const capture::ExrChannel& ch : openexr.channels) {
            SCOPED_TRACE(ch.name);
            EXPECT_EQ(header.at(ch.name),
                      ch.is_uint ? "32-bit unsigned integer" : "32-bit floating-point");
            const std::vector<float>& other = second.at(ch.name);
            ASSERT_EQ(other.size(), size_t(openexr.width) * openexr.height);
            size_t differ = 0;
            for (size_t i = 0; i < other.size(); ++i) {
                const float v = ch.is_uint ? float(ch.uints[i]) : ch.floats[i];
                differ += !(v == other[i] || (std::isnan(v) && std::isnan(other[i])));
            }
            EXPECT_EQ(differ, 0u);
        }
    }
}

// overdraw: layer 0 fills the view at linear depth 2 (scene_facts.h), so every texel of the
// depth EXR holds reverse-Z's n f / d projection of it: (n f / 2 - n) / (f - n). At 4x MSAA
// the layer-0 (sample0.) values are that too, and the per-pixel counts sum to the report's.
TEST(CaptureResources, OverdrawDepthIsItsProjectionAndCountsSumToTheReport) {
    Capture c = capture("resources-overdraw", "overdraw", "64x48",
                        "--resources depth,msaa_depth,forward_counts --set msaa=4 "
                        "--set count_fragments=on");
    ASSERT_FALSE(c.report.is_discarded());
    const double n = c.report["depth"]["znear"], f = c.report["depth"]["zfar"];
    const float expected = float((n * f / 2.0 - n) / (f - n));
    const capture::ExrImage msaa = capture::read_exr(c.dir / "resources/msaa_depth.exr");
    ASSERT_NE(msaa.find("sample0.Z"), nullptr);
    ASSERT_NE(msaa.find("sample3.Z"), nullptr);
    for (const float v : msaa.find("sample0.Z")->floats) ASSERT_NEAR(v, expected, 1e-6f);
    const capture::ExrImage depth = capture::read_exr(c.dir / "resources/depth.exr");
    for (const float v : depth.find("Z")->floats) ASSERT_NEAR(v, expected, 1e-6f);

    const capture::ExrImage counts = capture::read_exr(c.dir / "resources/forward_counts.exr");
    const capture::ExrChannel* count = counts.find("count");
    ASSERT_NE(count, nullptr);
    ASSERT_TRUE(count->is_uint);
    const uint64_t sum = std::accumulate(count->uints.begin(), count->uints.end(), uint64_t{0});
    uint64_t reported = 0;
    for (const auto& p : c.report["passes"])
        if (p["name"] == "forward") reported = p["shaded_fragments"];
    EXPECT_GT(sum, 0u);
    EXPECT_EQ(sum, reported);
}

TEST(CaptureResources, UnknownOrEmptyNamesAreUsageErrorsThatWriteNothing) {
    const fs::path out = fresh_dir("resources-bad") / "c";
    for (const std::string arg : {"nosuch", "''", "depth,,final"}) {
        const ProcessResult r = run_depthscope("capture --scene overdraw --size 32x32 --out " +
                                               out.string() + " --resources " + arg);
        EXPECT_EQ(r.exit_code, 2) << arg;
        EXPECT_EQ(count_lines(r.err), 1u) << r.err;
        EXPECT_EQ(r.err.rfind("depthscope: error: --resources", 0), 0u) << r.err;
        EXPECT_FALSE(fs::exists(out)) << arg;
    }
}

}  // namespace
}  // namespace ds::test
