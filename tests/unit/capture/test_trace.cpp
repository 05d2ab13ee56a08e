// The --trace writer on made-up passes (no device): the Trace Event Format's required fields,
// spans from the GPU times, tracks, overlapping passes, counters and the file's own text.
#include <gtest/gtest.h>

#include <unistd.h>
#include <cmath>
#include <filesystem>
#include <map>
#include <string>

#include "capture/trace.h"
#include "renderer/common/error.h"
#include "renderer/graph/profiler.h"

namespace ds::capture {
namespace {

namespace fs = std::filesystem;

PassResult pass(const char* name, double start_ms, double gpu_ms,
                graph::PassRole role = graph::PassRole::Frame) {
    PassResult p;
    p.name = name;
    p.role = role;
    p.gpu_start_ms = start_ms;
    p.gpu_ms = gpu_ms;
    return p;
}

std::vector<PassResult> three_passes() {
    std::vector<PassResult> passes = {pass("clear_counts", 0.0, 0.0125, graph::PassRole::Clear),
                                      pass("depth_prepass", 0.0125, 0.5),
                                      pass("forward", 0.5125, 1.25)};
    passes[1].vertex_shader_invocations = 36;
    passes[2].shaded_fragments = 512;
    passes[2].rasterized_fragments = 700;
    passes[2].reads = {"depth"};
    return passes;
}

TraceInput capture_input(std::vector<PassResult> passes) {
    return {.command = "capture",
            .scene = "made-up",
            .width = 32,
            .height = 16,
            .device = "gpu",
            .runs = {{.name = "capture made-up 32x16",
                      .settings = {{"prepass", "on"}, {"msaa", "1"}},
                      .frames = {std::move(passes)}}}};
}

std::vector<nlohmann::json> of_phase(const nlohmann::json& trace, const std::string& ph) {
    std::vector<nlohmann::json> out;
    for (const auto& e : trace["traceEvents"])
        if (e["ph"] == ph) out.push_back(e);
    return out;
}

// A time in whole ns as Perfetto's JSON importer reads µs: times 1000, truncated.
int64_t ns(const nlohmann::json& us) {
    return static_cast<int64_t>(us.get<double>() * 1000.0);
}

// The name a thread_name (or process_name) metadata event gives pid/tid.
std::string name_of(const nlohmann::json& trace, const char* what, int pid, int tid) {
    for (const auto& e : of_phase(trace, "M"))
        if (e["name"] == what && e["pid"] == pid && (tid == 0 || e["tid"] == tid))
            return e["args"]["name"];
    return "";
}

TEST(Trace, EveryEventHasTheRequiredFieldsAndTheTextIsTheJson) {
    const TraceInput in = capture_input(three_passes());
    const nlohmann::json trace = trace_json(in);
    EXPECT_EQ(nlohmann::json::parse(trace_text(in)), trace);
    EXPECT_EQ(trace["displayTimeUnit"], "ms");
    ASSERT_FALSE(trace["traceEvents"].empty());
    for (const auto& e : trace["traceEvents"]) {
        for (const char* field : {"name", "ph", "ts", "pid", "tid"})
            EXPECT_TRUE(e.contains(field)) << field << " missing: " << e.dump();
        EXPECT_TRUE(e["ts"].is_number()) << e.dump();
        if (e["ph"] == "X") {
            EXPECT_TRUE(e["dur"].is_number()) << e.dump();
        }
        if (e["ph"] == "C" || e["ph"] == "M") {
            EXPECT_TRUE(e["args"].is_object()) << e.dump();
        }
    }
}

TEST(Trace, ASpanPerPassFromItsGpuTimesOnTheGraphicsQueue) {
    const std::vector<PassResult> passes = three_passes();
    const nlohmann::json trace = trace_json(capture_input(passes));
    const auto spans = of_phase(trace, "X");
    ASSERT_EQ(spans.size(), passes.size());
    for (size_t i = 0; i < spans.size(); ++i) {
        const auto& s = spans[i];
        EXPECT_EQ(s["name"], passes[i].name);
        EXPECT_EQ(s["cat"], graph::pass_role_name(passes[i].role));
        EXPECT_NEAR(s["ts"].get<double>(), passes[i].gpu_start_ms * 1000.0, 1e-9);
        EXPECT_NEAR(s["dur"].get<double>(), passes[i].gpu_ms * 1000.0, 1e-9);
        EXPECT_EQ(s["pid"], 1);
        EXPECT_EQ(s["tid"], 1);
        EXPECT_EQ(s["args"]["gpu_ms"], passes[i].gpu_ms);
        EXPECT_FALSE(s["args"].contains("frame")) << "one frame: no frame number";
    }
    EXPECT_EQ(spans[1]["args"]["vertex_shader_invocations"], 36);
    EXPECT_EQ(spans[2]["args"]["shaded_fragments"], 512);
    EXPECT_EQ(spans[2]["args"]["rasterized_fragments"], 700);
    EXPECT_FALSE(spans[1]["args"].contains("shaded_fragments")) << "not counted is not 0";
    EXPECT_EQ(name_of(trace, "thread_name", 1, 1), "graphics queue");
    EXPECT_EQ(name_of(trace, "process_name", 1, 0), "capture made-up 32x16");
    EXPECT_EQ(trace["otherData"]["device"], "gpu");
    const auto instants = of_phase(trace, "i");
    ASSERT_EQ(instants.size(), 1u);
    EXPECT_EQ(instants[0]["name"], "settings");
    EXPECT_EQ(instants[0]["s"], "p");
    EXPECT_EQ(instants[0]["args"], (nlohmann::json{{"msaa", "1"}, {"prepass", "on"}}));
}

TEST(Trace, ShadedFragmentsAreACounterOverTheCountedPass) {
    const nlohmann::json trace = trace_json(capture_input(three_passes()));
    const auto counters = of_phase(trace, "C");
    ASSERT_EQ(counters.size(), 2u);  // forward's value from its start, 0 from its end
    EXPECT_EQ(counters[0]["name"], "fragments");
    EXPECT_DOUBLE_EQ(counters[0]["ts"].get<double>(), 512.5);
    EXPECT_EQ(counters[0]["args"], (nlohmann::json{{"shaded", 512}}));
    EXPECT_DOUBLE_EQ(counters[1]["ts"].get<double>(), 1762.5);
    EXPECT_EQ(counters[1]["args"], (nlohmann::json{{"shaded", 0}}));
    EXPECT_FALSE(counters[0].contains("id")) << "one frame, one counter";

    std::vector<PassResult> uncounted = three_passes();
    uncounted[2].shaded_fragments.reset();
    EXPECT_TRUE(of_phase(trace_json(capture_input(uncounted)), "C").empty());
}

// Back-to-back counted passes: the next value replaces the last at the instant they touch,
// with no 0 at that same instant.
TEST(Trace, TouchingCountedPassesHandOverWithoutAZeroBetween) {
    std::vector<PassResult> passes = {pass("depth_prepass", 0.0, 0.25), pass("forward", 0.25, 1)};
    passes[0].shaded_fragments = 10;
    passes[1].shaded_fragments = 20;
    const auto counters = of_phase(trace_json(capture_input(passes)), "C");
    ASSERT_EQ(counters.size(), 3u);
    EXPECT_EQ(counters[0]["args"]["shaded"], 10);
    EXPECT_DOUBLE_EQ(counters[1]["ts"].get<double>(), 250.0);
    EXPECT_EQ(counters[1]["args"]["shaded"], 20);
    EXPECT_EQ(counters[2]["args"]["shaded"], 0);
}

// A GPU that overlaps passes: the one that begins before the last ended goes on a further
// track, so every track's spans nest; the next pass that fits goes back to the first.
TEST(Trace, AnOverlappingPassGoesOnAFurtherTrackOfItsFrame) {
    const std::vector<PassResult> passes = {pass("a", 0.0, 1.0), pass("b", 0.5, 1.0),
                                            pass("c", 1.0, 0.25), pass("d", 1.25, 0.5)};
    const nlohmann::json trace = trace_json(capture_input(passes));
    const auto spans = of_phase(trace, "X");
    ASSERT_EQ(spans.size(), 4u);
    EXPECT_EQ(spans[0]["tid"], 1);
    EXPECT_EQ(spans[1]["tid"], 2);
    EXPECT_EQ(spans[2]["tid"], 1) << "c starts where a ended";
    EXPECT_EQ(spans[3]["tid"], 1);
    EXPECT_EQ(name_of(trace, "thread_name", 1, 2), "graphics queue overlap 2");
    EXPECT_NEAR(spans[1]["dur"].get<double>(), 1000.0, 1e-9) << "its own duration, uncut";
}

// Times from ticks whose period is no whole number of ns (52.083 ns, as some GPUs have):
// passes that touch on the GPU touch in the trace (one track), and every dur is gpu_ms to 1 ns.
TEST(Trace, PassesThatTouchOnTheGpuStayOnOneTrack) {
    // Pass 1's end (start + gpu_ms) rounds to 1 ns after pass 2's start, computed on its own.
    const std::vector<uint64_t> ticks = {1000,   818087, 818087, 819500,
                                         819500, 819600, 819600, 900000};
    const std::vector<graph::PassTime> times = graph::pass_times(ticks, 64, 52.083);
    std::vector<PassResult> passes;
    for (const graph::PassTime& t : times) passes.push_back(pass("p", t.start_ms, t.gpu_ms));
    const auto spans = of_phase(trace_json(capture_input(passes)), "X");
    ASSERT_EQ(spans.size(), 4u);
    for (size_t i = 0; i < spans.size(); ++i) {
        EXPECT_EQ(spans[i]["tid"], 1) << i;
        EXPECT_NEAR(spans[i]["dur"].get<double>(), passes[i].gpu_ms * 1000.0, 1e-3) << i;
        if (i > 0) {  // in whole ns, as Perfetto reads them
            EXPECT_EQ(ns(spans[i]["ts"]), ns(spans[i - 1]["ts"]) + ns(spans[i - 1]["dur"]));
        }
    }
}

// Every ts and dur reads back as the same whole ns whether a viewer truncates µs × 1000
// (Perfetto) or rounds it, so spans that touch touch there too.
TEST(Trace, TimesReadBackAsWholeNanosecondsTruncatedOrRounded) {
    std::vector<PassResult> passes;
    for (int i = 0; i < 3000; ++i) passes.push_back(pass("p", i * 0.0123457, 0.0123457));
    const auto spans = of_phase(trace_json(capture_input(passes)), "X");
    ASSERT_EQ(spans.size(), passes.size());
    for (size_t i = 0; i < spans.size(); ++i) {
        for (const char* field : {"ts", "dur"}) {
            const double us = spans[i][field].get<double>();
            ASSERT_EQ(ns(spans[i][field]), std::llround(us * 1000.0)) << field << " " << us;
        }
        EXPECT_EQ(spans[i]["tid"], 1);
        if (i > 0) {
            ASSERT_EQ(ns(spans[i]["ts"]), ns(spans[i - 1]["ts"]) + ns(spans[i - 1]["dur"])) << i;
        }
    }
}

TEST(Trace, BenchGivesEachRunAProcessAndEachFrameATrackFromZero) {
    TraceInput in;
    in.command = "bench";
    in.scene = "made-up";
    in.track_per_frame = true;
    for (int r = 0; r < 2; ++r) {
        TraceRun run;
        run.name = "run " + std::to_string(r + 1) + ": msaa=" + (r ? "4" : "1");
        run.settings = {{"msaa", r ? "4" : "1"}};
        for (int f = 0; f < 3; ++f) {
            run.frames.push_back(three_passes());
            run.frames.back()[2].gpu_ms += 0.001 * f;  // frames differ
        }
        in.runs.push_back(std::move(run));
    }
    const nlohmann::json trace = trace_json(in);
    const auto spans = of_phase(trace, "X");
    ASSERT_EQ(spans.size(), 2u * 3u * 3u);
    std::map<std::pair<int, int>, int> per_track;
    for (const auto& s : spans) {
        const int pid = s["pid"], tid = s["tid"];
        ++per_track[{pid, tid}];
        EXPECT_EQ(s["args"]["frame"], tid) << "one track per frame, frame N on track N";
        if (s["name"] == "clear_counts") {
            EXPECT_EQ(s["ts"].get<double>(), 0.0);
        }
        if (s["name"] == "forward") {
            EXPECT_NEAR(s["dur"].get<double>(), 1250.0 + tid - 1, 1e-6) << s.dump();
        }
    }
    EXPECT_EQ(per_track.size(), 6u);
    EXPECT_EQ(name_of(trace, "process_name", 2, 0), "run 2: msaa=4");
    EXPECT_EQ(name_of(trace, "thread_name", 2, 3), "frame 3");
    EXPECT_EQ(of_phase(trace, "i").size(), 2u) << "the settings once per run";
    // Frames lie over one another, so each has its own counter.
    const auto counters = of_phase(trace, "C");
    ASSERT_EQ(counters.size(), 2u * 3u * 2u);
    EXPECT_EQ(counters[0]["id"], "frame 1");
    EXPECT_EQ(counters.back()["id"], "frame 3");
}

TEST(Trace, KeepsWhatItShowsOfAPass) {
    PassResult p = three_passes()[2];
    p.quads = 140;
    const PassResult kept = trace_pass(p);
    EXPECT_EQ(kept.name, "forward");
    EXPECT_EQ(kept.gpu_start_ms, p.gpu_start_ms);
    EXPECT_EQ(kept.gpu_ms, p.gpu_ms);
    EXPECT_EQ(kept.shaded_fragments, p.shaded_fragments);
    EXPECT_EQ(kept.rasterized_fragments, p.rasterized_fragments);
    EXPECT_EQ(kept.quads, p.quads);
    EXPECT_TRUE(kept.reads.empty());
}

TEST(Trace, ADeviceWithoutTimestampsIsRefused) {
    DeviceInfo device;
    device.name = "gpu";
    device.timestamps = true;
    EXPECT_NO_THROW(check_trace_device("t.json", device));
    device.timestamps = false;
    try {
        check_trace_device("t.json", device);
        ADD_FAILURE() << "no throw";
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(),
                     "--trace t.json: gpu has no GPU timestamps: no pass has a start or a "
                     "duration to trace");
    }
}

TEST(Trace, ATraceInsideTheCaptureFolderIsRefused) {
    const fs::path root = fs::temp_directory_path() / ("ds-trace-" + std::to_string(::getpid()));
    fs::create_directories(root / "cap" / "sub");
    for (const fs::path& inside : {root / "cap" / "t.json", root / "cap" / "sub" / "t.json",
                                   root / "cap" / "." / "t.json"}) {
        EXPECT_THROW(check_trace_outside(inside, root / "cap"), UsageError) << inside;
        EXPECT_THROW(check_trace_outside(inside, root / "cap/"), UsageError) << inside;
    }
    EXPECT_NO_THROW(check_trace_outside(root / "t.json", root / "cap"));
    EXPECT_NO_THROW(check_trace_outside(root / "cap2" / "t.json", root / "cap"));
    fs::remove_all(root);
}

}  // namespace
}  // namespace ds::capture
