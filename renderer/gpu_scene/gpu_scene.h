#pragma once
// A Scene on the GPU: one vertex and one index buffer for every mesh, the instance buffer
// (model + normal matrices), textures with mips, samplers, and one descriptor set per
// material (lavapipe has no descriptor indexing). Immutable once built, but for the
// material_alpha_cutoff overrides and the MASK base colours' mips (alpha_mip_coverage,
// gpu_scene_alpha.cpp); set_scene() replaces the whole object.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/common/surface_name.h"
#include "renderer/scene/alpha_coverage.h"
#include "renderer/scene/scene.h"
#include "renderer/vk/buffer.h"
#include "renderer/vk/descriptors.h"
#include "renderer/vk/destroy_list.h"
#include "renderer/vk/image.h"
#include "renderer/vk/upload.h"

namespace ds {

namespace vk {
class Context;
}

// std140 twin of MaterialUniforms in shaders/common/bindings.glsl (flags: kMaterial* bits).
struct GpuMaterial {
    glm::vec4 base_color_factor{1.0f};
    glm::vec4 emissive_factor{0.0f};
    float metallic_factor = 1.0f;
    float roughness_factor = 1.0f;
    float normal_scale = 1.0f;
    float occlusion_strength = 1.0f;
    float alpha_cutoff = 0.5f;  // the glTF material's own
    uint32_t flags = 0;
    float alpha_cutoff_override = -1.0f;  // material_alpha_cutoff, < 0: none
    float pad = 0.0f;
    // Per texture (kTexture* order), KHR_texture_transform as two rows (a, b, tx, 0) and
    // (c, d, ty, 0): u' = a u + b v + tx, v' = c u + d v + ty. Identity without the extension.
    glm::vec4 uv_rows[10] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {1, 0, 0, 0}, {0, 1, 0, 0}, {1, 0, 0, 0},
                             {0, 1, 0, 0}, {1, 0, 0, 0}, {0, 1, 0, 0}, {1, 0, 0, 0}, {0, 1, 0, 0}};
};
static_assert(sizeof(GpuMaterial) == 224);
static_assert(offsetof(GpuMaterial, uv_rows) == 64);
static_assert(offsetof(GpuMaterial, alpha_cutoff_override) == 56);
inline constexpr uint32_t kMaterialHasNormalMap = 1u;
inline constexpr uint32_t kMaterialAlphaMask = 2u;  // alphaMode MASK (one-pipeline prepass)

// std430 twin of InstanceData.
struct GpuInstance {
    glm::mat4 model{1.0f};
    glm::mat4 normal_matrix{1.0f};
    uint32_t surface_base = 0;  // surface id of the instance's triangle 0 (SurfaceTable)
    uint32_t draw_group = 0;    // its scene::DrawGroup (count_draws' per-draw counters)
    uint32_t pad[2] = {};
};
static_assert(sizeof(GpuInstance) == 144);

// Surfaces (docs/history/issue-10.md): each triangle of each instance is one surface, id
// `base + triangle + 1` (0: nothing drawn). The table names them for reports and readouts.
struct SurfaceInstance {
    uint32_t base = 0;       // id of triangle 0, minus 1
    uint32_t triangles = 0;  // of its mesh
    uint32_t mesh = 0;       // scene::Scene indices
    uint32_t material = 0;
    std::string node;
};
struct SurfaceRef {
    uint32_t instance = 0;  // index into SurfaceTable::instances (= scene instance index)
    uint32_t triangle = 0;
};
struct SurfaceTable {
    std::vector<SurfaceInstance> instances;  // in scene instance order
    std::vector<std::string> mesh_names, material_names;
    // The instance and triangle of a surface id; none for 0 or an id past the last surface.
    std::optional<SurfaceRef> find(uint32_t id) const;
    // How reports name an instance's surfaces: its mesh, material and node.
    SurfaceName name(uint32_t instance) const;
};

struct GpuMesh {
    uint32_t first_index = 0;
    uint32_t index_count = 0;
    int32_t vertex_offset = 0;
    uint32_t material = 0;
};

