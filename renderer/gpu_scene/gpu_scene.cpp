#include "renderer/gpu_scene/gpu_scene.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "renderer/common/error.h"
#include "renderer/common/quoted.h"
#include "renderer/vk/check.h"
#include "renderer/vk/context.h"

namespace ds {
namespace {

constexpr VkDeviceSize kMinBufferSize = 16;  // Vulkan forbids empty buffers

// The box of `object`'s eight corners through `world` (an empty box stays empty).
scene::Bounds instance_world_bounds(const scene::Bounds& object, const glm::mat4& world) {
    scene::Bounds out;
    if (!object.valid()) return out;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p(corner & 1 ? object.max.x : object.min.x,
                          corner & 2 ? object.max.y : object.min.y,
                          corner & 4 ? object.max.z : object.min.z);
        out.extend(glm::vec3(world * glm::vec4(p, 1.0f)));
    }
    return out;
}

VkFilter filter(scene::Filter f) {
    return f == scene::Filter::Nearest ? VK_FILTER_NEAREST : VK_FILTER_LINEAR;
}

VkSamplerAddressMode address(scene::Wrap w) {
    switch (w) {
        case scene::Wrap::ClampToEdge:
            return VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
        case scene::Wrap::MirroredRepeat:
            return VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT;
        case scene::Wrap::Repeat:
            return VK_SAMPLER_ADDRESS_MODE_REPEAT;
    }
    return VK_SAMPLER_ADDRESS_MODE_REPEAT;
}

VkSamplerCreateInfo sampler_info(const scene::Sampler& s) {
    auto info = vk::make<VkSamplerCreateInfo>(VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO);
    info.magFilter = filter(s.mag);
    info.minFilter = filter(s.min);
    info.mipmapMode = s.mip == scene::Filter::Nearest ? VK_SAMPLER_MIPMAP_MODE_NEAREST
                                                      : VK_SAMPLER_MIPMAP_MODE_LINEAR;
    info.addressModeU = address(s.wrap_s);
    info.addressModeV = address(s.wrap_t);
    info.addressModeW = VK_SAMPLER_ADDRESS_MODE_REPEAT;
    // glTF min filters without a mipmap mode sample level 0 only.
    info.maxLod = s.mipmaps ? VK_LOD_CLAMP_NONE : 0.0f;
    return info;
}

glm::mat4 normal_matrix(const glm::mat4& model) {
    const glm::mat3 m(model);
    // A collapsed (zero-scale) instance has no inverse; its normals no longer matter.
    if (std::abs(glm::determinant(m)) < 1e-30f) return glm::mat4(m);
    return glm::mat4(glm::transpose(glm::inverse(m)));
}

GpuMaterial gpu_material(const scene::Material& m, bool has_normal_map) {
    GpuMaterial g;
    g.base_color_factor = m.base_color_factor;
    g.emissive_factor = glm::vec4(m.emissive_factor, 0.0f);
    g.metallic_factor = m.metallic_factor;
    g.roughness_factor = m.roughness_factor;
    g.normal_scale = m.normal_scale;
    g.occlusion_strength = m.occlusion_strength;
    g.alpha_cutoff = m.alpha_cutoff;
    g.flags = (has_normal_map ? kMaterialHasNormalMap : 0u) |
              (m.alpha_mode == scene::AlphaMode::Mask ? kMaterialAlphaMask : 0u);
    // The binding order of the material set: base colour, metallic-roughness, normal,
    // occlusion, emissive (shaders/common/bindings.glsl, kTexture*).
    const scene::TextureRef* refs[] = {&m.base_color, &m.metallic_roughness, &m.normal,
                                       &m.occlusion, &m.emissive};
    for (size_t i = 0; i < 5; ++i) {
        const std::array<glm::vec3, 2> rows = refs[i]->uv_rows();
        g.uv_rows[2 * i] = glm::vec4(rows[0], 0.0f);
        g.uv_rows[2 * i + 1] = glm::vec4(rows[1], 0.0f);
    }
    return g;
}

}  // namespace

