#include "capture/replay_info.h"

#include "renderer/common/error.h"
#include "renderer/common/quoted.h"
#include "renderer/common/sha256.h"

namespace ds::capture {
namespace {

constexpr const char* kBuiltinPrefix = "builtin:";

nlohmann::json vec3(const glm::vec3& v) {
    return {double(v.x), double(v.y), double(v.z)};
}

// The knobs a built-in scene is built from (registry: Invalidates::Scene).
nlohmann::json shaping_knobs(const Settings& settings) {
    nlohmann::json out = nlohmann::json::object();
    for (const SettingDef& def : SettingsRegistry::instance().all())
        if (def.invalidates == Invalidates::Scene) out[def.name] = settings.get(def.name);
    return out;
}

[[noreturn]] void bad(const std::filesystem::path& path, const std::string& why) {
    throw Error(escaped(path.string()) + ": " + why);
}

glm::vec3 read_vec3(const nlohmann::json& j, const std::filesystem::path& path, const char* what) {
    if (!j.is_array() || j.size() != 3 || !j[0].is_number() || !j[1].is_number() ||
        !j[2].is_number())
        bad(path, std::string("replay.camera.") + what + " is not three numbers");
    return {j[0].get<float>(), j[1].get<float>(), j[2].get<float>()};
}

float read_float(const nlohmann::json& j, const std::filesystem::path& path, const char* what) {
    if (!j.is_number()) bad(path, std::string("replay.camera.") + what + " is not a number");
    return j.get<float>();
}

}  // namespace

nlohmann::json replay_json(const scene::Scene& scene, const scene::Camera& camera,
                           const Settings& settings) {
    nlohmann::json source;
    if (scene.source.rfind(kBuiltinPrefix, 0) == 0) {
        source = {{"builtin", scene.source.substr(std::string(kBuiltinPrefix).size())},
                  {"shaped_by", shaping_knobs(settings)}};
    } else {
        const std::filesystem::path file = std::filesystem::absolute(scene.source);
        source = {{"file", file.string()}, {"sha256", sha256_file(file)}};
    }
    return {{"scene", source},
            {"camera",
             {{"position", vec3(camera.position)},
              {"forward", vec3(camera.forward)},
              {"up", vec3(camera.up)},
              {"yfov", double(camera.yfov)},
              {"znear", double(camera.znear)},
              {"zfar", double(camera.zfar)}}}};
}

ReplayInfo parse_replay(const nlohmann::json& report, const std::filesystem::path& path) {
    if (!report.is_object() || report.value("tool", "") != "depthscope")
        bad(path, "not a depthscope report");
    const auto* replay = report.contains("replay") ? &report["replay"] : nullptr;
    if (!replay || !replay->is_object() || !report.contains("version") ||
        !report["version"].is_string())
        bad(path, "no replay information (a capture of an older depthscope?)");
    ReplayInfo info;
    info.version = report["version"];
    const nlohmann::json& source = replay->value("scene", nlohmann::json());
    if (source.contains("builtin") && source["builtin"].is_string()) {
        info.builtin = source["builtin"];
    } else if (source.contains("file") && source["file"].is_string() && source.contains("sha256") &&
               source["sha256"].is_string()) {
        info.file = source["file"].get<std::string>();
        info.sha256 = source["sha256"];
    } else {
        bad(path, "replay.scene names neither a built-in scene nor a file with its sha256");
    }
    const nlohmann::json& c = replay->value("camera", nlohmann::json());
    if (!c.is_object()) bad(path, "replay.camera is missing");
    info.camera.position = read_vec3(c.value("position", nlohmann::json()), path, "position");
    info.camera.forward = read_vec3(c.value("forward", nlohmann::json()), path, "forward");
    info.camera.up = read_vec3(c.value("up", nlohmann::json()), path, "up");
    info.camera.yfov = read_float(c.value("yfov", nlohmann::json()), path, "yfov");
    info.camera.znear = read_float(c.value("znear", nlohmann::json()), path, "znear");
    info.camera.zfar = read_float(c.value("zfar", nlohmann::json()), path, "zfar");
    const nlohmann::json& size = report.value("size", nlohmann::json());
    if (!size.is_object() || !size.value("width", nlohmann::json()).is_number_unsigned() ||
        !size.value("height", nlohmann::json()).is_number_unsigned())
        bad(path, "size is missing");
    info.width = size["width"];
    info.height = size["height"];
    const nlohmann::json& settings = report.value("settings", nlohmann::json());
    if (!settings.is_object()) bad(path, "settings are missing");
    for (const auto& [name, value] : settings.items()) {
        if (!value.is_string()) bad(path, "settings." + name + " is not a string");
        info.settings.push_back(name + "=" + value.get<std::string>());
    }
    return info;
}

}  // namespace ds::capture
