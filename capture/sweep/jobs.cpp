#include "capture/sweep/jobs.h"

#include <map>

#include "capture/sweep/sweep_files.h"
#include "renderer/common/error.h"
#include "renderer/common/quoted.h"
#include "renderer/common/sha256.h"

namespace fs = std::filesystem;
using nlohmann::json;

namespace ds::capture::sweep {
namespace {

// A .gltf's external buffers and images (relative uris, not data: ones), for the content hash.
std::vector<std::string> external_uris(const fs::path& gltf) {
    std::vector<std::string> uris;
    if (gltf.extension() != ".gltf") return uris;
    const json doc = json::parse(read_text_file(gltf), nullptr, false);
    if (!doc.is_object()) return uris;  // the job's load reports it
    for (const char* key : {"buffers", "images"}) {
        if (!doc.contains(key) || !doc.at(key).is_array()) continue;
        for (const json& entry : doc.at(key)) {
            if (!entry.is_object() || !entry.contains("uri") || !entry.at("uri").is_string())
                continue;
            const std::string uri = entry.at("uri").get<std::string>();
            if (uri.rfind("data:", 0) != 0) uris.push_back(uri);
        }
    }
    return uris;
}

// The scene file's bytes and, for a .gltf, those of each external file it names.
std::string scene_file_digest(const fs::path& path) {
    std::string text = "file " + sha256_file(path) + "\n";
    for (const std::string& uri : external_uris(path)) {
        const fs::path part = path.parent_path() / uri;
        std::error_code ec;
        text += uri + " " + (fs::is_regular_file(part, ec) ? sha256_file(part) : "missing") + "\n";
    }
    return sha256_hex(text);
}

std::string camera_key(const CameraSpec& c) {
    return !c.camera.empty()    ? "camera " + c.camera
           : !c.look_at.empty() ? "look-at " + c.look_at
                                : "scene camera";
}

json action_json(const ActionSpec& a, const std::string& config_sha256, bool with_config_path) {
    json j = {{"action", action_name(a.kind)}};
    if (a.kind == ActionKind::Capture) j["resources"] = a.resources;
    if (a.kind == ActionKind::Bench) {
        j["frames"] = a.frames;
        j["warmup"] = a.warmup;
    }
    if (a.kind == ActionKind::Lint) {
        if (!a.fail_on.empty()) j["fail_on"] = a.fail_on;
        if (!a.config.empty()) j["config_sha256"] = config_sha256;
        if (!a.config.empty() && with_config_path) j["config"] = a.config;
    }
    return j;
}

Job make_job(const SceneSpec& scene, const std::string& scene_sha256, const CameraSpec& camera,
             const SettingSet& settings, const ActionSpec& action, const Manifest& m) {
    Job job;
    job.scene = scene.given;
    job.scene_sha256 = scene_sha256;
    job.scene_path = scene.path;
    job.camera = camera;
    job.settings = settings;
    job.action = action;
    if (!action.config.empty()) job.config_sha256 = sha256_file(action.config_path);
    if (action.kind != ActionKind::Lint) job.size = m.size;
    job.validate = m.validate && action.kind != ActionKind::Lint;
    job.id = sha256_hex(job.identity_json().dump()).substr(0, 16);
    return job;
}

void add_set_arguments(const Job& job, std::vector<std::string>& args) {
    for (const auto& [name, value] : job.settings) {
        args.push_back("--set");
        args.push_back(name + "=" + value);
    }
    if (!job.camera.camera.empty()) args.insert(args.end(), {"--camera", job.camera.camera});
    if (!job.camera.look_at.empty()) args.insert(args.end(), {"--look-at", job.camera.look_at});
}

}  // namespace

std::string Job::camera_label() const {
    return camera_key(camera);
}

std::string Job::settings_label() const {
    std::string out;
    for (const auto& [name, value] : settings) out += (out.empty() ? "" : " ") + name + "=" + value;
    return out.empty() ? "defaults" : out;
}

std::string Job::name() const {
    return camera_label() + " · " + settings_label() + " · " + action_name(action.kind);
}

json Job::identity_json() const {
    json settings_json = json::object();
    for (const auto& [name, value] : settings) settings_json[name] = value;
    return {{"scene_sha256", scene_sha256},
            {"camera", camera_key(camera)},
            {"settings", settings_json},
            {"action", action_json(action, config_sha256, false)},
            {"size", size},
            {"validate", validate}};
}

std::vector<Job> expand_jobs(const Manifest& m) {
    std::vector<Job> jobs;
    std::map<std::string, std::string> seen;  // id -> the first job's description
    for (const SceneSpec& scene : m.scenes) {
        const std::string digest =
            scene.builtin ? sha256_hex("builtin:" + scene.given) : scene_file_digest(scene.path);
        for (const CameraSpec& camera : m.cameras)
            for (const SettingSet& settings : m.settings)
                for (const ActionSpec& action : m.actions) {
                    Job job = make_job(scene, digest, camera, settings, action, m);
                    const std::string what = scene.given + " · " + job.name();
                    const auto [it, added] = seen.emplace(job.id, what);
                    if (!added)
                        throw InputError(escaped(m.file.string()) + ": " + quote(what) + " and " +
                                         quote(it->second) + " are the same job");
                    jobs.push_back(std::move(job));
                }
    }
    return jobs;
}

json job_json(const Job& job) {
    json j = {{"id", job.id},
              {"scene", job.scene},
              {"scene_sha256", job.scene_sha256},
              {"camera", {{"camera", job.camera.camera}, {"look_at", job.camera.look_at}}},
              {"settings", job.settings},
              {"action", action_json(job.action, job.config_sha256, true)},
              {"size", job.size},
              {"validate", job.validate}};
    return j;
}

Job job_from_json(const json& j, const std::string& where) {
    try {
        Job job;
        job.id = j.at("id").get<std::string>();
        job.scene = j.at("scene").get<std::string>();
        job.scene_sha256 = j.at("scene_sha256").get<std::string>();
        job.camera.camera = j.at("camera").at("camera").get<std::string>();
        job.camera.look_at = j.at("camera").at("look_at").get<std::string>();
        job.settings = j.at("settings").get<SettingSet>();
        const json& a = j.at("action");
        const std::string kind = a.at("action").get<std::string>();
        job.action.kind = kind == "bench"  ? ActionKind::Bench
                          : kind == "lint" ? ActionKind::Lint
                                           : ActionKind::Capture;
        job.action.resources = a.value("resources", "none");
        job.action.frames = a.value("frames", 5);
        job.action.warmup = a.value("warmup", 1);
        job.action.fail_on = a.value("fail_on", "");
        job.action.config = a.value("config", "");
        job.config_sha256 = a.value("config_sha256", "");
        job.size = j.at("size").get<std::string>();
        job.validate = j.at("validate").get<bool>();
        return job;
    } catch (const json::exception& e) {
        throw Error(escaped(where) + ": not a sweep job: " + e.what());
    }
}

std::vector<std::string> job_arguments(const Job& job, const fs::path& dir) {
    const std::string scene = job.scene_path.empty() ? job.scene : job.scene_path.string();
    std::vector<std::string> args;
    switch (job.action.kind) {
        case ActionKind::Capture:
            args = {"capture",
                    "--scene",
                    scene,
                    "--size",
                    job.size,
                    "--resources",
                    job.action.resources,
                    "--out",
                    (dir / "capture").string()};
            break;
        case ActionKind::Bench:
            args = {"bench",
                    "--scene",
                    scene,
                    "--size",
                    job.size,
                    "--frames",
                    std::to_string(job.action.frames),
                    "--warmup",
                    std::to_string(job.action.warmup),
                    "--json",
                    (dir / "bench.json").string()};
            break;
        case ActionKind::Lint:
            args = {"lint", scene, "--json", (dir / "lint.json").string()};
            if (!job.action.config.empty())
                args.insert(args.end(), {"--config", job.action.config_path.string()});
            if (!job.action.fail_on.empty())
                args.insert(args.end(), {"--fail-on", job.action.fail_on});
            break;
    }
    if (job.validate) args.push_back("--validate");
    add_set_arguments(job, args);
    return args;
}

}  // namespace ds::capture::sweep
