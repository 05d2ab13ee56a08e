#pragma once
// The one entry point for "a scene by name": a built-in scene or a .gltf / .glb path.
#include <string_view>

#include "renderer/scene/import_options.h"
#include "renderer/scene/scene.h"
#include "renderer/settings/settings.h"

namespace ds::scene {

// A built-in name (builtin::list()) is built with `settings` and imported as
// "builtin:NAME"; anything else is a file path (load_gltf). A path that does not exist throws
// InputError "PATH: no such file".
// `options` apply to files (built-in scenes have nothing to be lenient about).
Scene load_scene(std::string_view name_or_path, const Settings& settings,
                 const ImportOptions& options = {});

}  // namespace ds::scene
