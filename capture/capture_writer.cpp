#include "capture/capture_writer.h"

#include "capture/image_writer.h"
#include "capture/report.h"
#include "renderer/device_info.h"

namespace ds {

FrameResult render_capture_frame(Renderer& renderer, const CaptureSpec& spec) {
    renderer.camera_cut();  // a live renderer's history (the inspector's) stays out
    return renderer.render(spec.camera, spec.settings,
                           {.width = spec.width, .height = spec.height});
}

nlohmann::json write_capture_resources(Renderer& renderer, const CaptureSpec& spec,
                                       const FrameResult& reference,
                                       const capture::OutputDir& out) {
    const auto render = [&](std::span<const InspectRequest> requests) {
        renderer.camera_cut();
        return renderer.render(spec.camera, spec.settings,
                               {.width = spec.width,
                                .height = spec.height,
                                .read_back = ReadBack::Color,
                                .inspect = {requests.begin(), requests.end()}});
    };
    return capture::capture_resources(reference, spec.resources, render,
                                      out.staging_path("resources"));
}

void write_capture_report(const Renderer& renderer, const CaptureSpec& spec,
                          const FrameResult& frame, const nlohmann::json& graph,
                          nlohmann::json resources, const capture::Advice* advice,
                          const capture::OutputDir& out, const nlohmann::json* reference) {
    nlohmann::json report =
        capture::frame_report({.device = device_info(renderer),
                               .scene = spec.scene,
                               .settings = spec.settings,
                               .frame = frame,
                               .validation_messages = renderer.validation_message_count(),
                               .advice = advice,
                               .camera = &spec.camera,
                               .graph = &graph});
    report["resources"] = std::move(resources);
    if (reference) report["reference"] = *reference;
    capture::write_json(out.staging_path("report.json"), report);
}

FrameResult write_frame_capture(Renderer& renderer, const CaptureSpec& spec,
                                const capture::OutputDir& out) {
    FrameResult frame = render_capture_frame(renderer, spec);
    capture::write_png_rgba8(out.staging_path("final.png"), frame.width, frame.height, frame.rgba8);
    const nlohmann::json graph = renderer.graph_json();  // before the resources' frames
    nlohmann::json resources = write_capture_resources(renderer, spec, frame, out);
    write_capture_report(renderer, spec, frame, graph, std::move(resources), nullptr, out);
    return frame;
}

}  // namespace ds
