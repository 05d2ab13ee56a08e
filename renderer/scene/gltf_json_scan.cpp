#include "renderer/scene/gltf_json_scan.h"

#include <string>

#include "renderer/scene/import_limits.h"
#include "renderer/scene/import_util.h"

namespace ds::scene::detail {
namespace {

// The top-level array being counted ("nodes", "meshes", ...): its key and entries so far.
struct TopArray {
    std::string key;
    size_t entries = 0;
    bool open = false;
    size_t limit() const { return key == "nodes" ? limits::kMaxNodes : limits::kMaxArrayEntries; }
};

bool is_space(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}

// Index just past the string that opens at `i` (a '"'); an unterminated string ends the text
// (the parser reports it later).
size_t skip_string(std::string_view text, size_t i) {
    for (++i; i < text.size(); ++i) {
        if (text[i] == '\\')
            ++i;
        else if (text[i] == '"')
            return i + 1;
    }
    return text.size();
}

}  // namespace

void scan_json_limits(std::string_view text, size_t base) {
    int depth = 0;
    std::string last_top_key;  // the latest string seen directly inside the top-level object
    TopArray array;
    auto at = [&](size_t i) { return "byte " + std::to_string(base + i) + ": "; };
    size_t i = 0;
    while (i < text.size()) {
        const char c = text[i];
        if (array.open && depth == 2 && !is_space(c) && c != ']' && c != ',' && array.entries == 0)
            array.entries = 1;  // the first entry starts
        if (c == '"') {
            const size_t end = skip_string(text, i);
            if (depth == 1 && text[end - 1] == '"') last_top_key = text.substr(i + 1, end - i - 2);
            i = end;
            continue;
        }
        if (c == '{' || c == '[') {
            if (++depth > limits::kMaxJsonDepth)
                fail(at(i) + "JSON nested more than " + std::to_string(limits::kMaxJsonDepth) +
                     " levels deep (the limit)");
            if (c == '[' && depth == 2) array = {last_top_key, 0, true};
        } else if (c == '}' || c == ']') {
            if (depth == 2) array.open = false;
            depth = depth > 0 ? depth - 1 : 0;  // unbalanced: the parser reports it
        } else if (c == ',' && array.open && depth == 2) {
            if (++array.entries > array.limit())
                fail(at(i) + one_line(array.key) + " has more than " +
                     std::to_string(array.limit()) + " entries (the limit)");
        }
        ++i;
    }
}

}  // namespace ds::scene::detail
