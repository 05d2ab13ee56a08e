#include "renderer/shader/source_tree.h"

#include <cctype>
#include <fstream>
#include <set>
#include <sstream>

namespace ds::shader {

namespace fs = std::filesystem;

namespace {

void skip_blanks(std::string_view line, size_t& i) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
}

// Parses `# include "x"` / `#include <x>` at the start of a line (after blanks).
std::optional<IncludeDirective> parse_include_line(std::string_view line) {
    size_t i = 0;
    skip_blanks(line, i);
    if (i >= line.size() || line[i] != '#') return std::nullopt;
    ++i;
    skip_blanks(line, i);
    constexpr std::string_view kKeyword = "include";
    if (line.substr(i, kKeyword.size()) != kKeyword) return std::nullopt;
    i += kKeyword.size();
    skip_blanks(line, i);
    if (i >= line.size() || (line[i] != '"' && line[i] != '<')) return std::nullopt;
    const char close = line[i] == '"' ? '"' : '>';
    const size_t end = line.find(close, i + 1);
    if (end == std::string_view::npos) return std::nullopt;
    return IncludeDirective{std::string(line.substr(i + 1, end - i - 1)), close == '>'};
}

bool is_file(const fs::path& path) {
    std::error_code ec;
    return fs::is_regular_file(path, ec);
}

}  // namespace

std::vector<IncludeDirective> scan_includes(std::string_view text) {
    std::vector<IncludeDirective> includes;
    size_t start = 0;
    while (start <= text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        if (auto include = parse_include_line(text.substr(start, end - start))) {
            includes.push_back(std::move(*include));
        }
        start = end + 1;
    }
    return includes;
}

SourceTree::SourceTree(fs::path root) : root_(std::move(root)) {}

std::string SourceTree::name_of(const fs::path& absolute) const {
    const fs::path relative = absolute.lexically_normal().lexically_relative(root_);
    if (relative.empty() || *relative.begin() == "..") return absolute.generic_string();
    return relative.generic_string();
}

fs::path SourceTree::path_of(std::string_view name) const {
    const fs::path path(name);
    return (path.is_absolute() ? path : root_ / path).lexically_normal();
}

std::optional<fs::path> SourceTree::resolve(const IncludeDirective& include,
                                            std::string_view includer_name) const {
    const fs::path header(include.header);
    if (header.empty()) return std::nullopt;
    if (header.is_absolute()) {
        if (is_file(header)) return header.lexically_normal();
        return std::nullopt;
    }
    if (!include.system) {
        const fs::path local = (path_of(includer_name).parent_path() / header).lexically_normal();
        if (is_file(local)) return local;
    }
    const fs::path from_root = (root_ / header).lexically_normal();
    if (is_file(from_root)) return from_root;
    return std::nullopt;
}

const std::string* SourceTree::read(const fs::path& absolute) {
    auto [it, inserted] = texts_.try_emplace(absolute);
    if (inserted) {
        std::ifstream in(absolute, std::ios::binary);
        if (in && is_file(absolute)) {
            std::ostringstream text;
            text << in.rdbuf();
            if (!in.bad()) it->second = std::move(text).str();
        }
    }
    return it->second ? &*it->second : nullptr;
}

namespace {

// Depth-first, in include order; each file once (include guards make repeats empty anyway).
void collect(SourceTree& tree, const fs::path& file, std::set<fs::path>& seen, Dependencies& out) {
    const std::string* text = tree.read(file);
    if (text == nullptr) return;
    const std::string includer = tree.name_of(file);
    for (const IncludeDirective& include : scan_includes(*text)) {
        const auto resolved = tree.resolve(include, includer);
        if (!resolved || tree.read(*resolved) == nullptr) {
            out.unresolved.push_back(includer + " -> " + include.header);
            continue;
        }
        if (seen.insert(*resolved).second) {
            out.files.push_back(*resolved);
            collect(tree, *resolved, seen, out);
        }
    }
}

}  // namespace

Dependencies collect_dependencies(SourceTree& tree, const fs::path& main_file) {
    Dependencies deps;
    std::set<fs::path> seen{main_file};
    collect(tree, main_file, seen, deps);
    return deps;
}

}  // namespace ds::shader
