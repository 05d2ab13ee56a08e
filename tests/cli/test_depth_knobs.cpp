// depth_format, znear and zfar from the command line: a choice the device lacks and planes
// that are not 0 < znear < zfar are one usage-error line and leave no capture folder; set
// values reach report.json's depth block.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "tests/support/run_process.h"

namespace fs = std::filesystem;
using ds::test::count_lines;
using ds::test::run_depthscope;

namespace {

// Lavapipe has every depth format; the probe can be told to treat some as missing.
constexpr const char* kHideEnv = "DEPTHSCOPE_HIDE_DEPTH_FORMATS";

void expect_usage_error(const ds::test::ProcessResult& r, const fs::path& out,
                        const std::string& mention) {
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(count_lines(r.err), 1u) << r.err;
    EXPECT_EQ(r.err.rfind("depthscope: error: ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(mention), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out)) << r.err;
}

nlohmann::json report_of(const fs::path& dir) {
    return nlohmann::json::parse(ds::test::read_file(dir / "report.json"), nullptr, false);
}

}  // namespace

TEST(DepthCli, UnsupportedFormatIsOneLineAndWritesNothing) {
    const fs::path dir = ds::test::fresh_dir("depth-format-unsupported");
    ::setenv(kHideEnv, "D24_UNORM_S8_UINT,X8_D24_UNORM_PACK32", 1);
    auto r = run_depthscope("capture --scene overdraw --size 32x32 --set depth_format=d24 --out " +
                            (dir / "cap").string());
    auto info = run_depthscope("info");
    ::unsetenv(kHideEnv);
    expect_usage_error(r, dir / "cap", "depth_format=d24: " + ds::test::selected_device_name());
    EXPECT_NE(r.err.find("does not support it as a sampled depth attachment; supported: d32f "
                         "(D32_SFLOAT), d16 (D16_UNORM)"),
              std::string::npos)
        << r.err;
    for (const auto& entry : fs::directory_iterator(dir))
        ADD_FAILURE() << "left behind: " << entry.path();
    // `info` lists what the renderer sees.
    ASSERT_EQ(info.exit_code, 0) << info.err;
    EXPECT_EQ(info.out.find("D24_UNORM_S8_UINT"), std::string::npos) << info.out;
    EXPECT_NE(info.out.find("D16_UNORM"), std::string::npos) << info.out;
}

TEST(DepthCli, BadPlanesAreOneLineAndWriteNothing) {
    const fs::path dir = ds::test::fresh_dir("depth-planes-bad");
    const struct {
        const char* sets;
        const char* mention;
    } bad[] = {
        {"--set znear=0", "znear=0: the near plane must be above 0"},
        // The atrium camera's planes are 0.1 and 200.
        {"--set znear=500", "znear=500 must be below zfar=200 (the scene camera's)"},
        {"--set zfar=0.05", "znear=0.1 (the scene camera's) must be below zfar=0.05"},
        {"--set znear=2 --set zfar=1", "znear=2 must be below zfar=1"},
        {"--set znear=-1", "setting znear: -1 is out of range scene|0..1000000"},
        {"--set zfar=far", "setting zfar: 'far' is not a number"},
    };
    for (const auto& b : bad) {
        const fs::path out = dir / "cap";
        auto r = run_depthscope("capture --scene atrium --size 32x32 --out " + out.string() + " " +
                                b.sets);
        SCOPED_TRACE(b.sets);
        expect_usage_error(r, out, b.mention);
    }
    for (const auto& entry : fs::directory_iterator(dir))
        ADD_FAILURE() << "left behind: " << entry.path();
}

// report.json says the format in use and the effective planes; the scene's unless set.
TEST(DepthCli, ReportHasTheDepthBlock) {
    const fs::path dir = ds::test::fresh_dir("depth-report");
    auto plain =
        run_depthscope("capture --scene atrium --size 32x32 --out " + (dir / "a").string());
    ASSERT_EQ(plain.exit_code, 0) << plain.err;
    EXPECT_EQ(report_of(dir / "a")["depth"],
              nlohmann::json::parse(
                  R"({"format": "D32_SFLOAT", "znear": 0.1, "zfar": 200, "reverse_z": true})"));
    auto set = run_depthscope(
        "capture --validate --scene atrium --size 32x32 --set depth_format=d16 --set znear=0.5 "
        "--set zfar=60 --set reverse_z=off --out " +
        (dir / "b").string());
    ASSERT_EQ(set.exit_code, 0) << set.err;
    const nlohmann::json report = report_of(dir / "b");
    EXPECT_EQ(report["depth"],
              nlohmann::json::parse(
                  R"({"format": "D16_UNORM", "znear": 0.5, "zfar": 60, "reverse_z": false})"));
    EXPECT_EQ(report["settings"]["depth_format"], "d16");
    EXPECT_EQ(report["settings"]["znear"], "0.5");
}
