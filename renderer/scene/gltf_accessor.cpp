#include "renderer/scene/gltf_accessor.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "renderer/scene/import_limits.h"
#include "renderer/scene/import_util.h"

namespace ds::scene::detail {

using limits::kMaxAccessorElements;
using limits::kMaxZeroAccessorElements;

size_t component_size(int component_type) {
    switch (component_type) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return 1;
        case TINYGLTF_COMPONENT_TYPE_SHORT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            return 2;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        case TINYGLTF_COMPONENT_TYPE_FLOAT:
            return 4;
        default:
            return 0;
    }
}

namespace {

std::string component_name(int component_type) {
    switch (component_type) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
            return "byte";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return "unsigned byte";
        case TINYGLTF_COMPONENT_TYPE_SHORT:
            return "short";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            return "unsigned short";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
            return "unsigned int";
        case TINYGLTF_COMPONENT_TYPE_FLOAT:
            return "float";
        default:
            return std::to_string(component_type);
    }
}

int component_count(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR:
            return 1;
        case TINYGLTF_TYPE_VEC2:
            return 2;
        case TINYGLTF_TYPE_VEC3:
            return 3;
        case TINYGLTF_TYPE_VEC4:
            return 4;
        case TINYGLTF_TYPE_MAT2:
            return 4;
        case TINYGLTF_TYPE_MAT3:
            return 9;
        case TINYGLTF_TYPE_MAT4:
            return 16;
        default:
            return 0;
    }
}

bool is_matrix(int type) {
    return type == TINYGLTF_TYPE_MAT2 || type == TINYGLTF_TYPE_MAT3 || type == TINYGLTF_TYPE_MAT4;
}

// Matrix columns of 1- and 2-byte components start on 4-byte boundaries (glTF 2.0 3.6.2.4).
size_t element_size(int component_type, int type) {
    const size_t size = component_size(component_type);
    if (type == TINYGLTF_TYPE_MAT2 && size == 1) return 8;
    if (type == TINYGLTF_TYPE_MAT3 && size == 1) return 12;
    if (type == TINYGLTF_TYPE_MAT3 && size == 2) return 24;
    return size * static_cast<size_t>(component_count(type));
}

bool is_8_or_16_bit(int type) {
    return type == TINYGLTF_COMPONENT_TYPE_BYTE || type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
           type == TINYGLTF_COMPONENT_TYPE_SHORT || type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
}

bool allowed(Components allowed, int type, bool normalized) {
    if (type == TINYGLTF_COMPONENT_TYPE_FLOAT) return true;
    const bool is_unsigned = type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                             type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
    switch (allowed) {
        case Components::Float:
            return false;
        case Components::FloatOrUnorm:
            return normalized && is_unsigned;
        case Components::AnyInteger:
            return is_8_or_16_bit(type);
        case Components::Snorm:
            return normalized && is_8_or_16_bit(type) && !is_unsigned;
    }
    return false;
}

std::string allowed_text(Components allowed) {
    switch (allowed) {
        case Components::Float:
            return "float";
        case Components::FloatOrUnorm:
            return "float or normalized unsigned byte/short";
        case Components::AnyInteger:
            return "float or (unsigned) byte/short, KHR_mesh_quantization";
        case Components::Snorm:
            return "float or normalized byte/short, KHR_mesh_quantization";
    }
    return "float";
}

// offset + length <= size, without overflow.
bool fits(size_t offset, size_t length, size_t size) {
    return offset <= size && length <= size - offset;
}