vk::DescriptorSetLayout create_material_set_layout(vk::Context& context) {
    const VkShaderStageFlags frag = VK_SHADER_STAGE_FRAGMENT_BIT;
    const VkDescriptorType image = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    const VkDescriptorSetLayoutBinding bindings[] = {
        vk::layout_binding(kMaterialUniforms, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, frag),
        vk::layout_binding(kBaseColorTexture, image, frag),
        vk::layout_binding(kMetallicRoughnessTexture, image, frag),
        vk::layout_binding(kNormalTexture, image, frag),
        vk::layout_binding(kOcclusionTexture, image, frag),
        vk::layout_binding(kEmissiveTexture, image, frag),
    };
    return vk::DescriptorSetLayout(context, bindings, "material set layout");
}

GpuScene::GpuScene(vk::Context& context, const scene::Scene& scene,
                   VkDescriptorSetLayout material_layout)
    : context_(context), scene_name_(scene.name), draw_groups_(scene.draw_groups) {
    for (const scene::DrawGroup& group : draw_groups_) {
        // The passes index meshes and instances by these without further checks.
        if (group.mesh >= scene.meshes.size() ||
            uint64_t(group.first_instance) + group.instance_count > scene.instances.size())
            throw Error("scene: a draw group names a missing mesh or instance");
    }
    vk::UploadBatch batch(context);
    upload_geometry(scene, batch);
    upload_instances(scene, batch);
    upload_textures(scene, batch);
    create_samplers(scene);
    create_material_sets(scene, material_layout, batch);
    batch.submit();
    for (size_t g = 0; g < draw_groups_.size(); ++g)
        group_labels_.push_back(draw_groups_[g].instance_count > 0
                                    ? surfaces_.name(draw_groups_[g].first_instance).node
                                    : "group " + std::to_string(g));
}

void GpuScene::begin_group_label(VkCommandBuffer cmd, uint32_t group) const {
    context_.debug().begin_label(cmd, group_labels_.at(group).c_str(), {0.9f, 0.7f, 0.3f, 1.0f});
}

void GpuScene::end_group_label(VkCommandBuffer cmd) const {
    context_.debug().end_label(cmd);
}

void GpuScene::upload_geometry(const scene::Scene& scene, vk::UploadBatch& batch) {
    std::vector<scene::Vertex> vertices;
    std::vector<uint32_t> indices;
    for (const scene::Mesh& mesh : scene.meshes) {
        if (mesh.material >= scene.materials.size())
            throw Error("scene: mesh '" + mesh.name + "' names a missing material");
        meshes_.push_back({uint32_t(indices.size()), uint32_t(mesh.indices.size()),
                           int32_t(vertices.size()), mesh.material});
        vertices.insert(vertices.end(), mesh.vertices.begin(), mesh.vertices.end());
        indices.insert(indices.end(), mesh.indices.begin(), mesh.indices.end());
    }
    const VkDeviceSize vbytes = vertices.size() * sizeof(scene::Vertex);
    const VkDeviceSize ibytes = indices.size() * sizeof(uint32_t);
    // Storage usage too: compute passes (triangle_size) fetch positions and indices.
    vertices_ = vk::Buffer(context_,
                           {std::max(vbytes, kMinBufferSize),
                            VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
                                VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                            vk::MemoryUsage::GpuOnly, "scene vertices"});
    indices_ = vk::Buffer(context_,
                          {std::max(ibytes, kMinBufferSize),
                           VK_BUFFER_USAGE_INDEX_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
                               VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                           vk::MemoryUsage::GpuOnly, "scene indices"});
    batch.buffer(vertices_, vertices.data(), vbytes);
    batch.buffer(indices_, indices.data(), ibytes);
}

