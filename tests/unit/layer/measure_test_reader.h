#pragma once
// A module's interface read back for the measurement shader's tests: each user variable (not
// BuiltIn, not a block of BuiltIn members) of an entry point, keyed by location and component,
// with its type written out in full (the shape the validation layer matches stages by).
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <vector>

#include <glslang/SPIRV/spirv.hpp>

namespace ds::layer::testing {

struct Variable {
    uint32_t id = 0;
    // e.g. "v3<f32>", "[2]v4<f32>", "block{v3<f32>;u32;}", "struct{i32;f32;}"; a member's
    // Location / Component as " @L.C" after its type.
    std::string type;
    bool flat = false;     // decorated Flat
    bool flat_ok = false;  // every integer and 64-bit float in it is Flat (variable or member)
};

class InterfaceReader {
  public:
    explicit InterfaceReader(std::span<const uint32_t> spirv);

    // The user variables of `storage` in the interface of the first entry point of `model`,
    // by "location.component".
    std::map<std::string, Variable> user_variables(spv::ExecutionModel model,
                                                   spv::StorageClass storage) const;
    // All variables of `storage` in the module.
    size_t variables(spv::StorageClass storage) const;
    // The capabilities the module declares.
    std::vector<uint32_t> capabilities() const { return capabilities_; }

  private:
    struct Decoration {
        uint32_t member;  // UINT32_MAX for OpDecorate
        uint32_t decoration, value;
    };
    struct Def {
        spv::Op op;
        std::vector<uint32_t> operands;  // the result id's removed
    };
    const Def& def(uint32_t id) const;
    bool has(uint32_t id, uint32_t member, spv::Decoration d, uint32_t* value = nullptr) const;
    uint32_t element(uint32_t type) const;  // arrays stripped
    std::string describe(uint32_t type) const;
    bool flat_ok(uint32_t type, bool flat) const;

    std::map<uint32_t, Def> defs_;
    std::map<uint32_t, std::vector<Decoration>> decorations_;
    struct Entry {
        uint32_t model;
        std::vector<uint32_t> interface;
    };
    std::vector<Entry> entries_;
    std::vector<uint32_t> capabilities_;
};

}  // namespace ds::layer::testing
