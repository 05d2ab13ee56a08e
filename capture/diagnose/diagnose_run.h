#pragma once
// Diagnose (issue 24 point 5) on a Renderer that already exists: what `depthscope diagnose`
// (app/cmd_diagnose.cpp) and the inspector's Diagnose button share. Facade level, like
// capture_writer.h: it drives the Renderer and hands the frames to the pure checks of
// capture/diagnose/ (one per file), which name findings in diagnose/finding.h's shape.
//
// Frames: one measuring frame (the user's settings plus the measurement knobs below, the
// images the checks read inspected in the same frame), then the prepass advisor's own
// measurement (capture::measure_advice with kAdviceRun: one counting frame with the prepass
// and one without, kAdviceRun.warmup warm-up and kAdviceRun.frames timed frames of each,
// alternating): 1 + 2 + 2 × (1 + 3) = 11 frames. The advisor's first uncounted frame of the user's
// own prepass setting is the plain frame whose pipelines give the early-Z verdicts.
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "capture/advice.h"
#include "capture/diagnose/finding.h"
#include "renderer/common/device_info.h"
#include "renderer/renderer.h"
#include "renderer/scene/scene.h"
#include "renderer/settings/settings.h"

namespace ds::diagnose {

inline constexpr capture::AdviceRun kAdviceRun{.frames = 3, .warmup = 1};

// `settings` plus the measurement knobs this device can run: count_fragments, count_draws,
// zfight (which turns surface_id and depth_precision on), equal_check and depth_precision.
// Each only measures: the frame's image is the same (the passes' own tests say so). Detectors
// the device cannot run are appended to `skipped` with the reason.
Settings with_measurement_knobs(const Settings& settings, const DeviceInfo& device,
                                std::vector<SkippedDetector>& skipped);

// Diagnoses the view of `scene` (already the renderer's: Renderer::set_scene) from `camera` at
// `size` with the user's `settings`: renders the frames above, runs every check, ranks the
// findings. Blocks until done; call it on the thread that owns the renderer. Throws what
// Renderer::render throws (UsageError for settings the device refuses, ds::Error).
Diagnosis diagnose(Renderer& renderer, const scene::Scene& scene, const scene::Camera& camera,
                   const Settings& settings, VkExtent2D size);

}  // namespace ds::diagnose
