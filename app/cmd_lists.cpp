// The listing commands: info, scenes, settings.
#include <algorithm>
#include <cstdio>
#include <string>

#include "app/commands.h"
#include "renderer/device_info.h"
#include "renderer/scene/builtin/builtin.h"
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
