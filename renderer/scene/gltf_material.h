#pragma once
// glTF images, samplers, textures and materials -> Scene. Internal to renderer/scene; errors
// are InputError with a WHAT only.
#include <map>
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "renderer/scene/scene.h"

namespace ds::scene::detail {

// Images decoded to RGBA8 (1-4 components, 8 or 16 bits in). `srgb` is left false here. An
// image with a problem (index -> why: missing, undecodable) becomes a 1x1 white placeholder.
std::vector<Image> import_images(const tinygltf::Model& model,
                                 const std::map<size_t, std::string>& problems);
Image placeholder_image(std::string name);

// Textures the materials cannot use (texture index -> why: its image's problem, or an image
// only in an extension that is not decoded). gltf_dropped.h drops them from the materials.
using UnusableTextures = std::map<size_t, std::string>;

struct TextureInput {
    const std::map<size_t, std::string>& image_problems;
    bool strict = false;  // a texture without a usable image is an error, not a warning
};

// The file's samplers followed by one default sampler (linear, mipmapped, repeat), which
// textures without a sampler use.
std::vector<Sampler> import_samplers(const tinygltf::Model& model);

// A texture whose image is only in an extension gets a placeholder image appended to `images`.
std::vector<Texture> import_textures(const tinygltf::Model& model, uint32_t default_sampler,
                                     const TextureInput& in, std::vector<Image>& images,
                                     UnusableTextures& unusable);

std::vector<Material> import_materials(const tinygltf::Model& model);

// Marks images used as base colour or emissive as sRGB (colour data, not linear data).
void mark_srgb_images(const std::vector<Material>& materials, const std::vector<Texture>& textures,
                      std::vector<Image>& images);

}  // namespace ds::scene::detail
