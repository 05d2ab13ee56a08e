#pragma once
// --trace FILE.json: GPU pass timings as Chrome trace-event JSON (the "Trace Event Format"),
// which ui.perfetto.dev and chrome://tracing open. capture traces its written frame, bench every
// measured frame of every run. The file is one object:
//   {"traceEvents": [...], "displayTimeUnit": "ms", "otherData": {tool, command, scene, ...}}
// - a process per configuration ("pid" 1.. in run order, named by "process_name" metadata):
//   capture's one frame, or one bench run each (--matrix combination, + inspector);
// - a track ("tid") for the graphics queue, the one queue every pass runs on; bench: one per
//   measured frame ("frame N"), every frame from ts 0, so frames lie one under another;
// - per pass a complete event ("ph":"X"): name = the pass, cat = its role (frame, clear,
//   readback, measure, history), ts = its start after the frame's first timestamp, dur = its
//   gpu_ms, both in µs (whole ns, read back alike by viewers that truncate or round µs × 1000,
//   so back-to-back passes touch exactly; dur is gpu_ms to 2 ns); args: gpu_ms and the pass's
//   counters. A pass that begins before the one before it ended (a GPU that overlaps passes)
//   goes on a further track of its frame ("… overlap 2"): viewers nest the spans of a track;
// - a process-scoped instant event "settings" at ts 0 whose args are every setting;
// - count_fragments=on: a counter ("ph":"C") "fragments", series "shaded": a pass's shaded
//   fragments from its start, 0 after its end (bench: one counter per frame, "id" "frame N").
// A device without timestamps has no start or duration to show: --trace is refused there.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "renderer/common/device_info.h"
#include "renderer/passes/frame_result.h"

namespace ds::capture {

// One process of the trace: the frames one configuration rendered.
struct TraceRun {
    std::string name;  // "capture atrium 160x90", "run 2: prepass=off"
    std::map<std::string, std::string, std::less<>> settings;
    std::vector<std::vector<PassResult>> frames;  // each frame's passes, in execution order
};

struct TraceInput {
    std::string command;  // "capture" | "bench"
    std::string scene;
    uint32_t width = 0, height = 0;
    std::string device;
    bool track_per_frame = false;  // bench: a track per frame; else one "graphics queue"
    std::vector<TraceRun> runs;
};

// What the trace keeps of a pass (bench holds every measured frame's): name, role, times and
// counters, without the declarations and per-draw lists.
PassResult trace_pass(const PassResult& pass);

// The trace as JSON (tests read it back); trace_text() is the file's text, one event a line.
nlohmann::json trace_json(const TraceInput& in);
std::string trace_text(const TraceInput& in);

// Before any frame: the device must time its passes. Throws ds::Error "--trace PATH: …".
void check_trace_device(const std::filesystem::path& path, const DeviceInfo& device);
// capture: the trace may not lie in the capture folder, which the capture replaces whole.
// Throws ds::UsageError.
void check_trace_outside(const std::filesystem::path& path,
                         const std::filesystem::path& capture_dir);
// The trace onto PATH through a temporary file renamed into place (write_file_atomically).
void write_trace(const std::filesystem::path& path, const TraceInput& in);

}  // namespace ds::capture
