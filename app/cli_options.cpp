// The shared option builders (cli_options.h).
#include "app/cli_options.h"

#include "renderer/common/error.h"
#include "renderer/common/quoted.h"

namespace ds::app {

// A whole-number option's value in min..max; throws UsageError naming the option.
int parse_count(const std::string& option, const std::string& text, int min, int max) {
    const std::optional<uint32_t> value = parse_digits(text);
    if (!value || *value < uint32_t(min) || *value > uint32_t(max))
        throw UsageError(option + " expects a whole number in " + std::to_string(min) + ".." +
                         std::to_string(max) + ", got " + quote(text));
    return int(*value);
}

// A whole-number option read by parse_count rather than CLI11's own conversion.
CLI::Option* add_count_option(CLI::App& cmd, const std::string& name, int& target, int min, int max,
                              const std::string& help) {
    return cmd
        .add_option_function<std::string>(
            name,
            [&target, name, min, max](const std::string& text) {
                target = parse_count(name, text, min, max);
            },
            help)
        ->type_name("N");
}

// A path option: an empty value is an error, not "no path" (which would mean the default).
CLI::Option* add_path_option(CLI::App& cmd, const std::string& name, std::string& target,
                             const std::string& help) {
    return cmd
        .add_option_function<std::string>(
            name,
            [&target, name](const std::string& text) {
                if (text.empty()) throw UsageError(name + " expects a path, got ''");
                target = text;
            },
            help)
        ->type_name("PATH");
}

// A text option that remembers whether it was given (an empty value included).
CLI::Option* add_text_option(CLI::App& cmd, const std::string& name,
                             std::optional<std::string>& target, const std::string& help) {
    return cmd.add_option_function<std::string>(
        name, [&target](const std::string& text) { target = text; }, help);
}

// Options every rendering subcommand shares.
// Every command that loads a scene takes it (scene::ImportOptions::strict).
void add_strict_flag(CLI::App& cmd, Options& o) {
    cmd.add_flag("--strict", o.strict,
                 "refuse a scene file whose texture is missing, does not decode or is in an "
                 "unsupported format (one error) instead of dropping that texture with a warning");
}

void add_render_options(CLI::App& cmd, Options& o, bool with_scene) {
    cmd.add_flag("--validate", o.validate,
                 "enable VK_LAYER_KHRONOS_validation; any validation message makes the exit "
                 "code 3");
    cmd.add_option("--device", o.device, "Vulkan device: index or name substring (see `info`)");
    add_strict_flag(cmd, o);
    if (with_scene) {
        cmd.add_option("--scene", o.scene, "built-in scene name (see `scenes`) or .gltf/.glb path");
    }
    cmd.add_option("--set", o.sets, "setting as name=value, repeatable (see `settings`)")
        ->type_name("NAME=VALUE");
}

// --camera NAME|INDEX and --look-at, which exclude each other: the view a command renders
// (app/view_camera.h). `what` says what the view replaces ("the scene's camera").

ViewChoice add_view_choice(CLI::App& cmd, Options& o, std::optional<std::string>& look_at_text,
                           const std::string& what) {
    ViewChoice v;
    v.camera = cmd.add_option_function<std::string>(
                      "--camera",
                      [&o](const std::string& text) {
                          if (text.empty())
                              throw UsageError(
                                  "--camera expects a camera node's name or index (see "
                                  "`depthscope cameras SCENE`), got ''");
                          o.camera = text;
                      },
                      "instead of " + what +
                          ": the scene's camera node NAME (exact) or INDEX, as `depthscope "
                          "cameras SCENE` lists them (perspective ones)")
                   ->type_name("NAME|INDEX");
    v.look_at = add_text_option(cmd, "--look-at", look_at_text,
                                "instead of " + what +
                                    ": a camera at EX,EY,EZ looking at TX,TY,TZ, up +Y, with a "
                                    "vertical field of view of FOV degrees (10..120; default the "
                                    "scene camera's); the scene camera's near plane, the far "
                                    "plane holding the whole scene")
                    ->type_name("EX,EY,EZ:TX,TY,TZ[:FOV]");
    v.camera->excludes(v.look_at);
    return v;
}

}  // namespace ds::app
