#pragma once
// A sweep's jobs (docs/sweep.md): the manifest expanded to scenes x cameras x setting sets x
// actions, each with an ID that hashes what the job computes (the scene's content, the camera,
// the sorted settings, the action and its options, the size), not where it sits in the
// manifest; and the command line of `depthscope` that runs it.
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "capture/sweep/manifest.h"

namespace ds::capture::sweep {

struct Job {
    std::string id;            // 16 hex digits of the SHA-256 of identity_json()
    std::string scene;         // as the manifest gives it
    std::string scene_sha256;  // a file's bytes (and its glTF's external files); a built-in: of
                               // "builtin:NAME"
    std::filesystem::path scene_path;  // a file's resolved path ("" for a built-in; not stored)
    CameraSpec camera;
    SettingSet settings;
    ActionSpec action;
    std::string config_sha256;  // lint --config's bytes ("" without one)
    std::string size;           // capture and bench ("" for lint, which takes none)
    bool validate = false;

    std::string camera_label() const;    // "scene camera", "camera 2", "look-at 0,1,8:0,1,0"
    std::string settings_label() const;  // "prepass=off msaa=4", "defaults"
    // "camera · settings · action": a JUnit test case's name (its class is the scene).
    std::string name() const;
    // What the ID hashes.
    nlohmann::json identity_json() const;
};

// Every job of the manifest in its order (scenes, then cameras, setting sets, actions). Hashes
// each scene file once. Throws InputError naming the manifest when two entries make one job.
std::vector<Job> expand_jobs(const Manifest& manifest);

// The stored form (manifest.json's "jobs"): everything but the resolved paths. job_from_json
// throws Error "WHERE: …" on a malformed entry.
nlohmann::json job_json(const Job& job);
Job job_from_json(const nlohmann::json& json, const std::string& where);

// `depthscope` arguments (after the executable) that run `job` with its outputs in `dir`:
// capture into DIR/capture/, bench --json DIR/bench.json, lint --json DIR/lint.json. Needs
// the resolved paths (a job expanded from a manifest, not one read back).
std::vector<std::string> job_arguments(const Job& job, const std::filesystem::path& dir);

}  // namespace ds::capture::sweep
