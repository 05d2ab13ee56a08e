#include "layer/spirv/measure.h"

#include <algorithm>
#include <array>
#include <set>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>

#include "layer/spirv/counters.h"
#include "layer/spirv/module.h"
#include "layer/spirv/module_index.h"
#include "renderer/common/error.h"

namespace ds::layer {

namespace {

constexpr uint32_t kRasterizedSlot = 2;  // DrawCounters member and counts[] offset
constexpr uint32_t kSpirv10 = 0x00010000;

// The copy of a stage type in the fragment module, and whether an Input of it must be Flat.
struct Copied {
    uint32_t id = 0;
    bool flat = false;  // holds an integer or a 64-bit float
};

// Copies types (and the constants array lengths use) from the stage module into the fragment
// module, each once; scalars, vectors and matrices are shared with the fragment module's own.
class TypeCopier {
  public:
    TypeCopier(const ModuleIndex& from, Module& to) : from_(from), to_(to) {}

    Copied type(uint32_t id);
    // The scalar types copied, (OpTypeInt or OpTypeFloat, width): the capabilities they need.
    const std::set<std::pair<spv::Op, uint32_t>>& scalars() const { return scalars_; }
    // Stage struct id -> fragment struct id (for their names).
    const std::unordered_map<uint32_t, uint32_t>& structs() const { return structs_; }

  private:
    Copied copy(const Instruction& t);
    Copied copy_struct(const Instruction& t);
    uint32_t constant(uint32_t id);

