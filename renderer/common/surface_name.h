#pragma once
// Plain data every layer may name: reports, the GPU scene's surface table and the passes
// that find fighting or doubly shaded surfaces.
#include <compare>
#include <string>

namespace ds {

// A surface as reports name it: the mesh, material and node of its instance (a surface is
// one triangle of one instance; reports group by instance).
struct SurfaceName {
    std::string mesh, material, node;
    auto operator<=>(const SurfaceName&) const = default;
};

}  // namespace ds
