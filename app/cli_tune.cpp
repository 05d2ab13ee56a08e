// `depthscope tune msaa|alpha` (capture/tune/): its options.
#include <charconv>

#include "app/cli_options.h"
#include "renderer/common/error.h"
#include "renderer/common/quoted.h"

namespace ds::app {
namespace {

// What both sweeps share: the view, the size, the cost, the outputs.
void add_tune_options(CLI::App& cmd, Options& o, SizeTexts& texts) {
    add_render_options(cmd, o, /*with_scene=*/true);
    add_text_option(cmd, "--size", texts.render, "render size WIDTHxHEIGHT (default 1280x720)")
        ->type_name("WxH");
    add_view_choice(cmd, o, texts.look_at, "the scene's camera");
    cmd.add_option_function<std::string>(
           "--cost",
           [&o](const std::string& text) {
               if (text != "ms" && text != "fragments")
                   throw UsageError("--cost expects ms or fragments, got " + quote(text));
               o.tune_cost = text;
           },
           "what a candidate costs: fragments (shaded fragments of every pass, exact and the "
           "same on every run; the default) or ms (the frame's and each pass's GPU ms, medians "
           "of --frames timed frames)")
        ->type_name("ms|fragments");
    add_count_option(cmd, "--frames", o.tune_frames, 1, 1000,
                     "--cost ms: timed frames per candidate (default 5)");
    add_count_option(cmd, "--warmup", o.tune_warmup, 0, 1000,
                     "--cost ms: frames rendered before timing (default 1)");
    add_path_option(cmd, "--json", o.out,
                    "also write the results as JSON to FILE (a new file or a regular one)");
    add_path_option(cmd, "--plot", o.plot, "also write a plot of error against cost as PNG to FILE")
        ->type_name("FILE.png");
}

float parse_step(const std::string& text) {
    float value = -1;
    const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || ptr != text.data() + text.size() || !(value >= 0.01f && value <= 0.5f))
        throw UsageError("--step expects a number in 0.01..0.5, got " + quote(text));
    return value;
}

}  // namespace

TuneCommands add_tune_command(CLI::App& app, Options& o, SizeTexts& texts) {
    TuneCommands t;
    t.tune = app.add_subcommand(
        "tune",
        "score settings against a supersampled reference (4x4 samples per pixel, every sample "
        "shaded, box-resolved in linear HDR; gtao and contact_shadows off in it and in every "
        "candidate): `tune msaa` sweeps msaa x sample_shading x alpha_to_coverage, `tune alpha` "
        "each MASK material's cutoff");
    t.tune->require_subcommand(1);
    t.msaa = t.tune->add_subcommand(
        "msaa",
        "every msaa count of the device x sample_shading x alpha_to_coverage: SSIM and edge "
        "error against the reference, cost, the Pareto front and the best setting for a few "
        "budgets");
    add_tune_options(*t.msaa, o, texts);
    t.alpha = t.tune->add_subcommand(
        "alpha",
        "for each MASK material, a sweep of its cutoff (and alpha_to_coverage at msaa > 1): "
        "coverage error against the reference in the material's pixels, discarded fragments, "
        "cost, and the cutoff that best matches the reference's coverage");
    add_tune_options(*t.alpha, o, texts);
    t.alpha
        ->add_option("--material", o.tune_materials,
                     "a MASK material's name (repeatable; default every MASK material)")
        ->type_name("NAME");
    t.alpha
        ->add_option_function<std::string>(
            "--step", [&o](const std::string& text) { o.tune_step = parse_step(text); },
            "the cutoff sweep's step (default 0.05): step, 2 step, … below 1, and the "
            "material's own cutoff")
        ->type_name("S");
    return t;
}

}  // namespace ds::app
