#pragma once
// The compiled graph as JSON (report.json's "graph"): the same facts as dump_graph's text —
// every resource (format, size, samples, semantic, lifetime, usage), every pass in order with
// the barriers recorded before it and what it reads and writes, the end-of-frame barriers —
// in a form a script can walk and a replay can compare.
#include <span>

#include <nlohmann/json.hpp>

#include "renderer/graph/plan.h"
#include "renderer/graph/subpass.h"

namespace ds::graph {

nlohmann::json graph_json(VkExtent2D output, std::span<const ResourceInfo> resources,
                          std::span<const PassInfo> passes, const BarrierPlan& plan,
                          std::span<const GroupPlan> groups = {});

}  // namespace ds::graph