double decode(const uint8_t* p, int component_type, bool normalized) {
    switch (component_type) {
        case TINYGLTF_COMPONENT_TYPE_BYTE: {
            int8_t v;
            std::memcpy(&v, p, sizeof v);
            return normalized ? std::max(v / 127.0, -1.0) : v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return normalized ? *p / 255.0 : *p;
        case TINYGLTF_COMPONENT_TYPE_SHORT: {
            int16_t v;
            std::memcpy(&v, p, sizeof v);
            return normalized ? std::max(v / 32767.0, -1.0) : v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            uint16_t v;
            std::memcpy(&v, p, sizeof v);
            return normalized ? v / 65535.0 : v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
            uint32_t v;
            std::memcpy(&v, p, sizeof v);
            return normalized ? v / 4294967295.0 : v;
        }
        case TINYGLTF_COMPONENT_TYPE_FLOAT: {
            float v;
            std::memcpy(&v, p, sizeof v);
            return v;
        }
        default:
            return 0.0;
    }
}

std::string accessor_name(int index) {
    return "accessor " + std::to_string(index);
}

const tinygltf::BufferView& checked_view(const tinygltf::Model& model, int index,
                                         const std::string& user) {
    if (index < 0 || static_cast<size_t>(index) >= model.bufferViews.size())
        fail(user + ": bufferView " + std::to_string(index) + " out of range");
    const tinygltf::BufferView& view = model.bufferViews[static_cast<size_t>(index)];
    const std::string name = "bufferView " + std::to_string(index);
    if (view.buffer < 0 || static_cast<size_t>(view.buffer) >= model.buffers.size())
        fail(name + ": buffer " + std::to_string(view.buffer) + " out of range");
    const size_t size = model.buffers[static_cast<size_t>(view.buffer)].data.size();
    if (view.byteLength == 0) fail(name + ": byteLength is 0");
    if (!fits(view.byteOffset, view.byteLength, size))
        fail(name + " out of buffer range (offset " + std::to_string(view.byteOffset) +
             " + length " + std::to_string(view.byteLength) + " > " + std::to_string(size) +
             " bytes in buffer " + std::to_string(view.buffer) + ")");
    if (view.byteStride != 0 &&
        (view.byteStride < 4 || view.byteStride > 252 || view.byteStride % 4 != 0))
        fail(name + ": invalid byteStride " + std::to_string(view.byteStride));
    return view;
}

const uint8_t* view_data(const tinygltf::Model& model, const tinygltf::BufferView& view) {
    return model.buffers[static_cast<size_t>(view.buffer)].data.data() + view.byteOffset;
}

// Validated location of an accessor's elements; data == nullptr means "all zeros".
struct Span {
    const tinygltf::Accessor* accessor = nullptr;
    const uint8_t* data = nullptr;
    size_t stride = 0;
    size_t element_size = 0;
    size_t component_size = 0;
    int components = 0;
};

// Where the sparse substitutions of an accessor live (already range-checked).
struct SparseSpan {
    size_t count = 0;
    const uint8_t* indices = nullptr;
    int index_type = 0;
    const uint8_t* values = nullptr;
};

SparseSpan checked_sparse(const tinygltf::Model& model, const tinygltf::Accessor& accessor,
                          size_t element_size, const std::string& name) {
    const auto& sparse = accessor.sparse;
    if (!sparse.isSparse) return {};
    if (sparse.count <= 0 || static_cast<size_t>(sparse.count) > accessor.count)
        fail(name + ": invalid sparse count " + std::to_string(sparse.count));
    const size_t count = static_cast<size_t>(sparse.count);
    const int index_type = sparse.indices.componentType;
    if (index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
        index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
        fail(name + ": invalid sparse index component type " + component_name(index_type));
    const auto& index_view = checked_view(model, sparse.indices.bufferView, name + " sparse");
    const auto& value_view = checked_view(model, sparse.values.bufferView, name + " sparse");
    if (sparse.indices.byteOffset < 0 || sparse.values.byteOffset < 0)
        fail(name + ": negative sparse byteOffset");
    const size_t index_offset = static_cast<size_t>(sparse.indices.byteOffset);
    const size_t value_offset = static_cast<size_t>(sparse.values.byteOffset);
    if (!fits(index_offset, count * component_size(index_type), index_view.byteLength))
        fail(name + ": sparse indices out of bufferView range");
    if (!fits(value_offset, count * element_size, value_view.byteLength))
        fail(name + ": sparse values out of bufferView range");
    return {count, view_data(model, index_view) + index_offset, index_type,
            view_data(model, value_view) + value_offset};
}

Span checked_span(const tinygltf::Model& model, int index, const std::string& user) {
    if (index < 0 || static_cast<size_t>(index) >= model.accessors.size())
        fail(user + ": accessor " + std::to_string(index) + " out of range");
    const tinygltf::Accessor& accessor = model.accessors[static_cast<size_t>(index)];
    const std::string name = accessor_name(index);
    Span span;
    span.accessor = &accessor;
    span.component_size = component_size(accessor.componentType);
    span.components = component_count(accessor.type);
    if (span.component_size == 0)
        fail(name + ": invalid componentType " + std::to_string(accessor.componentType));
    if (span.components == 0) fail(name + ": invalid type " + std::to_string(accessor.type));
    if (accessor.count == 0) fail(name + ": count is 0");
    const size_t max_count =
        accessor.bufferView >= 0 ? kMaxAccessorElements : kMaxZeroAccessorElements;
    if (accessor.count > max_count)
        fail(name + ": count " + std::to_string(accessor.count) + " is too large");
    span.element_size = element_size(accessor.componentType, accessor.type);
    if (accessor.bufferView >= 0) {
        const auto& view = checked_view(model, accessor.bufferView, name);
        span.stride = view.byteStride != 0 ? view.byteStride : span.element_size;
        if (span.stride < span.element_size)
            fail(name + ": byteStride " + std::to_string(span.stride) +
                 " is smaller than the element size " + std::to_string(span.element_size));
        // glTF 2.0 3.6.2.4: every component starts on a multiple of its size. The reads here
        // would not mind (memcpy), but such a file is broken, and GPU-side users would.
        const size_t start = view.byteOffset + accessor.byteOffset;
        if (start % span.component_size != 0 || span.stride % span.component_size != 0)
            fail(name + ": misaligned: byte " + std::to_string(start) + " of the buffer, stride " +
                 std::to_string(span.stride) + ", for " + component_name(accessor.componentType) +
                 " components");
        const size_t needed = (accessor.count - 1) * span.stride + span.element_size;
        if (!fits(accessor.byteOffset, needed, view.byteLength))
            fail(name + " out of bufferView range (offset " + std::to_string(accessor.byteOffset) +
                 " + " + std::to_string(needed) + " bytes > length " +
                 std::to_string(view.byteLength) + " of bufferView " +
                 std::to_string(accessor.bufferView) + ")");
        span.data = view_data(model, view) + accessor.byteOffset;
    }
    checked_sparse(model, accessor, span.element_size, name);
    return span;
}

// Calls set(element, bytes) for every sparse substitution, in order.
template <typename Set>
void apply_sparse(const tinygltf::Model& model, const Span& span, int index, Set&& set) {
    const std::string name = accessor_name(index);
    const SparseSpan sparse = checked_sparse(model, *span.accessor, span.element_size, name);
    const size_t index_size = component_size(sparse.index_type);
    for (size_t k = 0; k < sparse.count; ++k) {
        const auto element =
            static_cast<size_t>(decode(sparse.indices + k * index_size, sparse.index_type, false));
        static_assert(sizeof(size_t) >= sizeof(uint32_t));
        if (element >= span.accessor->count)
            fail(name + ": sparse index " + std::to_string(element) + " out of range");
        if (k > 0) {
            const auto previous = static_cast<size_t>(
                decode(sparse.indices + (k - 1) * index_size, sparse.index_type, false));
            if (element <= previous) fail(name + ": sparse indices are not increasing");
        }
        set(element, sparse.values + k * span.element_size);
    }
}

}  // namespace

void validate_buffer_views(const tinygltf::Model& model) {
    for (size_t i = 0; i < model.bufferViews.size(); ++i)
        checked_view(model, static_cast<int>(i), "model");
}

void validate_accessors(const tinygltf::Model& model) {
    for (size_t i = 0; i < model.accessors.size(); ++i)
        checked_span(model, static_cast<int>(i), "model");
}

size_t accessor_count(const tinygltf::Model& model, int index, const std::string& what) {
    return checked_span(model, index, what).accessor->count;
}

std::vector<float> read_floats(const tinygltf::Model& model, int index, const FloatRead& spec,
                               const std::string& what) {
    const Span span = checked_span(model, index, what);
    const tinygltf::Accessor& accessor = *span.accessor;
    const std::string name = what + " (" + accessor_name(index) + ")";
    if (span.components != spec.components || is_matrix(accessor.type))
        fail(name + ": type must be " +
             (spec.components == 1 ? std::string("SCALAR")
                                   : "VEC" + std::to_string(spec.components)));
    const int type = accessor.componentType;
    if (!allowed(spec.allowed, type, accessor.normalized))
        fail(name + ": component type " + component_name(type) +
             (accessor.normalized ? " normalized" : "") + " is not allowed (need " +
             allowed_text(spec.allowed) + ")");

    const size_t n = static_cast<size_t>(span.components);
    std::vector<float> out(accessor.count * n, 0.0f);
    auto load_element = [&](size_t element, const uint8_t* p) {
        for (size_t c = 0; c < n; ++c)
            out[element * n + c] =
                static_cast<float>(decode(p + c * span.component_size, type, accessor.normalized));
    };
    if (span.data != nullptr)
        for (size_t e = 0; e < accessor.count; ++e) load_element(e, span.data + e * span.stride);
    apply_sparse(model, span, index, load_element);
    for (size_t i = 0; i < out.size(); ++i)
        if (!std::isfinite(out[i]))
            fail(name + ": non-finite value (NaN/Inf) at element " + std::to_string(i / n));
    return out;
}

std::vector<uint32_t> read_indices(const tinygltf::Model& model, int index,
                                   const std::string& what) {
    const Span span = checked_span(model, index, what);
    const tinygltf::Accessor& accessor = *span.accessor;
    const std::string name = what + " (" + accessor_name(index) + ")";
    if (accessor.type != TINYGLTF_TYPE_SCALAR) fail(name + ": type must be SCALAR");
    const int type = accessor.componentType;
    if (type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
        type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
        fail(name + ": component type " + component_name(type) +
             " is not allowed (need unsigned byte, short or int)");

    std::vector<uint32_t> out(accessor.count, 0);
    auto load_element = [&](size_t element, const uint8_t* p) {
        out[element] = static_cast<uint32_t>(decode(p, type, false));
    };
    if (span.data != nullptr)
        for (size_t e = 0; e < accessor.count; ++e) load_element(e, span.data + e * span.stride);
    apply_sparse(model, span, index, load_element);
    return out;
}

}  // namespace ds::scene::detail