std::optional<SurfaceRef> SurfaceTable::find(uint32_t id) const {
    if (id == 0) return std::nullopt;
    const uint32_t index = id - 1;
    // The last instance whose base is at or below the index.
    auto it = std::upper_bound(instances.begin(), instances.end(), index,
                               [](uint32_t v, const SurfaceInstance& s) { return v < s.base; });
    if (it == instances.begin()) return std::nullopt;
    --it;
    if (index - it->base >= it->triangles) return std::nullopt;
    return SurfaceRef{uint32_t(it - instances.begin()), index - it->base};
}

SurfaceName SurfaceTable::name(uint32_t instance) const {
    const SurfaceInstance& s = instances.at(instance);
    return {mesh_names.at(s.mesh), material_names.at(s.material), s.node};
}

void GpuScene::upload_instances(const scene::Scene& scene, vk::UploadBatch& batch) {
    std::vector<GpuInstance> gpu;
    gpu.reserve(scene.instances.size());
    for (const scene::Mesh& mesh : scene.meshes) surfaces_.mesh_names.push_back(mesh.name);
    for (const scene::Material& m : scene.materials) surfaces_.material_names.push_back(m.name);
    instance_groups_.assign(scene.instances.size(), 0);
    for (size_t g = 0; g < draw_groups_.size(); ++g)
        for (uint32_t i = 0; i < draw_groups_[g].instance_count; ++i)
            instance_groups_[draw_groups_[g].first_instance + i] = uint32_t(g);
    uint64_t base = 0;
    for (const scene::Instance& inst : scene.instances) {
        if (inst.mesh >= scene.meshes.size()) throw Error("scene: instance of a missing mesh");
        const scene::Mesh& mesh = scene.meshes[inst.mesh];
        const uint32_t triangles = uint32_t(mesh.indices.size() / 3);
        if (base + triangles >= UINT32_MAX)
            throw Error("scene: more than 2^32 - 2 triangles in all instances (surface ids)");
        surfaces_.instances.push_back(
            {uint32_t(base), triangles, inst.mesh, mesh.material, inst.node});
        gpu.push_back({inst.world,
                       normal_matrix(inst.world),
                       uint32_t(base),
                       instance_groups_[gpu.size()],
                       {}});
        base += triangles;
        const glm::vec3 center = scene.meshes[inst.mesh].bounds.center();
        instance_centers_.push_back(glm::vec3(inst.world * glm::vec4(center, 1.0f)));
        instance_bounds_.push_back(instance_world_bounds(mesh.bounds, inst.world));
    }
    upload_bounds(batch);
    const VkDeviceSize bytes = gpu.size() * sizeof(GpuInstance);
    instances_ =
        vk::Buffer(context_, {std::max(bytes, kMinBufferSize),
                              VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                              vk::MemoryUsage::GpuOnly, "scene instances"});
    batch.buffer(instances_, gpu.data(), bytes);
}

void GpuScene::upload_bounds(vk::UploadBatch& batch) {
    std::vector<glm::vec4> boxes;
    boxes.reserve(instance_bounds_.size() * 2);
    for (const scene::Bounds& b : instance_bounds_) {
        boxes.emplace_back(b.min, 0.0f);
        boxes.emplace_back(b.max, 0.0f);
    }
    const VkDeviceSize bytes = boxes.size() * sizeof(glm::vec4);
    bounds_buffer_ =
        vk::Buffer(context_, {std::max(bytes, kMinBufferSize),
                              VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                              vk::MemoryUsage::GpuOnly, "scene instance bounds"});
    batch.buffer(bounds_buffer_, boxes.data(), bytes);
}

