#pragma once
// One capture as `capture` and `replay` (and the inspector's F12) make it: what to render and
// where to write it. write_capture renders the frame from job.scene.camera, writes final.png,
// the selected resources and report.json into job.out all or nothing, and returns the exit code.
#include <filesystem>

#include "app/cli.h"
#include "capture/resource_capture.h"
#include "renderer/scene/scene.h"
#include "renderer/settings/settings.h"

namespace ds::app {

struct CaptureJob {
    Settings settings;
    scene::Scene scene;  // its camera is the one the frame is seen from
    capture::ResourceSelection resources;
    std::filesystem::path out;  // "" = captures/YYYYmmdd-HHMMSS-SCENE
};

// Uses o.size, o.device, o.validate, o.ui, o.view_resource, o.renderdoc, o.advise and
// o.dump_graph. Throws like capture does (UsageError, ds::Error); nothing is left on failure.
int write_capture(const Options& o, const CaptureJob& job);

}  // namespace ds::app
