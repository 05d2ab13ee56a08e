// --trace FILE.json through the real executable (issue 13): the file parses as JSON with the
// Trace Event Format's required fields, a span per pass whose dur is that pass's gpu_ms in
// report.json (capture) or in bench's --json (every measured frame of every run) to 1 µs,
// shaded-fragment counters, and a bad target refused before any work.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <sys/sysmacros.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tests/support/run_process.h"

namespace fs = std::filesystem;
using ds::test::expect_one_error_line;
using ds::test::run_depthscope;
using nlohmann::json;

namespace {

constexpr double kMicrosecond = 1.0;  // the acceptance's tolerance, in the trace's unit

std::vector<json> of_phase(const json& trace, const std::string& ph) {
    std::vector<json> out;
    for (const auto& e : trace["traceEvents"])
        if (e["ph"] == ph) out.push_back(e);
    return out;
}

std::string meta_name(const json& trace, const char* what, int pid, int tid) {
    for (const auto& e : of_phase(trace, "M"))
        if (e["name"] == what && e["pid"] == pid && e["tid"] == tid) return e["args"]["name"];
    return "";
}

// What every event of the format needs (dur for complete events), and spans that a viewer can
// nest: on each track, in whole ns as Perfetto reads them, a span ends by the next one's start
// or holds it.
void expect_well_formed(const json& trace) {
    ASSERT_TRUE(trace.is_object());
    ASSERT_TRUE(trace["traceEvents"].is_array());
    ASSERT_FALSE(trace["traceEvents"].empty());
    std::map<std::pair<int, int>, std::vector<std::pair<int64_t, int64_t>>> tracks;
    for (const auto& e : trace["traceEvents"]) {
        ASSERT_TRUE(e["name"].is_string()) << e.dump();
        ASSERT_TRUE(e["ph"].is_string()) << e.dump();
        ASSERT_TRUE(e["ts"].is_number()) << e.dump();
        ASSERT_TRUE(e["pid"].is_number_integer()) << e.dump();
        ASSERT_TRUE(e["tid"].is_number_integer()) << e.dump();
        const std::string ph = e["ph"];
        EXPECT_TRUE(ph == "X" || ph == "M" || ph == "C" || ph == "i") << e.dump();
        if (ph == "M" || ph == "C" || ph == "i") {
            EXPECT_TRUE(e["args"].is_object()) << e.dump();
        }
        if (ph != "X") continue;
        ASSERT_TRUE(e["dur"].is_number()) << e.dump();
        EXPECT_GE(e["ts"].get<double>(), 0.0) << e.dump();
        EXPECT_GE(e["dur"].get<double>(), 0.0) << e.dump();
        // As Perfetto's importer reads them: µs × 1000, truncated.
        const int64_t ts = static_cast<int64_t>(e["ts"].get<double>() * 1000.0);
        tracks[{e["pid"], e["tid"]}].push_back(
            {ts, ts + static_cast<int64_t>(e["dur"].get<double>() * 1000.0)});
    }
    for (auto& [track, spans] : tracks) {
        std::sort(spans.begin(), spans.end());
        for (size_t i = 1; i < spans.size(); ++i)
            EXPECT_TRUE(spans[i].first >= spans[i - 1].second ||
                        spans[i].second <= spans[i - 1].second)
                << "pid " << track.first << " tid " << track.second << ": span at "
                << spans[i].first << " ns crosses the end of the one before";
    }
}

}  // namespace

