#pragma once
// The one place that talks to glslang: parse (with our Includer), link, emit SPIR-V.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "renderer/shader/compiler.h"
#include "renderer/shader/source_tree.h"

namespace ds::shader {

// Bumped whenever the options below change what SPIR-V comes out: part of every cache key.
std::string glslang_version_tag();

struct GlslangOutput {
    std::vector<uint32_t> spirv;
    std::vector<std::filesystem::path> includes;  // absolute, every file glslang included
};

// Compiles `main_file` (inside tree.root()) for Vulkan 1.3 / SPIR-V 1.6 with `preamble`
// processed before it. Throws ShaderError with "FILE:LINE: message" lines.
GlslangOutput run_glslang(SourceTree& tree, const std::filesystem::path& main_file, Stage stage,
                          const std::string& preamble);

}  // namespace ds::shader
