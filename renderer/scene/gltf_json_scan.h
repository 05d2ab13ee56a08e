#pragma once
// A byte scan of a glTF document's JSON text, made before any JSON parser sees it: both
// nlohmann::json (the precheck) and tinygltf recurse once per nesting level, and both allocate
// per array entry, so depth and entry counts are bounded here first (import_limits.h).
// Internal to renderer/scene; errors are InputError "byte N: WHAT" (N counts from the start
// of the file).
#include <cstddef>
#include <string_view>

namespace ds::scene::detail {

// `text` is the JSON; `base` is its offset in the file (20 for a GLB JSON chunk).
// Checks nesting depth (objects and arrays, strings and escapes respected, extras and
// extensions included) and the entries of each top-level array (kMaxNodes for `nodes`).
void scan_json_limits(std::string_view text, size_t base);

}  // namespace ds::scene::detail
