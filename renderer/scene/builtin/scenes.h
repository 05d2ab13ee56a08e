#pragma once
// One builder per built-in scene (one .cpp each); builtin.cpp dispatches by name. A scene
// with knobs declares them in its file (knob.h) and the scene list gathers them.
#include <vector>

#include <tiny_gltf.h>

#include "renderer/settings/knob.h"

namespace ds::scene::builtin {

tinygltf::Model build_atrium(const Settings& settings);
tinygltf::Model build_overdraw(const Settings& settings);
std::vector<SettingDef> overdraw_knobs();
tinygltf::Model build_zfight(const Settings& settings);
std::vector<SettingDef> zfight_knobs();
tinygltf::Model build_foliage(const Settings& settings);
tinygltf::Model build_edges(const Settings& settings);
tinygltf::Model build_decals(const Settings& settings);

}  // namespace ds::scene::builtin
