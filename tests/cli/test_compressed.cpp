// Compressed and quantized glTF (issue 27): the atrium exported again, with the variants of
// tests/data/compressed/ (gltfpack, gltf-pipeline; README.md there says how each was made)
// beside it, rendered through the real executable with validation.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "tests/support/run_process.h"

namespace ds::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const fs::path kData = fs::path(DS_SOURCE_DIR) / "tests/data/compressed";

// The plain export and the compressed files side by side (they name its PNG textures), one
// folder per test (ctest runs the tests of this file at once).
fs::path prepared_folder() {
    static const fs::path dir = [] {
        const fs::path d =
            fresh_dir(std::string("compressed-") +
                      ::testing::UnitTest::GetInstance()->current_test_info()->name());
        EXPECT_EQ(run_depthscope("export-scene atrium " + (d / "atrium.gltf").string()).exit_code,
                  0);
        for (const auto& entry : fs::directory_iterator(kData))
            if (entry.path().extension() != ".md")
                fs::copy_file(entry.path(), d / entry.path().filename());
        return d;
    }();
    return dir;
}

fs::path capture(const std::string& file, int msaa) {
    const fs::path dir = prepared_folder();
    const fs::path out =
        dir / ("out_" + fs::path(file).stem().string() + "_" + std::to_string(msaa));
    const ProcessResult r = run_depthscope(
        "capture --validate --size 640x360 --set zfight=on --set msaa=" + std::to_string(msaa) +
        " --scene " + (dir / file).string() + " --out " + out.string());
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

// Quantized files load and render what they hold (validation clean); the geometry decodes to
// the same picture up to quantization: a wrong decode (no texture transform, a filter left
// out) differs in most of the image.
TEST(Compressed, QuantizedVariantsRenderWhatTheyHold) {
    const fs::path plain = capture("atrium.gltf", 1);
    for (const char* file : {"quant.gltf", "quant_c.gltf", "draco.gltf"}) {
        SCOPED_TRACE(file);
        const fs::path out = capture(file, 1);
        EXPECT_LT(percent_over_8(plain, out), 15.0);
    }
}

// Debian's meshoptimizer decodes the v0 codec only: the successor extension is refused by name.
TEST(Compressed, KhrMeshoptCompressionIsRefusedByName) {
    const fs::path dir = prepared_folder();
    std::string text = read_file(dir / "lossless_c.gltf");
    for (size_t at = 0; (at = text.find("EXT_meshopt_compression", at)) != std::string::npos;)
        text.replace(at, 3, "KHR");
    const fs::path file = dir / "khr_meshopt.gltf";
    { std::ofstream(file) << text; }
    const ProcessResult r = run_depthscope("capture --size 32x32 --scene " + file.string() +
                                           " --out " + (dir / "never").string());
    expect_one_error_line(r, 1, "KHR_meshopt_compression is not supported");
    EXPECT_FALSE(fs::exists(dir / "never"));
}

}  // namespace
}  // namespace ds::test