void GpuScene::upload_textures(const scene::Scene& scene, vk::UploadBatch& batch) {
    const VkImageUsageFlags usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                                    VK_IMAGE_USAGE_TRANSFER_SRC_BIT;  // blit source for mips
    images_.reserve(scene.images.size() + 2);  // batch keeps pointers to the images
    for (const scene::Image& img : scene.images) {
        if (img.width == 0 || img.height == 0 ||
            img.rgba8.size() != size_t(img.width) * img.height * 4)
            throw Error("scene: image '" + img.name + "' has no or inconsistent RGBA8 data");
        images_.emplace_back(
            context_,
            vk::ImageDesc{img.width, img.height, vk::mip_level_count(img.width, img.height),
                          img.srgb ? VK_FORMAT_R8G8B8A8_SRGB : VK_FORMAT_R8G8B8A8_UNORM, usage,
                          VK_SAMPLE_COUNT_1_BIT, img.name.c_str()});
        mip_fills_.push_back(upload_image(images_.back(), img, batch));
    }
    // 1x1 defaults for missing textures: white (factor only) and a flat tangent-space normal.
    const uint8_t white[4] = {255, 255, 255, 255};
    const uint8_t flat[4] = {128, 128, 255, 255};
    white_image_ = uint32_t(images_.size());
    images_.emplace_back(context_, vk::ImageDesc{1, 1, 1, VK_FORMAT_R8G8B8A8_UNORM, usage,
                                                 VK_SAMPLE_COUNT_1_BIT, "default white"});
    batch.texture(images_.back(), white);
    flat_normal_image_ = uint32_t(images_.size());
    images_.emplace_back(context_, vk::ImageDesc{1, 1, 1, VK_FORMAT_R8G8B8A8_UNORM, usage,
                                                 VK_SAMPLE_COUNT_1_BIT, "default normal"});
    batch.texture(images_.back(), flat);
}

// Level 0 with blitted mips, or where the format cannot be blitted every level of the CPU's
// box chain (scene/alpha_mips.h: sRGB colour averaged in linear light).
vk::MipFill GpuScene::upload_image(const vk::Image& dst, const scene::Image& img,
                                   vk::UploadBatch& batch) {
    if (dst.mip_levels() == 1 || vk::supports_blit_mips(context_, dst.format()))
        return batch.texture(dst, img.rgba8.data());
    const std::vector<scene::MipImage> chain =
        scene::box_mip_chain(img.width, img.height, img.rgba8, img.srgb);
    std::vector<const uint8_t*> levels;
    for (const scene::MipImage& level : chain) levels.push_back(level.rgba8.data());
    return batch.texture(dst, levels);  // copied into the staging buffer here
}

void GpuScene::create_samplers(const scene::Scene& scene) {
    for (const scene::Sampler& s : scene.samplers)
        samplers_.emplace_back(context_, sampler_info(s), "scene sampler");
    samplers_.emplace_back(context_, sampler_info(scene::Sampler{}), "default sampler");
}

bool GpuScene::texture_valid(const scene::Scene& scene, const scene::TextureRef& ref) {
    return ref.present() && size_t(ref.texture) < scene.textures.size() &&
           scene.textures[size_t(ref.texture)].image < scene.images.size();
}

std::pair<VkImageView, VkSampler> GpuScene::texture_binding(const scene::Scene& scene,
                                                            const scene::TextureRef& ref,
                                                            uint32_t fallback_image) const {
    if (!texture_valid(scene, ref))
        return {images_[fallback_image].view(), samplers_.back().handle()};
    const scene::Texture& tex = scene.textures[size_t(ref.texture)];
    // samplers_ mirrors scene.samplers, plus our default at the end.
    const size_t sampler = tex.sampler < scene.samplers.size() ? tex.sampler : samplers_.size() - 1;
    return {images_[tex.image].view(), samplers_[sampler].handle()};
}

