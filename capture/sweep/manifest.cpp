#include "capture/sweep/manifest.h"

#include "capture/sweep/sweep_files.h"
#include "renderer/common/error.h"
#include "renderer/common/quoted.h"
#include "renderer/scene/builtin/builtin.h"
#include "renderer/settings/settings.h"

namespace fs = std::filesystem;
using nlohmann::json;

namespace ds::capture::sweep {
namespace {

// Throws "MANIFEST: KEY: WHY".
class Reader {
  public:
    explicit Reader(const fs::path& file) : file_(file), base_(file.parent_path()) {}

    [[noreturn]] void fail(const std::string& key, const std::string& why) const {
        throw InputError(escaped(file_.string()) + ": " + escaped(key) + ": " + why);
    }

    // Every key of `object` must be one of `known`.
    void only_keys(const json& object, const std::string& at,
                   std::initializer_list<const char*> known) const {
        for (const auto& [key, value] : object.items()) {
            bool ok = false;
            for (const char* k : known) ok = ok || key == k;
            if (!ok) fail(at.empty() ? key : at + "." + key, "unknown key");
        }
    }

    const json& array_of(const json& doc, const char* key, bool required) const {
        static const json kEmpty = json::array();
        if (!doc.contains(key)) {
            if (required) fail(key, "missing (a non-empty array)");
            return kEmpty;
        }
        const json& a = doc.at(key);
        if (!a.is_array() || a.empty()) fail(key, "expects a non-empty array");
        return a;
    }

    std::string text(const json& value, const std::string& key) const {
        if (!value.is_string() || value.get<std::string>().empty())
            fail(key, "expects a non-empty string, got " + value.dump());
        return value.get<std::string>();
    }

    fs::path resolve(const std::string& given) const {
        const fs::path p(given);
        return p.is_absolute() || base_.empty() ? p : base_ / p;
    }

    const fs::path& file() const { return file_; }

