#pragma once
// How report.json names a surface: {"mesh", "material", "node"} (every pass's section).
#include <nlohmann/json.hpp>

#include "renderer/common/surface_name.h"

namespace ds {

inline nlohmann::json surface_json(const SurfaceName& s) {
    return {{"mesh", s.mesh}, {"material", s.material}, {"node", s.node}};
}

}  // namespace ds
