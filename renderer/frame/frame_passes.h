#pragma once
// The frame's passes, in execution order: the one list that building the graph, rebuilding
// pipelines, the skipped list and collecting results iterate (DESIGN.md "How to add a pass").
#include <memory>
#include <vector>

#include "renderer/passes/frame_pass.h"

namespace ds {

std::vector<std::unique_ptr<passes::FramePass>> make_frame_passes(
    const passes::PassServices& services);

}  // namespace ds