  private:
    fs::path file_, base_;
};

std::string key_at(const char* array, size_t i) {
    return std::string(array) + "[" + std::to_string(i) + "]";
}

SceneSpec read_scene(const Reader& r, const json& value, const std::string& key) {
    SceneSpec s;
    s.given = r.text(value, key);
    if (scene::builtin::exists(s.given)) {
        s.builtin = true;
        return s;
    }
    s.path = r.resolve(s.given);
    std::error_code ec;
    if (!fs::is_regular_file(s.path, ec))
        r.fail(key, quote(s.given) + " is neither a built-in scene (see `depthscope scenes`) " +
                        "nor a file (" + escaped(s.path.string()) + ": no such file)");
    return s;
}

CameraSpec read_camera(const Reader& r, const json& value, const std::string& key) {
    if (!value.is_object())
        r.fail(key, "expects an object: {}, {\"camera\": …} or {\"look_at\": …}");
    r.only_keys(value, key, {"camera", "look_at"});
    CameraSpec c;
    if (value.contains("camera")) {
        const json& v = value.at("camera");
        c.camera =
            v.is_number_unsigned() ? std::to_string(v.get<uint64_t>()) : r.text(v, key + ".camera");
    }
    if (value.contains("look_at")) c.look_at = r.text(value.at("look_at"), key + ".look_at");
    if (!c.camera.empty() && !c.look_at.empty())
        r.fail(key, "camera and look_at exclude each other");
    return c;
}

// A JSON scalar as a setting's text: strings as they are, booleans on/off, numbers.
std::string setting_text(const Reader& r, const json& value, const std::string& key) {
    if (value.is_string()) return value.get<std::string>();
    if (value.is_boolean()) return value.get<bool>() ? "on" : "off";
    if (value.is_number_integer()) return value.dump();
    if (value.is_number_float()) return value.dump();
    r.fail(key, "expects a string, number or boolean, got " + value.dump());
}

// One setting set, checked against the settings registry and canonicalised.
SettingSet read_setting_set(const Reader& r, const json& value, const std::string& key,
                            const SettingSet& common) {
    if (!value.is_object()) r.fail(key, "expects an object of setting: value");
    Settings check;
    SettingSet out = common;
    for (const auto& [name, v] : value.items()) {
        const std::string at = key.empty() ? name : key + "." + name;
        try {
            check.set(name, setting_text(r, v, at));
        } catch (const UsageError& e) {
            r.fail(at, e.what());
        }
        out[name] = check.get(name);
    }
    return out;
}

int read_count(const Reader& r, const json& v, const std::string& key, int min, int max) {
    if (!v.is_number_integer() || v.get<int64_t>() < min || v.get<int64_t>() > max)
        r.fail(key, "expects a whole number in " + std::to_string(min) + ".." +
                        std::to_string(max) + ", got " + v.dump());
    return int(v.get<int64_t>());
}

ActionKind action_kind(const Reader& r, const std::string& name, const std::string& key) {
    if (name == "capture") return ActionKind::Capture;
    if (name == "bench") return ActionKind::Bench;
    if (name == "lint") return ActionKind::Lint;
    r.fail(key, "expects capture, bench or lint, got " + quote(name));
}

void read_action_options(const Reader& r, const json& v, const std::string& key, ActionSpec& a) {
    if (a.kind == ActionKind::Capture) {
        r.only_keys(v, key, {"action", "resources"});
        if (v.contains("resources")) a.resources = r.text(v.at("resources"), key + ".resources");
    } else if (a.kind == ActionKind::Bench) {
        r.only_keys(v, key, {"action", "frames", "warmup"});
        if (v.contains("frames"))
            a.frames = read_count(r, v.at("frames"), key + ".frames", 1, 100000);
        if (v.contains("warmup"))
            a.warmup = read_count(r, v.at("warmup"), key + ".warmup", 0, 100000);
    } else {
        r.only_keys(v, key, {"action", "fail_on", "config"});
        if (v.contains("fail_on")) {
            a.fail_on = r.text(v.at("fail_on"), key + ".fail_on");
            if (a.fail_on != "error" && a.fail_on != "warning" && a.fail_on != "info")
                r.fail(key + ".fail_on", "expects error, warning or info, got " + quote(a.fail_on));
        }
        if (v.contains("config")) {
            a.config = r.text(v.at("config"), key + ".config");
            a.config_path = r.resolve(a.config);
            std::error_code ec;
            if (!fs::is_regular_file(a.config_path, ec))
                r.fail(key + ".config", escaped(a.config_path.string()) + ": no such file");
        }
    }
}

// "capture", or {"action": "bench", "frames": 5, …}.
ActionSpec read_action(const Reader& r, const json& value, const std::string& key) {
    ActionSpec a;
    if (value.is_string()) {
        a.kind = action_kind(r, value.get<std::string>(), key);
        return a;
    }
    if (!value.is_object() || !value.contains("action"))
        r.fail(key, "expects capture, bench, lint or an object with \"action\"");
    a.kind = action_kind(r, r.text(value.at("action"), key + ".action"), key + ".action");
    read_action_options(r, value, key, a);
    return a;
}

bool read_bool(const Reader& r, const json& doc, const char* key) {
    if (!doc.contains(key)) return false;
    if (!doc.at(key).is_boolean()) r.fail(key, "expects true or false");
    return doc.at(key).get<bool>();
}

void read_lists(const Reader& r, const json& doc, Manifest& m) {
    const json& scenes = r.array_of(doc, "scenes", true);
    for (size_t i = 0; i < scenes.size(); ++i)
        m.scenes.push_back(read_scene(r, scenes[i], key_at("scenes", i)));
    const json& cameras = r.array_of(doc, "cameras", false);
    for (size_t i = 0; i < cameras.size(); ++i)
        m.cameras.push_back(read_camera(r, cameras[i], key_at("cameras", i)));
    if (m.cameras.empty()) m.cameras.emplace_back();
    SettingSet common;
    if (doc.contains("common_settings"))
        common = read_setting_set(r, doc.at("common_settings"), "common_settings", {});
    const json& sets = r.array_of(doc, "settings", false);
    for (size_t i = 0; i < sets.size(); ++i)
        m.settings.push_back(read_setting_set(r, sets[i], key_at("settings", i), common));
    if (m.settings.empty()) m.settings.push_back(common);
    const json& actions = r.array_of(doc, "actions", true);
    for (size_t i = 0; i < actions.size(); ++i)
        m.actions.push_back(read_action(r, actions[i], key_at("actions", i)));
}

}  // namespace

const char* action_name(ActionKind kind) {
    switch (kind) {
        case ActionKind::Capture:
            return "capture";
        case ActionKind::Bench:
            return "bench";
        case ActionKind::Lint:
            return "lint";
    }
    return "?";
}

Manifest parse_manifest(std::string_view text, const fs::path& file) {
    const Reader r(file);
    Manifest m;
    m.file = file;
    m.source = json::parse(text, nullptr, /*allow_exceptions=*/false);
    if (m.source.is_discarded()) throw InputError(escaped(file.string()) + ": not valid JSON");
    if (!m.source.is_object()) throw InputError(escaped(file.string()) + ": expects a JSON object");
    r.only_keys(
        m.source, "",
        {"scenes", "cameras", "settings", "common_settings", "actions", "size", "validate"});
    read_lists(r, m.source, m);
    if (m.source.contains("size")) m.size = r.text(m.source.at("size"), "size");
    m.validate = read_bool(r, m.source, "validate");
    return m;
}

Manifest read_manifest(const fs::path& file) {
    return parse_manifest(read_text_file(file), file);
}

}  // namespace ds::capture::sweep
