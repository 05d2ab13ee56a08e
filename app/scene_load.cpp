#include "app/scene_load.h"

#include <cstdio>

#include "renderer/scene/loader.h"

namespace ds::app {

scene::Scene load_command_scene(const Options& o, std::string_view name, const Settings& settings) {
    scene::Scene scene = scene::load_scene(name, settings, {o.strict});
    for (const auto& w : scene.warnings)
        std::fprintf(stderr, "depthscope: warning: %s: %s\n", scene.source.c_str(), w.c_str());
    return scene;
}

}  // namespace ds::app
