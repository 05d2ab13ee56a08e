#include "renderer/scene/loader.h"

#include <filesystem>
#include <string>

#include "renderer/common/error.h"
#include "renderer/scene/builtin/builtin.h"
#include "renderer/scene/import_util.h"
#include "renderer/scene/importer.h"

namespace ds::scene {

Scene load_scene(std::string_view name_or_path, const Settings& settings,
                 const ImportOptions& options) {
    const std::string name(name_or_path);
    if (builtin::exists(name))
        return import_model(builtin::build(name, settings), name, "builtin:" + name);

    const std::filesystem::path path(name);
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) {
        // A bare word was more likely meant as a built-in name: say which ones exist.
        std::string hint;
        if (!path.has_extension() && !path.has_parent_path()) {
            for (const builtin::Info& info : builtin::list())
                hint += (hint.empty() ? " (built-in scenes: " : ", ") + info.name;
            if (!hint.empty()) hint += ")";
        }
        throw InputError(detail::printable(name) + ": no such file" + hint);
    }
    return load_gltf(path, options);
}

}  // namespace ds::scene
