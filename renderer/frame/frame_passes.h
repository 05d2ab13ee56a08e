#pragma once
// The frame's passes, in execution order: the one list that configuring the frame, building
// the graph, rebuilding pipelines, the skipped list, collecting results and the registry's
// pass knobs iterate (DESIGN.md "How to add a pass"), and the joins that run after collection.
#include <memory>
#include <span>
#include <vector>

#include "renderer/passes/frame_pass.h"

namespace ds {

std::vector<std::unique_ptr<passes::FramePass>> make_frame_passes(
    const passes::PassServices& services);

// The knobs the listed passes declare, in list order (the registry's pass knobs).
std::vector<SettingDef> frame_pass_knobs();

// Steps after every pass collected: each combines results of two passes (frame_joins.h).
using FrameJoin = void (*)(FrameResult& frame);
std::span<const FrameJoin> frame_joins();

}  // namespace ds