// Material set bindings (set 1): uniforms, then the five textures in this order.
enum MaterialBinding : uint32_t {
    kMaterialUniforms = 0,
    kBaseColorTexture = 1,
    kMetallicRoughnessTexture = 2,
    kNormalTexture = 3,
    kOcclusionTexture = 4,
    kEmissiveTexture = 5,
};
// The layout every pass that draws materials binds as set 1.
vk::DescriptorSetLayout create_material_set_layout(vk::Context& context);

class GpuScene {
  public:
    GpuScene(vk::Context& context, const scene::Scene& scene,
             VkDescriptorSetLayout material_layout);  // uploads and waits

    VkBuffer vertex_buffer() const { return vertices_.handle(); }
    VkBuffer index_buffer() const { return indices_.handle(); }
    VkBuffer instance_buffer() const { return instances_.handle(); }
    VkDescriptorSet material_set(uint32_t material) const { return material_sets_.at(material); }

    const std::vector<GpuMesh>& meshes() const { return meshes_; }
    const SurfaceTable& surfaces() const { return surfaces_; }
    // A debug-utils label around a draw group's draw, named as reports name the group (its
    // first instance's node), so tools that see the frame's commands (`depthscope layer`,
    // RenderDoc) can tell the draws apart. No-ops without VK_EXT_debug_utils.
    void begin_group_label(VkCommandBuffer cmd, uint32_t group) const;
    void end_group_label(VkCommandBuffer cmd) const;
    const std::vector<scene::DrawGroup>& draw_groups() const { return draw_groups_; }
    // Per scene instance, the index of its draw group (groups partition the instances).
    const std::vector<uint32_t>& instance_groups() const { return instance_groups_; }
    // Groups of coplanar overlays (scene::DrawGroup::decal): the decals pass's.
    size_t decal_groups() const {
        return size_t(std::count_if(draw_groups_.begin(), draw_groups_.end(),
                                    [](const scene::DrawGroup& g) { return g.decal; }));
    }
    // World-space centre of each instance's bounds (sorting blended draws).
    const std::vector<glm::vec3>& instance_centers() const { return instance_centers_; }
    // World-space box of each instance (its mesh's box through its matrix: the eight corners'
    // box), on the host and as a storage buffer (std430 vec4 min, vec4 max per instance): the
    // Hi-Z pass's per-draw test.
    const std::vector<scene::Bounds>& instance_bounds() const { return instance_bounds_; }
    VkBuffer instance_bounds_buffer() const { return bounds_buffer_.handle(); }
    // How each image's mip chain was filled (the report says which path ran).
    const std::vector<vk::MipFill>& mip_fills() const { return mip_fills_; }

    // material_alpha_cutoff (name -> cutoff): the cutoff of every MASK material of that name,
    // which wins over alpha_cutoff and the material's own (common/bindings.glsl); materials not
    // named get none. Throws UsageError, listing the scene's MASK materials, for a name that is
    // none of them. Rewrites the material uniforms only when the overrides change, and then
    // waits for the device to be idle first: frames in flight read them.
    void set_alpha_cutoff_overrides(const std::map<std::string, float, std::less<>>& by_name);

    // alpha_mip_coverage for the MASK materials with a base colour texture, at each one's
    // effective cutoff (scene::effective_alpha_cutoff: its override as set above, else
    // `global_cutoff`, else its own). Preserve binds, per (image, cutoff, baseColorFactor.a),
    // an image whose mips were made on the CPU with level 0's coverage (scene::
    // preserved_mip_chain); box binds the scene's image (blitted mips). Does only what changed:
    // new images are uploaded (and waited for), the material sets are rewritten after the
    // device is idle (frames in flight read them), images no longer bound are retired to
    // `retired` (vk/destroy_list.h), never destroyed here. Call after the overrides.
    void set_alpha_mips(scene::AlphaMipMode mode, std::optional<float> global_cutoff,
                        vk::DestroyList& retired);
    // Per MASK material with a base colour texture (material order), as set_alpha_mips last
    // left them: the box chain's coverage per level, and the uploaded chain's with preserve.
    const std::vector<scene::MaterialAlphaCoverage>& alpha_coverage() const {
        return alpha_coverage_;
    }

