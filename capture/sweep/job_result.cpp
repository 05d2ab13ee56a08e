#include "capture/sweep/job_result.h"

#include <csignal>
#include <cstring>

#include "capture/sweep/sweep_files.h"
#include "renderer/common/error.h"

namespace fs = std::filesystem;
using nlohmann::json;

namespace ds::capture::sweep {
namespace {

// The process's error line from its log ("depthscope: error: …"), else its last line.
std::string log_message(const fs::path& log) {
    std::string text;
    try {
        text = read_text_file(log);
    } catch (const Error&) {
        return "";
    }
    std::string last, error;
    size_t start = 0;
    while (start < text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        const std::string line = text.substr(start, end - start);
        if (!line.empty()) last = line;
        if (line.rfind("depthscope: error: ", 0) == 0) error = line;
        start = end + 1;
    }
    return error.empty() ? last : error;
}

json pass_counts(const json& passes) {
    json out = json::object();
    if (!passes.is_array()) return out;
    for (const json& pass : passes) {
        if (!pass.is_object() || !pass.contains("name")) continue;
        json counts = json::object();
        for (const char* key : {"rasterized_fragments", "shaded_fragments", "discarded_fragments"})
            if (pass.contains(key)) counts[key] = pass.at(key);
        if (counts.empty()) continue;
        std::string name = pass.at("name").is_string() ? pass.at("name").get<std::string>() : "?";
        for (int n = 2; out.contains(name); ++n)
            name = pass.at("name").get<std::string>() + "#" + std::to_string(n);
        out[name] = counts;
    }
    return out;
}

// What the action wrote, folded into `result`; throws Error when it is missing or unreadable.
void read_outputs(const Job& job, const fs::path& dir, json& result) {
    switch (job.action.kind) {
        case ActionKind::Capture: {
            const json report = read_json_file(dir / "capture" / "report.json");
            result["outputs"] = {{"final", "capture/final.png"}, {"report", "capture/report.json"}};
            result["device"] = report.value("device", json::object());
            result["counts"] = report_counts(report);
            break;
        }
        case ActionKind::Bench: {
            const json bench = read_json_file(dir / "bench.json");
            const json& run = bench.at("runs").at(0);
            json passes = json::object();
            for (const json& pass : run.at("passes"))
                passes[pass.at("name").get<std::string>()] = pass.at("gpu_ms").at("median");
            result["outputs"] = {{"bench", "bench.json"}};
            result["timings"] = {{"frame_ms", run.at("frame_ms")}, {"pass_gpu_ms_median", passes}};
            break;
        }
        case ActionKind::Lint: {
            const json lint = read_json_file(dir / "lint.json");
            json issues = json::object();
            for (const char* key : {"numErrors", "numWarnings", "numInfos", "numHints"})
                issues[key] = lint.at("issues").at(key);
            result["outputs"] = {{"lint", "lint.json"}};
            result["lint"] = issues;
            break;
        }
    }
}

std::string exit_text(const ChildExit& exit) {
    if (exit.signal != 0) {
        const char* name = sigabbrev_np(exit.signal);
        return std::string("killed by SIG") + (name ? name : std::to_string(exit.signal).c_str());
    }
    return "exit code " + std::to_string(exit.exit_code);
}

}  // namespace

json report_counts(const json& report) {
    json counts = json::object();
    if (!report.is_object()) return counts;
    const json passes = pass_counts(report.value("passes", json()));
    if (!passes.empty()) counts["passes"] = passes;
    for (const char* section : {"zfight", "equal_check"})
        if (report.contains(section)) counts[section] = report.at(section);
    return counts;
}

json job_result(const Job& job, const ChildExit& exit, const fs::path& dir) {
    json result = {{"id", job.id},
                   {"scene", job.scene},
                   {"name", job.name()},
                   {"action", action_name(job.action.kind)},
                   {"seconds", exit.seconds}};
    if (exit.signal != 0)
        result["signal"] = exit.signal;
    else
        result["exit_code"] = exit.exit_code;
    std::string failure;
    // A lint that found issues at --fail-on still wrote its JSON: read it either way.
    if (exit.signal == 0 && (exit.exit_code == 0 || job.action.kind == ActionKind::Lint)) {
        try {
            read_outputs(job, dir, result);
        } catch (const std::exception& e) {
            failure = std::string("its output: ") + e.what();
        }
    }
    if (exit.signal != 0 || exit.exit_code != 0) {
        // The staging folder's name holds the sweep's PID: the message names the job's folder,
        // so that a failure reads the same from every run (sweep.json compares byte for byte).
        std::string line = log_message(dir / "log.txt");
        const std::string staging = dir.string();
        for (size_t at = line.find(staging); !staging.empty() && at != std::string::npos;
             at = line.find(staging, at))
            line.replace(at, staging.size(), "jobs/" + job.id);
        failure = exit_text(exit) + (line.empty() ? "" : ": " + line);
        // lint's exit 1 with its report read: the findings at --fail-on are the reason.
        if (exit.signal == 0 && exit.exit_code == 1 && result.contains("lint"))
            failure = "lint: " + std::to_string(result["lint"].value("numErrors", 0)) +
                      " errors, " + std::to_string(result["lint"].value("numWarnings", 0)) +
                      " warnings, " + std::to_string(result["lint"].value("numInfos", 0)) +
                      " infos at --fail-on " +
                      (job.action.fail_on.empty() ? "error" : job.action.fail_on) + " (lint.json)";
    }
    result["status"] = failure.empty() ? "passed" : "failed";
    if (!failure.empty()) result["message"] = failure;
    return result;
}

std::vector<std::string> json_differences(const json& a, const json& b, const std::string& path) {
    std::vector<std::string> out;
    const auto where = [&](const std::string& key) {
        return path.empty() ? key : path + "." + key;
    };
    if (a.is_object() && b.is_object()) {
        for (const auto& [key, value] : a.items()) {
            const auto d =
                json_differences(value, b.contains(key) ? b.at(key) : json(), where(key));
            out.insert(out.end(), d.begin(), d.end());
        }
        for (const auto& [key, value] : b.items())
            if (!a.contains(key)) out.push_back(where(key) + ": absent -> " + value.dump());
        return out;
    }
    if (a.is_array() && b.is_array() && a.size() != b.size()) {
        out.push_back(path + ": " + std::to_string(a.size()) + " entries -> " +
                      std::to_string(b.size()));
        return out;
    }
    if (a.is_array() && b.is_array()) {
        for (size_t i = 0; i < a.size(); ++i) {
            const auto d = json_differences(a[i], b[i], path + "[" + std::to_string(i) + "]");
            out.insert(out.end(), d.begin(), d.end());
        }
        return out;
    }
    if (a != b)
        out.push_back(path + ": " + (a.is_null() ? "absent" : a.dump()) + " -> " +
                      (b.is_null() ? "absent" : b.dump()));
    return out;
}

}  // namespace ds::capture::sweep
