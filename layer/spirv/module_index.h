#pragma once
// A module's globals (types, constants, variables) and decorations by id, and the user outputs
// of an entry point: what the rewrites that read an interface share (measure.cpp,
// instance_output.cpp). Internal to layer/spirv/.
//
// The index points into the Module's sections: build it again after adding to Global or
// Annotation.
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "layer/spirv/module.h"

namespace ds::layer {

struct ModuleIndex {
    std::unordered_map<uint32_t, const Instruction*> defs;  // types, constants, variables
    std::unordered_map<uint32_t, std::vector<const Instruction*>> decorations;  // (member) decorate
};

ModuleIndex index_module(const Module& m);

// The global whose result id is `id`; throws ds::Error when there is none.
const Instruction& def_of(const ModuleIndex& s, uint32_t id);
// The OpDecorate / OpMemberDecorate of `id` (a variable or a struct type).
const std::vector<const Instruction*>& decorations_of(const ModuleIndex& s, uint32_t id);
// Whether `id` has OpDecorate `d`.
bool decorated(const ModuleIndex& s, uint32_t id, spv::Decoration d);
// Whether a member of struct `id` is BuiltIn (gl_PerVertex).
bool member_builtin(const ModuleIndex& s, uint32_t id);
// `type` without its (outer) array dimensions.
uint32_t element_type(const ModuleIndex& s, uint32_t type);

// The entry's user outputs: the Output variables of its interface that are neither BuiltIn nor
// (arrays of) structs with BuiltIn members.
std::vector<const Instruction*> user_outputs(const ModuleIndex& s, const Instruction& ep);

}  // namespace ds::layer
