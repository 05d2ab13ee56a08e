#pragma once
// The one settings registry (DESIGN decision 4). Every knob: name, type, default, allowed
// values or range, help text and what a change invalidates. The CLI (`--set name=value`), the
// UI, report.json and reproducing a capture all go through it.
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace ds {

// Map: a list of NAME=NUMBER pairs ("a=0.3,b=0.7"; empty: none), each number in min..max; the
// names are free text that the knob's user checks (material_alpha_cutoff: material names).
enum class SettingType { Bool, Int, Float, Enum, Map };

// What changing a knob invalidates, from cheapest to most expensive.
enum class Invalidates { Nothing, Pipelines, Resources, Scene };

struct SettingDef {
    std::string name;
    std::string group;  // "scene", "lighting", ... (UI grouping)
    SettingType type = SettingType::Bool;
    std::string default_value;
    double min = 0.0;  // Int / Float
    double max = 0.0;
    std::vector<std::string> choices;  // Enum ("on"/"off" for Bool); Float: keywords also allowed
    std::string help;
    Invalidates invalidates = Invalidates::Nothing;

    std::string type_name() const;   // "bool", "int", "float", "enum", "map"
    std::string range_text() const;  // "on|off", "1..64", "0.01..16", "a|b|c", "NAME=0..1,..."
};

class SettingsRegistry {
  public:
    static const SettingsRegistry& instance();
    const std::vector<SettingDef>& all() const { return defs_; }
    const SettingDef* find(std::string_view name) const;  // nullptr when unknown
    const SettingDef& at(std::string_view name) const;    // throws UsageError when unknown

  private:
    SettingsRegistry();
    std::vector<SettingDef> defs_;
};

// A full set of values, one per registered knob, stored in canonical text form.
class Settings {
  public:
    Settings();  // every knob at its default

    // Throws UsageError for an unknown name (listing the valid names) or a bad value (listing
    // what is allowed). Values are canonicalised ("true"/"1" -> "on", "0.50" -> "0.5"; a Map
    // " b = 0.50, a=1" -> "a=1,b=0.5": trimmed, sorted by name, numbers as for Float).
    void set(std::string_view name, std::string_view value);
    void apply(std::string_view assignment);  // "name=value"

    bool get_bool(std::string_view name) const;
    int get_int(std::string_view name) const;
    float get_float(std::string_view name) const;         // throws UsageError on a keyword value
    const std::string& get(std::string_view name) const;  // canonical text
    // A Map knob's pairs by name (empty when none); format_map() writes them back.
    std::map<std::string, float, std::less<>> get_map(std::string_view name) const;

    const std::map<std::string, std::string, std::less<>>& values() const { return values_; }
    // Knobs whose value differs from `other`, by name.
    std::vector<std::string> diff(const Settings& other) const;

  private:
    std::map<std::string, std::string, std::less<>> values_;
};

// A Map knob's value for `pairs`: "a=0.3,b=0.7" (sorted by name, numbers as Float writes them).
std::string format_map(const std::map<std::string, float, std::less<>>& pairs);

}  // namespace ds
