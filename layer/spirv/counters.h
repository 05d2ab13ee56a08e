#pragma once
// What the fragment shader rewrite (instrument.cpp) and the measurement shader (measure.cpp)
// share: entry point look-up, the counter buffers of instrument.h's CounterBindings, FragCoord,
// and the code that counts one fragment. Internal to layer/spirv/.
#include <cstdint>
#include <initializer_list>
#include <string_view>
#include <vector>

#include "layer/spirv/instrument.h"
#include "layer/spirv/module.h"

namespace ds::layer {

constexpr uint32_t kSpirv13 = 0x00010300;
constexpr uint32_t kSpirv14 = 0x00010400;

// OpName `text` for `id`.
void add_name(Module& m, uint32_t id, std::string_view text);
bool has_extension(const Module& m, std::string_view name);

// Where the interface ids of an OpEntryPoint start (after model, function and name).
size_t interface_start(const Instruction& ep);
void add_to_interface(Instruction& ep, uint32_t id);
// The index in Section::EntryPoint of the first entry point named `name` whose execution model
// is one of `models`, or SIZE_MAX.
size_t find_entry_point(const Module& m, std::string_view name,
                        std::initializer_list<spv::ExecutionModel> models);

// The ids the counting code uses.
struct Counters {
    uint32_t uint_type = 0, bool_type = 0, float_type = 0, vec4_type = 0;
    uint32_t frag_coord = 0;  // Input variable, BuiltIn FragCoord
    uint32_t draw = 0, pixel = 0, uint_pointer = 0;
    uint32_t zero = 0, one = 0, four = 0, scope = 0;
};

// Every global the counting code needs: types (reused when present), constants, FragCoord (the
// module's, else a new one), the two buffers, the extension SPIR-V < 1.3 needs for the
// StorageBuffer storage class.
Counters add_counter_globals(Module& m, const CounterBindings& b);

// Appends to `out`: DrawCounters[slot] += 1; counts[(y * width + x) * 4 + slot] += 1 inside
// width x height, else counts[0] += 0 (no branch: the block stays whole). `slot` is the id of
// a uint constant.
void emit_count(Module& m, const Counters& c, uint32_t slot, std::vector<Instruction>& out);

}  // namespace ds::layer
