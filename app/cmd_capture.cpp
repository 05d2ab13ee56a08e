// capture and export-scene: load a scene, render or write it, and leave complete output only.
#include <cstdio>
#include <optional>

#include <renderdoc_app.h>

#include "app/capture_job.h"
#include "app/commands.h"
#include "app/exit_code.h"
#include "app/scene_load.h"
#include "app/view_camera.h"
#include "capture/capture_writer.h"
#include "capture/file_output.h"
#include "capture/image_writer.h"
#include "capture/output_dir.h"
#include "capture/renderdoc.h"
#include "capture/resource_capture.h"
#include "capture/trace.h"
#include "capture/tune/reference_files.h"
#include "renderer/common/error.h"
#include "renderer/common/quoted.h"
#include "renderer/device_info.h"
#include "renderer/renderer.h"
#include "renderer/scene/builtin/builtin.h"
#include "renderer/scene/loader.h"
#include "ui/headless.h"

#ifndef DS_CAPTURE_ROOT
#define DS_CAPTURE_ROOT "captures"
#endif

namespace ds::app {
namespace {

// capture --ui: UI frames drawn before the one written (the panels show the frames before).
constexpr int kUiCaptureFrames = 3;

Settings settings_from(const Options& o) {
    Settings settings;
    for (const auto& assignment : o.sets) settings.apply(assignment);
    return settings;
}

std::filesystem::path capture_dir(const std::filesystem::path& out, const scene::Scene& scene) {
    if (!out.empty()) return out;
    return capture::default_capture_dir(DS_CAPTURE_ROOT, scene.name);
}

// --renderdoc: RenderDoc's API, attached before any output exists; else null.
std::unique_ptr<capture::RenderDoc> attach_renderdoc(const Options& o) {
    std::unique_ptr<capture::RenderDoc> renderdoc;
    if (o.renderdoc && !(renderdoc = capture::RenderDoc::attach())) {
        throw UsageError(
            "--renderdoc: RenderDoc is not loaded in this process (run under `renderdoccmd "
            "capture`)");
    }
    return renderdoc;
}

// RenderDoc around the frame that is written, with --renderdoc; without it, nothing.
struct FrameCapture {
    capture::RenderDoc* renderdoc = nullptr;
    void* device_pointer = nullptr;
    std::filesystem::path path_template;

