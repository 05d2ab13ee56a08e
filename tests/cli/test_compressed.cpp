// What compressed and quantized glTF render (issue 27): the atrium exported again, with the
// variants of tests/data/compressed/ (gltfpack, gltf-pipeline; README.md there says how each
// was made) beside it, rendered through the real executable with validation. That every file
// loads (the sanitizer stage's share) is cli_tests' test_compressed_load.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "tests/cli/compressed_files.h"
#include "tests/support/run_process.h"

namespace ds::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

fs::path capture(const std::string& file, int msaa, const std::string& extra = "") {
    const fs::path dir = compressed_folder();
    const fs::path out = dir / ("out_" + fs::path(file).stem().string() + "_" +
                                std::to_string(msaa) + (extra.empty() ? "" : "_counted"));
    const ProcessResult r = run_depthscope(
        "capture --validate --size 640x360 --set zfight=on --set msaa=" + std::to_string(msaa) +
        extra + " --scene " + (dir / file).string() + " --out " + out.string());
    EXPECT_EQ(r.exit_code, 0) << file << ": " << r.err;
    return out;
}

// Surfaces by node name: Z-fight pairs and decal overlays as the report names them.
std::set<std::string> by_node(const json& report) {
    std::set<std::string> out;
    for (const json& p : report["zfight"]["pairs"])
        out.insert("zfight " + p["a"]["node"].get<std::string>() + " / " +
                   p["b"]["node"].get<std::string>());
    for (const json& o : report["decals"]["overlays"])
        out.insert("decal " + o["overlay"]["node"].get<std::string>() + " on " +
                   o["base"]["node"].get<std::string>());
    return out;
}

double percent_over_8(const fs::path& a, const fs::path& b) {
    const Png pa = read_png(a / "final.png"), pb = read_png(b / "final.png");
    return 100.0 * double(differing_pixels(pa, pb, 7)) / double(pa.width * pa.height);
}

// Lossless compression changes nothing a depth tool reports: gltfpack without quantization
// (with and without EXT_meshopt_compression) and Draco without quantization render as the
// plain export (at most 0.1 % of pixels over 8/255) with the same Z-fights and decals.
TEST(Compressed, LosslessVariantsRenderAsThePlainExport) {
    for (int msaa : {1, 4}) {
        const fs::path plain = capture("atrium.gltf", msaa);
        const json expected = json::parse(read_file(plain / "report.json"));
        for (const char* file : {"lossless.gltf", "lossless_c.gltf", "draco_raw.gltf"}) {
            SCOPED_TRACE(std::string(file) + " msaa " + std::to_string(msaa));
            const fs::path out = capture(file, msaa);
            EXPECT_LE(percent_over_8(plain, out), 0.1);
            const json report = json::parse(read_file(out / "report.json"));
            EXPECT_EQ(by_node(report), by_node(expected));
            EXPECT_FALSE(by_node(report).empty());
        }
    }
}

// Every fragment a pass rasterized, summed over the frame's passes (count_fragments=on).
uint64_t rasterized(const json& report) {
    uint64_t sum = 0;
    for (const json& pass : report["passes"])
        if (pass.contains("rasterized_fragments"))
            sum += pass["rasterized_fragments"].get<uint64_t>();
    return sum;
}

// Quantized files render exactly what they hold: as the float file that the compressor's own
// decoder makes of them (gltfpack reading its output back with -noq; gltf-pipeline's
// uncompressed fallback, decoded by draco3d), with the same Z-fights and decals. Against the
// plain export, what a depth tool counts survives: the frame's rasterized fragments stay within
// 0.5 %. (Its pixels do not: quantization moves texels and vertices; tests/data/compressed/
// README.md has what each variant differs by and where.)
TEST(Compressed, QuantizedVariantsRenderAsTheirOwnToolsDecodeThem) {
    const std::string counted = " --set count_fragments=on";
    const uint64_t plain =
        rasterized(json::parse(read_file(capture("atrium.gltf", 1, counted) / "report.json")));
    ASSERT_GT(plain, 0u);
    const std::pair<const char*, const char*> pairs[] = {{"quant.gltf", "quant_float.gltf"},
                                                         {"quant_c.gltf", "quant_c_float.gltf"},
                                                         {"draco.gltf", "draco_float.gltf"}};
    for (const auto& [file, decoded] : pairs) {
        SCOPED_TRACE(file);
        const fs::path a = capture(file, 1, counted), b = capture(decoded, 1, counted);
        EXPECT_LE(percent_over_8(a, b), 0.1);
        const json ra = json::parse(read_file(a / "report.json"));
        const json rb = json::parse(read_file(b / "report.json"));
        EXPECT_EQ(by_node(ra), by_node(rb));
        EXPECT_EQ(rasterized(ra), rasterized(rb));
        EXPECT_LE(std::abs(double(rasterized(ra)) - double(plain)), 0.005 * double(plain))
            << rasterized(ra) << " fragments, the plain export " << plain;
    }
}

// gltf-pipeline's default Draco (11-bit positions) moves the far wall's face 1.2 mm towards
// the room, in front of the three posters that lay on it: they no longer show, no Z-fight says
// so, and the report names each as buried under the wall. The plain export has none.
TEST(Compressed, DracoBuriesTheFarWallsPostersAndTheReportNamesThem) {
    const auto buried = [](const std::string& file) {
        const fs::path dir = compressed_folder();
        const fs::path out = dir / ("buried_" + fs::path(file).stem().string());
        EXPECT_EQ(run_depthscope("capture --size 160x90 --scene " + (dir / file).string() +
                                 " --out " + out.string())
                      .exit_code,
                  0);
        std::set<std::string> names;
        const json report = json::parse(read_file(out / "report.json"));
        for (const json& b : report["decals"]["buried"])
            names.insert(b["overlay"]["node"].get<std::string>() + " under " +
                         b["base"]["node"].get<std::string>() + " by " +
                         std::to_string(int(std::lround(b["gap"].get<double>() * 1e4))) + "e-4");
        return names;
    };
    EXPECT_EQ(buried("atrium.gltf"), std::set<std::string>{});
    // diagnose says it as an error, each naming the poster and the wall.
    const fs::path dir = compressed_folder();
    const ProcessResult d =
        run_depthscope("diagnose --size 160x90 --scene " + (dir / "draco.gltf").string());
    EXPECT_EQ(d.exit_code, 0) << d.err;
    size_t lines = 0;
    for (size_t at = 0; (at = d.out.find("DECAL_BURIED", at)) != std::string::npos; ++at) {
        ++lines;
        EXPECT_EQ(d.out.rfind("error", at), d.out.rfind('\n', at) + 1) << d.out;
    }
    EXPECT_EQ(lines, 3u) << d.out;
    EXPECT_NE(d.out.find("decal_poster_far_left lies 1.22 mm behind far_wall"), std::string::npos)
        << d.out;
    EXPECT_EQ(buried("draco.gltf"),
              (std::set<std::string>{"decal_poster_far_high under far_wall by 12e-4",
                                     "decal_poster_far_left under far_wall by 12e-4",
                                     "decal_poster_far_right under far_wall by 12e-4"}));
}

}  // namespace
}  // namespace ds::test
