#pragma once
// The files of one shader compile: how `#include` names resolve, how files are named in
// messages, and the text of each file read once, so the cache key and glslang see the same
// bytes even if a file is edited mid-compile.
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ds::shader {

struct IncludeDirective {
    std::string header;   // as written between the quotes or angle brackets
    bool system = false;  // <...> rather than "..."
};

// Every `#include` line of a GLSL text, in order. A deliberately simple scan (no #if
// evaluation): it may find more includes than glslang will take, never fewer.
std::vector<IncludeDirective> scan_includes(std::string_view text);

class SourceTree {
  public:
    explicit SourceTree(std::filesystem::path root);

    const std::filesystem::path& root() const { return root_; }

    // Name used in messages and by glslang: relative to the root ("common/brdf.glsl"), or the
    // absolute path for a file outside it.
    std::string name_of(const std::filesystem::path& absolute) const;
    // Inverse of name_of.
    std::filesystem::path path_of(std::string_view name) const;

    // Same search as glslangValidator -I<root>: "..." looks next to the including file first,
    // then in the root; <...> looks in the root only. Returns an absolute, normalised path.
    std::optional<std::filesystem::path> resolve(const IncludeDirective& include,
                                                 std::string_view includer_name) const;

    // The file's text, read on first use and kept; nullptr if it cannot be read.
    const std::string* read(const std::filesystem::path& absolute);

  private:
    std::filesystem::path root_;
    // std::map: node-based, so the strings handed to glslang never move.
    std::map<std::filesystem::path, std::optional<std::string>> texts_;
};

// A source and what it includes, recursively, as the scan sees it: what the cache key covers.
struct Dependencies {
    std::vector<std::filesystem::path> files;  // resolved and readable, first-seen order
    std::vector<std::string> unresolved;       // "includer -> header" entries that did not resolve
};
Dependencies collect_dependencies(SourceTree& tree, const std::filesystem::path& main_file);

}  // namespace ds::shader
