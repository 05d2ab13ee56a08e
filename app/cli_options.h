#pragma once
// The command line's shared option builders (cli.cpp, cli_tune.cpp): CLI11 options that parse
// into Options with depthscope's own checks and one-line usage errors.
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "app/cli.h"

namespace ds::app {

// --size texts, parsed once the command is known: the window's (view) or the render's. Unset
// when the option is absent; an empty text given on the command line is an error, not the
// default.
struct SizeTexts {
    std::optional<std::string> render;
    std::optional<std::string> window;
    std::optional<std::string> at;       // pixel --at
    std::optional<std::string> look_at;  // --look-at (the view)
};

// A whole-number option's value in min..max; throws UsageError naming the option.
int parse_count(const std::string& option, const std::string& text, int min, int max);
// A whole-number option read by parse_count rather than CLI11's own conversion.
CLI::Option* add_count_option(CLI::App& cmd, const std::string& name, int& target, int min, int max,
                              const std::string& help);
// A path option: an empty value is an error, not "no path" (which would mean the default).
CLI::Option* add_path_option(CLI::App& cmd, const std::string& name, std::string& target,
                             const std::string& help);
// A text option that remembers whether it was given (an empty value included).
CLI::Option* add_text_option(CLI::App& cmd, const std::string& name,
                             std::optional<std::string>& target, const std::string& help);
// --strict: every command that loads a scene takes it (scene::ImportOptions::strict).
void add_strict_flag(CLI::App& cmd, Options& o);
// --validate, --device, --strict, (--scene,) --set: what every rendering subcommand shares.
void add_render_options(CLI::App& cmd, Options& o, bool with_scene);

// --camera NAME|INDEX and --look-at, which exclude each other: the view a command renders
// (app/view_camera.h). `what` says what the view replaces ("the scene's camera").
struct ViewChoice {
    CLI::Option* camera = nullptr;
    CLI::Option* look_at = nullptr;
};
ViewChoice add_view_choice(CLI::App& cmd, Options& o, std::optional<std::string>& look_at_text,
                           const std::string& what);

// tune msaa|alpha (cli_tune.cpp).
struct TuneCommands {
    CLI::App* tune = nullptr;
    CLI::App* msaa = nullptr;
    CLI::App* alpha = nullptr;
};
TuneCommands add_tune_command(CLI::App& app, Options& o, SizeTexts& texts);
// lint SCENE… (cli_lint.cpp).
CLI::App* add_lint_command(CLI::App& app, Options& o, SizeTexts& texts);

// sweep (cli_sweep.cpp).
CLI::App* add_sweep_command(CLI::App& app, Options& o);

}  // namespace ds::app
