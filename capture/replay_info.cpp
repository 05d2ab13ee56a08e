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

// `field` of `c` into `out`; false when it is not `N` numbers (N = 1: a number).
template <int N>
bool read_numbers(const nlohmann::json& c, const char* field, float* out) {
    const nlohmann::json& j = c.value(field, nlohmann::json());
    if (N == 1) {
        if (!j.is_number()) return false;
        *out = j.get<float>();
        return true;
    }
    if (!j.is_array() || j.size() != N) return false;
    for (size_t i = 0; i < N; ++i) {
        if (!j[i].is_number()) return false;
        out[i] = j[i].get<float>();
    }
    return true;
}

}  // namespace

nlohmann::json camera_json(const scene::Camera& camera) {
    return {{"position", vec3(camera.position)},
            {"forward", vec3(camera.forward)},
            {"up", vec3(camera.up)},
            {"yfov", double(camera.yfov)},
            {"znear", double(camera.znear)},
            {"zfar", double(camera.zfar)}};
}

std::optional<std::string> read_camera(const nlohmann::json& c, scene::Camera& out) {
    if (!c.is_object()) return "is not an object";
    for (auto [field, target] :
         {std::pair{"position", &out.position}, {"forward", &out.forward}, {"up", &out.up}})
        if (!read_numbers<3>(c, field, &(*target)[0]))
            return std::string(field) + " is not three numbers";
    for (auto [field, target] :
         {std::pair{"yfov", &out.yfov}, {"znear", &out.znear}, {"zfar", &out.zfar}})
        if (!read_numbers<1>(c, field, target)) return std::string(field) + " is not a number";
    return std::nullopt;
}

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
    return {{"scene", source}, {"camera", camera_json(camera)}};
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
    if (const std::optional<std::string> why = read_camera(c, info.camera))
        bad(path, "replay.camera." + *why);
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
