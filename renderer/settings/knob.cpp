#include "renderer/settings/knob.h"

#include <utility>

namespace ds {

bool knob_value(const Settings& s, Knob<bool> k) {
    return s.get_bool(k.name);
}
int knob_value(const Settings& s, Knob<int> k) {
    return s.get_int(k.name);
}
float knob_value(const Settings& s, Knob<float> k) {
    return s.get_float(k.name);
}
std::optional<float> knob_value(const Settings& s, Knob<OptionalFloat> k) {
    const std::string& text = s.get(k.name);
    for (const std::string& keyword : SettingsRegistry::instance().at(k.name).choices)
        if (text == keyword) return std::nullopt;
    return s.get_float(k.name);
}
const std::string& knob_value(const Settings& s, Knob<KnobEnum> k) {
    return s.get(k.name);
}
std::map<std::string, float, std::less<>> knob_value(const Settings& s, Knob<KnobMap> k) {
    return s.get_map(k.name);
}

SettingDef bool_knob(Knob<bool> k, std::string group, bool def, std::string help, Invalidates inv) {
    return SettingDef{k.name,
                      std::move(group),
                      SettingType::Bool,
                      def ? "on" : "off",
                      0,
                      0,
                      {"on", "off"},
                      std::move(help),
                      inv};
}

SettingDef enum_knob(Knob<KnobEnum> k, std::string group, std::vector<std::string> choices,
                     std::string help, Invalidates inv) {
    std::string def = choices.front();
    return SettingDef{k.name,
                      std::move(group),
                      SettingType::Enum,
                      std::move(def),
                      0,
                      0,
                      std::move(choices),
                      std::move(help),
                      inv};
}

SettingDef int_knob(Knob<int> k, std::string group, int def, int min, int max, std::string help,
                    Invalidates inv, std::vector<std::string> allowed) {
    return SettingDef{k.name,      std::move(group), SettingType::Int,   std::to_string(def),
                      double(min), double(max),      std::move(allowed), std::move(help),
                      inv};
}

SettingDef float_knob(Knob<float> k, std::string group, std::string def, double min, double max,
                      std::string help, Invalidates inv) {
    return SettingDef{
        k.name, std::move(group), SettingType::Float, std::move(def), min, max, {}, std::move(help),
        inv};
}

SettingDef optional_float_knob(Knob<OptionalFloat> k, std::string group, std::string keyword,
                               std::string def, double min, double max, std::string help,
                               Invalidates inv) {
    return SettingDef{k.name,
                      std::move(group),
                      SettingType::Float,
                      std::move(def),
                      min,
                      max,
                      {std::move(keyword)},
                      std::move(help),
                      inv};
}

SettingDef map_knob(Knob<KnobMap> k, std::string group, double min, double max, std::string help,
                    Invalidates inv) {
    return SettingDef{k.name, std::move(group), SettingType::Map, "", min, max, {}, std::move(help),
                      inv};
}

}  // namespace ds
