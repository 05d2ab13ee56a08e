#pragma once
// FrameResult::tiler from the compiled graph: seed 002's budget and merge verdict for the
// frame's subpass group (render_path=subpass), with which of its images got lazily allocated
// memory. None when the frame has no group.
#include <optional>

#include "renderer/graph/graph.h"
#include "renderer/graph/tiler.h"

namespace ds {

std::optional<graph::TilerReport> tiler_summary(const graph::RenderGraph& graph);

}  // namespace ds
