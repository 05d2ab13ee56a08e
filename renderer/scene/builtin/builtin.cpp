#include "renderer/scene/builtin/builtin.h"

#include <array>

#include "renderer/common/error.h"
#include "renderer/scene/builtin/scenes.h"

namespace ds::scene::builtin {

namespace {

using BuildFn = tinygltf::Model (*)(const Settings&);

struct Entry {
    const char* name;
    const char* description;
    BuildFn build;
    std::vector<SettingDef> (*knobs)() = nullptr;  // the scene's own knobs, if any
};

// The first entry is the default scene.
constexpr std::array<Entry, 6> kScenes = {{
    {"atrium",
     "Sponza-like courtyard: two floors of arcades, curtains, masked foliage, coplanar decals",
     build_atrium},
    {"overdraw", "overdraw_layers view-filling opaque quads at known depths, drawn back to front",
     build_overdraw, overdraw_knobs},
    {"zfight", "coplanar and nearly coplanar quad pairs from 1 m to 5 km (znear 0.01, zfar 1e4)",
     build_zfight, zfight_knobs},
    {"foliage", "alpha-masked cards with an alpha ramp (0 to 1 across) for cutoff tuning",
     build_foliage},
    {"edges", "thin rods, wires, gratings and slanted slabs on a bright backdrop (MSAA)",
     build_edges},
    {"decals",
     "room corner with OPAQUE, MASK and BLEND overlays lying exactly on its walls and floor",
     build_decals},
}};

// The registry's scene knobs, in list order (settings/knob.h).
std::vector<SettingDef> scene_knobs() {
    return gather_knobs(kScenes);
}
const KnobSource kSceneKnobs(KnobOwner::Scenes, &scene_knobs);

const Entry* find(std::string_view name) {
    for (const Entry& e : kScenes) {
        if (name == e.name) return &e;
    }
    return nullptr;
}

}  // namespace

const std::vector<Info>& list() {
    static const std::vector<Info> infos = [] {
        std::vector<Info> out;
        for (const Entry& e : kScenes) out.push_back({e.name, e.description});
        return out;
    }();
    return infos;
}

bool exists(std::string_view name) {
    return find(name) != nullptr;
}

tinygltf::Model build(std::string_view name, const Settings& settings) {
    const Entry* entry = find(name);
    if (entry == nullptr) {
        std::string valid;
        for (const Entry& e : kScenes) valid += (valid.empty() ? "" : ", ") + std::string(e.name);
        throw UsageError("unknown built-in scene '" + std::string(name) + "' (valid: " + valid +
                         ")");
    }
    return entry->build(settings);
}

}  // namespace ds::scene::builtin
