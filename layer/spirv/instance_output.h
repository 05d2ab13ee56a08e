#pragma once
// The vertex shader half of the survival shader's instance id (survival.h): a copy of an
// application's vertex shader that passes gl_InstanceIndex on to the fragment stage in one more
// user output. Pure SPIR-V, no Vulkan, no SPIRV-Tools.
//
// The rewrite of the entry point `entry` (ExecutionModel Vertex):
// - an Output variable of type uint, decorated Flat and Location `location`: the first
//   location after every location its user outputs use (0 when it has none). A user output is
//   an Output variable of the entry's interface that is not BuiltIn nor a block of BuiltIn
//   members (gl_PerVertex); it uses Location L (the variable's, or each block member's) up to
//   L + its type's locations: 1 for a scalar or vector of 32 bits or less, and for a 64-bit
//   one of up to 2 components; 2 for a 64-bit vec3 / vec4; a matrix: its columns'; an array:
//   length times its element's; a struct: the sum of its members';
// - the module's Input variable decorated BuiltIn InstanceIndex (int or uint), else a new one
//   (int);
// - at the start of the entry's function (after the OpVariables of its first block): the
//   output = gl_InstanceIndex, bitcast to uint;
// - both variables in the entry's interface (Input / Output: at any SPIR-V version).
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace ds::layer {

struct InstanceOutput {
    std::vector<uint32_t> spirv;
    uint32_t location = 0;  // of the new output: the survival shader's instance_location
};

// Throws ds::Error (one sentence) for a malformed module (an output without Location, a type
// whose locations it cannot count) or no Vertex entry point named `entry`.
InstanceOutput add_instance_output(std::span<const uint32_t> vertex, std::string_view entry);

}  // namespace ds::layer
