#pragma once
// The settings of depthscope's Vulkan layer (issue 29), given as `depthscope layer --set k=v`
// and passed to the layer in DEPTHSCOPE_LAYER_SETTINGS: the launcher refuses a bad one before
// the application starts, the layer reads the same names with the same rules. Names and
// ranges are those of depthscope's own knobs.
//   zfight=on|off       Z-fight pairs between depth-writing draws (off)
//   zfight_steps=0..1024 the largest gap, in steps of the attachment's depth format (4)
//   equal_check=on|off  holes and ties of EQUAL-tested draws against an earlier prepass (off)
#include <cstdint>
#include <map>
#include <string>

#include "renderer/common/error.h"

namespace ds {

struct LayerSettings {
    bool zfight = false;
    uint32_t zfight_steps = 4;
    bool equal_check = false;

    static constexpr uint32_t kMaxZfightSteps = 1024;
    // What the depth-writing passes need recorded: the nearest fragment and those near it.
    bool depth_records() const { return zfight || equal_check; }
};

namespace layer_settings_detail {

inline bool on_off(const std::string& name, const std::string& value) {
    if (value == "on") return true;
    if (value == "off") return false;
    throw UsageError("layer: setting '" + name + "' expects on or off, got '" + value + "'");
}

inline uint32_t steps(const std::string& value) {
    const bool digits = !value.empty() && value.size() <= 5 &&
                        value.find_first_not_of("0123456789") == std::string::npos;
    if (!digits || std::stoul(value) > LayerSettings::kMaxZfightSteps)
        throw UsageError("layer: setting 'zfight_steps' expects a whole number from 0 to " +
                         std::to_string(LayerSettings::kMaxZfightSteps) + ", got '" + value + "'");
    return uint32_t(std::stoul(value));
}

}  // namespace layer_settings_detail

// Throws UsageError (one sentence) for an unknown name or a bad value.
inline LayerSettings parse_layer_settings(const std::map<std::string, std::string>& pairs) {
    LayerSettings s;
    for (const auto& [name, value] : pairs) {
        if (name == "zfight")
            s.zfight = layer_settings_detail::on_off(name, value);
        else if (name == "equal_check")
            s.equal_check = layer_settings_detail::on_off(name, value);
        else if (name == "zfight_steps")
            s.zfight_steps = layer_settings_detail::steps(value);
        else
            throw UsageError("layer: unknown setting '" + name +
                             "' (the layer's settings: zfight, zfight_steps, equal_check)");
    }
    return s;
}

}  // namespace ds
