#include "renderer/settings/settings.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>
#include <sstream>

#include "renderer/common/error.h"
#include "renderer/common/quoted.h"

namespace ds {
namespace {

SettingDef bool_knob(std::string name, std::string group, bool def, std::string help,
                     Invalidates inv) {
    return SettingDef{std::move(name),
                      std::move(group),
                      SettingType::Bool,
                      def ? "on" : "off",
                      0,
                      0,
                      {"on", "off"},
                      std::move(help),
                      inv};
}

SettingDef enum_knob(std::string name, std::string group, std::vector<std::string> choices,
                     std::string help, Invalidates inv) {
    std::string def = choices.front();
    return SettingDef{std::move(name),
                      std::move(group),
                      SettingType::Enum,
                      std::move(def),
                      0,
                      0,
                      std::move(choices),
                      std::move(help),
                      inv};
}

// `allowed`: when given, the only values within min..max that the knob takes.
SettingDef int_knob(std::string name, std::string group, int def, int min, int max,
                    std::string help, Invalidates inv, std::vector<std::string> allowed = {}) {
    return SettingDef{std::move(name),     std::move(group), SettingType::Int,
                      std::to_string(def), double(min),      double(max),
                      std::move(allowed),  std::move(help),  inv};
}

SettingDef float_knob(std::string name, std::string group, std::string def, double min, double max,
                      std::string help, Invalidates inv) {
    return SettingDef{std::move(name),
                      std::move(group),
                      SettingType::Float,
                      std::move(def),
                      min,
                      max,
                      {},
                      std::move(help),
                      inv};
}

SettingDef map_knob(std::string name, std::string group, double min, double max, std::string help,
                    Invalidates inv) {
    return SettingDef{std::move(name),
                      std::move(group),
                      SettingType::Map,
                      "",
                      min,
                      max,
                      {},
                      std::move(help),
                      inv};
}

// A depth plane: "scene" (the scene camera's) or a distance; never a pipeline or resource
// change (the projection is a uniform).
SettingDef plane_knob(std::string name, std::string help) {
    SettingDef def = float_knob(std::move(name), "prepass and depth", "scene", 0, 1000000,
                                std::move(help), Invalidates::Nothing);
    def.choices = {"scene"};  // the keyword beside the number
    return def;
}

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

// The registry. Each issue that adds a knob adds it here, with help text.
SettingsRegistry::SettingsRegistry() {
    using I = Invalidates;
    defs_ = {
        // Prepass and depth.
        bool_knob("prepass", "prepass and depth", true,
                  "depth prepass; off: forward writes depth with GREATER (gtao and "
                  "contact_shadows need the prepass and are skipped)",
                  I::Nothing),
        // Which pipelines the prepass has; forward, GTAO and contact shadows adapt (DESIGN.md
        // "As built (issue 14: prepass_mode)").
        enum_knob("prepass_mode", "prepass and depth", {"gbuffer", "depth"},
                  "prepass on: gbuffer writes depth, normals and roughness (forward reads them); "
                  "depth is Z only (opaque: no fragment stage, masked: the alpha test), forward "
                  "computes normals and roughness itself and gtao / contact_shadows read normals "
                  "reconstructed from depth (normals_from_depth)",
                  I::Nothing),
        // Seed 002's tiler path (DESIGN.md "As built (issue 15: the subpass path)").
        enum_knob("render_path", "prepass and depth", {"dynamic", "subpass"},
                  "dynamic: every pass on its own (dynamic rendering); subpass: depth prepass, "
                  "forward and sky as two subpasses of one render pass, forward reading normals "
                  "and roughness as input attachments (tile memory on a tiler); needs the prepass; "
                  "gtao, contact_shadows and the per-pass diagnostics do not run on it",
                  I::Nothing),
        enum_knob("depth_compare", "prepass and depth", {"equal", "greater_or_equal"},
                  "forward pass depth test against the prepass depth (prepass on)", I::Nothing),
        bool_knob("masked_split", "prepass and depth", true,
                  "separate prepass pipeline for MASK materials; off: one pipeline with discard "
                  "for all geometry (loses early-Z)",
                  I::Nothing),
        bool_knob("prepass_sort", "prepass and depth", true,
                  "prepass draws opaque and masked instances front to back (prepass_mode=depth: "
                  "whole instanced groups, by their nearest instance; off: instanced groups in "
                  "the scene's authored order, every hidden layer shaded)",
                  I::Nothing),
        bool_knob("invariant", "prepass and depth", true,
                  "off: forward computes gl_Position with a different but mathematically equal "
                  "expression, to show what EQUAL does without invariance",
                  I::Pipelines),
        bool_knob("reverse_z", "prepass and depth", true,
                  "reverse-Z depth (clear 0, GREATER); off: clear 1, LESS", I::Nothing),
        // Which of these the device offers is checked per frame (the registry cannot know).
        enum_knob("depth_format", "prepass and depth", {"d32f", "d24", "d16"},
                  "scene depth format, as the device supports it: d32f D32_SFLOAT (else "
                  "D32_SFLOAT_S8_UINT), d24 D24_UNORM_S8_UINT (else X8_D24_UNORM_PACK32), d16 "
                  "D16_UNORM; the shadow map keeps its own",
                  I::Resources),
        // 0 passes the registry so that znear=0 meets the planes' own check (0 < znear < zfar,
        // checked against the scene camera's when rendering).
        plane_knob("znear",
                   "near plane in scene units; scene: the scene camera's own (must stay below "
                   "the far plane)"),
        plane_knob("zfar",
                   "far plane in scene units; scene: the scene camera's own (must stay above "
                   "the near plane)"),
        // A sample count Vulkan has (1, 2, 4, 8: anything else is a usage error); whether the
        // device supports it for colour and depth is checked per frame (the registry is
        // static, the device is not): lavapipe offers 1 and 4.
        int_knob("msaa", "msaa", 1, 1, 8,
                 "samples per pixel (1, 2, 4 or 8, as the device allows); > 1: depth, normals, "
                 "roughness and HDR colour are multisampled and resolved inline (depth keeps "
                 "the nearest sample)",
                 I::Pipelines, {"1", "2", "4", "8"}),
        bool_knob("sample_shading", "msaa", false,
                  "msaa > 1: forward shades every sample (minSampleShading 1), so specular "
                  "and texture detail inside a pixel is antialiased too, at up to msaa times "
                  "the shading cost",
                  I::Pipelines),
        // Alpha.
        SettingDef{"alpha_cutoff",
                   "alpha",
                   SettingType::Float,
                   "material",
                   0,
                   1,
                   {"material"},
                   "alpha test cutoff for MASK materials; material: each material's own "
                   "(material_alpha_cutoff wins over it)",
                   I::Nothing},
        // Checked against the scene when rendering: every NAME must be a MASK material.
        map_knob("material_alpha_cutoff", "alpha", 0, 1,
                 "per-material alpha test cutoff, NAME=V[,NAME=V...]: NAME a MASK material of "
                 "the scene by its glTF name (unnamed: 'material N', N its glTF index; a name "
                 "sets every material so named); wins over alpha_cutoff, which wins over the "
                 "material's own alphaCutoff",
                 I::Nothing),
        bool_knob("alpha_to_coverage", "alpha", false,
                  "msaa > 1: MASK materials turn alpha (sharpened around the cutoff) into "
                  "sample coverage instead of discarding, so cut-out edges are antialiased",
                  I::Pipelines),
        // Passes.
        bool_knob("shadows", "passes", true, "directional-light shadow map (PCF in forward)",
                  I::Nothing),
        bool_knob("gtao", "passes", true, "ground-truth AO from prepass depth and normals",
                  I::Nothing),
        bool_knob("contact_shadows", "passes", true, "screen-space march toward the sun",
                  I::Nothing),
        bool_knob("sky", "passes", true, "procedural sky behind the geometry", I::Nothing),
        bool_knob("decal_pass", "passes", true,
                  "coplanar overlays (classified at load: triangles lying on another surface and "
                  "inside it) skip shadow, prepass and forward and are drawn once by the decals "
                  "pass after forward; off: drawn like any surface (they Z-fight)",
                  I::Nothing),
        // Measurement.
        bool_knob("count_fragments", "measurement", false,
                  "count, per pixel, the fragments each geometry pass (shadow, prepass, "
                  "forward, decals, transparent) rasterized, shaded and discarded, and its "
                  "quads (report: rasterized_fragments, shaded_fragments, "
                  "discarded_fragments, quad_overdraw)",
                  I::Pipelines),
        bool_knob("count_discards", "measurement", false,
                  "count fragments the masked prepass pipeline ran and discarded "
                  "(masked_discards in the report)",
                  I::Pipelines),
        bool_knob("count_draws", "measurement", false,
                  "per draw group: visible pixels (from surface_id), samples passed (a precise "
                  "occlusion query per draw in the prepass, or forward without it) and shaded "
                  "fragments per counting pass (report draws, Draws panel; turns on "
                  "count_fragments and surface_id)",
                  I::Pipelines),
        // Diagnostics: each adds its passes and images only when on.
        bool_knob("surface_id", "diagnostics", false,
                  "the prepass also writes surface_id: per pixel, the surface (triangle of an "
                  "instance) that won the depth test (on whenever zfight is)",
                  I::Pipelines),
        bool_knob("zfight", "diagnostics", false,
                  "Z-fight detector: re-rasterises opaque and masked geometry and counts, per "
                  "pixel, other surfaces within zfight_steps depth steps of the stored depth "
                  "(image zfight, report zfight)",
                  I::Pipelines),
        int_knob("zfight_steps", "diagnostics", 4, 0, 1024,
                 "zfight: the largest gap, in representable steps of the depth format (ULPs of "
                 "D32_SFLOAT, unorm steps of D24 / D16), that still counts as a fight",
                 I::Nothing),
        bool_knob("depth_precision", "diagnostics", false,
                  "image depth_precision: per pixel, the distance along the view ray to the "
                  "next representable depth value (format, planes, direction), in scene units "
                  "(on whenever zfight is)",
                  I::Nothing),
        bool_knob("hiz", "diagnostics", false,
                  "prepass on: the hiz pass builds a Hi-Z pyramid from the prepass depth "
                  "(images hiz.0 ... hiz.N, each texel the farthest of its children; at msaa > 1 "
                  "level 0 is the farthest sample); with count_draws each draw's screen bounds "
                  "are tested against it (report draws[].hiz next to samples_passed)",
                  I::Nothing),
        bool_knob("equal_check", "diagnostics", false,
                  "prepass on, depth_compare=equal, msaa=1: marks pixels the prepass covered "
                  "that forward did not shade (holes) and pixels forward shaded more than once "
                  "(ties); image equal_check, report equal_check (turns on count_fragments)",
                  I::Pipelines),
        int_knob("overdraw_layers", "scene", 8, 1, 64,
                 "overdraw scene: number of view-filling quads, drawn back to front", I::Scene),
        int_knob("zfight_pairs", "scene", 6, 1, 16,
                 "zfight scene: number of coplanar / nearly coplanar quad pairs", I::Scene),
        float_knob("sun_azimuth", "lighting", "35", -360, 360,
                   "sun direction around the vertical axis, degrees", I::Nothing),
        float_knob("sun_elevation", "lighting", "55", 1, 90,
                   "sun height above the horizon, degrees", I::Nothing),
        float_knob("sun_intensity", "lighting", "3", 0, 100, "sun illuminance (linear scale)",
                   I::Nothing),
        float_knob("ambient", "lighting", "0.35", 0, 10,
                   "hemispherical sky/ground ambient strength", I::Nothing),
        float_knob("exposure", "lighting", "1", 0.01, 64,
                   "exposure multiplier applied before tonemapping", I::Nothing),
        SettingDef{"fov",
                   "camera",
                   SettingType::Float,
                   "scene",
                   10,
                   120,
                   {"scene"},
                   "vertical field of view in degrees; scene: the scene camera's own",
                   I::Nothing},
        float_knob("render_scale", "camera", "1", 0.25, 2,
                   "inspector: the frame renders at the viewer's size times this (below 1 keeps "
                   "a CPU device interactive); capture and bench render at --size",
                   I::Resources),
        float_knob("motion_scale", "camera", "0.5", 0.1, 1,
                   "inspector: while the camera moves, frames render at this times the render "
                   "size, and at the full size once it stops",
                   I::Nothing),
        bool_knob("continuous", "camera", false,
                  "inspector: render a scene frame every UI frame (for the timing history); "
                  "off: only when something that affects the frame changed",
                  I::Nothing),
    };
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