void GpuScene::create_material_sets(const scene::Scene& scene, VkDescriptorSetLayout layout,
                                    vk::UploadBatch& batch) {
    const uint32_t count = uint32_t(scene.materials.size());
    const uint32_t sets = std::max(count, 1u);  // a pool must allow at least one set
    const VkDeviceSize stride =
        vk::align_up(sizeof(GpuMaterial), context_.limits().minUniformBufferOffsetAlignment);
    material_stride_ = stride;
    std::vector<uint8_t>& bytes = material_bytes_;
    bytes.assign(std::max<VkDeviceSize>(stride * count, kMinBufferSize), 0);
    cutoff_overrides_.assign(count, -1.0f);
    const VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, sets},
                                          {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 5 * sets}};
    pool_ = vk::DescriptorPool(context_, sets, sizes, "material sets");
    material_uniforms_ =
        vk::Buffer(context_, {bytes.size(),
                              VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                              vk::MemoryUsage::GpuOnly, "material uniforms"});

    for (uint32_t i = 0; i < count; ++i) {
        const scene::Material& m = scene.materials[i];
        material_keys_.push_back({m.name, m.alpha_mode == scene::AlphaMode::Mask});
        const GpuMaterial g = gpu_material(m, texture_valid(scene, m.normal));
        std::memcpy(bytes.data() + i * stride, &g, sizeof g);

        material_sets_.push_back(pool_.allocate(layout));
        vk::DescriptorWriter writer;
        writer.buffer(kMaterialUniforms, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
                      material_uniforms_.handle(), i * stride, sizeof(GpuMaterial));
        auto add = [&](uint32_t binding, const scene::TextureRef& ref, uint32_t fallback) {
            auto [view, sampler] = texture_binding(scene, ref, fallback);
            writer.image(binding, view, sampler);
        };
        add(kBaseColorTexture, m.base_color, white_image_);
        if (scene::masked_base_color_image(scene, i)) {
            auto [view, sampler] = texture_binding(scene, m.base_color, white_image_);
            remember_masked(scene, i, view, sampler);
        }
        add(kMetallicRoughnessTexture, m.metallic_roughness, white_image_);
        add(kNormalTexture, m.normal, flat_normal_image_);
        add(kOcclusionTexture, m.occlusion, white_image_);
        add(kEmissiveTexture, m.emissive, white_image_);
        writer.update(context_.device(), material_sets_.back());
    }
    batch.buffer(material_uniforms_, bytes.data(), bytes.size());
}

void GpuScene::set_alpha_cutoff_overrides(
    const std::map<std::string, float, std::less<>>& by_name) {
    std::vector<float> overrides(material_keys_.size(), -1.0f);
    for (const auto& [name, cutoff] : by_name) {
        bool found = false;
        for (size_t i = 0; i < material_keys_.size(); ++i) {
            if (!material_keys_[i].masked || material_keys_[i].name != name) continue;
            overrides[i] = cutoff;
            found = true;
        }
        if (found) continue;
        std::vector<std::string> masked;
        for (const MaterialKey& key : material_keys_)
            if (key.masked) masked.push_back(key.name);
        std::sort(masked.begin(), masked.end());
        masked.erase(std::unique(masked.begin(), masked.end()), masked.end());
        std::string list;
        for (const std::string& m : masked) list += (list.empty() ? "" : ", ") + m;
        throw UsageError("material_alpha_cutoff: no masked material \"" + escaped(name) + "\" in " +
                         scene_name_ + " (masked: " + (list.empty() ? "none" : list) + ")");
    }
    if (overrides == cutoff_overrides_) return;

    for (size_t i = 0; i < overrides.size(); ++i)
        std::memcpy(material_bytes_.data() + i * material_stride_ +
                        offsetof(GpuMaterial, alpha_cutoff_override),
                    &overrides[i], sizeof(float));
    // Every frame that may still read the uniforms finishes before the copy overwrites them
    // (Renderer::render already waits for its frame; a setting change is rare enough to pay).
    context_.wait_idle();
    vk::UploadBatch batch(context_);
    batch.buffer(material_uniforms_, material_bytes_.data(), material_bytes_.size());
    batch.submit();
    cutoff_overrides_ = std::move(overrides);
}

}  // namespace ds
