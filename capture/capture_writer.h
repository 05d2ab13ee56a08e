#pragma once
// A capture's frame written through a Renderer that already exists: what `capture` and
// `replay` (app/cmd_capture.cpp, with a renderer of their own) and the inspector's F12 (ui/,
// with its live renderer) share, so that a capture from the inspector is a normal capture.
// Facade level: it drives the Renderer and feeds the writers of capture/. Files go
// into an OutputDir's staging folder; the caller commits it.
#include <cstdint>

#include <nlohmann/json.hpp>

#include "capture/advice.h"
#include "capture/output_dir.h"
#include "capture/resource_capture.h"
#include "renderer/passes/frame_result.h"
#include "renderer/renderer.h"
#include "renderer/scene/scene.h"
#include "renderer/settings/settings.h"

namespace ds {

// What a capture shows: the scene (already set on the renderer), the camera it is seen from,
// every setting, the size, and the resources to write.
struct CaptureSpec {
    const scene::Scene& scene;
    const scene::Camera& camera;
    const Settings& settings;
    uint32_t width = 0, height = 0;
    const capture::ResourceSelection& resources;
};

// The captured frame, from a camera cut: no temporal history, so a fresh renderer (replay)
// renders the same pixels from the same camera and settings. Read back in full.
FrameResult render_capture_frame(Renderer& renderer, const CaptureSpec& spec);

// The selected resources into resources/ (resource_capture.h: the frame rendered again per
// batch, each from a camera cut, each equal to `reference`'s final image, a frame from a cut
// itself); returns report.json's "resources" array.
nlohmann::json write_capture_resources(Renderer& renderer, const CaptureSpec& spec,
                                       const FrameResult& reference, const capture::OutputDir& out);

// report.json for `frame` (the one final.png holds) with its compiled graph (taken right after
// that frame, before the resources' frames), the resources array and, with --advise, advice.
// `reference`: capture --reference's section (capture/tune/reference_files.h), or none.
void write_capture_report(const Renderer& renderer, const CaptureSpec& spec,
                          const FrameResult& frame, const nlohmann::json& graph,
                          nlohmann::json resources, const capture::Advice* advice,
                          const capture::OutputDir& out, const nlohmann::json* reference = nullptr);

// The plain capture: render_capture_frame, final.png, the resources and report.json, staged in
// `out` (not committed). Returns the written frame. Throws like the parts (ds::Error,
// UsageError); the staging folder is the caller's to drop.
FrameResult write_frame_capture(Renderer& renderer, const CaptureSpec& spec,
                                const capture::OutputDir& out);

}  // namespace ds
