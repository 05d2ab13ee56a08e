// Every compressed and quantized atrium of tests/data/compressed/ loads and renders, small and
// without a warning: the decoders' paths (meshopt, Draco, quantized attributes, texture
// transforms) under the sanitizer stage, which runs cli_tests whole. What they render is
// compressed_tests' test_compressed.cpp.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "tests/cli/compressed_files.h"
#include "tests/support/run_process.h"

namespace ds::test {
namespace {

namespace fs = std::filesystem;

// Each file that names a compression or quantization extension, at 64x36.
TEST(CompressedFiles, EveryVariantLoadsAndRendersWithoutAWarning) {
    const fs::path dir = compressed_folder();
    int files = 0;
    for (const auto& entry : fs::directory_iterator(dir)) {
        if (entry.path().extension() != ".gltf") continue;
        const std::string text = read_file(entry.path());
        if (text.find("KHR_mesh_quantization") == std::string::npos &&
            text.find("EXT_meshopt_compression") == std::string::npos &&
            text.find("KHR_draco_mesh_compression") == std::string::npos)
            continue;  // plain floats: nothing to decode
        ++files;
        const fs::path out = dir / ("small_" + entry.path().stem().string());
        const ProcessResult r = run_depthscope("capture --size 64x36 --scene " +
                                               entry.path().string() + " --out " + out.string());
        EXPECT_EQ(r.exit_code, 0) << entry.path().filename() << ": " << r.err;
        EXPECT_EQ(r.err, "") << entry.path().filename();
        EXPECT_TRUE(fs::exists(out / "final.png")) << entry.path().filename();
    }
    EXPECT_EQ(files, 5);  // lossless_c, quant, quant_c, draco_raw, draco
}

// Debian's meshoptimizer decodes the v0 codec only: the successor extension is refused by name.
TEST(CompressedFiles, KhrMeshoptCompressionIsRefusedByName) {
    const fs::path dir = compressed_folder();
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
