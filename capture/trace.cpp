#include "capture/trace.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <system_error>

#include "capture/file_output.h"
#include "renderer/common/error.h"
#include "renderer/common/quoted.h"

namespace ds::capture {
namespace {

namespace fs = std::filesystem;

// Whole nanoseconds, so that passes that touch on the GPU touch in the trace (viewers nest the
// spans of a track by comparing their ends) whatever the tick period; dur stays gpu_ms to 2 ns.
int64_t to_ns(double ms) {
    return std::llround(ms * 1e6);
}
// µs for whole ns: the nearest double, or the next one up where that times 1000 falls short of
// NS, since Perfetto's importer truncates µs × 1000 (2086.423 would read as 2086422 ns). A reader
// that rounds gets NS either way.
double to_us(int64_t ns) {
    double us = double(ns) / 1000.0;
    while (static_cast<int64_t>(us * 1000.0) < ns) us = std::nextafter(us, HUGE_VAL);
    return us;
}
constexpr int64_t kRoundingNs = 1;

nlohmann::json metadata(const char* name, int pid, int tid, nlohmann::json args) {
    return {{"name", name}, {"ph", "M"},  {"ts", 0},
            {"pid", pid},   {"tid", tid}, {"args", std::move(args)}};
}

// The pass's own numbers, as report.json names them.
nlohmann::json pass_args(const PassResult& p) {
    nlohmann::json args = {{"gpu_ms", p.gpu_ms},
                           {"gpu_start_ms", p.gpu_start_ms},
                           {"vertex_shader_invocations", p.vertex_shader_invocations},
                           {"fragment_shader_invocations", p.fragment_shader_invocations},
                           {"clipping_primitives", p.clipping_primitives}};
    if (p.rasterized_fragments) args["rasterized_fragments"] = *p.rasterized_fragments;
    if (p.shaded_fragments) args["shaded_fragments"] = *p.shaded_fragments;
    if (p.discarded_fragments) args["discarded_fragments"] = *p.discarded_fragments;
    if (p.quads) args["quads"] = *p.quads;
    return args;
}

// A pass as placed: its span in whole ns and the track it went on.
struct Placed {
    const PassResult* pass = nullptr;
    int64_t begin = 0, end = 0;
    int tid = 0;
};

// The events of one process (one configuration): its tracks, spans and counters.
class ProcessEvents {
  public:
    ProcessEvents(const TraceInput& in, int pid, nlohmann::json& events)
        : in_(in), pid_(pid), events_(events) {}

    void add_run(const TraceRun& run) {
        events_.push_back(metadata("process_name", pid_, 1, {{"name", run.name}}));
        events_.push_back(metadata("process_sort_index", pid_, 1, {{"sort_index", pid_}}));
        add_settings(run, /*tid=*/1);  // the first frame's first track, made next
        for (size_t f = 0; f < run.frames.size(); ++f) add_frame(run.frames[f], f);
    }

  private:
    int new_track(const std::string& name) {
        const int tid = next_tid_++;
        events_.push_back(metadata("thread_name", pid_, tid, {{"name", name}}));
        events_.push_back(metadata("thread_sort_index", pid_, tid, {{"sort_index", tid}}));
        return tid;
    }

    // Every setting on one event a click shows (a process-scoped instant at the frame's start).
    void add_settings(const TraceRun& run, int tid) {
        nlohmann::json settings = nlohmann::json::object();
        for (const auto& [name, value] : run.settings) settings[name] = value;
        events_.push_back({{"name", "settings"},
                           {"cat", "settings"},
                           {"ph", "i"},
                           {"s", "p"},
                           {"ts", 0},
                           {"pid", pid_},
                           {"tid", tid},
                           {"args", std::move(settings)}});
    }

    // A frame's passes onto its tracks: each on the first one whose last span has ended by its
    // start (in execution order), a new track when none has. A start within 1 ns of that end is
    // rounding (start and start + gpu_ms are rounded apart; with a tick period of no whole ns
    // they can disagree by one) and becomes that end, so passes that touch on the GPU touch.
    void add_frame(const std::vector<PassResult>& passes, size_t frame) {
        const std::string track =
            in_.track_per_frame ? "frame " + std::to_string(frame + 1) : "graphics queue";
        std::vector<int64_t> track_end{INT64_MIN};
        std::vector<int> tids{new_track(track)};
        std::vector<Placed> placed;
        for (const PassResult& p : passes) {
            int64_t begin = to_ns(p.gpu_start_ms);
            const int64_t end = std::max(begin, to_ns(p.gpu_start_ms + p.gpu_ms));
            size_t t = 0;
            while (t < track_end.size() && track_end[t] > begin + kRoundingNs) ++t;
            if (t == track_end.size()) {
                track_end.push_back(INT64_MIN);
                tids.push_back(new_track(track + " overlap " + std::to_string(t + 1)));
            }
            if (track_end[t] != INT64_MIN && begin - track_end[t] <= kRoundingNs)
                begin = std::min(track_end[t], end);
            track_end[t] = end;
            placed.push_back({&p, begin, end, tids[t]});
        }
        for (const Placed& s : placed) add_span(s, frame);
        add_counters(placed, frame, tids.front());
    }

