// sweep: a manifest's jobs as child processes into DIR/jobs/ID/, the shard's share of them, the
// merge of one or more sweep folders, and the baseline comparison (capture/sweep/, docs/sweep.md).
#include <cstdio>
#include <set>

#include "app/cli.h"
#include "app/commands.h"
#include "app/sweep_child.h"
#include "capture/file_output.h"
#include "capture/output_dir.h"
#include "capture/report.h"
#include "capture/sweep/baseline.h"
#include "capture/sweep/job_result.h"
#include "capture/sweep/manifest.h"
#include "capture/sweep/shard.h"
#include "capture/sweep/sweep_files.h"
#include "capture/sweep/sweep_report.h"
#include "renderer/common/error.h"
#include "renderer/common/quoted.h"

namespace fs = std::filesystem;

namespace ds::app {
namespace {

using namespace capture::sweep;

void warn(const std::string& warning) {
    if (!warning.empty()) std::fprintf(stderr, "depthscope: warning: %s\n", warning.c_str());
}

// What the manifest's texts mean to the command line (size, look_at), checked before any job.
void check_command_line_values(const Manifest& m) {
    const auto fail = [&](const std::string& key, const std::exception& e) {
        throw InputError(escaped(m.file.string()) + ": " + key + ": " + e.what());
    };
    try {
        (void)parse_size(m.size);
    } catch (const UsageError& e) {
        fail("size", e);
    }
    for (size_t i = 0; i < m.cameras.size(); ++i) {
        if (m.cameras[i].look_at.empty()) continue;
        try {
            (void)parse_look_at(m.cameras[i].look_at);
        } catch (const UsageError& e) {
            fail("cameras[" + std::to_string(i) + "].look_at", e);
        }
    }
}

std::optional<Shard> chosen_shard(const Options& o) {
    if (!o.sweep_shard.empty()) return parse_shard(o.sweep_shard);
    return shard_from_environment(
        process_environment(), o.sweep_shards ? std::optional<int>(o.sweep_shards) : std::nullopt);
}

// A baseline folder must hold a merged sweep before any work, and not be the one written.
void check_baseline(const Options& o) {
    if (o.sweep_baseline.empty()) return;
    if (same_folder(o.sweep_baseline, o.out))
        throw UsageError("--baseline " + escaped(o.sweep_baseline) +
                         " is the --out folder: compare with an earlier sweep's folder");
    std::error_code ec;
    if (!fs::is_regular_file(fs::path(o.sweep_baseline) / "sweep.json", ec))
        throw InputError("--baseline " + escaped(o.sweep_baseline) +
                         ": no sweep.json (a merged sweep's folder)");
}

// One job: its process into a staging folder, result.json beside its outputs, then the folder
// moved into place whole. Returns whether it passed.
bool run_job(const Job& job, const fs::path& out, size_t n, size_t total) {
    capture::OutputDir dir(job_dir(out, job.id), job_folder_content());
    const ChildExit exit =
        run_child(job_arguments(job, dir.staging_dir()), dir.staging_path("log.txt"));
    const nlohmann::json result = job_result(job, exit, dir.staging_dir());
    capture::write_json(dir.staging_path("result.json"), result);
    warn(dir.commit());
    const std::string status = result.at("status").get<std::string>();
    std::printf("sweep: %zu/%zu %s · %s: %s (%.1f s)%s%s\n", n, total, job.scene.c_str(),
                job.name().c_str(), status.c_str(), exit.seconds, status == "passed" ? "" : ": ",
                status == "passed" ? "" : escaped(result.value("message", "")).c_str());
    std::fflush(stdout);
    return status == "passed";
}

// Every job's outcome: from the first folder of `dirs` that has its result, copied into `out`.
std::vector<JobOutcome> collect(const std::vector<Job>& jobs, const std::vector<fs::path>& dirs,
                                const fs::path& out) {
    std::vector<JobOutcome> outcomes;
    for (const Job& job : jobs) {
        JobOutcome o{job, std::nullopt};
        for (const fs::path& dir : dirs) {
            o.result = read_job_result(dir, job.id);
            if (!o.result) continue;
            if (!same_folder(dir, out)) warn(copy_job(dir, out, job.id));
            break;
        }
        outcomes.push_back(std::move(o));
    }
    return outcomes;
}

// sweep.json, junit.xml and report.md of the merged jobs in `out`; the exit code.
int write_merged(const SweepManifest& m, const std::vector<fs::path>& dirs, const fs::path& out,
                 const std::string& baseline_dir) {
    const std::vector<JobOutcome> outcomes = collect(m.jobs, dirs, out);
    std::optional<BaselineReport> baseline;
    std::vector<std::string> lines;
    if (!baseline_dir.empty()) {
        baseline = compare_with_baseline(outcomes, out, baseline_dir);
        lines = baseline_lines(*baseline, outcomes);
    }
    const nlohmann::json summary = sweep_json(outcomes);
    capture::write_json_atomically("sweep.json", out / "sweep.json", summary);
    capture::write_file_atomically("junit.xml", out / "junit.xml",
                                   junit_xml(outcomes, baseline ? &*baseline : nullptr));
    capture::write_file_atomically(
        "report.md", out / "report.md",
        report_markdown(outcomes, baseline ? &*baseline : nullptr, lines));
    for (const std::string& line : lines) std::printf("sweep: baseline: %s\n", line.c_str());
    const int regressions = baseline ? baseline->regression_count() : 0;
    std::printf(
        "sweep: %zu jobs: %d passed, %d failed, %d without a result%s; wrote %s "
        "(sweep.json, junit.xml, report.md)\n",
        outcomes.size(), summary.at("passed").get<int>(), summary.at("failed").get<int>(),
        summary.at("no_result").get<int>(),
        baseline ? (", " + std::to_string(regressions) + " regressions").c_str() : "",
        escaped(out.string()).c_str());
    const bool all_passed = summary.at("passed").get<size_t>() == outcomes.size();
    return all_passed && regressions == 0 ? 0 : 1;
}

std::vector<std::string> job_ids(const std::vector<Job>& jobs) {
    std::vector<std::string> ids;
    for (const Job& job : jobs) ids.push_back(job.id);
    return ids;
}

int run_merge(const Options& o) {
    check_baseline(o);
    std::vector<fs::path> dirs;
    std::vector<std::string> without;  // folders without manifest.json
    std::optional<SweepManifest> manifest;
    for (const std::string& d : o.sweep_merge) {
        dirs.emplace_back(d);
        const std::optional<SweepManifest> m = read_sweep_manifest(d);
        if (!m)
            without.push_back(d);
        else if (!manifest)
            manifest = m;
        else if (job_ids(m->jobs) != job_ids(manifest->jobs))
            throw InputError("--merge " + escaped(d) + ": another sweep's folder (its " +
                             "manifest.json differs from the first's)");
    }
    if (!manifest) throw InputError("--merge: no folder holds a sweep's manifest.json");
    for (const std::string& d : without)
        warn("--merge " + escaped(d) + ": no manifest.json (its shard wrote nothing): its " +
             "jobs have no result unless another folder has them");
    prepare_sweep_folder(o.out, "--out");
    write_sweep_manifest(o.out, *manifest);
    return write_merged(*manifest, dirs, o.out, o.sweep_baseline);
}

}  // namespace

int run_sweep(const Options& o) {
    if (!o.sweep_merge.empty()) return run_merge(o);
    if (o.sweep_manifest.empty())
        throw UsageError("sweep needs a MANIFEST (or --merge DIR…) (see --help)");
    const Manifest manifest = read_manifest(o.sweep_manifest);
    check_command_line_values(manifest);
    const SweepManifest expanded{manifest.source, expand_jobs(manifest)};
    const std::optional<Shard> shard = chosen_shard(o);
    if (shard && !o.sweep_baseline.empty())
        throw UsageError("--baseline compares a whole sweep: give it to the merge, not to shard " +
                         std::to_string(shard->index) + "/" + std::to_string(shard->count));
    check_baseline(o);
    std::vector<std::string> ids = job_ids(expanded.jobs);
    if (shard) ids = shard_ids(ids, *shard);
    const std::set<std::string> mine(ids.begin(), ids.end());
    prepare_sweep_folder(o.out, "--out");
    write_sweep_manifest(o.out, expanded);
    if (shard)
        std::printf("sweep: shard %d/%d (%s): %zu of %zu jobs\n", shard->index, shard->count,
                    shard->source.c_str(), mine.size(), expanded.jobs.size());
    size_t n = 0, failed = 0;
    for (const Job& job : expanded.jobs)
        if (mine.count(job.id) && !run_job(job, o.out, ++n, mine.size())) ++failed;
    if (!shard) return write_merged(expanded, {fs::path(o.out)}, o.out, o.sweep_baseline);
    std::printf("sweep: shard %d/%d: %zu passed, %zu failed; merge with sweep --merge\n",
                shard->index, shard->count, n - failed, failed);
    return failed == 0 ? 0 : 1;
}

}  // namespace ds::app
