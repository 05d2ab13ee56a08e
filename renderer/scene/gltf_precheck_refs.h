#pragma once
// The part of the precheck (gltf_precheck.h) that looks at values rather than JSON types, on
// the parsed document, before tinygltf: data: URIs, buffer view strides and ranges that
// tinygltf would use unchecked or report without saying where, accessor types, the accessors a
// primitive names, and the files the document references.
// Internal to renderer/scene; errors are InputError "JSON.PATH: WHAT".
#include <vector>

#include <nlohmann/json.hpp>

#include "renderer/scene/gltf_precheck.h"

namespace ds::scene::detail {

// `doc` has passed the JSON type checks. Returns the buffers and images that name files.
std::vector<FileRef> check_references(const nlohmann::json& doc);

}  // namespace ds::scene::detail
