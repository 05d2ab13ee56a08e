#pragma once
// What the SPIR-V rewrites of layer/spirv/ share (instrument.cpp, measure.cpp, survival.cpp,
// instance_output.cpp): entry point look-up, the function-start insertion point, the layer's
// storage buffers, FragCoord, and the code that counts one fragment. Internal to layer/spirv/.
#include <cstdint>
#include <initializer_list>
#include <string_view>
#include <unordered_set>
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

// The ids of the module's non-semantic extended instruction sets (their OpExtInst may sit
// among a function's OpVariables).
std::unordered_set<uint32_t> non_semantic_sets(const Module& m);
// Whether `in` may lead a function's first block: OpVariable, and the OpLine / OpNoLine /
// non-semantic OpExtInst (`debug_sets`) among them. Code added at a function's start follows.
bool leads_first_block(const Instruction& in, const std::unordered_set<uint32_t>& debug_sets);
// The index in Section::Function where code added at the start of `function` goes: after the
// instructions leading its first block. Throws ds::Error when the function has no body.
size_t function_start(const Module& m, uint32_t function);

// Appends instructions with a result to a block of function code.
struct Emitter {
    Module& m;
    std::vector<Instruction>& out;

    // The new result id.
    uint32_t operator()(spv::Op op, uint32_t type, std::vector<uint32_t> operands) {
        const uint32_t id = m.new_id();
        operands.insert(operands.begin(), {type, id});
        out.push_back({op, std::move(operands)});
        return id;
    }
};

// The ids the counting code uses.
struct Counters {
    uint32_t uint_type = 0, bool_type = 0, float_type = 0, vec4_type = 0;
    uint32_t frag_coord = 0;  // Input variable, BuiltIn FragCoord
    uint32_t draw = 0, pixel = 0, uint_pointer = 0;
    uint32_t zero = 0, one = 0, four = 0, scope = 0;
};

// The globals every generated code uses: the uint and bool types, FragCoord (the module's, else
// a new one) with its vec4 and float types, the uint constants 0, 1, 4 and the atomics' scope
// (Device, QueueFamily under the Vulkan memory model). The other fields stay 0.
Counters add_common_globals(Module& m);
// An OpTypeRuntimeArray of `uint_type`, ArrayStride 4.
uint32_t add_uint_runtime_array(Module& m, uint32_t uint_type);
// A Block struct of four uints (and a trailing runtime array `runtime_array` unless it is 0),
// std430 offsets, in a StorageBuffer variable at (set, binding), named ds_<type_name>. Returns the
// variable.
uint32_t add_buffer(Module& m, const Counters& c, std::string_view type_name, uint32_t set,
                    uint32_t binding, uint32_t runtime_array);
// OpExtension SPV_KHR_storage_buffer_storage_class below SPIR-V 1.3 (once), which the
// StorageBuffer storage class needs there.
void require_storage_buffer_class(Module& m);

// Every global the counting code needs: types (reused when present), constants, FragCoord (the
// module's, else a new one), the two buffers, the extension SPIR-V < 1.3 needs for the
// StorageBuffer storage class.
Counters add_counter_globals(Module& m, const CounterBindings& b);

// A new Flat uint variable of `storage` (Input or Output) at `location`, named ds_instance.
uint32_t add_flat_uint(Module& m, uint32_t uint_type, spv::StorageClass storage,
                       uint32_t location);

// Appends to `out`: DrawCounters[slot] += 1; counts[(y * width + x) * 4 + slot] += 1 inside
// width x height, else counts[0] += 0 (no branch: the block stays whole). `slot` is the id of
// a uint constant.
void emit_count(Module& m, const Counters& c, uint32_t slot, std::vector<Instruction>& out);

}  // namespace ds::layer
