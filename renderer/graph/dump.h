#pragma once
// The compiled graph as text (DESIGN decision 5): passes in order with the barriers recorded
// before each and what each reads and writes; every resource with its format, size, samples,
// semantic and lifetime. `depthscope capture --dump-graph` prints it; tests read it.
#include <span>
#include <string>

#include "renderer/graph/plan.h"
#include "renderer/graph/rendering.h"
#include "renderer/graph/subpass.h"

namespace ds::graph {

// `groups`: the compiled frame's subpass groups (render passes), printed after the passes;
// `renderings`: per pass, the dynamic rendering the graph begins for it (rendering.h).
std::string dump_graph(VkExtent2D output, std::span<const ResourceInfo> resources,
                       std::span<const PassInfo> passes, const BarrierPlan& plan,
                       std::span<const GroupPlan> groups = {},
                       std::span<const RenderingPlan> renderings = {});

// One barrier on one line: "colour: UNDEFINED -> COLOR_ATTACHMENT_OPTIMAL, NONE/NONE -> ...".
std::string describe_barrier(const Barrier& barrier, std::span<const ResourceInfo> resources);

}  // namespace ds::graph
