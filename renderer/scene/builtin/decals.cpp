// decals: a room corner with coplanar overlays lying exactly on its walls and floor (seed 004:
// Sponza's layered meshes share the vertices of the wall under them, so every one of them
// passes an EQUAL depth test). OPAQUE, MASK and BLEND overlays in saturated colours on grey,
// so a test can tell an overlay's pixels by hue. Layout: see scene_facts.h.
#include <string>

#include "renderer/scene/builtin/gltf_builder.h"
#include "renderer/scene/builtin/scene_facts.h"
#include "renderer/scene/builtin/scenes.h"

namespace ds::scene::builtin {

namespace {

using facts::DecalsAlpha;
using facts::DecalsSurface;

// The left wall and its overlay are authored in a local frame (cell axes +X, +Y) and placed by
// one non-identity node transform, as an exporter writes a rotated wall; the other surfaces are
// authored in world space.
constexpr int kPlacedSurface = 1;

bool placed_by_node(int surface) {
    return surface == kPlacedSurface;
}

// Cells [range) of surface `s`, in the frame its node places.
MeshData surface_cells(int s, GridRange range, float uv_per_meter) {
    const DecalsSurface& f = facts::kDecalsSurfaces[s];
    const glm::vec2 cell(facts::kDecalsCell);
    if (placed_by_node(s))
        return make_grid(glm::vec3(0.0f), {1, 0, 0}, {0, 1, 0}, cell, range, uv_per_meter);
    return make_grid(f.origin, f.axis_u, f.axis_v, cell, range, uv_per_meter);
}

Transform surface_transform(int s) {
    if (!placed_by_node(s)) return {};
    const DecalsSurface& f = facts::kDecalsSurfaces[s];
    // The rotation that takes the local cell axes to the world ones.
    const glm::mat3 axes(f.axis_u, f.axis_v, glm::cross(f.axis_u, f.axis_v));
    return {f.origin, glm::quat_cast(axes)};
}

// Alpha 1 for u < kDecalsMaskKeep, 0 beyond, white: the material's factor gives the colour.
// The split falls on a texel edge, so linear filtering puts alpha 0.5 exactly there.
Pixels split_alpha_texture(int size) {
    Pixels p(size, size);
    const int keep = static_cast<int>(facts::kDecalsMaskKeep * static_cast<float>(size));
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x)
            p.set(x, y, glm::vec4(1.0f, 1.0f, 1.0f, x < keep ? 1.0f : 0.0f));
    return p;
}

int overlay_material(ModelBuilder& b, const facts::DecalsOverlay& o, int mask_texture) {
    MaterialSpec s;
    s.name = o.node;
    s.base_color = glm::vec4(o.colour, 1.0f);
    s.roughness = 0.9f;
    if (o.alpha == DecalsAlpha::Mask) {
        s.alpha = Alpha::Mask;
        s.alpha_cutoff = facts::kDecalsMaskCutoff;
        s.base_color_texture = mask_texture;
    } else if (o.alpha == DecalsAlpha::Blend) {
        s.alpha = Alpha::Blend;
        s.base_color.a = facts::kDecalsBlendAlpha;
    }
    return b.add_material(s);
}

}  // namespace

tinygltf::Model build_decals(const Settings& /*settings*/) {
    ModelBuilder b;
    MaterialSpec grey;
    grey.name = "grey";
    grey.base_color = glm::vec4(facts::kDecalsBaseColour, 1.0f);
    grey.roughness = 0.9f;
    const int base = b.add_material(grey);
    // Bases first, then the overlays in facts order: authored order, as a file has it.
    int s = 0;
    for (const DecalsSurface& f : facts::kDecalsSurfaces) {
        const MeshData grid = surface_cells(s, {0, f.cells_u, 0, f.cells_v}, 0.5f);
        b.add_node(f.node, b.add_mesh(f.node, grid, base), surface_transform(s));
        ++s;
    }
    const int mask =
        b.add_texture("decals_split_alpha", split_alpha_texture(64), SamplerKind::Clamp);
    for (const facts::DecalsOverlay& o : facts::kDecalsOverlays) {
        const MeshData cells = surface_cells(o.surface, {o.i0, o.i1, o.j0, o.j1}, 0.0f);
        b.add_node(o.node, b.add_mesh(o.node, cells, overlay_material(b, o, mask)),
                   surface_transform(o.surface));
    }
    // From the open corner, above head height, looking into the far corner: every overlay
    // whole and well inside the view, none at a grazing angle.
    CameraSpec cam;
    cam.yfov = 0.9f;
    cam.znear = 0.1f;
    cam.zfar = 50.0f;
    b.add_camera("camera", cam, {2.2f, 2.7f, 4.6f}, {-0.9f, 0.4f, -0.6f});
    return b.finish("decals");
}

}  // namespace ds::scene::builtin
