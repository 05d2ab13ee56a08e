// Output is all or nothing (issue 12): a capture into an existing folder replaces it whole or
// leaves it exactly as it was; a write cut short (a file-size limit) is an error that leaves
// nothing; a signal removes the staging folder; --json never replaces anything but a regular
// file, and a bad target is refused before any frame is rendered.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <thread>

#include "tests/support/run_process.h"

namespace fs = std::filesystem;
using ds::test::expect_one_error_line;
using ds::test::run_depthscope;

namespace {

// Every path under `dir` with its content ("<dir>" for a folder): equal snapshots mean the
// folder is exactly as it was.
std::map<std::string, std::string> snapshot(const fs::path& dir) {
    std::map<std::string, std::string> out;
    for (const auto& entry : fs::recursive_directory_iterator(dir)) {
        const std::string rel = fs::relative(entry.path(), dir).string();
        out[rel] = entry.is_directory() ? "<dir>" : ds::test::read_file(entry.path());
    }
    return out;
}

// Anything beside `out` whose name starts with out's and holds ".tmp-": a staging folder or a
// temporary file left behind.
void expect_no_leftovers(const fs::path& out) {
    const std::string stem = out.filename().string() + ".tmp-";
    for (const auto& entry : fs::directory_iterator(out.parent_path()))
        if (entry.path().filename().string().rfind(stem, 0) == 0)
            ADD_FAILURE() << "left behind: " << entry.path();
}

ds::test::ProcessResult capture(const fs::path& out, const std::string& extra = "") {
    return run_depthscope("capture --scene overdraw --size 16x16 --out " + out.string() + " " +
                          extra);
}

}  // namespace

TEST(Output, ACaptureReplacesAnExistingCaptureWhole) {
    const fs::path out = ds::test::fresh_dir("output-replace") / "cap";
    ASSERT_EQ(capture(out).exit_code, 0);
    const std::string first = ds::test::read_file(out / "report.json");
    { std::ofstream(out / "old.rdc") << "an earlier RenderDoc capture"; }
    const auto r = capture(out, "--set exposure=2");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(r.err.empty()) << r.err;
    const std::string second = ds::test::read_file(out / "report.json");
    EXPECT_NE(second, first);
    EXPECT_NE(second.find("\"exposure\": \"2\""), std::string::npos);
    // The folder is the new capture, not a merge: the old capture's .rdc went with it.
    EXPECT_FALSE(fs::exists(out / "old.rdc"));
    expect_no_leftovers(out);
}

// A folder that holds more than a capture (here a folder named report.json, where the new
// report would have to go) is refused before any work, and stays as it was.
TEST(Output, AFolderHoldingMoreThanACaptureIsRefusedAndKept) {
    const fs::path out = ds::test::fresh_dir("output-refused") / "cap";
    fs::create_directories(out / "report.json");
    { std::ofstream(out / "report.json" / "keep") << "mine"; }
    { std::ofstream(out / "final.png") << "not a png"; }
    const auto before = snapshot(out);
    const auto r = capture(out);
    expect_one_error_line(r, 1, "holds more than a capture ('report.json')");
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_EQ(snapshot(out), before);
    expect_no_leftovers(out);
}

// The step that puts the new capture in place fails for real (an immutable folder cannot be
// renamed, even by root): the existing capture is untouched and no staging folder is left.
TEST(Output, AFailedSwapLeavesTheExistingFolderAsItWas) {
    const fs::path out = ds::test::fresh_dir("output-immutable") / "cap";
    ASSERT_EQ(capture(out).exit_code, 0);
    const auto before = snapshot(out);
    if (std::system(("chattr +i " + out.string() + " 2>/dev/null").c_str()) != 0)
        GTEST_SKIP() << "chattr +i is not possible here (needs CAP_LINUX_IMMUTABLE and ext4/xfs)";
    const auto r = capture(out, "--set exposure=2");
    std::system(("chattr -i " + out.string()).c_str());
    expect_one_error_line(r, 1, "cannot replace the existing folder");
    EXPECT_EQ(snapshot(out), before);
    expect_no_leftovers(out);
}

