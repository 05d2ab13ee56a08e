#pragma once
// Run-time GLSL -> SPIR-V compiler (DESIGN decision 10): glslang as a library so shaders can
// be hot reloaded, `#include` resolved against the shader root, defines injected through the
// preamble, and SPIR-V cached on disk by a hash of everything that can change the output.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "renderer/common/error.h"

namespace ds::shader {

enum class Stage { Vertex, Fragment, Compute };

struct Define {
    std::string name, value;
};

struct CompileResult {
    std::vector<uint32_t> spirv;
    // The source and every include, absolute: what a hot reloader has to watch.
    std::vector<std::filesystem::path> files;
    bool from_cache = false;
};

// A shader failed to open, preprocess, compile or link. what() is one or more lines
// "FILE:LINE: message", FILE relative to the shader root (e.g. "common/brdf.glsl:12: ...").
class ShaderError : public ds::Error {
  public:
    explicit ShaderError(const std::string& what, std::vector<std::filesystem::path> files = {})
        : ds::Error(what), files_(std::move(files)) {}

    // The files the failed compile read (absolute), so a hot reloader can keep watching them
    // and retry once one of them is fixed. May be empty (e.g. the source itself is missing).
    const std::vector<std::filesystem::path>& files() const { return files_; }

  private:
    std::vector<std::filesystem::path> files_;
};

// One Compiler is meant for one thread at a time; separate Compilers may run concurrently
// (glslang's process state is initialised once, thread-safely; cache writes are atomic).
class Compiler {
  public:
    // An empty cache_dir disables the disk cache.
    explicit Compiler(std::filesystem::path shader_root = default_shader_root(),
                      std::filesystem::path cache_dir = default_cache_dir());

    // relative_path is relative to the shader root. Throws ShaderError.
    CompileResult compile(const std::filesystem::path& relative_path, Stage stage,
                          const std::vector<Define>& defines = {});

    // compiles: glslang runs (failed ones too); cache_hits: results served from disk.
    struct Stats {
        uint64_t compiles = 0, cache_hits = 0;
    };
    const Stats& stats() const { return stats_; }

    const std::filesystem::path& shader_root() const { return root_; }
    const std::filesystem::path& cache_dir() const { return cache_dir_; }

    // $DEPTHSCOPE_SHADER_DIR, else the build tree's shaders/ (DS_SHADER_DIR).
    static std::filesystem::path default_shader_root();
    // $DEPTHSCOPE_CACHE_DIR, else $XDG_CACHE_HOME/depthscope/spirv, else
    // ~/.cache/depthscope/spirv; empty (no disk cache) when none of them is set.
    static std::filesystem::path default_cache_dir();

  private:
    std::filesystem::path root_;
    std::filesystem::path cache_dir_;
    Stats stats_;
};

}  // namespace ds::shader
