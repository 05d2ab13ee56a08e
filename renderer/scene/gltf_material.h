#pragma once
// glTF images, samplers, textures and materials -> Scene. Internal to renderer/scene; errors
// are InputError with a WHAT only.
#include <vector>

#include <tiny_gltf.h>

#include "renderer/scene/scene.h"

namespace ds::scene::detail {

// Images decoded to RGBA8 (1-4 components, 8 or 16 bits in). `srgb` is left false here.
std::vector<Image> import_images(const tinygltf::Model& model);

// The file's samplers followed by one default sampler (linear, mipmapped, repeat), which
// textures without a sampler use.
std::vector<Sampler> import_samplers(const tinygltf::Model& model);

std::vector<Texture> import_textures(const tinygltf::Model& model, uint32_t default_sampler);

std::vector<Material> import_materials(const tinygltf::Model& model);

// Marks images used as base colour or emissive as sRGB (colour data, not linear data).
void mark_srgb_images(const std::vector<Material>& materials, const std::vector<Texture>& textures,
                      std::vector<Image>& images);

}  // namespace ds::scene::detail
