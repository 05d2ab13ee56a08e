#pragma once
// One builder per built-in scene (one .cpp each); builtin.cpp dispatches by name.
#include <tiny_gltf.h>

#include "renderer/settings/settings.h"

namespace ds::scene::builtin {

tinygltf::Model build_atrium(const Settings& settings);
tinygltf::Model build_overdraw(const Settings& settings);
tinygltf::Model build_zfight(const Settings& settings);
tinygltf::Model build_foliage(const Settings& settings);
tinygltf::Model build_edges(const Settings& settings);
tinygltf::Model build_decals(const Settings& settings);

}  // namespace ds::scene::builtin
