#include "ui/config.h"

#include <cstdlib>
#include <fstream>
#include <system_error>

#include "renderer/common/error.h"

namespace ds::ui {

std::filesystem::path config_dir() {
    if (const char* dir = std::getenv("DEPTHSCOPE_CONFIG_DIR"); dir && *dir) return dir;
    if (const char* xdg = std::getenv("XDG_CONFIG_HOME"); xdg && *xdg)
        return std::filesystem::path(xdg) / "depthscope";
    if (const char* home = std::getenv("HOME"); home && *home)
        return std::filesystem::path(home) / ".config" / "depthscope";
    return {};
}

std::filesystem::path bookmarks_file(const std::filesystem::path& dir) {
    return dir.empty() ? dir : dir / "cameras.json";
}

SavedState load_state(const std::filesystem::path& file) {
    SavedState state;
    std::ifstream in(file);
    if (!in) return state;
    std::string line;
    Settings probe;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        const auto eq = line.find('=');
        if (eq == std::string::npos) {
            state.ignored.push_back(line);
            continue;
        }
        if (line.compare(0, eq, "scene") == 0) {
            state.scene = line.substr(eq + 1);
            continue;
        }
        try {
            probe.apply(line);
            state.sets.push_back(line);
        } catch (const std::exception&) {
            state.ignored.push_back(line);
        }
    }
    return state;
}

void save_state(const std::filesystem::path& file, const std::string& scene,
                const Settings& settings) {
    std::error_code ec;
    std::filesystem::create_directories(file.parent_path(), ec);
    const std::filesystem::path temp = file.string() + ".tmp";
    {
        std::ofstream out(temp, std::ios::trunc);
        if (!out) throw Error(temp.string() + ": cannot write");
        out << "# depthscope inspector: the scene and the settings that differ from their "
               "defaults (written on exit)\n";
        if (!scene.empty()) out << "scene=" << scene << "\n";
        const Settings defaults;
        for (const std::string& name : settings.diff(defaults))
            out << name << "=" << settings.get(name) << "\n";
        if (!out.flush()) throw Error(temp.string() + ": cannot write");
    }
    std::filesystem::rename(temp, file, ec);
    if (ec) throw Error(file.string() + ": " + ec.message());
}

}  // namespace ds::ui