    const ModuleIndex& from_;
    Module& to_;
    std::unordered_map<uint32_t, Copied> done_;
    std::unordered_set<uint32_t> open_;  // being copied: a type that contains itself
    std::unordered_map<uint32_t, uint32_t> constants_, structs_;
    std::set<std::pair<spv::Op, uint32_t>> scalars_;
};

Copied TypeCopier::type(uint32_t id) {
    if (const auto it = done_.find(id); it != done_.end()) return it->second;
    if (!open_.insert(id).second) throw Error("SPIR-V: a type contains itself");
    const Copied c = copy(def_of(from_, id));
    open_.erase(id);
    done_[id] = c;
    return c;
}

Copied TypeCopier::copy(const Instruction& t) {
    const std::vector<uint32_t> rest(t.operands.begin() + (t.operands.empty() ? 0 : 1),
                                     t.operands.end());
    switch (t.op) {
        case spv::OpTypeBool:
            return {to_.type(t.op, {}), true};
        case spv::OpTypeInt:
            scalars_.insert({t.op, t.operand(1)});
            return {to_.type(t.op, rest), true};
        case spv::OpTypeFloat:
            scalars_.insert({t.op, t.operand(1)});
            return {to_.type(t.op, rest), t.operand(1) == 64};
        case spv::OpTypeVector:
        case spv::OpTypeMatrix: {
            const Copied component = type(t.operand(1));
            return {to_.type(t.op, {component.id, t.operand(2)}), component.flat};
        }
        case spv::OpTypeArray: {
            const Copied element = type(t.operand(1));
            const uint32_t length = constant(t.operand(2));
            const uint32_t id = to_.new_id();
            to_.add(Section::Global, t.op, {id, element.id, length});
            return {id, element.flat};
        }
        case spv::OpTypeStruct:
            return copy_struct(t);
        default:
            throw Error("SPIR-V: an output's type (opcode " + std::to_string(t.op) +
                        ") is not one the measurement shader copies");
    }
}

// A struct with the member types copied, the Block decoration and member Location / Component
// decorations; Flat on each member holding an integer or a 64-bit float.
Copied TypeCopier::copy_struct(const Instruction& t) {
    std::vector<uint32_t> operands{0};
    std::vector<uint32_t> flat_members;
    for (size_t i = 1; i < t.operands.size(); ++i) {
        const Copied member = type(t.operands[i]);
        operands.push_back(member.id);
        if (member.flat) flat_members.push_back(uint32_t(i - 1));
    }
    const uint32_t id = operands[0] = to_.new_id();
    to_.add(Section::Global, spv::OpTypeStruct, operands);
    structs_[t.operand(0)] = id;
    for (const Instruction* d : decorations_of(from_, t.operand(0))) {
        if (d->op == spv::OpDecorate && d->operand(1) == spv::DecorationBlock)
            to_.add(Section::Annotation, spv::OpDecorate, {id, spv::DecorationBlock});
        const uint32_t member_decoration = d->operand(2);
        if (d->op == spv::OpMemberDecorate && (member_decoration == spv::DecorationLocation ||
                                               member_decoration == spv::DecorationComponent))
            to_.add(Section::Annotation, spv::OpMemberDecorate,
                    {id, d->operand(1), member_decoration, d->operand(3)});
    }
    for (uint32_t member : flat_members)
        to_.add(Section::Annotation, spv::OpMemberDecorate, {id, member, spv::DecorationFlat});
    return {id, !flat_members.empty()};
}

// An array length: an OpConstant, or an OpSpecConstant with its SpecId.
uint32_t TypeCopier::constant(uint32_t id) {
    if (const auto it = constants_.find(id); it != constants_.end()) return it->second;
    const Instruction& c = def_of(from_, id);
    if ((c.op != spv::OpConstant && c.op != spv::OpSpecConstant) || c.operands.size() < 3)
        throw Error("SPIR-V: an output array's length is not an OpConstant or OpSpecConstant");
    std::vector<uint32_t> operands = c.operands;
    operands[0] = type(c.operand(0)).id;
    operands[1] = constants_[id] = to_.new_id();
    to_.add(Section::Global, c.op, operands);
    for (const Instruction* d : decorations_of(from_, id))
        if (d->op == spv::OpDecorate && d->operand(1) == spv::DecorationSpecId)
            to_.add(Section::Annotation, spv::OpDecorate,
                    {operands[1], spv::DecorationSpecId, d->operand(2)});
    return operands[1];
}

// The Input variable mirroring `output`: its type, Location and Component; Flat when its type
// needs it (on the members of a struct type, copy_struct's).
uint32_t add_input(const ModuleIndex& s, TypeCopier& types, Module& fs, const Instruction& output) {
    const uint32_t pointee = def_of(s, output.operand(0)).operand(2);
    const Copied t = types.type(pointee);
    const uint32_t pointer = fs.type(spv::OpTypePointer, {spv::StorageClassInput, t.id});
    const uint32_t id = fs.new_id();
    fs.add(Section::Global, spv::OpVariable, {pointer, id, spv::StorageClassInput});
    for (const Instruction* d : decorations_of(s, output.operand(1))) {
        if (d->op == spv::OpDecorate &&
            (d->operand(1) == spv::DecorationLocation || d->operand(1) == spv::DecorationComponent))
            fs.add(Section::Annotation, spv::OpDecorate, {id, d->operand(1), d->operand(2)});
    }
    if (t.flat && def_of(s, element_type(s, pointee)).op != spv::OpTypeStruct)
        fs.add(Section::Annotation, spv::OpDecorate, {id, spv::DecorationFlat});
    return id;
}

// The stage's capabilities (and extensions) that the copied scalar types need.
void add_capabilities(const Module& stage, const TypeCopier& types, Module& fs) {
    struct Need {
        spv::Capability capability;
        spv::Op type;
        uint32_t width;
    };
    constexpr std::array<Need, 7> needs{{
        {spv::CapabilityFloat64, spv::OpTypeFloat, 64},
        {spv::CapabilityInt64, spv::OpTypeInt, 64},
        {spv::CapabilityFloat16, spv::OpTypeFloat, 16},
        {spv::CapabilityInt16, spv::OpTypeInt, 16},
        {spv::CapabilityInt8, spv::OpTypeInt, 8},
        {spv::CapabilityStorageInputOutput16, spv::OpTypeFloat, 16},
        {spv::CapabilityStorageInputOutput16, spv::OpTypeInt, 16},
    }};
    auto used = [&](spv::Capability cap) {
        return std::any_of(needs.begin(), needs.end(), [&](const Need& n) {
            return n.capability == cap && types.scalars().contains({n.type, n.width});
        });
    };
    for (const Instruction& in : stage.section(Section::Capability))
        if (used(spv::Capability(in.operand(0))))
            fs.add(Section::Capability, spv::OpCapability, {in.operand(0)});
    const bool sixteen = types.scalars().contains({spv::OpTypeFloat, 16}) ||
                         types.scalars().contains({spv::OpTypeInt, 16});
    for (const Instruction& in : stage.section(Section::Extension)) {
        const std::string name = read_string(in.operands);
        if (sixteen &&
            (name == "SPV_KHR_16bit_storage" || name == "SPV_AMD_gpu_shader_half_float" ||
             name == "SPV_AMD_gpu_shader_int16"))
            fs.add(Section::Extension, spv::OpExtension, in.operands);
    }
}

// OpName / OpMemberName of the stage's that name a copied variable or struct.
void copy_names(const Module& stage, const std::unordered_map<uint32_t, uint32_t>& copies,
                Module& fs) {
    for (const Instruction& in : stage.section(Section::DebugName)) {
        const auto it = copies.find(in.operand(0));
        if (it == copies.end()) continue;
        std::vector<uint32_t> operands = in.operands;
        operands[0] = it->second;
        fs.add(Section::DebugName, in.op, std::move(operands));
    }
}

// Fragment entry point "main" with `inputs` (and FragCoord, and from SPIR-V 1.4 on the
// buffers) in its interface; its body counts the fragment rasterized (`c` null: does nothing).
void add_entry(Module& fs, const Counters* c, const std::vector<uint32_t>& inputs) {
    const uint32_t void_type = fs.type(spv::OpTypeVoid, {});
    const uint32_t function_type = fs.type(spv::OpTypeFunction, {void_type});
    const uint32_t main = fs.new_id();
    std::vector<uint32_t> ep{spv::ExecutionModelFragment, main};
    for (uint32_t w : string_words("main")) ep.push_back(w);
    ep.insert(ep.end(), inputs.begin(), inputs.end());
    if (c) ep.push_back(c->frag_coord);
    if (c && fs.version() >= kSpirv14) ep.insert(ep.end(), {c->draw, c->pixel});
    fs.add(Section::EntryPoint, spv::OpEntryPoint, std::move(ep));
    fs.add(Section::ExecutionMode, spv::OpExecutionMode, {main, spv::ExecutionModeOriginUpperLeft});
    add_name(fs, main, "main");

    std::vector<Instruction>& body = fs.section(Section::Function);
    body.push_back(
        {spv::OpFunction, {void_type, main, spv::FunctionControlMaskNone, function_type}});
    body.push_back({spv::OpLabel, {fs.new_id()}});
    if (c) emit_count(fs, *c, fs.constant(c->uint_type, kRasterizedSlot), body);
    body.push_back({spv::OpReturn, {}});
    body.push_back({spv::OpFunctionEnd, {}});
}

// The fragment shader mirroring `spirv`'s entry's outputs; `b` null: it counts nothing.
std::vector<uint32_t> mirroring_fragment(std::span<const uint32_t> spirv, std::string_view entry,
                                         const CounterBindings* b) {
    const Module stage(spirv);
    const size_t ep =
        find_entry_point(stage, entry,
                         {spv::ExecutionModelVertex, spv::ExecutionModelTessellationEvaluation,
                          spv::ExecutionModelGeometry});
    if (ep == SIZE_MAX)
        throw Error("SPIR-V: the module has no Vertex, TessellationEvaluation or Geometry " +
                    ("entry point named \"" + std::string(entry) + "\""));
    if (b && b->draw_binding == b->pixel_binding)
        throw Error("SPIR-V measure: the draw and pixel counters need different bindings");
    const ModuleIndex s = index_module(stage);

    const std::array<uint32_t, 5> header{spv::MagicNumber, std::max(stage.version(), kSpirv10), 0,
                                         1, 0};
    Module fs(header);
    fs.add(Section::Capability, spv::OpCapability, {spv::CapabilityShader});
    fs.add(Section::MemoryModel, spv::OpMemoryModel,
           {spv::AddressingModelLogical, spv::MemoryModelGLSL450});
    Counters c;
    if (b) c = add_counter_globals(fs, *b);

    TypeCopier types(s, fs);
    std::vector<uint32_t> inputs;
    std::unordered_map<uint32_t, uint32_t> copies;  // stage id -> fragment id, for names
    for (const Instruction* output : user_outputs(s, stage.section(Section::EntryPoint)[ep])) {
        inputs.push_back(add_input(s, types, fs, *output));
        copies[output->operand(1)] = inputs.back();
    }
    copies.insert(types.structs().begin(), types.structs().end());
    add_capabilities(stage, types, fs);
    copy_names(stage, copies, fs);
    add_entry(fs, b ? &c : nullptr, inputs);
    return fs.words();
}

}  // namespace

std::vector<uint32_t> measurement_fragment(std::span<const uint32_t> spirv, std::string_view entry,
                                           const CounterBindings& b) {
    return mirroring_fragment(spirv, entry, &b);
}

std::vector<uint32_t> passthrough_fragment(std::span<const uint32_t> spirv,
                                           std::string_view entry) {
    return mirroring_fragment(spirv, entry, nullptr);
}

}  // namespace ds::layer
