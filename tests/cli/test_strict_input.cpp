// Numbers are checked, values are quoted (issue 12): every malformed number is a usage error
// (exit 2, one line, nothing written) before any work, and an error that repeats the user's
// text escapes its control characters so that it stays one line.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "tests/support/run_process.h"

namespace fs = std::filesystem;
using ds::test::count_lines;
using ds::test::run_depthscope;

namespace {

// `args` (after "capture --out DIR") must give one error line naming
// `mention`, exit `code`, no stdout and no capture folder.
void expect_refused(const std::string& args, const std::string& mention, int code = 2) {
    const fs::path out = ds::test::fresh_dir("strict-input") / "cap";
    const auto r = run_depthscope("capture --out " + out.string() + " " + args,
                                  /*timeout_s=*/30);
    EXPECT_EQ(r.exit_code, code) << args << "\n" << r.err;
    EXPECT_EQ(count_lines(r.err), 1u) << args << "\n" << r.err;
    EXPECT_EQ(r.err.rfind("depthscope: error: ", 0), 0u) << args << "\n" << r.err;
    EXPECT_NE(r.err.find(mention), std::string::npos) << args << "\n" << r.err;
    EXPECT_TRUE(r.out.empty()) << args << "\n" << r.out;
    EXPECT_FALSE(fs::exists(out)) << args;
    for (const auto& entry : fs::directory_iterator(out.parent_path()))
        ADD_FAILURE() << args << ": left behind " << entry.path();
}

}  // namespace

// The issue's cases: each was accepted (a wrapped size, the default size, a stof failure at
// render time with exit 1) or printed over two lines.
TEST(StrictInput, TheIssuesCasesAreOneLineUsageErrors) {
    expect_refused("--size 4294967297x1",
                   "--size expects WIDTHxHEIGHT between 1x1 and "
                   "16384x16384, got '4294967297x1'");
    expect_refused("--size ''", "got ''");
    expect_refused("--size 0x0", "got '0x0'");
    // sh's single quotes hold the newline itself.
    expect_refused("--set 'prepass=on\noff'", "setting prepass: 'on\\noff' is not on|off");
    expect_refused("--set sun_intensity=1e-320", "setting sun_intensity: 1e-320 is too small");
    expect_refused("--set msaa=3", "setting msaa: 3 is not one of 1|2|4|8");
}

TEST(StrictInput, SizesAndPixelsAreDigitsOnlyWithoutWrapAround) {
    for (const char* size :
         {"' 64x64'", "'64x64 '", "+64x64", "-1x5", "64X64", "64x", "x64", "0x40x40", "64x64x1",
          "16385x1", "1x16385", "4294967296x4294967296", "0x10", "1e2x1e2", "'64\tx64'"})
        expect_refused(std::string("--size ") + size, "--size expects WIDTHxHEIGHT");
    for (const char* at :
         {"4294967296,0", "0,4294967297", "16384,0", "-0,1", "1,", "'1;2'", "''"}) {
        const auto r = run_depthscope(std::string("pixel --scene overdraw --size 8x8 --at ") + at);
        EXPECT_EQ(r.exit_code, 2) << at << "\n" << r.err;
        EXPECT_EQ(count_lines(r.err), 1u) << at << "\n" << r.err;
        EXPECT_NE(r.err.find("--at expects X,Y"), std::string::npos) << at << "\n" << r.err;
        EXPECT_TRUE(r.out.empty()) << at << "\n" << r.out;
    }
}

// CLI11 alone would take 0x10 as 16, 010 as 8 and " 5" as 5; here a count is decimal digits.
TEST(StrictInput, CountOptionsAreDigitsOnlyAndInRange) {
    for (const char* value : {"0x10", "' 5'", "'5 '", "+3", "-1", "1e3", "2.0", "''",
                              "99999999999999999999", "4294967297", "100001"}) {
        for (const char* option : {"--frames", "--warmup"}) {
            const auto r = run_depthscope(std::string("bench --scene overdraw --size 8x8 ") +
                                          option + " " + value);
            EXPECT_EQ(r.exit_code, 2) << option << " " << value << "\n" << r.err;
            EXPECT_EQ(count_lines(r.err), 1u) << option << " " << value << "\n" << r.err;
            EXPECT_NE(r.err.find(std::string(option) + " expects a whole number in "),
                      std::string::npos)
                << r.err;
            EXPECT_TRUE(r.out.empty()) << "no frame rendered: " << r.out;
        }
    }
    // --frames 0 is no bench (1..100000); the inspector's own --frames takes 0 (never close).
    EXPECT_EQ(run_depthscope("bench --scene overdraw --frames 0").exit_code, 2);
    EXPECT_EQ(run_depthscope("view --frames 0x1").exit_code, 2);
    // An empty path is no path: not the default folder or no file at all.
    for (const char* args : {"capture --scene overdraw --size 8x8 --out ''",
                             "bench --scene overdraw --size 8x8 --json ''",
                             "pixel --scene overdraw --size 8x8 --at 1,1 --json ''"}) {
        const auto r = run_depthscope(args);
        EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
        EXPECT_EQ(count_lines(r.err), 1u) << args << "\n" << r.err;
        EXPECT_NE(r.err.find("expects a path, got ''"), std::string::npos) << r.err;
        EXPECT_TRUE(r.out.empty()) << r.out;
    }
}

// Every echo of the user's text stays one line: the settings, the command line's own parser
// (CLI11), --matrix, --view, the device's name and a scene file's name.
TEST(StrictInput, EchoedValuesAreEscapedOntoOneLine) {
    const struct {
        const char* args;
        const char* mention;
        int code;
    } cases[] = {
        {"--set 'no\nsuch=1'", "unknown setting 'no\\nsuch'", 2},
        {"--set 'exposure=1\t2'", "'1\\t2' is not a number", 2},
        {"--set 'depth_compare=equal\r'", "'equal\\r' is not one of", 2},
        {"--set 'material_alpha_cutoff=a\nb'", "'a\\nb' is not NAME=V", 2},
        {"--scene foliage --size 8x8 --set 'material_alpha_cutoff=x\ny=0.5'",
         "no masked material \"x\\ny\"", 2},
        {"--size '64\nx64'", "got '64\\nx64'", 2},
        {"'--bogus\nx'", "--bogus\\nx", 2},
        {"--scene edges --size 320x180 --ui --view 'final\nx'",
         "--view final\\nx: this frame has no such image", 2},
        {"--scene overdraw --device 'no\ngpu'", "no device name contains 'no\\ngpu'", 1},
        {"--scene overdraw --device 99999999999999999999",
         "no device with index 99999999999999999999", 1},
    };
    for (const auto& c : cases) expect_refused(c.args, c.mention, c.code);
    for (const auto& [matrix, mention] :
         {std::pair{"'ms\na'", "--matrix expects name=value1,value2,..., got 'ms\\na'"},
          std::pair{"'msaa=1\n\n4'", "setting msaa: '1\\n\\n4' is not a number"}}) {
        const auto r = run_depthscope(std::string("bench --scene overdraw --matrix ") + matrix);
        EXPECT_EQ(r.exit_code, 2) << r.err;
        EXPECT_EQ(count_lines(r.err), 1u) << r.err;
        EXPECT_NE(r.err.find(mention), std::string::npos) << r.err;
    }
    // A file name the loader repeats: the line is escaped as a whole at the top.
    expect_refused("--scene '/nonexistent/a\nb.gltf'", "/nonexistent/a\\nb.gltf", 1);
}
