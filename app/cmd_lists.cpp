// The listing commands: info, scenes, cameras, settings.
#include <algorithm>
#include <cstdio>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "app/commands.h"
#include "app/scene_load.h"
#include "renderer/common/quoted.h"
#include "renderer/device_info.h"
#include "renderer/scene/builtin/builtin.h"
#include "renderer/scene/loader.h"
#include "renderer/settings/settings.h"

namespace ds::app {

int run_info(const Options& options) {
    // A --device request that matches nothing throws; with no suitable device all are listed.
    for (const ListedDevice& d : list_devices(options.device))
        std::printf("%s%s\n", d.selected ? "[selected] " : "", d.description.c_str());
    return 0;
}

int run_scenes() {
    for (const auto& s : scene::builtin::list()) {
        std::printf("%-10s %s\n", s.name.c_str(), s.description.c_str());
    }
    return 0;
}

namespace {

// "0.1", "1000", "infinite" (a perspective camera without zfar)
std::string plane_text(float value, bool infinite) {
    if (infinite) return "infinite";
    char text[32];
    std::snprintf(text, sizeof text, "%g", double(value));
    return text;
}

}  // namespace

int run_cameras(const Options& o) {
    Settings settings;
    for (const auto& assignment : o.sets) settings.apply(assignment);
    const scene::Scene scene = load_command_scene(o, o.scene, settings);
    if (scene.cameras.empty()) {
        std::printf("%s has no camera nodes (its view is framed from the scene's bounds)\n",
                    scene.name.c_str());
        return 0;
    }
    std::vector<std::string> names;  // one line each, whatever the file holds
    size_t name_w = 4;
    for (const scene::SceneCamera& c : scene.cameras) {
        names.push_back(c.name.empty() ? "-" : escaped(c.name));
        name_w = std::max(name_w, names.back().size());
    }
    std::printf("%-5s  %-*s  %-12s  %6s  %-10s  %-10s  %s\n", "INDEX", int(name_w), "NAME", "TYPE",
                "YFOV", "ZNEAR", "ZFAR", "NODE");
    for (size_t i = 0; i < scene.cameras.size(); ++i) {
        const scene::SceneCamera& c = scene.cameras[i];
        const bool perspective = c.type == scene::SceneCamera::Type::Perspective;
        char fov[32] = "-";
        if (perspective) std::snprintf(fov, sizeof fov, "%.2f", double(glm::degrees(c.yfov)));
        std::printf("%-5zu  %-*s  %-12s  %6s  %-10s  %-10s  %d%s\n", i, int(name_w),
                    names[i].c_str(), scene::to_string(c.type), fov,
                    plane_text(c.znear, false).c_str(),
                    plane_text(c.zfar, perspective && c.zfar == 0.0f).c_str(), c.gltf_node,
                    perspective && !c.camera ? " (no view direction)" : "");
    }
    return 0;
}

int run_settings() {
    // Columns as wide as their widest entry, so long ranges never push the help text.
    const auto& defs = SettingsRegistry::instance().all();
    size_t name_w = 4, default_w = 7, range_w = 5;
    for (const auto& d : defs) {
        name_w = std::max(name_w, d.name.size());
        default_w = std::max(default_w, d.default_value.size());
        range_w = std::max(range_w, d.range_text().size());
    }
    auto row = [&](const std::string& name, const std::string& type, const std::string& def,
                   const std::string& range, const std::string& help) {
        std::printf("%-*s  %-5s  %-*s  %-*s  %s\n", int(name_w), name.c_str(), type.c_str(),
                    int(default_w), def.c_str(), int(range_w), range.c_str(), help.c_str());
    };
    row("NAME", "TYPE", "DEFAULT", "RANGE", "HELP");
    for (const auto& d : defs) {
        row(d.name, d.type_name(), d.default_value, d.range_text(), d.help);
    }
    return 0;
}

}  // namespace ds::app
