#pragma once
// Shared dimensions and materials of the atrium scene (atrium.cpp builds the architecture,
// atrium_dressing.cpp the curtains, plants, decals and camera).
//
// Layout (metres, glTF Y up): the courtyard runs along Z from -18 to +18 and spans x in
// [-5, 5]; arcades of columns and arches stand on the lines x = +-5 on two floors; the
// galleries behind them reach the outer walls at x = +-9. End walls close z = +-18. The
// default camera stands near z = +18 and looks down -Z.
#include "renderer/scene/builtin/gltf_builder.h"

namespace ds::scene::builtin::atrium {

constexpr float kHalfLength = 18.0f;
constexpr float kArcadeX = 5.0f;
constexpr float kOuterX = 9.0f;
constexpr float kBay = 4.0f;  // column spacing
constexpr int kBays = 9;      // columns at z = -18 + 4k, k = 0..9
constexpr float kWallHeight = 12.0f;
constexpr float kWallCell = 2.0f;      // wall and floor grid cell (decals are whole cells)
constexpr float kColumnHeight = 4.0f;  // ground floor springing line
constexpr float kArchHeight = 2.4f;
constexpr float kArchDepth = 0.8f;
constexpr float kUpperFloor = kColumnHeight + kArchHeight;  // 6.4
constexpr float kUpperScale = 0.75f;                        // upper columns are 3 m
constexpr float kUpperSpringing = kUpperFloor + kColumnHeight * kUpperScale;  // 9.4
constexpr float kUpperArchScale = 2.0f / kArchHeight;  // upper arch blocks are 2 m tall
constexpr float kRoofBottom = kUpperSpringing + 2.0f;  // 11.4
// How far a part is sunk into, or stands proud of, the part it meets (column plinths into the
// floor, arch tops under the upper floors, the loggia's arches and roof against the side
// arcades'): more than a d24 step at the far plane, so no two surfaces of the scene share a
// plane where they overlap (depthscope lint finds none).
constexpr float kEmbed = 0.05f;

struct Materials {
    int floor = -1;
    int brick = -1;
    int marble = -1;
    int sandstone = -1;
    int plaster = -1;
    int wood = -1;
    int terracotta = -1;
};

// The inner faces of the walls and the floor, as grids of kWallCell cells. A decal covering
// cells of a surface is built from the same Surface, so its triangles are bit-identical.
struct Surface {
    glm::vec3 origin;
    glm::vec3 axis_u;
    glm::vec3 axis_v;
    int cells_u;
    int cells_v;
};
Surface far_wall();    // z = -18, faces +Z (the wall the default camera looks at)
Surface near_wall();   // z = +18, faces -Z
Surface left_wall();   // x = -9, faces +X
Surface right_wall();  // x = +9, faces -X
Surface ground();      // y = 0, faces +Y (the floor)

MeshData surface_mesh(const Surface& s, GridRange range, float uv_per_meter);

// The architecture's materials (atrium.cpp); the dressing adds its own.
Materials add_materials(ModelBuilder& b);
// Curtains, planters with foliage, decals and the default camera (atrium_dressing.cpp).
void add_dressing(ModelBuilder& b, const Materials& m);

}  // namespace ds::scene::builtin::atrium
