// The listing commands: info, scenes, settings.
#include <cstdio>

#include "app/commands.h"
#include "renderer/common/error.h"
#include "renderer/scene/builtin/builtin.h"
#include "renderer/settings/settings.h"
#include "renderer/vk/capabilities.h"

namespace ds::app {

int run_info(const Options& options) {
    const auto reports = vk::probe_all_devices();
    std::vector<vk::DeviceCandidate> candidates;
    for (const auto& r : reports) candidates.push_back(r.candidate);
    // The same rule the renderer uses. With no suitable device, still list them all (each says
    // why it was refused); a --device request that matches nothing stays an error.
    uint32_t selected = UINT32_MAX;
    try {
        selected = vk::select_device(candidates, options.device);
    } catch (const Error&) {
        if (!options.device.empty()) throw;
    }
    for (const auto& r : reports) {
        std::printf("%s%s\n", r.candidate.index == selected ? "[selected] " : "",
                    vk::format_report(r).c_str());
    }
    return 0;
}

int run_scenes() {
    for (const auto& s : scene::builtin::list()) {
        std::printf("%-10s %s\n", s.name.c_str(), s.description.c_str());
    }
    return 0;
}

int run_settings() {
    std::printf("%-18s %-6s %-8s %-14s %s\n", "NAME", "TYPE", "DEFAULT", "RANGE", "HELP");
    for (const auto& d : SettingsRegistry::instance().all()) {
        std::printf("%-18s %-6s %-8s %-14s %s\n", d.name.c_str(), d.type_name().c_str(),
                    d.default_value.c_str(), d.range_text().c_str(), d.help.c_str());
    }
    return 0;
}

}  // namespace ds::app
