// The malformed-file corpus through the real executable: `depthscope capture --scene FILE` on
// each file of malformed_corpus.h (with --strict: a broken texture is otherwise a warning, see
// test_missing_textures.cpp) must print exactly one line `depthscope: error: FILE: ...`
// (naming the JSON path, byte offset or uri the case expects), exit 1 within 10 s, peak under
// 2 GiB, write no output folder and print no sanitizer report. One ctest test per file:
// MalformedCorpus/... (the sanitizer stage selects them by that name).
#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <set>
#include <thread>

#include <gtest/gtest.h>

#include "malformed_corpus.h"
#include "tests/support/run_process.h"

namespace ds::test::corpus {
namespace {

constexpr int kTimeLimitS = 10;
constexpr long kMemoryLimitKb = 2L * 1024 * 1024;  // 2 GiB

struct Measured {
    int exit_code = -1;
    std::string out;
    std::string err;
    double seconds = 0;
    long max_rss_kb = 0;  // the child's peak resident set (wait4), not an address-space limit
    bool timed_out = false;
};

// Runs DS_EXECUTABLE ARGS with stdin from /dev/null, killing it after kTimeLimitS.
Measured run_measured(const std::vector<std::string>& args, const fs::path& io) {
    const fs::path out_file = io.string() + ".out";
    const fs::path err_file = io.string() + ".err";
    const auto start = std::chrono::steady_clock::now();
    const pid_t pid = ::fork();
    if (pid == 0) {
        const int in = ::open("/dev/null", O_RDONLY);
        const int out = ::open(out_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int err = ::open(err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        ::dup2(in, 0);
        ::dup2(out, 1);
        ::dup2(err, 2);
        std::vector<char*> argv{const_cast<char*>(DS_EXECUTABLE)};
        for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        ::execv(DS_EXECUTABLE, argv.data());
        ::_exit(127);
    }
    Measured r;
    int status = 0;
    struct rusage usage {};
    while (::wait4(pid, &status, WNOHANG, &usage) == 0) {
        if (std::chrono::steady_clock::now() - start > std::chrono::seconds(kTimeLimitS)) {
            ::kill(pid, SIGKILL);
            ::wait4(pid, &status, 0, &usage);
            r.timed_out = true;
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    r.max_rss_kb = usage.ru_maxrss;
    r.out = read_file(out_file);
    r.err = read_file(err_file);
    fs::remove(out_file);
    fs::remove(err_file);
    return r;
}

// The valid export every case starts from, made once per test process.
const fs::path& base_export() {
    static const fs::path base = [] {
        const fs::path dir = fresh_dir("malformed-base-" + std::to_string(::getpid()));
        const ProcessResult r =
            run_depthscope("export-scene foliage " + (dir / "foliage.gltf").string());
        EXPECT_EQ(r.exit_code, 0) << r.err;
        return dir;
    }();
    return base;
}

class MalformedCorpus : public ::testing::TestWithParam<Case> {};

TEST_P(MalformedCorpus, RefusedWithOneErrorLine) {
    const Case& c = GetParam();
    SCOPED_TRACE(c.name + ": " + c.reason);
    const Workspace w(fs::path(DS_TEST_WORK_DIR) / "malformed" / c.name, base_export());
    const fs::path scene = c.make(w);
    const fs::path out = w.dir() / "out";
    const Measured r = run_measured({"capture", "--strict", "--scene", scene.string(), "--out",
                                     out.string(), "--size", "32x32"},
                                    w.dir().string() + "-io");

    std::printf("%s: exit %d, %.2f s, peak %ld MiB: %s", c.name.c_str(), r.exit_code, r.seconds,
                r.max_rss_kb / 1024, r.err.c_str());
    EXPECT_FALSE(r.timed_out) << "still running after " << kTimeLimitS << " s";
    EXPECT_LT(r.seconds, kTimeLimitS);
    EXPECT_LT(r.max_rss_kb, kMemoryLimitKb) << "peak " << r.max_rss_kb / 1024 << " MiB";
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_EQ(count_lines(r.err), 1u) << r.err;
    EXPECT_EQ(r.out, "");
    const std::string prefix = "depthscope: error: " + scene.string() + ": ";
    EXPECT_EQ(r.err.rfind(prefix, 0), 0u) << r.err;
    EXPECT_NE(r.err.find(c.expect), std::string::npos)
        << "expected \"" << c.expect << "\" in " << r.err;
    for (const char* report : {"AddressSanitizer", "runtime error:", "LeakSanitizer"})
        EXPECT_EQ((r.out + r.err).find(report), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out));
    for (const auto& entry : fs::directory_iterator(w.dir()))
        EXPECT_FALSE(entry.path().filename().string().starts_with("out"))
            << "left behind: " << entry.path();
    if (!::testing::Test::HasFailure()) fs::remove_all(w.dir());
}

INSTANTIATE_TEST_SUITE_P(Files, MalformedCorpus, ::testing::ValuesIn(all_cases()),
                         [](const ::testing::TestParamInfo<Case>& info) {
                             return info.param.name;
                         });

// The issue asks for at least 60 files, each named once.
TEST(MalformedCorpusSize, AtLeastSixtyDistinctFiles) {
    std::set<std::string> names;
    for (const Case& c : all_cases()) EXPECT_TRUE(names.insert(c.name).second) << c.name;
    EXPECT_GE(names.size(), 60u);
}

}  // namespace
}  // namespace ds::test::corpus
