#include "renderer/settings/settings.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <sstream>

#include "renderer/common/error.h"
#include "renderer/common/quoted.h"
#include "renderer/settings/frame_knobs.h"
#include "renderer/settings/knob.h"

namespace ds {
namespace {

// Shortest text that reads back to the same float ("0.5", "45", "1e-05").
std::string format_number(double v) {
    std::ostringstream out;
    out.precision(7);
    out << v;
    return out.str();
}

std::string join(const std::vector<std::string>& items, std::string_view sep) {
    std::string out;
    for (size_t i = 0; i < items.size(); ++i) {
        if (i) out += sep;
        out += items[i];
    }
    return out;
}

std::string canonical_bool(const SettingDef& def, std::string_view v) {
    if (v == "on" || v == "true" || v == "1" || v == "yes") return "on";
    if (v == "off" || v == "false" || v == "0" || v == "no") return "off";
    throw UsageError("setting " + def.name + ": " + quote(v) + " is not on|off");
}

// A Float or Map number must reach the float that get_float() / get_map() return as itself or
// as a normal float: a denormal (or anything below FLT_MIN) would turn into 0 or a denormal
// there, which the registry's range check never saw.
// The stored text has 7 digits, so the check is on the value read back from it.
bool fits_normal_float(double value) {
    const std::string text = format_number(value);
    double stored = 0.0;
    std::from_chars(text.data(), text.data() + text.size(), stored);
    const double magnitude = std::fabs(stored);
    return value == 0.0 || (magnitude >= std::numeric_limits<float>::min() &&
                            magnitude <= std::numeric_limits<float>::max());
}

// `entry`: a Map's entry name, said in the message. Only what std::from_chars reads whole is a
// number: no sign but '-', no spaces, no hex, no inf/nan.
double parse_number(const SettingDef& def, std::string_view v, std::string_view entry = {}) {
    const std::string subject =
        "setting " + def.name + (entry.empty() ? "" : ": " + escaped(entry));
    const std::string range = def.type == SettingType::Map
                                  ? format_number(def.min) + ".." + format_number(def.max)
                                  : def.range_text();
    double value = 0.0;
    const char* end = v.data() + v.size();
    auto [ptr, ec] = std::from_chars(v.data(), end, value);
    if (v.empty() || ec != std::errc() || ptr != end || !std::isfinite(value)) {
        throw UsageError(subject + ": " + quote(v) + " is not a number (" + def.type_name() +
                         " in " + range + ")");
    }
    if (def.type != SettingType::Int && !fits_normal_float(value)) {
        throw UsageError(subject + ": " + std::string(v) +
                         " is too small for a float (nonzero values need a magnitude of at "
                         "least 1.17549e-38)");
    }
    if (value == 0.0) value = 0.0;  // -0 reads as 0
    if (value < def.min || value > def.max) {
        throw UsageError(subject + ": " + std::string(v) + " is out of range " + range);
    }
    return value;
}

std::string_view trim(std::string_view v) {
    while (!v.empty() && std::isspace(static_cast<unsigned char>(v.front()))) v.remove_prefix(1);
    while (!v.empty() && std::isspace(static_cast<unsigned char>(v.back()))) v.remove_suffix(1);
    return v;
}

// A Map value: comma-separated NAME=V entries (names and values trimmed; a name may hold '=',
// the value follows the last one), each name once, each V a number in min..max.
std::map<std::string, double, std::less<>> parse_map(const SettingDef& def, std::string_view text) {
    std::map<std::string, double, std::less<>> pairs;
    const std::string_view all = trim(text);
    if (all.empty()) return pairs;
    const std::string subject = "setting " + def.name + ": ";
    const std::string expected = " (expected NAME=V[,NAME=V...] with V in " +
                                 format_number(def.min) + ".." + format_number(def.max) + ")";
    for (size_t start = 0;;) {
        const size_t comma = std::min(all.find(',', start), all.size());
        const std::string_view entry = trim(all.substr(start, comma - start));
        const size_t eq = entry.rfind('=');
        if (entry.empty()) throw UsageError(subject + "empty entry in " + quote(all) + expected);
        if (eq == std::string_view::npos)
            throw UsageError(subject + quote(entry) + " is not NAME=V" + expected);
        const std::string_view name = trim(entry.substr(0, eq));
        if (name.empty()) throw UsageError(subject + quote(entry) + " has no name" + expected);
        const double value = parse_number(def, trim(entry.substr(eq + 1)), name);
        if (!pairs.emplace(std::string(name), value).second)
            throw UsageError(subject + escaped(name) + " is given twice");
        if (comma == all.size()) break;
        start = comma + 1;
    }
    return pairs;
}

// Sorted by name (the map's order), numbers as Float writes them.
std::string canonical_map(const SettingDef& def, std::string_view v) {
    std::vector<std::string> entries;
    for (const auto& [name, value] : parse_map(def, v))
        entries.push_back(name + "=" + format_number(value));
    return join(entries, ",");
}

// An Int within min..max (ints by construction) and, when the knob lists them, one of its
// choices (msaa: the sample counts Vulkan has; which the device offers is checked per frame).
std::string canonical_int(const SettingDef& def, std::string_view v) {
    const double value = parse_number(def, v);
    if (value != std::floor(value)) {
        throw UsageError("setting " + def.name + ": " + quote(v) + " is not an integer (" +
                         def.range_text() + ")");
    }
    std::string text = std::to_string(static_cast<long long>(value));
    if (!def.choices.empty() &&
        std::find(def.choices.begin(), def.choices.end(), text) == def.choices.end()) {
        throw UsageError("setting " + def.name + ": " + text + " is not one of " +
                         def.range_text());
    }
    return text;
}

std::string canonical_value(const SettingDef& def, std::string_view v) {
    switch (def.type) {
        case SettingType::Bool:
            return canonical_bool(def, v);
        case SettingType::Int:
            return canonical_int(def, v);
        case SettingType::Float:
            for (const auto& keyword : def.choices) {
                if (keyword == v) return keyword;
            }
            return format_number(parse_number(def, v));
        case SettingType::Enum:
            for (const auto& c : def.choices) {
                if (c == v) return c;
            }
            throw UsageError("setting " + def.name + ": " + quote(v) + " is not one of " +
                             def.range_text());
        case SettingType::Map:
            return canonical_map(def, v);
    }
    return std::string(v);
}

}  // namespace

std::string SettingDef::type_name() const {
    switch (type) {
        case SettingType::Bool:
            return "bool";
        case SettingType::Int:
            return "int";
        case SettingType::Float:
            return "float";
        case SettingType::Enum:
            return "enum";
        case SettingType::Map:
            return "map";
    }
    return "?";
}

std::string SettingDef::range_text() const {
    switch (type) {
        case SettingType::Bool:
        case SettingType::Enum:
            return join(choices, "|");
        case SettingType::Int:
            return choices.empty() ? format_number(min) + ".." + format_number(max)
                                   : join(choices, "|");
        case SettingType::Float: {
            const std::string range = format_number(min) + ".." + format_number(max);
            return choices.empty() ? range : join(choices, "|") + "|" + range;
        }
        case SettingType::Map:
            return "NAME=" + format_number(min) + ".." + format_number(max) + ",...";
    }
    return "";
}

namespace {

struct Sources {
    std::vector<std::pair<KnobOwner, KnobSource::Declare>> list;
    bool frozen = false;  // the registry was built: a later source would be missed
};
Sources& sources() {
    static Sources s;
    return s;
}

}  // namespace

KnobSource::KnobSource(KnobOwner owner, Declare declare) {
    Sources& s = sources();
    if (s.frozen) {
        std::fputs("depthscope: error: a knob source registered after the registry was built\n",
                   stderr);
        std::abort();
    }
    s.list.emplace_back(owner, declare);
}

// The frame-wide knobs, then every registered source by owner (passes, scenes, inspector),
// each in its own declaration order. A name declared twice is a programming error.
SettingsRegistry::SettingsRegistry() {
    Sources& s = sources();
    s.frozen = true;
    defs_ = knobs::frame_knobs();
    std::stable_sort(s.list.begin(), s.list.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    for (const auto& [owner, declare] : s.list)
        for (SettingDef& def : declare()) defs_.push_back(std::move(def));
    for (size_t i = 0; i < defs_.size(); ++i)
        for (size_t j = 0; j < i; ++j)
            if (defs_[i].name == defs_[j].name) {
                std::fprintf(stderr, "depthscope: error: knob %s is declared twice\n",
                             defs_[i].name.c_str());
                std::abort();
            }
}

const SettingsRegistry& SettingsRegistry::instance() {
    static const SettingsRegistry registry;
    return registry;
}

const SettingDef* SettingsRegistry::find(std::string_view name) const {
    for (const auto& d : defs_) {
        if (d.name == name) return &d;
    }
    return nullptr;
}

const SettingDef& SettingsRegistry::at(std::string_view name) const {
    if (const SettingDef* d = find(name)) return *d;
    std::vector<std::string> names;
    for (const auto& d : defs_) names.push_back(d.name);
    throw UsageError("unknown setting " + quote(name) + " (valid: " + join(names, ", ") + ")");
}

Settings::Settings() {
    for (const auto& d : SettingsRegistry::instance().all()) values_[d.name] = d.default_value;
}

void Settings::set(std::string_view name, std::string_view value) {
    const SettingDef& def = SettingsRegistry::instance().at(name);
    values_[def.name] = canonical_value(def, value);
}

void Settings::apply(std::string_view assignment) {
    const size_t eq = assignment.find('=');
    if (eq == std::string_view::npos || eq == 0) {
        throw UsageError("--set expects name=value, got " + quote(assignment));
    }
    set(assignment.substr(0, eq), assignment.substr(eq + 1));
}

std::map<std::string, float, std::less<>> Settings::get_map(std::string_view name) const {
    const SettingDef& def = SettingsRegistry::instance().at(name);
    if (def.type != SettingType::Map) throw UsageError("setting " + def.name + " is not a map");
    std::map<std::string, float, std::less<>> out;
    for (const auto& [key, value] : parse_map(def, get(name))) out.emplace(key, float(value));
    return out;
}

const std::string& Settings::get(std::string_view name) const {
    auto it = values_.find(name);
    if (it == values_.end()) SettingsRegistry::instance().at(name);  // throws with the list
    return it->second;
}

bool Settings::get_bool(std::string_view name) const {
    return get(name) == "on";
}

// The stored text is canonical (set() made it), so these conversions succeed; should one not,
// it is a ds::Error, never a std exception from stoi/stof.
int Settings::get_int(std::string_view name) const {
    const std::string& value = get(name);
    int out = 0;
    const auto [ptr, ec] = std::from_chars(value.data(), value.data() + value.size(), out);
    if (ec != std::errc() || ptr != value.data() + value.size())
        throw Error("setting " + std::string(name) + ": " + quote(value) + " is not an int");
    return out;
}

float Settings::get_float(std::string_view name) const {
    const std::string& value = get(name);
    for (const auto& keyword : SettingsRegistry::instance().at(name).choices) {
        if (value == keyword) {
            throw UsageError("setting " + std::string(name) + " is " + quote(value) +
                             ", not a number");
        }
    }
    float out = 0.0f;
    const auto [ptr, ec] = std::from_chars(value.data(), value.data() + value.size(), out);
    if (ec != std::errc() || ptr != value.data() + value.size() || !std::isfinite(out))
        throw Error("setting " + std::string(name) + ": " + quote(value) + " is not a float");
    return out;
}

std::vector<std::string> Settings::diff(const Settings& other) const {
    std::vector<std::string> names;
    for (const auto& [name, value] : values_) {
        if (other.get(name) != value) names.push_back(name);
    }
    return names;
}

std::string format_map(const std::map<std::string, float, std::less<>>& pairs) {
    std::vector<std::string> entries;
    for (const auto& [name, value] : pairs) entries.push_back(name + "=" + format_number(value));
    return join(entries, ",");
}

}  // namespace ds
