#pragma once
// Textures a scene cannot use (a missing or undecodable image file, an image only in an
// extension that is not decoded) are dropped from the materials, which keep their factors:
// for a depth tool a base colour matters only where a masked material tests its alpha. One
// warning line per cause (an image file, an extension) names the textures it takes and what
// each material that used them does now.
// Internal to renderer/scene.
#include <string>
#include <vector>

#include "renderer/scene/gltf_material.h"

namespace ds::scene::detail {

std::vector<std::string> drop_unusable_textures(std::vector<Material>& materials,
                                                const UnusableTextures& unusable);

}  // namespace ds::scene::detail
