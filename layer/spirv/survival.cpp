#include "layer/spirv/survival.h"

#include <string>

#include "layer/spirv/counters.h"
#include "layer/spirv/module.h"
#include "layer/spirv/survival_memory.h"
#include "renderer/common/error.h"

namespace ds::layer {

namespace {

// ZPixels.mode values.
constexpr uint32_t kModeNearestForward = 1, kModeNearestReverse = 2, kModeRecord = 3,
                   kModeEqualCount = 4;
constexpr uint32_t kOneFloatBits = 0x3F800000;  // 1.0f

// The ids the survival code uses.
struct SurvivalIds {
    Counters c;  // common globals; c.draw = DrawCounters
    uint32_t zpixels = 0, records = 0, uint_pointer = 0, instance = 0;  // instance: 0 if none
    // uint constants
    uint32_t two = 0, three = 0, sixteen = 0, low16 = 0, bits32 = 0, bits24 = 0, all = 0;
    uint32_t one_bits = 0;
    uint32_t mode_forward = 0, mode_reverse = 0, mode_record = 0, mode_equal = 0;
    // float constants
    uint32_t f_zero = 0, f_half = 0, f_one = 0, unorm24 = 0, unorm16 = 0;
};

void check_survival_bindings(const Module& m, const SurvivalBindings& b, const SurvivalOptions& o) {
    if (b.draw_binding == b.zpixel_binding || b.draw_binding == b.record_binding ||
        b.zpixel_binding == b.record_binding)
        throw Error(
            "SPIR-V survival: the draw, z-pixel and record buffers need different bindings");
    for (const Instruction& in : m.section(Section::Annotation)) {
        if (in.op != spv::OpDecorate) continue;
        if (in.operand(1) == spv::DecorationDescriptorSet && in.operand(2) == b.set)
            throw Error("SPIR-V: the module already uses descriptor set " + std::to_string(b.set) +
                        ", the set the survival buffers need");
        const Instruction* v =
            in.operand(1) == spv::DecorationLocation && in.operand(2) == o.instance_location
                ? m.global(in.operand(0))
                : nullptr;
        if (v && v->op == spv::OpVariable && v->operand(2) == spv::StorageClassInput)
            throw Error("SPIR-V: the fragment shader already has an input at Location " +
                        std::to_string(o.instance_location) + ", the instance's");
    }
}

SurvivalIds add_survival_globals(Module& m, const SurvivalBindings& b, const SurvivalOptions& o) {
    SurvivalIds s;
    s.c = add_common_globals(m);
    const uint32_t u = s.c.uint_type, f = s.c.float_type;
    const uint32_t words = add_uint_runtime_array(m, u);
    s.c.draw = add_buffer(m, s.c, "DrawCounters", b.set, b.draw_binding, 0);
    s.zpixels = add_buffer(m, s.c, "ZPixels", b.set, b.zpixel_binding, words);
    s.records = add_buffer(m, s.c, "Records", b.set, b.record_binding, words);
    s.uint_pointer = m.type(spv::OpTypePointer, {spv::StorageClassStorageBuffer, u});
    require_storage_buffer_class(m);
    if (o.instance_location != UINT32_MAX)
        s.instance = add_flat_uint(m, u, spv::StorageClassInput, o.instance_location);

    s.two = m.constant(u, 2), s.three = m.constant(u, 3), s.sixteen = m.constant(u, 16);
    s.low16 = m.constant(u, 0xFFFF), s.bits32 = m.constant(u, 32), s.bits24 = m.constant(u, 24);
    s.all = m.constant(u, 0xFFFFFFFF), s.one_bits = m.constant(u, kOneFloatBits);
    s.mode_forward = m.constant(u, kModeNearestForward);
    s.mode_reverse = m.constant(u, kModeNearestReverse);
    s.mode_record = m.constant(u, kModeRecord), s.mode_equal = m.constant(u, kModeEqualCount);
    s.f_zero = m.constant(f, 0), s.f_half = m.constant(f, 0x3F000000);
    s.f_one = m.constant(f, kOneFloatBits);
    s.unorm24 = m.constant(f, 0x4B7FFFFF);  // 16777215.0f
    s.unorm16 = m.constant(f, 0x477FFF00);  // 65535.0f
    return s;
}

// What the survival code reads of the fragment and of ZPixels.
struct FragmentValues {
    uint32_t z = 0, zb = 0, inside = 0, pixel = 0, pair = 0;  // pixel: p (0 outside); pair: 2p
    uint32_t mode = 0, params = 0, nearest = 0;               // nearest: pointer to words[2p]
};

uint32_t load_member(Emitter& e, const SurvivalIds& s, uint32_t buffer, uint32_t member) {
    return e(spv::OpLoad, s.c.uint_type, {e(spv::OpAccessChain, s.uint_pointer, {buffer, member})});
}

FragmentValues emit_fragment(Emitter& e, const SurvivalIds& s) {
    const uint32_t u = s.c.uint_type, b = s.c.bool_type, f = s.c.float_type;
    const uint32_t coord = e(spv::OpLoad, s.c.vec4_type, {s.c.frag_coord});
    const uint32_t x = e(spv::OpConvertFToU, u, {e(spv::OpCompositeExtract, f, {coord, 0})});
    const uint32_t y = e(spv::OpConvertFToU, u, {e(spv::OpCompositeExtract, f, {coord, 1})});
    FragmentValues r;
    r.z = e(spv::OpCompositeExtract, f, {coord, 2});
    r.zb = e(spv::OpBitcast, u, {r.z});
    const uint32_t width = load_member(e, s, s.zpixels, s.c.zero);
    const uint32_t height = load_member(e, s, s.zpixels, s.c.one);
    r.params = load_member(e, s, s.zpixels, s.two);
    r.mode = load_member(e, s, s.zpixels, s.three);
    r.inside = e(spv::OpLogicalAnd, b,
                 {e(spv::OpULessThan, b, {x, width}), e(spv::OpULessThan, b, {y, height})});
    const uint32_t p = e(spv::OpIAdd, u, {e(spv::OpIMul, u, {y, width}), x});
    r.pixel = e(spv::OpSelect, u, {r.inside, p, s.c.zero});
    r.pair = e(spv::OpIMul, u, {r.pixel, s.two});
    r.nearest = e(spv::OpAccessChain, s.uint_pointer, {s.zpixels, s.c.four, r.pair});
    return r;
}

// inside && mode == `mode`.
uint32_t in_mode(Emitter& e, const SurvivalIds& s, const FragmentValues& fr, uint32_t mode) {
    const uint32_t b = s.c.bool_type;
    return e(spv::OpLogicalAnd, b, {fr.inside, e(spv::OpIEqual, b, {fr.mode, mode})});
}

// The nearest depth (modes 1, 2) and the EQUAL survivors (mode 4): one atomic each, neutral
// where the mode does not apply.
void emit_nearest_and_equal(Emitter& e, const SurvivalIds& s, const FragmentValues& fr) {
    const uint32_t u = s.c.uint_type, scope = s.c.scope, relaxed = s.c.zero;
    const uint32_t min_value =
        e(spv::OpSelect, u, {in_mode(e, s, fr, s.mode_forward), fr.zb, s.all});
    e(spv::OpAtomicUMin, u, {fr.nearest, scope, relaxed, min_value});
    const uint32_t max_value =
        e(spv::OpSelect, u, {in_mode(e, s, fr, s.mode_reverse), fr.zb, s.c.zero});
    e(spv::OpAtomicUMax, u, {fr.nearest, scope, relaxed, max_value});
    const uint32_t equal_index = e(spv::OpIAdd, u, {fr.pair, s.c.one});
    const uint32_t equal =
        e(spv::OpAccessChain, s.uint_pointer, {s.zpixels, s.c.four, equal_index});
    const uint32_t add = e(spv::OpSelect, u, {in_mode(e, s, fr, s.mode_equal), s.c.one, s.c.zero});
    e(spv::OpAtomicIAdd, u, {equal, scope, relaxed, add});
}

// |a - b| of two uints.
uint32_t abs_difference(Emitter& e, const SurvivalIds& s, uint32_t a, uint32_t b) {
    const uint32_t u = s.c.uint_type;
    return e(spv::OpSelect, u,
             {e(spv::OpUGreaterThanEqual, s.c.bool_type, {a, b}), e(spv::OpISub, u, {a, b}),
              e(spv::OpISub, u, {b, a})});
}

// uint(v * levels + 0.5) for v in [0, 1].
uint32_t quantize(Emitter& e, const SurvivalIds& s, uint32_t v, uint32_t levels) {
    const uint32_t f = s.c.float_type;
    return e(spv::OpConvertFToU, s.c.uint_type,
             {e(spv::OpFAdd, f, {e(spv::OpFMul, f, {v, levels}), s.f_half})});
}

// The distance of the fragment's depth from the nearest one in steps of the depth format.
// Unorm: z clamped to [0, 1] and near used only when its bits are a float in [0, 1] (else
// 0xFFFFFFFF steps), so that no float-to-uint conversion is out of range.
uint32_t emit_steps(Emitter& e, const SurvivalIds& s, const FragmentValues& fr, uint32_t near) {
    const uint32_t u = s.c.uint_type, b = s.c.bool_type, f = s.c.float_type;
    const uint32_t depth_bits = e(spv::OpShiftRightLogical, u, {fr.params, s.sixteen});
    const uint32_t levels =
        e(spv::OpSelect, f, {e(spv::OpIEqual, b, {depth_bits, s.bits24}), s.unorm24, s.unorm16});
    const uint32_t above_zero = e(spv::OpFOrdGreaterThan, b, {fr.z, s.f_zero});
    const uint32_t z_low = e(spv::OpSelect, f, {above_zero, fr.z, s.f_zero});  // NaN: 0
    const uint32_t below_one = e(spv::OpFOrdLessThan, b, {z_low, s.f_one});
    const uint32_t z = e(spv::OpSelect, f, {below_one, z_low, s.f_one});
    const uint32_t near_valid = e(spv::OpULessThanEqual, b, {near, s.one_bits});
    const uint32_t near_float =
        e(spv::OpSelect, f, {near_valid, e(spv::OpBitcast, f, {near}), s.f_zero});
    const uint32_t unorm_steps =
        abs_difference(e, s, quantize(e, s, z, levels), quantize(e, s, near_float, levels));
    const uint32_t unorm = e(spv::OpSelect, u, {near_valid, unorm_steps, s.all});
    const uint32_t float_steps = abs_difference(e, s, fr.zb, near);
    return e(spv::OpSelect, u, {e(spv::OpIEqual, b, {depth_bits, s.bits32}), float_steps, unorm});
}

// Mode 3: a record of the fragment when it is within max_steps of the nearest depth, else
// the scratch record 0.
void emit_record(Emitter& e, const SurvivalIds& s, const FragmentValues& fr, uint32_t steps) {
    const uint32_t u = s.c.uint_type, b = s.c.bool_type, ptr = s.uint_pointer;
    const uint32_t max_steps = e(spv::OpBitwiseAnd, u, {fr.params, s.low16});
    const uint32_t hit =
        e(spv::OpLogicalAnd, b,
          {in_mode(e, s, fr, s.mode_record), e(spv::OpULessThanEqual, b, {steps, max_steps})});
    const uint32_t count = e(spv::OpAccessChain, ptr, {s.records, s.c.zero});
    const uint32_t i =
        e(spv::OpAtomicIAdd, u,
          {count, s.c.scope, s.c.zero, e(spv::OpSelect, u, {hit, s.c.one, s.c.zero})});
    const uint32_t capacity = load_member(e, s, s.records, s.c.one);
    const uint32_t kept = e(spv::OpLogicalAnd, b, {hit, e(spv::OpULessThan, b, {i, capacity})});
    const uint32_t slot = e(spv::OpSelect, u, {kept, e(spv::OpIAdd, u, {i, s.c.one}), s.c.zero});
    const uint32_t first = e(spv::OpIMul, u, {slot, s.c.four});
    const uint32_t instance = s.instance ? e(spv::OpLoad, u, {s.instance}) : s.all;
    const uint32_t fields[4] = {fr.pixel, load_member(e, s, s.c.draw, s.three), instance, fr.zb};
    const uint32_t offsets[4] = {s.c.zero, s.c.one, s.two, s.three};
    for (size_t k = 0; k < 4; ++k) {
        const uint32_t index = e(spv::OpIAdd, u, {first, offsets[k]});
        const uint32_t word = e(spv::OpAccessChain, ptr, {s.records, s.c.four, index});
        e.out.push_back({spv::OpStore, {word, fields[k]}});
    }
}

void emit_survival(Module& m, const SurvivalIds& s, std::vector<Instruction>& out) {
    Emitter e{m, out};
    const FragmentValues fr = emit_fragment(e, s);
    emit_nearest_and_equal(e, s, fr);
    // After this invocation's own atomics on words[2p]: an atomic load, as others may write it.
    const uint32_t near = e(spv::OpAtomicLoad, s.c.uint_type, {fr.nearest, s.c.scope, s.c.zero});
    emit_record(e, s, fr, emit_steps(e, s, fr, near));
}

// Inserts the survival code before every return of `function`; returns how many.
size_t insert_survival(Module& m, const SurvivalIds& s, uint32_t function) {
    size_t returns = 0;
    bool found = false, inside = false;
    std::vector<Instruction> out;
    for (Instruction& in : m.section(Section::Function)) {
        if (in.op == spv::OpFunction) inside = in.operand(1) == function;
        if (inside && in.op == spv::OpLabel) found = true;
        if (inside && (in.op == spv::OpReturn || in.op == spv::OpReturnValue)) {
            emit_survival(m, s, out);
            ++returns;
        }
        out.push_back(std::move(in));
    }
    if (!found) throw Error("SPIR-V: the entry point's function has no body in the module");
    m.section(Section::Function) = std::move(out);
    return returns;
}

bool has_execution_mode(const Module& m, uint32_t function, spv::ExecutionMode mode) {
    for (const Instruction& in : m.section(Section::ExecutionMode))
        if (in.op == spv::OpExecutionMode && in.operand(0) == function && in.operand(1) == mode)
            return true;
    return false;
}

}  // namespace

std::vector<uint32_t> survival_fragment(std::span<const uint32_t> fragment, std::string_view entry,
                                        const SurvivalBindings& b, const SurvivalOptions& o) {
    Module m(fragment);
    const size_t ep = find_entry_point(m, entry, {spv::ExecutionModelFragment});
    if (ep == SIZE_MAX)
        throw Error("SPIR-V: the module has no Fragment entry point named \"" + std::string(entry) +
                    "\"");
    check_survival_bindings(m, b, o);
    const uint32_t function = m.section(Section::EntryPoint)[ep].operand(1);

    remove_memory_effects(m);
    const SurvivalIds s = add_survival_globals(m, b, o);
    insert_survival(m, s, function);

    Instruction& entry_point = m.section(Section::EntryPoint)[ep];
    add_to_interface(entry_point, s.c.frag_coord);
    if (s.instance) add_to_interface(entry_point, s.instance);
    if (m.version() >= kSpirv14)
        for (uint32_t id : {s.c.draw, s.zpixels, s.records}) add_to_interface(entry_point, id);
    if (o.early_fragment_tests &&
        !has_execution_mode(m, function, spv::ExecutionModeEarlyFragmentTests))
        m.add(Section::ExecutionMode, spv::OpExecutionMode,
              {function, spv::ExecutionModeEarlyFragmentTests});
    return m.words();
}

bool reads_input_attachments(std::span<const uint32_t> spirv) {
    const Module m(spirv);
    for (const Instruction& in : m.section(Section::Global))
        if (in.op == spv::OpTypeImage && in.operand(2) == spv::DimSubpassData) return true;
    return false;
}

}  // namespace ds::layer