    void add_span(const Placed& s, size_t frame) {
        nlohmann::json args = pass_args(*s.pass);
        if (in_.track_per_frame) args["frame"] = frame + 1;
        events_.push_back({{"name", s.pass->name},
                           {"cat", graph::pass_role_name(s.pass->role)},
                           {"ph", "X"},
                           {"ts", to_us(s.begin)},
                           {"dur", to_us(s.end - s.begin)},
                           {"pid", pid_},
                           {"tid", s.tid},
                           {"args", std::move(args)}});
    }

    // Shaded fragments from each counted pass's start; back to 0 at its end unless the next
    // counted pass has begun by then (two values at one instant would leave the order to the
    // viewer's sort).
    void add_counters(const std::vector<Placed>& placed, size_t frame, int tid) {
        std::vector<const Placed*> counted;
        for (const Placed& s : placed)
            if (s.pass->shaded_fragments) counted.push_back(&s);
        for (size_t i = 0; i < counted.size(); ++i) {
            add_counter(counted[i]->begin, *counted[i]->pass->shaded_fragments, frame, tid);
            if (i + 1 == counted.size() || counted[i + 1]->begin > counted[i]->end)
                add_counter(counted[i]->end, 0, frame, tid);
        }
    }

    void add_counter(int64_t ns, uint64_t shaded, size_t frame, int tid) {
        nlohmann::json event = {{"name", "fragments"},
                                {"cat", "counters"},
                                {"ph", "C"},
                                {"ts", to_us(ns)},
                                {"pid", pid_},
                                {"tid", tid},
                                {"args", {{"shaded", shaded}}}};
        // Frames lie over one another: a counter each, or their values would interleave.
        if (in_.track_per_frame) event["id"] = "frame " + std::to_string(frame + 1);
        events_.push_back(std::move(event));
    }

    const TraceInput& in_;
    const int pid_;
    nlohmann::json& events_;
    int next_tid_ = 1;
};

}  // namespace

PassResult trace_pass(const PassResult& pass) {
    PassResult p;
    p.name = pass.name;
    p.role = pass.role;
    p.gpu_ms = pass.gpu_ms;
    p.gpu_start_ms = pass.gpu_start_ms;
    p.vertex_shader_invocations = pass.vertex_shader_invocations;
    p.fragment_shader_invocations = pass.fragment_shader_invocations;
    p.clipping_primitives = pass.clipping_primitives;
    p.shaded_fragments = pass.shaded_fragments;
    p.discarded_fragments = pass.discarded_fragments;
    p.rasterized_fragments = pass.rasterized_fragments;
    p.quads = pass.quads;
    return p;
}

nlohmann::json trace_json(const TraceInput& in) {
    nlohmann::json events = nlohmann::json::array();
    for (size_t r = 0; r < in.runs.size(); ++r)
        ProcessEvents(in, int(r + 1), events).add_run(in.runs[r]);
    return {{"traceEvents", std::move(events)},
            {"displayTimeUnit", "ms"},
            {"otherData",
             {{"tool", "depthscope"},
              {"command", in.command},
              {"scene", in.scene},
              {"size", {in.width, in.height}},
              {"device", in.device},
              {"time",
               "GPU timestamps, in µs: each frame's ts 0 is its first pass's begin timestamp"}}}};
}

std::string trace_text(const TraceInput& in) {
    const nlohmann::json json = trace_json(in);
    std::string text = "{\"traceEvents\": [\n";
    const nlohmann::json& events = json["traceEvents"];
    for (size_t i = 0; i < events.size(); ++i)
        text += events[i].dump() + (i + 1 < events.size() ? ",\n" : "\n");
    text += "],\n\"displayTimeUnit\": " + json["displayTimeUnit"].dump() + ",\n";
    text += "\"otherData\": " + json["otherData"].dump() + "}\n";
    return text;
}

void check_trace_device(const fs::path& path, const DeviceInfo& device) {
    if (!device.timestamps)
        throw Error("--trace " + escaped(path.string()) + ": " + device.name +
                    " has no GPU timestamps: no pass has a start or a duration to trace");
}

void check_trace_outside(const fs::path& path, const fs::path& capture_dir) {
    std::error_code error;
    const fs::path folder = fs::weakly_canonical(fs::absolute(path, error).parent_path(), error);
    fs::path dir = fs::weakly_canonical(fs::absolute(capture_dir, error), error);
    if (error) return;  // check_output_file has looked at PATH's folder already
    if (dir.filename().empty()) dir = dir.parent_path();  // "DIR/" names DIR
    const auto [d, f] = std::mismatch(dir.begin(), dir.end(), folder.begin(), folder.end());
    if (d == dir.end())
        throw UsageError("--trace " + escaped(path.string()) + ": inside the capture folder " +
                         escaped(capture_dir.string()) +
                         ", which the capture replaces whole: write the trace elsewhere");
}

void write_trace(const fs::path& path, const TraceInput& in) {
    write_file_atomically("--trace", path, trace_text(in));
}

}  // namespace ds::capture