// report.json cannot be written (the file-size limit cuts it short after final.png was staged
// whole): the existing capture is untouched.
TEST(Output, AReportCutShortLeavesTheExistingFolderAsItWas) {
    const fs::path out = ds::test::fresh_dir("output-report-cut") / "cap";
    ASSERT_EQ(capture(out).exit_code, 0);
    // The premise: this capture's PNG fits in 4 KiB, its report does not.
    ASSERT_LT(fs::file_size(out / "final.png"), 4096u);
    ASSERT_GT(fs::file_size(out / "report.json"), 4096u);
    const auto before = snapshot(out);
    const auto r = ds::test::run_depthscope_under_file_limit(
        4, "capture --scene overdraw --size 16x16 --resources none --set exposure=2 --out " +
               out.string());
    expect_one_error_line(r, 1, "report.json: cannot write: File too large");
    EXPECT_EQ(snapshot(out), before);
    expect_no_leftovers(out);
}

// SIGXFSZ would end the process with no word; here the PNG's write fails with EFBIG, the run
// says so in one line and leaves nothing (it used to print `wrote` and exit 0).
TEST(Output, AFileSizeLimitIsAnErrorThatLeavesNothing) {
    const fs::path out = ds::test::fresh_dir("output-ulimit") / "cap";
    const auto r = ds::test::run_depthscope_under_file_limit(
        8, "capture --scene atrium --size 256x256 --out " + out.string());
    expect_one_error_line(r, 1, "final.png: cannot write: File too large");
    EXPECT_EQ(r.out.find("wrote"), std::string::npos) << r.out;
    EXPECT_FALSE(fs::exists(out));
    expect_no_leftovers(out);

    const fs::path json = out.parent_path() / "pixel.json";
    const auto p = ds::test::run_depthscope_under_file_limit(
        1, "pixel --scene overdraw --size 32x32 --at 16,16 --json " + json.string());
    expect_one_error_line(p, 1, "cannot write: File too large");
    EXPECT_FALSE(fs::exists(json));
    expect_no_leftovers(json);
}

namespace {

// Starts `depthscope ARGS...` with the signals' default actions (a parent may ignore SIGPIPE
// or SIGINT, and a child inherits that); its output goes to /dev/null.
pid_t start_depthscope(const std::vector<std::string>& args) {
    const pid_t pid = ::fork();
    if (pid != 0) return pid;
    for (const int s : {SIGTERM, SIGINT, SIGHUP, SIGPIPE}) ::signal(s, SIG_DFL);
    sigset_t none;
    sigemptyset(&none);
    ::sigprocmask(SIG_SETMASK, &none, nullptr);
    std::freopen("/dev/null", "w", stdout);
    std::freopen("/dev/null", "w", stderr);
    std::vector<char*> argv{const_cast<char*>(DS_EXECUTABLE)};
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(DS_EXECUTABLE, argv.data());
    ::_exit(127);
}

// Waits until `path` exists while `pid` runs; false when the process ended first or 60 s passed.
bool wait_for(const fs::path& path, pid_t pid) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (std::chrono::steady_clock::now() < deadline) {
        if (fs::exists(path)) return true;
        int status = 0;
        if (::waitpid(pid, &status, WNOHANG) == pid) return false;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return false;
}

}  // namespace

