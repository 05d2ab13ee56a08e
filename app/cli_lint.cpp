// `depthscope lint SCENE…` (capture/lint/): its options.
#include "app/cli_options.h"
#include "renderer/common/error.h"
#include "renderer/common/quoted.h"

namespace ds::app {

CLI::App* add_lint_command(CLI::App& app, Options& o, SizeTexts& texts) {
    auto* lint = app.add_subcommand(
        "lint",
        "check scenes' content before anyone flies a camera, in glTF-Validator's report shape: "
        "coplanar overlaps, duplicates, near-coplanar fights with the distance they start at "
        "per depth format, degenerate triangles, decals, alpha modes, overdraw from the scene's "
        "cameras, the depth range");
    add_render_options(*lint, o, /*with_scene=*/false);
    lint->add_option("scenes", o.lint_scenes, "built-in scene names or .gltf/.glb paths")
        ->required()
        ->type_name("SCENE…");
    add_text_option(*lint, "--size", texts.render,
                    "OVERDRAW's render size WIDTHxHEIGHT (default 640x360)")
        ->type_name("WxH");
    add_view_choice(*lint, o, texts.look_at, "the scene's cameras (or the fit-inside view)");
    add_path_option(*lint, "--json", o.out,
                    "also write the reports as JSON to FILE (glTF-Validator's shape; an array "
                    "for several scenes; a new file or a regular one)");
    add_path_option(*lint, "--config", o.lint_config,
                    "glTF-Validator's config keys as JSON: ignore, only, override, max-issues "
                    "(and depthscope's thresholds)");
    add_path_option(*lint, "--images", o.lint_images,
                    "write the worst views' overdraw heat maps as PNG into DIR (made if missing)")
        ->type_name("DIR");
    lint->add_option_function<std::string>(
            "--fail-on",
            [&o](const std::string& text) {
                if (text != "error" && text != "warning" && text != "info")
                    throw UsageError("--fail-on expects error, warning or info, got " +
                                     quote(text));
                o.fail_on = text;
            },
            "exit 1 when a finding is at this level or more severe (default error)")
        ->type_name("error|warning|info");
    return lint;
}

}  // namespace ds::app
