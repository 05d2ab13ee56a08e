#pragma once
// A private shader root and cache folder per test, so tests never touch the user's cache and
// never see each other's files.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "renderer/shader/compiler.h"

namespace ds::shader::testing {

class ShaderTest : public ::testing::Test {
  protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = std::filesystem::temp_directory_path() /
               ("ds_shader_" + std::to_string(::getpid()) + "_" + info->test_suite_name() + "_" +
                info->name());
        std::filesystem::remove_all(dir_);
        std::filesystem::create_directories(root());
    }
    void TearDown() override { std::filesystem::remove_all(dir_); }

    std::filesystem::path root() const { return dir_ / "shaders"; }
    std::filesystem::path cache() const { return dir_ / "cache"; }

    void write(const std::string& relative, const std::string& text) const {
        const auto path = root() / relative;
        std::filesystem::create_directories(path.parent_path());
        std::ofstream(path, std::ios::binary | std::ios::trunc) << text;
    }

    // Runs `fn`, expects a ShaderError and returns its message.
    template <typename Fn>
    static std::string error_of(Fn&& fn) {
        try {
            fn();
        } catch (const ShaderError& e) {
            return e.what();
        }
        ADD_FAILURE() << "no ShaderError thrown";
        return {};
    }

    std::filesystem::path dir_;
};

// Shared sources. Line numbers matter: tests assert on them.
inline constexpr const char* kVertex = R"(#version 460
layout(location = 0) in vec3 position;
void main() { gl_Position = vec4(position, 1.0); }
)";

inline constexpr const char* kCompute = R"(#version 460
layout(local_size_x = 8) in;
layout(set = 0, binding = 0) buffer Data { uint values[]; };
void main() { values[gl_GlobalInvocationID.x] *= 2u; }
)";

// A fragment shader that includes common/inc.glsl and uses scale().
inline constexpr const char* kIncludingFragment = R"(#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/inc.glsl"
layout(location = 0) out vec4 color;
void main() { color = vec4(scale(0.5)); }
)";

inline std::string include_returning(const std::string& value) {
    return "#ifndef INC_GLSL\n#define INC_GLSL\nfloat scale(float x) { return x * " + value +
           "; }\n#endif\n";
}

}  // namespace ds::shader::testing
