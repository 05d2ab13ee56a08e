// Resource exhaustion through the real executable (issue 12): a size beyond the device's image
// limits, or a frame whose estimated memory exceeds the device-local heap, is one error line
// and exit 1 before the frame is rendered, and leaves no capture folder. DEPTHSCOPE_DEVICE_LIMITS
// lowers the device's limits so every device (lavapipe's 16384 and 2 GiB, an H200's) meets them.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "tests/support/run_process.h"

namespace fs = std::filesystem;
using ds::test::count_lines;
using ds::test::run_depthscope;

namespace {

constexpr const char* kLimitsEnv = "DEPTHSCOPE_DEVICE_LIMITS";

// `depthscope ARGS` with the device's limits lowered by `limits`; how long it took in seconds.
ds::test::ProcessResult run_limited(const char* limits, const std::string& args,
                                    double* seconds = nullptr) {
    ::setenv(kLimitsEnv, limits, 1);
    const auto start = std::chrono::steady_clock::now();
    auto r = run_depthscope(args);
    if (seconds)
        *seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ::unsetenv(kLimitsEnv);
    return r;
}

void expect_one_line_exit_1(const ds::test::ProcessResult& r, const std::string& mention) {
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_EQ(count_lines(r.err), 1u) << r.err;
    EXPECT_EQ(r.err.rfind("depthscope: error: ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(mention), std::string::npos) << r.err;
}

}  // namespace

TEST(Resources, SizeBeyondTheImageLimitIsOneLine) {
    const fs::path out = ds::test::fresh_dir("res-size") / "cap";
    const auto r =
        run_limited("image=512", "capture --scene overdraw --size 640x360 --out " + out.string());
    expect_one_line_exit_1(r, "a 640x360 frame at msaa=1 is larger than ");
    EXPECT_NE(r.err.find("at most 512x512 (maxImageDimension2D 512"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out));
    const auto info = run_limited("image=512", "info");
    EXPECT_NE(info.out.find("image size limit:     512 (framebuffer 512x512)"), std::string::npos)
        << info.out;
}

TEST(Resources, FrameOverTheHeapIsRefusedQuicklyWithTheEstimate) {
    const fs::path out = ds::test::fresh_dir("res-heap") / "cap";
    double seconds = 0;
    const auto r = run_limited(
        "heap_mib=64", "capture --scene atrium --size 1920x1080 --out " + out.string(), &seconds);
    expect_one_line_exit_1(r, "a 1920x1080 frame at msaa=1 needs about ");
    EXPECT_NE(r.err.find("the largest '"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("more than the 64.0 MiB device-local heap"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out));
    EXPECT_LT(seconds, 30.0) << "refused before the frame is rendered";
}

// The case: 16384x16384 rendered for minutes in 12 GB on lavapipe, whose heap says
// 2 GiB. Pinned to that heap, every device refuses it at once, at msaa 1 and 8.
TEST(Resources, Size16384IsRefusedAgainstA2GiBHeap) {
    for (const char* msaa : {"1", "8"}) {
        const fs::path out = ds::test::fresh_dir("res-16384") / "cap";
        double seconds = 0;
        const auto r = run_limited("heap_mib=2048",
                                   std::string("capture --scene edges --size 16384x16384 --set "
                                               "msaa=") +
                                       msaa + " --out " + out.string(),
                                   &seconds);
        // msaa=8 on a device without 8 samples: the sample-count line, also before any work.
        expect_one_line_exit_1(r, std::string("msaa=") + msaa);
        EXPECT_FALSE(fs::exists(out));
        EXPECT_LT(seconds, 30.0) << r.err;
    }
}

TEST(Resources, BadLimitsVariableIsOneLine) {
    const auto r = run_limited("heap=lots", "info");
    expect_one_line_exit_1(r, "DEPTHSCOPE_DEVICE_LIMITS: expected NAME=N");
}