TEST(TraceCli, CaptureHasASpanPerReportPassWithItsGpuTime) {
    const fs::path dir = ds::test::fresh_dir("trace-capture");
    const fs::path trace_path = dir / "frame.json";
    const auto r = run_depthscope(
        "capture --validate --scene overdraw --size 64x64 --resources none --set shadows=off "
        "--set count_fragments=on --out " +
        (dir / "cap").string() + " --trace " + trace_path.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("wrote " + trace_path.string()), std::string::npos) << r.out;
    const json trace = json::parse(ds::test::read_file(trace_path));
    const json report = json::parse(ds::test::read_file(dir / "cap" / "report.json"));
    expect_well_formed(trace);
    EXPECT_EQ(trace["displayTimeUnit"], "ms");
    EXPECT_EQ(meta_name(trace, "process_name", 1, 1), "capture overdraw 64x64");
    EXPECT_EQ(meta_name(trace, "thread_name", 1, 1), "graphics queue");

    const std::vector<json> spans = of_phase(trace, "X");
    const json& passes = report["passes"];
    ASSERT_EQ(spans.size(), passes.size());
    std::map<std::string, json> span_of;
    for (size_t i = 0; i < spans.size(); ++i) {
        SCOPED_TRACE(passes[i]["name"].get<std::string>());
        EXPECT_EQ(spans[i]["name"], passes[i]["name"]);
        EXPECT_EQ(spans[i]["cat"], passes[i]["kind"]);
        EXPECT_EQ(spans[i]["pid"], 1);
        EXPECT_NEAR(spans[i]["dur"].get<double>(), passes[i]["gpu_ms"].get<double>() * 1000.0,
                    kMicrosecond);
        EXPECT_EQ(spans[i]["args"]["gpu_ms"], passes[i]["gpu_ms"]);
        if (i > 0) {  // one queue: in execution order
            EXPECT_GE(spans[i]["ts"].get<double>(), spans[i - 1]["ts"].get<double>());
        }
        span_of[spans[i]["name"]] = spans[i];
    }
    EXPECT_EQ(spans.front()["ts"].get<double>(), 0.0) << "the frame's first timestamp is 0";
    EXPECT_GT(spans.back()["ts"].get<double>(), 0.0);

    // Every counted pass's shaded fragments, as report.json has them, from its span's start.
    const std::vector<json> counters = of_phase(trace, "C");
    size_t counted = 0;
    for (const auto& p : passes) {
        if (!p.contains("shaded_fragments")) continue;
        ++counted;
        const json& span = span_of[p["name"]];
        EXPECT_EQ(span["args"]["shaded_fragments"], p["shaded_fragments"]);
        const bool found = std::any_of(counters.begin(), counters.end(), [&](const json& c) {
            return c["ts"] == span["ts"] && c["args"]["shaded"] == p["shaded_fragments"];
        });
        EXPECT_TRUE(found) << p["name"] << ": no counter at " << span["ts"];
    }
    EXPECT_GE(counted, 2u) << "depth_prepass and forward count with count_fragments=on";
    for (const auto& c : counters) EXPECT_EQ(c["name"], "fragments") << c.dump();

    const std::vector<json> instants = of_phase(trace, "i");
    ASSERT_EQ(instants.size(), 1u);
    EXPECT_EQ(instants[0]["args"], report["settings"]);
}