  private:
    void upload_geometry(const scene::Scene& scene, vk::UploadBatch& batch);
    void upload_instances(const scene::Scene& scene, vk::UploadBatch& batch);
    void upload_bounds(vk::UploadBatch& batch);
    void upload_textures(const scene::Scene& scene, vk::UploadBatch& batch);
    vk::MipFill upload_image(const vk::Image& dst, const scene::Image& img, vk::UploadBatch& batch);
    void create_samplers(const scene::Scene& scene);
    static bool texture_valid(const scene::Scene& scene, const scene::TextureRef& ref);
    // View and sampler for a texture reference; the fallback image when it is missing.
    std::pair<VkImageView, VkSampler> texture_binding(const scene::Scene& scene,
                                                      const scene::TextureRef& ref,
                                                      uint32_t fallback_image) const;
    void create_material_sets(const scene::Scene& scene, VkDescriptorSetLayout layout,
                              vk::UploadBatch& batch);

    struct MaterialKey {
        std::string name;
        bool masked = false;
    };
    // A MASK material's base colour (gpu_scene_alpha.cpp): its scene image, kept on the host
    // for preserve's chains, and the binding it has without them.
    struct MaskedBase {
        uint32_t material = 0;
        uint32_t image = 0;
        scene::Material source;
        VkImageView view = VK_NULL_HANDLE;
        VkSampler sampler = VK_NULL_HANDLE;
    };
    // One chain: an image at a cutoff and a baseColorFactor.a.
    struct AlphaKey {
        uint32_t image = 0;
        float cutoff = 0.0f, factor = 1.0f;
        auto operator<=>(const AlphaKey&) const = default;
    };
    struct PreservedImage {
        vk::Image image;
        std::vector<scene::LevelCoverage> coverage;
    };
    void remember_masked(const scene::Scene& scene, uint32_t material, VkImageView view,
                         VkSampler sampler);
    const std::vector<scene::LevelCoverage>& box_coverage(const AlphaKey& key);
    PreservedImage& preserved(const AlphaKey& key, vk::UploadBatch& batch);
    void bind_base_colors(const std::vector<std::optional<AlphaKey>>& want);

    vk::Context& context_;
    std::string scene_name_;
    std::vector<MaterialKey> material_keys_;  // per material
    std::vector<float> cutoff_overrides_;     // per material, as uploaded; < 0: none
    std::vector<uint8_t> material_bytes_;     // the material uniforms as uploaded
    VkDeviceSize material_stride_ = 0;
    vk::Buffer vertices_;
    vk::Buffer indices_;
    vk::Buffer instances_;
    vk::Buffer material_uniforms_;
    std::vector<vk::Image> images_;  // scene images, then the two defaults
    std::vector<vk::Sampler> samplers_;
    vk::DescriptorPool pool_;
    std::vector<VkDescriptorSet> material_sets_;
    std::vector<GpuMesh> meshes_;
    std::vector<scene::DrawGroup> draw_groups_;
    std::vector<uint32_t> instance_groups_;
    std::vector<glm::vec3> instance_centers_;
    std::vector<scene::Bounds> instance_bounds_;
    vk::Buffer bounds_buffer_;
    SurfaceTable surfaces_;
    std::vector<std::string> group_labels_;
    std::vector<vk::MipFill> mip_fills_;
    // alpha_mip_coverage (gpu_scene_alpha.cpp): what set_alpha_mips last made.
    std::vector<MaskedBase> masked_;
    std::map<uint32_t, scene::Image> masked_images_;  // masked_'s images by index (level 0)
    std::map<AlphaKey, std::vector<scene::LevelCoverage>> box_coverage_;
    std::map<AlphaKey, PreservedImage> preserved_;  // bound now (stable addresses)
    std::vector<std::optional<AlphaKey>> bound_;    // per masked_: its preserved image
    std::vector<scene::MaterialAlphaCoverage> alpha_coverage_;
    std::optional<std::pair<scene::AlphaMipMode, std::vector<float>>> alpha_state_;
    uint32_t white_image_ = 0;  // indices into images_
    uint32_t flat_normal_image_ = 0;
};

}  // namespace ds
