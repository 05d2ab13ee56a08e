#include "renderer/shader/compiler.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>

#include "renderer/shader/glslang_backend.h"
#include "renderer/shader/hash.h"
#include "renderer/shader/source_tree.h"
#include "renderer/shader/spirv_cache.h"

#ifndef DS_SHADER_DIR
#define DS_SHADER_DIR "shaders"
#endif

namespace ds::shader {

namespace fs = std::filesystem;

namespace {

// An unset or empty variable counts as absent.
const char* env(const char* name) {
    const char* value = std::getenv(name);
    return value != nullptr && value[0] != '\0' ? value : nullptr;
}

fs::path absolute_normal(const fs::path& path) {
    if (path.empty()) return path;
    std::error_code ec;
    fs::path absolute = fs::absolute(path, ec);
    return (ec ? path : absolute).lexically_normal();
}

bool is_identifier(const std::string& name) {
    if (name.empty() || std::isdigit(static_cast<unsigned char>(name[0]))) return false;
    return std::all_of(name.begin(), name.end(),
                       [](unsigned char c) { return std::isalnum(c) != 0 || c == '_'; });
}

// Defines go into glslang's preamble, a string of its own before the source: the source's
// line numbers stay as they are and #version may still come first in the file.
std::string make_preamble(const std::vector<Define>& defines, const std::string& main_name) {
    std::string preamble;
    for (const Define& define : defines) {
        if (!is_identifier(define.name)) {
            throw ShaderError(main_name + ": bad define name '" + define.name + "'");
        }
        if (define.value.find_first_of("\r\n") != std::string::npos) {
            throw ShaderError(main_name + ": define " + define.name + " has a line break");
        }
        preamble += "#define " + define.name + " " + define.value + "\n";
    }
    return preamble;
}

int stage_index(Stage stage) {
    return static_cast<int>(stage);
}

// Everything that can change the SPIR-V: compiler and options, stage, defines, and the name
// and text of the source and of every include it reaches.
uint64_t cache_key(SourceTree& tree, const fs::path& main_file, Stage stage,
                   const std::string& preamble, const Dependencies& deps) {
    Hasher hash;
    hash.field(glslang_version_tag()).u64(stage_index(stage)).field(preamble);
    hash.field(tree.name_of(main_file)).field(*tree.read(main_file));
    hash.u64(deps.files.size());
    for (const fs::path& file : deps.files) {
        hash.field(tree.name_of(file)).field(*tree.read(file));
    }
    hash.u64(deps.unresolved.size());
    for (const std::string& entry : deps.unresolved) hash.field(entry);
    return hash.digest();
}

template <typename T>
void append_unique(std::vector<T>& to, const std::vector<T>& from) {
    for (const T& item : from) {
        if (std::find(to.begin(), to.end(), item) == to.end()) to.push_back(item);
    }
}

}  // namespace

Compiler::Compiler(fs::path shader_root, fs::path cache_dir)
    : root_(absolute_normal(shader_root)), cache_dir_(absolute_normal(cache_dir)) {}

fs::path Compiler::default_shader_root() {
    if (const char* dir = env("DEPTHSCOPE_SHADER_DIR")) return dir;
    return DS_SHADER_DIR;
}

fs::path Compiler::default_cache_dir() {
    if (const char* dir = env("DEPTHSCOPE_CACHE_DIR")) return dir;
    // XDG: a relative XDG_CACHE_HOME is invalid and must be ignored.
    if (const char* xdg = env("XDG_CACHE_HOME"); xdg != nullptr && fs::path(xdg).is_absolute()) {
        return fs::path(xdg) / "depthscope" / "spirv";
    }
    if (const char* home = env("HOME")) return fs::path(home) / ".cache" / "depthscope" / "spirv";
    return {};
}

CompileResult Compiler::compile(const fs::path& relative_path, Stage stage,
                                const std::vector<Define>& defines) {
    SourceTree tree(root_);
    const fs::path main_file = tree.path_of(relative_path.generic_string());
    const std::string main_name = tree.name_of(main_file);
    if (tree.read(main_file) == nullptr) throw ShaderError(main_name + ": cannot open");

    const std::string preamble = make_preamble(defines, main_name);
    const Dependencies deps = collect_dependencies(tree, main_file);
    CompileResult result;
    result.files.push_back(main_file);
    append_unique(result.files, deps.files);

    const SpirvCache cache(cache_dir_);
    const uint64_t key = cache_key(tree, main_file, stage, preamble, deps);
    if (auto spirv = cache.load(key)) {
        ++stats_.cache_hits;
        result.spirv = std::move(*spirv);
        result.from_cache = true;
        return result;
    }

    ++stats_.compiles;
    GlslangOutput out;
    try {
        out = run_glslang(tree, main_file, stage, preamble);
    } catch (const ShaderError& e) {
        std::vector<fs::path> files = result.files;
        append_unique(files, e.files());
        throw ShaderError(e.what(), std::move(files));
    }
    // The key only covers what the scan found; should glslang have read anything else, the
    // entry could go stale unnoticed, so it is not stored.
    const bool key_covers_all =
        std::all_of(out.includes.begin(), out.includes.end(), [&](const fs::path& f) {
            return std::find(result.files.begin(), result.files.end(), f) != result.files.end();
        });
    if (key_covers_all) cache.store(key, out.spirv);
    append_unique(result.files, out.includes);
    result.spirv = std::move(out.spirv);
    return result;
}

}  // namespace ds::shader