    void start() const {
        if (renderdoc) renderdoc->start(device_pointer, path_template);
    }
    void end() const {
        if (renderdoc) renderdoc->end(device_pointer);
    }
};

// --ui: the inspector over the frame, offscreen, through the window's code: the first UI
// frame lays the panels out, the next ones show the frames before them. Writes final.png.
FrameResult capture_ui_frame(const Options& o, Renderer& renderer, const Settings& settings,
                             const scene::Scene& scene, const capture::OutputDir& out,
                             const FrameCapture& rdc) {
    ui::HeadlessUi headless(renderer, settings, scene, {o.size.width, o.size.height});
    headless.inspector().queue(ui::SelectResource{o.view_resource});
    std::vector<uint8_t> pixels;
    for (int i = 0; i < kUiCaptureFrames; ++i) {
        if (i + 1 == kUiCaptureFrames) rdc.start();
        pixels = headless.frame();
    }
    rdc.end();
    capture::write_png_rgba8(out.staging_path("final.png"), o.size.width, o.size.height, pixels);
    FrameResult frame = headless.inspector().frame();
    if (!frame.inspected) {
        std::string images;
        for (const ResourceSummary& r : frame.resources)
            if (r.is_image) images += (images.empty() ? "" : ", ") + r.name;
        throw UsageError("--view " + escaped(o.view_resource) + ": this frame has no such image (" +
                         images + ")");
    }
    return frame;
}

// The frame alone (from a camera cut, capture/capture_writer.h), written as final.png.
FrameResult capture_plain_frame(Renderer& renderer, const CaptureSpec& spec,
                                const capture::OutputDir& out, const FrameCapture& rdc) {
    rdc.start();
    FrameResult frame = render_capture_frame(renderer, spec);
    rdc.end();
    capture::write_png_rgba8(out.staging_path("final.png"), frame.width, frame.height, frame.rgba8);
    return frame;
}

// --advise: the prepass advisor over the same camera, size and settings (prepass on and off,
// counted once each, timed kAdviceFrames times), rendered after the written frame.
capture::Advice advise(const Options& o, Renderer& renderer, const Settings& settings,
                       const scene::Scene& scene) {
    const capture::RenderFrame render = [&](const Settings& s) {
        return renderer.render(
            scene.camera, s,
            {.width = o.size.width, .height = o.size.height, .read_back = ReadBack::No});
    };
    const capture::Advice advice =
        capture::advise(capture::measure_advice(settings, render, capture::AdviceRun{}));
    std::printf("depthscope: advice: %s\n", capture::verdict_line(advice).c_str());
    return advice;
}

// --resources: the selected graph images (capture/capture_writer.h). With --ui the written
// frame is the inspector's third, so a fresh frame from a cut is the reference the batches
// must equal.
nlohmann::json write_resources(const Options& o, Renderer& renderer, const CaptureSpec& spec,
                               const FrameResult& frame, const capture::OutputDir& out) {
    if (!o.ui) return write_capture_resources(renderer, spec, frame, out);
    FrameResult reference = render_capture_frame(renderer, spec);
    reference.resources = frame.resources;
    return write_capture_resources(renderer, spec, reference, out);
}

// --trace: the written frame's passes (capture/trace.h), written before the capture is
// committed, so that a trace that cannot be written leaves no capture folder either.
void write_trace(const Options& o, const Renderer& renderer, const scene::Scene& scene,
                 const Settings& settings, const FrameResult& frame) {
    capture::write_trace(
        o.trace, {.command = "capture",
                  .scene = scene.name,
                  .width = frame.width,
                  .height = frame.height,
                  .device = device_info(renderer).name,
                  .runs = {{.name = "capture " + scene.name + " " + std::to_string(frame.width) +
                                    "x" + std::to_string(frame.height),
                            .settings = settings.values(),
                            .frames = {frame.passes}}}});
    std::printf("depthscope: wrote %s\n", o.trace.c_str());
}

}  // namespace

int write_capture(const Options& o, const CaptureJob& job) {
    // --trace's target before any work: a directory or a device node there is refused now.
    if (!o.trace.empty()) capture::check_output_file("--trace", o.trace);
    const Settings& settings = job.settings;
    const scene::Scene& scene = job.scene;
    const std::unique_ptr<capture::RenderDoc> renderdoc = attach_renderdoc(o);
    capture::OutputDir out(capture_dir(job.out, scene));
    if (!o.trace.empty()) capture::check_trace_outside(o.trace, out.final_dir());

    RendererOptions renderer_options;
    renderer_options.validate = o.validate;
    renderer_options.device = o.device;
    Renderer renderer(renderer_options);
    if (!o.trace.empty()) capture::check_trace_device(o.trace, device_info(renderer));
    renderer.set_scene(scene);
    const FrameCapture rdc{renderdoc.get(),
                           RENDERDOC_DEVICEPOINTER_FROM_VKINSTANCE(renderer.instance()),
                           out.staging_path("frame")};
    const CaptureSpec spec{scene,        scene.camera,  settings,
                           o.size.width, o.size.height, job.resources};
    const FrameResult frame = o.ui ? capture_ui_frame(o, renderer, settings, scene, out, rdc)
                                   : capture_plain_frame(renderer, spec, out, rdc);
    const std::string graph_text = o.dump_graph ? renderer.graph_dump() : std::string();
    const nlohmann::json graph = renderer.graph_json();
    // Before anything is committed: a failure here leaves no capture folder.
    nlohmann::json resources = write_resources(o, renderer, spec, frame, out);
    std::optional<capture::Advice> advice;
    if (o.advise) advice = advise(o, renderer, settings, scene);
    std::optional<nlohmann::json> reference;
    if (o.reference)
        reference = tune::write_reference(renderer, scene, scene.camera, settings, frame,
                                          out.staging_path("resources"));
    write_capture_report(renderer, spec, frame, graph, std::move(resources),
                         advice ? &*advice : nullptr, out, reference ? &*reference : nullptr);
    if (o.dump_graph) std::printf("%s\n", graph_text.c_str());
    if (!o.trace.empty()) write_trace(o, renderer, scene, settings, frame);
    const std::string warning = out.commit();
    if (!warning.empty()) std::fprintf(stderr, "depthscope: warning: %s\n", warning.c_str());
    std::printf("depthscope: wrote %s\n", out.final_dir().c_str());
    return validation_exit_code(renderer);
}

int run_capture(const Options& o) {
    CaptureJob job;
    job.settings = settings_from(o);
    job.resources = capture::parse_resource_selection(o.resources);
    job.out = o.out;
    // Input first: a bad file fails before any Vulkan work, and before output exists.
    job.scene = load_command_scene(o, o.scene, job.settings);
    job.scene.camera = view_camera(o, job.scene);  // --camera, --look-at: refused before output
    return write_capture(o, job);
}

int run_export_scene(const Options& o) {
    if (!scene::builtin::exists(o.scene)) {
        scene::builtin::build(o.scene, Settings{});  // throws the error that lists the names
    }
    const auto model = scene::builtin::build(o.scene, settings_from(o));
    scene::builtin::export_model(model, o.out);
    std::printf("depthscope: wrote %s\n", o.out.c_str());
    return 0;
}

}  // namespace ds::app
