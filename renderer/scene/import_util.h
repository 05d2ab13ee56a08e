#pragma once
// Small helpers shared by the glTF import files. Internal to renderer/scene.
#include <cfloat>
#include <cmath>
#include <string>
#include <string_view>

#include "renderer/common/error.h"
#include "renderer/common/quoted.h"

namespace ds::scene::detail {

// Import helpers throw InputError with a WHAT only; import_model / load_gltf prefix the source
// ("FILE: WHAT"), so one message format holds for files and built-in scenes alike.
[[noreturn]] inline void fail(std::string what) {
    throw InputError(std::move(what));
}

// A double from the file as a float; NaN, Inf and values beyond float range are rejected (the
// conversion itself would be undefined behaviour).
inline float to_float(double value, const std::string& what) {
    if (!std::isfinite(value) || std::fabs(value) > double{FLT_MAX}) fail(what + " is not finite");
    return static_cast<float>(value);
}

// The first non-empty line of `text`, trimmed, with control characters replaced: error
// messages end up on one line of `depthscope: error: ...`.
inline std::string one_line(std::string_view text) {
    std::string line;
    for (char c : text) {
        if (c == '\n' || c == '\r') {
            if (line.find_first_not_of(' ') != std::string::npos) break;
            line.clear();
            continue;
        }
        const auto u = static_cast<unsigned char>(c);
        line.push_back(u < 0x20 || u == 0x7f ? ' ' : c);
    }
    const size_t first = line.find_first_not_of(' ');
    if (first == std::string::npos) return {};
    const size_t last = line.find_last_not_of(' ');
    return line.substr(first, last - first + 1);
}

// A name for the start of a message ("PATH: WHAT"): a path may hold any byte but '/' and NUL,
// so control characters are escaped as everywhere else (renderer/common/quoted.h), keeping the
// message on one line.
inline std::string printable(std::string_view text) {
    return escaped(text);
}

// A value from the file, quoted for a message: one line, at most 200 characters shown (a uri
// may be megabytes long).
inline std::string quote_value(std::string_view text) {
    constexpr size_t kShown = 200;
    std::string line = one_line(text.substr(0, kShown + 1));
    if (line.size() > kShown) line = line.substr(0, kShown) + "...";
    return "\"" + line + "\"";
}

// The compression extensions decoded (gltf_prepare.h, gltf_decode.h).
inline constexpr const char* kMeshoptExtension = "EXT_meshopt_compression";
inline constexpr const char* kDracoExtension = "KHR_draco_mesh_compression";

// Extensions the importer implements (no "is ignored" warning).
inline bool is_decoded_extension(std::string_view name) {
    return name == "KHR_mesh_quantization" || name == kMeshoptExtension ||
           name == kDracoExtension || name == "KHR_texture_transform";
}

// Extensions that may appear in `extensionsRequired`: the ones decoded (mesh quantization,
// meshopt and Draco compression, texture transforms) and the ones ignored because they only
// add shading detail (the base PBR material stays a faithful approximation) or name texture
// formats whose textures are dropped with a warning (gltf_material.cpp).
inline bool is_supported_required_extension(std::string_view name) {
    return name.starts_with("KHR_materials_") || name == "KHR_texture_transform" ||
           name == "KHR_lights_punctual" || name == "KHR_mesh_quantization" ||
           name == "EXT_meshopt_compression" || name == "KHR_draco_mesh_compression" ||
           name == "KHR_texture_basisu" || name == "EXT_texture_webp";
}

// Why a required extension is refused, named where a reason is known.
inline std::string unsupported_extension_message(std::string_view name) {
    std::string message = "required extension " + one_line(name) + " is not supported";
    if (name == "KHR_meshopt_compression")
        message +=
            " (Debian's meshoptimizer 0.18 decodes EXT_meshopt_compression only; "
            "gltfpack -c writes that, -cz this)";
    return message;
}

// glTF 2.x only; an absent version means a glTF 1.0 file (2.0 made `asset.version` required).
inline bool is_supported_version(std::string_view version) {
    return version.starts_with("2.");
}

inline std::string version_message(std::string_view version) {
    const std::string shown = version.empty() || version == "1" ? "1.0" : std::string(version);
    return "glTF " + shown + " is not supported (need 2.0)";
}

}  // namespace ds::scene::detail
