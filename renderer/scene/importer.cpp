#include "renderer/scene/importer.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "renderer/scene/decals.h"
#include "renderer/scene/gltf_accessor.h"
#include "renderer/scene/gltf_dropped.h"
#include "renderer/scene/gltf_material.h"
#include "renderer/scene/gltf_mesh.h"
#include "renderer/scene/gltf_nodes.h"
#include "renderer/scene/import_util.h"
#include "renderer/scene/mesh_ops.h"

namespace ds::scene {
namespace {

using namespace detail;

void check_header(const tinygltf::Model& model) {
    if (!is_supported_version(model.asset.version)) fail(version_message(model.asset.version));
    for (const std::string& extension : model.extensionsRequired)
        if (!is_supported_required_extension(extension))
            fail(unsupported_extension_message(extension));
}

// Every (placement, primitive) as an instance, in traversal order.
std::vector<Instance> place_instances(const std::vector<MeshPlacement>& placements,
                                      const MeshImport& meshes) {
    std::vector<Instance> placed;
    for (const MeshPlacement& placement : placements)
        for (uint32_t mesh : meshes.by_gltf_mesh[static_cast<size_t>(placement.gltf_mesh)])
            placed.push_back({mesh, placement.world, placement.node, placement.gltf_node});
    return placed;
}

// Instances sharing (mesh, alpha mode, double-sided, decal) form one instanced draw (seed 000);
// coplanar overlays are found first (decals.h), so a mesh used both as an overlay and not
// makes two groups. Groups keep first-use order; each group's instances are made contiguous,
// in traversal order. Scene::decals names overlay and base by their final indices.
void build_draw_groups(Scene& scene, std::vector<Instance> placed) {
    const OverlayClasses classes = classify_overlays(scene.meshes, placed);
    const std::vector<int32_t>& base = classes.decal_base;
    struct Key {
        uint32_t mesh;
        AlphaMode alpha_mode;
        bool double_sided;
        bool decal;
        auto operator<=>(const Key&) const = default;
    };
    std::map<Key, size_t> group_of;
    std::vector<std::vector<size_t>> members;  // per group, indices into `placed`
    for (size_t i = 0; i < placed.size(); ++i) {
        const uint32_t mesh = placed[i].mesh;
        const Material& material = scene.materials[scene.meshes[mesh].material];
        const Key key{mesh, material.alpha_mode, material.double_sided, base[i] >= 0};
        const auto [it, added] = group_of.try_emplace(key, scene.draw_groups.size());
        if (added) {
            scene.draw_groups.push_back({mesh, key.alpha_mode, key.double_sided, 0, 0, key.decal});
            members.emplace_back();
        }
        members[it->second].push_back(i);
    }
    std::vector<uint32_t> final_index(placed.size());
    for (size_t g = 0; g < scene.draw_groups.size(); ++g) {
        DrawGroup& group = scene.draw_groups[g];
        group.first_instance = static_cast<uint32_t>(scene.instances.size());
        group.instance_count = static_cast<uint32_t>(members[g].size());
        for (size_t i : members[g]) {
            final_index[i] = static_cast<uint32_t>(scene.instances.size());
            scene.instances.push_back(std::move(placed[i]));
        }
    }
    for (size_t i = 0; i < placed.size(); ++i)
        if (base[i] >= 0)
            scene.decals.push_back({final_index[i], final_index[static_cast<size_t>(base[i])]});
    std::sort(scene.decals.begin(), scene.decals.end(),
              [](const Decal& a, const Decal& b) { return a.instance < b.instance; });
    for (const BuriedOverlay& b : classes.buried)
        scene.buried.push_back({final_index[b.instance], final_index[b.base], b.gap});
    std::sort(
        scene.buried.begin(), scene.buried.end(),
        [](const BuriedOverlay& a, const BuriedOverlay& b) { return a.instance < b.instance; });
}

// A file camera without zfar asks for an infinite projection; the renderer wants a finite
// range, so reach past the far side of the scene instead.
void finite_far(Camera& camera, const Bounds& bounds) {
    if (camera.zfar != 0.0f) return;
    const float reach =
        glm::length(bounds.center() - camera.position) + glm::length(bounds.extent());
    camera.zfar = std::max(2.0f * reach, 1000.0f * camera.znear);
}

// Every camera node (placed ones with a finite far plane), the first perspective one as the
// scene's camera, else a view framed from the bounds.
void set_cameras(Scene& scene, SceneWalk walk) {
    for (SceneCamera& c : walk.cameras)
        if (c.camera) finite_far(*c.camera, scene.bounds);
    scene.cameras = std::move(walk.cameras);
    if (!walk.camera) {
        scene.camera = frame_bounds(scene.bounds);
        return;
    }
    finite_far(*walk.camera, scene.bounds);
    scene.file_camera = walk.camera;
    scene.camera = *walk.camera;
}

void add_warnings(const tinygltf::Model& model, Scene& scene, const MeshImport& meshes) {
    // What is not implemented: the file still draws (required ones were refused earlier), but
    // the user should know what is missing from the picture.
    for (const std::string& extension : model.extensionsUsed)
        if (!is_decoded_extension(extension))
            scene.warnings.push_back("extension " + one_line(extension) + " is ignored");
    for (const auto& [mode, count] : meshes.skipped_modes)
        scene.warnings.push_back("skipped " + std::to_string(count) + " " + mode +
                                 " primitive(s): only TRIANGLES are drawn");
    for (size_t i = 0; i < scene.materials.size(); ++i) {
        const Material& m = scene.materials[i];
        for (const TextureRef* ref :
             {&m.base_color, &m.metallic_roughness, &m.normal, &m.occlusion, &m.emissive}) {
            if (ref->present() && ref->uv_set != 0) {
                scene.warnings.push_back("material " + std::to_string(i) + " uses TEXCOORD_" +
                                         std::to_string(ref->uv_set) +
                                         ": only TEXCOORD_0 is imported");
                break;
            }
        }
    }
}

bool bounds_finite(const Bounds& b) {
    const glm::vec3 e = b.extent();
    return b.valid() && std::isfinite(b.min.x + b.min.y + b.min.z + b.max.x + b.max.y + b.max.z) &&
           std::isfinite(glm::length(e));
}

std::string nothing_to_draw(int scene_index, const MeshImport& meshes) {
    uint32_t skipped = 0;
    for (const auto& entry : meshes.skipped_modes) skipped += entry.second;
    std::string what =
        "nothing to draw: scene " + std::to_string(scene_index) + " places no triangle mesh";
    if (skipped > 0) what += " (skipped " + std::to_string(skipped) + " non-triangle primitives)";
    return what;
}

Scene import_checked(const tinygltf::Model& model, std::string name, std::string source,
                     const ImportOptions& options,
                     const std::map<size_t, std::string>& image_problems) {
    check_header(model);
    const int scene_index = pick_scene(model);
    validate_buffer_views(model);
    validate_accessors(model);

    Scene scene;
    scene.name = std::move(name);
    scene.source = std::move(source);
    scene.gltf_mesh_count = static_cast<uint32_t>(model.meshes.size());
    scene.images = import_images(model, image_problems);
    scene.samplers = import_samplers(model);
    UnusableTextures unusable;
    scene.textures = import_textures(model, static_cast<uint32_t>(scene.samplers.size() - 1),
                                     {image_problems, options.strict}, scene.images, unusable);
    scene.materials = import_materials(model);
    const std::vector<std::string> dropped = drop_unusable_textures(scene.materials, unusable);
    const auto default_material = static_cast<uint32_t>(scene.materials.size());
    const MeshImport meshes = import_meshes(model, default_material, scene.meshes);
    if (meshes.uses_default_material) {
        Material fallback;
        fallback.name = "default";
        scene.materials.push_back(fallback);
    }

    SceneWalk walk = walk_scene(model, scene_index);
    build_draw_groups(scene, place_instances(walk.placements, meshes));
    if (scene.instances.empty()) fail(nothing_to_draw(scene_index, meshes));
    for (const Instance& instance : scene.instances)
        scene.bounds.extend(transform_bounds(scene.meshes[instance.mesh].bounds, instance.world));
    if (!bounds_finite(scene.bounds)) fail("scene bounds are not finite");

    mark_srgb_images(scene.materials, scene.textures, scene.images);
    set_cameras(scene, std::move(walk));
    scene.warnings = dropped;
    add_warnings(model, scene, meshes);
    return scene;
}

}  // namespace

Scene import_model(const tinygltf::Model& model, std::string name, std::string source,
                   const ImportOptions& options) {
    return detail::import_parsed(model, std::move(name), std::move(source), options, {});
}

Scene detail::import_parsed(const tinygltf::Model& model, std::string name, std::string source,
                            const ImportOptions& options,
                            const std::map<size_t, std::string>& image_problems) {
    const std::string prefix = source;
    try {
        return import_checked(model, std::move(name), std::move(source), options, image_problems);
    } catch (const InputError& e) {
        throw InputError(prefix + ": " + one_line(e.what()));
    }
}

}  // namespace ds::scene
