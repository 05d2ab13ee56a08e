#pragma once
// The scene a command renders: scene::load_scene with the command's --strict, each warning the
// import made (a texture dropped, a texCoord other than 0) printed as one line on stderr,
// "depthscope: warning: FILE: …", before any frame. Every command that loads a scene calls it,
// so none of them drops a texture silently (report.json's scene.warnings keeps the lines).
#include <string_view>

#include "app/cli.h"
#include "renderer/scene/scene.h"
#include "renderer/settings/settings.h"

namespace ds::app {

scene::Scene load_command_scene(const Options& o, std::string_view name, const Settings& settings);

}  // namespace ds::app