// Each signal once the staging folder exists; SIGTERM once it holds final.png too (--advise
// renders for a while after the PNG is staged). The process ends by the signal itself, and
// neither the staging folder nor the capture folder is left.
TEST(Output, ASignalDuringACaptureRemovesTheStagingFolder) {
    const fs::path dir = ds::test::fresh_dir("output-signal");
    const struct {
        int signal;
        const char* wait_for;  // inside the staging folder; "" for the folder itself
    } cases[] = {{SIGTERM, "final.png"}, {SIGTERM, ""}, {SIGINT, ""}, {SIGHUP, ""}, {SIGPIPE, ""}};
    int n = 0;
    for (const auto& c : cases) {
        const fs::path out = dir / ("cap" + std::to_string(n++));
        const pid_t pid = start_depthscope(
            {"capture", "--scene", "atrium", "--size", "320x180", "--advise", "--out", out});
        ASSERT_GT(pid, 0);
        const fs::path staging = out.string() + ".tmp-" + std::to_string(pid);
        const bool seen = wait_for(staging / c.wait_for, pid);
        if (seen) ::kill(pid, c.signal);
        int status = 0;
        ::waitpid(pid, &status, 0);
        ASSERT_TRUE(seen) << "the capture ended before " << (staging / c.wait_for)
                          << " appeared; status " << status;
        EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == c.signal)
            << strsignal(c.signal) << ": status " << status;
        EXPECT_FALSE(fs::exists(staging)) << strsignal(c.signal);
        EXPECT_FALSE(fs::exists(out)) << strsignal(c.signal);
    }
    for (const auto& entry : fs::directory_iterator(dir))
        ADD_FAILURE() << "left behind: " << entry.path();
}

// --json names a FIFO, a directory, a symbolic link, a device node or a file in no folder:
// refused in one line before the benchmark starts (nothing on stdout: no frame, not even the
// header), and the node is still what it was. /dev/null itself is never used: a device node
// made here stands for it, so a mistake could only replace that.
TEST(Output, JsonTargetsOtherThanARegularFileAreRefusedBeforeAnyFrame) {
    const fs::path dir = ds::test::fresh_dir("output-json");
    ASSERT_EQ(::mkfifo((dir / "fifo").c_str(), 0600), 0);
    fs::create_directory(dir / "folder");
    { std::ofstream(dir / "real.json") << "keep"; }
    fs::create_symlink(dir / "real.json", dir / "link.json");
    const bool have_node = ::mknod((dir / "null").c_str(), S_IFCHR | 0666, makedev(1, 3)) == 0;
    struct Target {
        std::string name;
        std::string why;
    };
    std::vector<Target> targets = {{"fifo", "is a FIFO"},
                                   {"folder", "is a directory"},
                                   {"link.json", "is a symbolic link"},
                                   {"missing/out.json", "no folder"}};
    if (have_node) targets.push_back({"null", "is a device node"});
    for (const auto& t : targets) {
        const fs::path path = dir / t.name;
        const auto start = std::chrono::steady_clock::now();
        const auto r = run_depthscope(
            "bench --scene overdraw --size 64x64 --frames 100000 --json " + path.string());
        const double s =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        expect_one_error_line(r, 1, "--json " + path.string() + ": " + t.why);
        EXPECT_TRUE(r.out.empty()) << t.name << ": " << r.out;
        EXPECT_LT(s, 10.0) << t.name;
        const auto p =
            run_depthscope("pixel --scene overdraw --size 8x8 --at 1,1 --json " + path.string());
        expect_one_error_line(p, 1, "--json " + path.string() + ": " + t.why);
        EXPECT_TRUE(p.out.empty()) << t.name << ": " << p.out;
    }
    EXPECT_TRUE(fs::is_fifo(dir / "fifo"));
    EXPECT_TRUE(fs::is_symlink(dir / "link.json"));
    EXPECT_EQ(ds::test::read_file(dir / "real.json"), "keep");
    EXPECT_TRUE(fs::is_empty(dir / "folder"));
    if (have_node) {
        EXPECT_TRUE(fs::is_character_file(dir / "null"));
    } else {
        GTEST_SKIP() << "mknod is not allowed here: the device-node case was not run";
    }
}

// A regular file is replaced whole, through a temporary file that does not stay.
TEST(Output, JsonReplacesARegularFile) {
    const fs::path json = ds::test::fresh_dir("output-json-regular") / "bench.json";
    { std::ofstream(json) << "old"; }
    const auto r = run_depthscope(
        "bench --scene overdraw --size 16x16 --frames 1 --warmup 0 --json " + json.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(ds::test::read_file(json).rfind("{", 0), 0u);
    expect_no_leftovers(json);
}
