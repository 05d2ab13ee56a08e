#pragma once
// A sweep's folder on disk (docs/sweep.md "Output"): DIR/manifest.json (the manifest and its
// expansion), DIR/jobs/ID/ (one job's result.json, log.txt and its action's outputs, each
// folder moved into place whole by an OutputDir), and the merged files (sweep.json, junit.xml,
// report.md). Everything is written whole or not at all (file_output.h, output_dir.h).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "capture/output_dir.h"
#include "capture/sweep/jobs.h"

namespace ds::capture::sweep {

// A regular file's bytes (at most 64 MiB). Throws InputError "PATH: …".
std::string read_text_file(const std::filesystem::path& path);
// A JSON document from a regular file. Throws InputError "PATH: …".
nlohmann::json read_json_file(const std::filesystem::path& path);

// What a job folder holds (result.json, log.txt, capture/, bench.json, lint.json): the only
// content an existing DIR/jobs/ID/ may have to be replaced by a new run of the job.
ReplaceableContent job_folder_content();

// Before any work: DIR is absent or a folder holding only a sweep's files (manifest.json,
// jobs/, sweep.json, junit.xml, report.md and their temporary files); then makes DIR/jobs/.
// Throws Error "DIR: …" (`option` names it: "--out").
void prepare_sweep_folder(const std::filesystem::path& dir, const std::string& option);

// DIR/manifest.json: {"tool", "manifest": the document, "jobs": [job_json…]}.
struct SweepManifest {
    nlohmann::json manifest;
    std::vector<Job> jobs;
};
void write_sweep_manifest(const std::filesystem::path& dir, const SweepManifest& m);
// nullopt when DIR/manifest.json does not exist; throws InputError when it is not one.
std::optional<SweepManifest> read_sweep_manifest(const std::filesystem::path& dir);

std::filesystem::path job_dir(const std::filesystem::path& dir, const std::string& id);
// DIR/jobs/ID/result.json, nullopt when the job has no result there (never ran, or killed
// before its folder was moved into place). Throws InputError for an unreadable one.
std::optional<nlohmann::json> read_job_result(const std::filesystem::path& dir,
                                              const std::string& id);
// FROM/jobs/ID/ copied to TO/jobs/ID/ whole (hard links where the file system allows).
// Returns OutputDir::commit's warning ("" or the old files' leftover folder).
[[nodiscard]] std::string copy_job(const std::filesystem::path& from,
                                   const std::filesystem::path& to, const std::string& id);
// Are two paths the same folder (both existing).
bool same_folder(const std::filesystem::path& a, const std::filesystem::path& b);

}  // namespace ds::capture::sweep
