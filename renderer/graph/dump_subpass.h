#pragma once
// Subpass groups as text and JSON, for dump_graph / graph_json: each render pass with its
// attachments (format, samples, load and store ops, layouts, transient or stored), its
// subpasses (passes, colour / input / resolve / depth references) and its dependencies.
#include <iosfwd>
#include <span>

#include <nlohmann/json.hpp>

#include "renderer/graph/subpass.h"

namespace ds::graph {

void dump_groups(std::ostream& out, std::span<const GroupPlan> groups,
                 std::span<const ResourceInfo> resources, std::span<const PassInfo> passes);
nlohmann::json groups_json(std::span<const GroupPlan> groups,
                           std::span<const ResourceInfo> resources,
                           std::span<const PassInfo> passes);

}  // namespace ds::graph