TEST(TraceCli, NoCountersWithoutCountFragments) {
    const fs::path dir = ds::test::fresh_dir("trace-uncounted");
    const auto r = run_depthscope("capture --scene overdraw --size 32x32 --resources none --out " +
                                  (dir / "cap").string() + " --trace " + (dir / "t.json").string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const json trace = json::parse(ds::test::read_file(dir / "t.json"));
    expect_well_formed(trace);
    EXPECT_FALSE(of_phase(trace, "X").empty());
    EXPECT_TRUE(of_phase(trace, "C").empty());
}

// Every measured frame of every run: a run's process holds `frames` spans of each pass, on a
// track per frame, whose durations have the --json's median, min and max.
TEST(TraceCli, BenchSpansEveryMeasuredFrameOfEveryRun) {
    const fs::path dir = ds::test::fresh_dir("trace-bench");
    const auto r = run_depthscope(
        "bench --validate --scene overdraw --size 64x64 --frames 3 --warmup 1 "
        "--matrix prepass=on,off --json " +
        (dir / "bench.json").string() + " --trace " + (dir / "trace.json").string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const json trace = json::parse(ds::test::read_file(dir / "trace.json"));
    const json bench = json::parse(ds::test::read_file(dir / "bench.json"));
    expect_well_formed(trace);
    ASSERT_EQ(bench["runs"].size(), 2u);
    const std::vector<json> spans = of_phase(trace, "X");
    const std::vector<json> instants = of_phase(trace, "i");
    size_t listed = 0;
    for (size_t run = 0; run < 2; ++run) {
        const int pid = int(run + 1);
        const json& out = bench["runs"][run];
        EXPECT_EQ(meta_name(trace, "process_name", pid, 1),
                  "run " + std::to_string(run + 1) + ": prepass=" + (run ? "off" : "on"));
        for (int f = 1; f <= 3; ++f)
            EXPECT_EQ(meta_name(trace, "thread_name", pid, f), "frame " + std::to_string(f));
        const auto settings = std::find_if(instants.begin(), instants.end(),
                                           [&](const json& e) { return e["pid"] == pid; });
        ASSERT_NE(settings, instants.end());
        EXPECT_EQ((*settings)["args"], out["settings"]);
        for (const auto& p : out["passes"]) {
            SCOPED_TRACE(p["name"].get<std::string>() + " in run " + std::to_string(run + 1));
            std::vector<double> ms;
            std::vector<int> frames;
            for (const auto& s : spans) {
                if (s["pid"] != pid || s["name"] != p["name"]) continue;
                EXPECT_EQ(s["cat"], p["kind"]);
                ms.push_back(s["dur"].get<double>() / 1000.0);
                frames.push_back(s["args"]["frame"]);
            }
            listed += ms.size();
            ASSERT_EQ(ms.size(), 3u);
            std::sort(frames.begin(), frames.end());
            EXPECT_EQ(frames, (std::vector<int>{1, 2, 3}));
            std::sort(ms.begin(), ms.end());
            EXPECT_NEAR(ms[0] * 1000, p["gpu_ms"]["min"].get<double>() * 1000, kMicrosecond);
            EXPECT_NEAR(ms[1] * 1000, p["gpu_ms"]["median"].get<double>() * 1000, kMicrosecond);
            EXPECT_NEAR(ms[2] * 1000, p["gpu_ms"]["max"].get<double>() * 1000, kMicrosecond);
        }
    }
    EXPECT_EQ(listed, spans.size()) << "every span is a pass --json lists";
}

// A target that is no regular file or new name in a folder: one line before any work (no
// frame, no capture folder), and the node as it was. A trace inside the capture's own folder
// (which the capture replaces whole) and --trace with --soak or --advise: usage errors.
TEST(TraceCli, BadTargetsAreRefusedBeforeAnyWork) {
    const fs::path dir = ds::test::fresh_dir("trace-bad");
    ASSERT_EQ(::mkfifo((dir / "fifo").c_str(), 0600), 0);
    fs::create_directory(dir / "folder");
    const bool have_node = ::mknod((dir / "null").c_str(), S_IFCHR | 0666, makedev(1, 3)) == 0;
    std::vector<std::pair<std::string, std::string>> targets = {
        {"fifo", "is a FIFO"}, {"folder", "is a directory"}, {"missing/t.json", "no folder"}};
    if (have_node) targets.push_back({"null", "is a device node"});
    for (const auto& [name, why] : targets) {
        const fs::path path = dir / name;
        const auto start = std::chrono::steady_clock::now();
        const auto b = run_depthscope(
            "bench --scene overdraw --size 64x64 --frames 100000 --trace " + path.string());
        EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
                  10.0);
        expect_one_error_line(b, 1, "--trace " + path.string() + ": " + why);
        EXPECT_TRUE(b.out.empty()) << name << ": " << b.out;
        const auto c = run_depthscope("capture --scene overdraw --size 16x16 --out " +
                                      (dir / "cap").string() + " --trace " + path.string());
        expect_one_error_line(c, 1, "--trace " + path.string() + ": " + why);
        EXPECT_TRUE(c.out.empty()) << name << ": " << c.out;
        EXPECT_FALSE(fs::exists(dir / "cap")) << name;
    }
    EXPECT_TRUE(fs::is_fifo(dir / "fifo"));
    EXPECT_TRUE(fs::is_empty(dir / "folder"));
    if (have_node) {
        EXPECT_TRUE(fs::is_character_file(dir / "null"));
    }

    // An existing capture folder: the trace would go with the old files.
    ASSERT_EQ(run_depthscope("capture --scene overdraw --size 16x16 --resources none --out " +
                             (dir / "cap").string())
                  .exit_code,
              0);
    const std::string report = ds::test::read_file(dir / "cap" / "report.json");
    const auto inside =
        run_depthscope("capture --scene overdraw --size 16x16 --out " + (dir / "cap").string() +
                       " --trace " + (dir / "cap" / "t.json").string());
    expect_one_error_line(inside, 2, "inside the capture folder");
    EXPECT_FALSE(fs::exists(dir / "cap" / "t.json"));
    EXPECT_EQ(ds::test::read_file(dir / "cap" / "report.json"), report) << "the capture as it was";

    for (const char* other : {"--advise", "--soak 5"}) {
        const auto o = run_depthscope(std::string("bench --scene overdraw ") + other + " --trace " +
                                      (dir / "t.json").string());
        expect_one_error_line(o, 2, "one at a time");
        EXPECT_TRUE(o.out.empty()) << other << ": " << o.out;
    }
    expect_one_error_line(run_depthscope("bench --trace ''"), 2, "--trace expects a path");
    EXPECT_FALSE(fs::exists(dir / "t.json"));
    if (!have_node) GTEST_SKIP() << "mknod is not allowed here: the device-node case was not run";
}

// A write cut short (a file-size limit) is one line and leaves no trace and no temporary file.
TEST(TraceCli, AWriteCutShortLeavesNothing) {
    const fs::path trace = ds::test::fresh_dir("trace-ulimit") / "t.json";
    const auto r = ds::test::run_depthscope_under_file_limit(
        2, "bench --scene overdraw --size 16x16 --frames 2 --warmup 0 --trace " + trace.string());
    expect_one_error_line(r, 1, "cannot write: File too large");
    EXPECT_TRUE(fs::is_empty(trace.parent_path())) << "no trace, no temporary file";
}
