// Bounds-checked reading of glTF accessors (glTF 2.0 §3.6.2: accessors,
// sparse accessors, normalised integers). Every count and offset comes from
// the file, so each is checked before it is used to read or to allocate.
#include "assets/gltf_accessors.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "core/error.hpp"

namespace facet::gltf_detail {

void bad(const std::string& path, const std::string& what) {
    throw Error(ExitCode::invalid_input, path + ": " + what);
}

const tinygltf::Accessor& accessor_at(const tinygltf::Model& model, int index,
                                      const std::string& path, const std::string& what) {
    if (index < 0 || static_cast<size_t>(index) >= model.accessors.size())
        bad(path, what + " refers to missing accessor " + std::to_string(index));
    return model.accessors[index];
}

namespace {

double read_component(const uint8_t* p, int type, bool normalized) {
    switch (type) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT: {
            float f;
            std::memcpy(&f, p, 4);
            return f;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
            uint8_t v = *p;
            return normalized ? v / 255.0 : v;
        }
        case TINYGLTF_COMPONENT_TYPE_BYTE: {
            int8_t v;
            std::memcpy(&v, p, 1);
            return normalized ? std::max(v / 127.0, -1.0) : v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            uint16_t v;
            std::memcpy(&v, p, 2);
            return normalized ? v / 65535.0 : v;
        }
        case TINYGLTF_COMPONENT_TYPE_SHORT: {
            int16_t v;
            std::memcpy(&v, p, 2);
            return normalized ? std::max(v / 32767.0, -1.0) : v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
            uint32_t v;
            std::memcpy(&v, p, 4);
            return v;
        }
        default:
            return 0;
    }
}

// The bytes of a buffer view region, bounds-checked.
const uint8_t* view_bytes(const tinygltf::Model& model, int view_index, size_t offset,
                          size_t stride, size_t count, size_t element_size, const std::string& path,
                          const std::string& what) {
    if (view_index < 0 || static_cast<size_t>(view_index) >= model.bufferViews.size())
        bad(path, what + " refers to missing bufferView " + std::to_string(view_index));
    const auto& view = model.bufferViews[view_index];
    if (view.buffer < 0 || static_cast<size_t>(view.buffer) >= model.buffers.size())
        bad(path, what + ": bufferView refers to missing buffer " + std::to_string(view.buffer));
    const auto& buffer = model.buffers[view.buffer];
    // Each comparison is arranged so that no sum or product can wrap around:
    // the counts and offsets come straight from the file.
    if (view.byteOffset > buffer.data.size() ||
        view.byteLength > buffer.data.size() - view.byteOffset)
        bad(path,
            what + ": bufferView runs past the end of its buffer (is the .bin missing or short?)");
    if (count > 0 &&
        (offset > view.byteLength || element_size > view.byteLength - offset ||
         count - 1 > (view.byteLength - offset - element_size) / std::max<size_t>(stride, 1)))
        bad(path, what + ": data runs past the end of its bufferView");
    return buffer.data.data() + view.byteOffset + offset;
}

// An accessor without a bufferView is zeros (plus sparse values); nothing in
// the file bounds its count, so a hostile count would allocate without limit.
constexpr size_t kMaxDatalessCount = size_t(1) << 24;

// The accessor's data, checked against its bufferView before anything is
// allocated from its count; nullptr when it has no bufferView.
const uint8_t* accessor_bytes(const tinygltf::Model& model, const tinygltf::Accessor& acc,
                              size_t element, size_t& stride, const std::string& path,
                              const std::string& what) {
    stride = element;
    if (acc.bufferView < 0) {
        if (acc.count > kMaxDatalessCount)
            bad(path,
                what + ": accessor without data claims " + std::to_string(acc.count) + " elements");
        return nullptr;
    }
    if (static_cast<size_t>(acc.bufferView) >= model.bufferViews.size())
        bad(path, what + " refers to missing bufferView " + std::to_string(acc.bufferView));
    const auto& view = model.bufferViews[acc.bufferView];
    if (view.byteStride) stride = view.byteStride;
    return view_bytes(model, acc.bufferView, acc.byteOffset, stride, acc.count, element, path,
                      what);
}

}  // namespace

void check_accessor_data(const tinygltf::Model& model, int index, const std::string& path,
                         const std::string& what) {
    const auto& acc = accessor_at(model, index, path, what);
    const int components = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(acc.type));
    const int comp_size =
        tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(acc.componentType));
    if (components <= 0 || comp_size <= 0)
        bad(path, what + " has an unknown type or component type");
    size_t stride = 0;
    accessor_bytes(model, acc, static_cast<size_t>(comp_size) * components, stride, path, what);
}

// Reads an accessor as floats, `components` per element, applying sparse substitution.
std::vector<float> read_floats(const tinygltf::Model& model, int index, int components,
                               const std::string& path, const std::string& what) {
    const auto& acc = accessor_at(model, index, path, what);
    int have = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(acc.type));
    if (have != components)
        bad(path, what + " has " + std::to_string(have) + " components per element, expected " +
                      std::to_string(components));
    int comp_size = tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(acc.componentType));
    if (comp_size <= 0) bad(path, what + " has an unknown component type");
    size_t element = static_cast<size_t>(comp_size) * components;
    size_t stride = element;
    const uint8_t* base = accessor_bytes(model, acc, element, stride, path, what);
    std::vector<float> out(acc.count * components, 0.0f);
    if (base) {
        for (size_t i = 0; i < acc.count; ++i)
            for (int c = 0; c < components; ++c)
                out[i * components + c] = static_cast<float>(read_component(
                    base + i * stride + c * comp_size, acc.componentType, acc.normalized));
    }
    if (acc.sparse.isSparse) {
        const auto& sp = acc.sparse;
        int index_size =
            tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(sp.indices.componentType));
        if (index_size <= 0) bad(path, what + ": sparse indices have an unknown type");
        const uint8_t* idx =
            view_bytes(model, sp.indices.bufferView, sp.indices.byteOffset, index_size, sp.count,
                       index_size, path, what + " (sparse indices)");
        const uint8_t* val = view_bytes(model, sp.values.bufferView, sp.values.byteOffset, element,
                                        sp.count, element, path, what + " (sparse values)");
        for (int i = 0; i < sp.count; ++i) {
            auto target = static_cast<size_t>(
                read_component(idx + i * index_size, sp.indices.componentType, false));
            if (target >= acc.count) bad(path, what + ": sparse index out of range");
            for (int c = 0; c < components; ++c)
                out[target * components + c] = static_cast<float>(read_component(
                    val + i * element + c * comp_size, acc.componentType, acc.normalized));
        }
    }
    for (float f : out)
        if (!std::isfinite(f)) bad(path, what + " contains a value that is not finite");
    return out;
}

std::vector<uint32_t> read_indices(const tinygltf::Model& model, int index,
                                   const std::string& path) {
    if (index < 0 || static_cast<size_t>(index) >= model.accessors.size())
        bad(path, "primitive indices refer to missing accessor " + std::to_string(index));
    const auto& acc = model.accessors[index];
    if (acc.type != TINYGLTF_TYPE_SCALAR) bad(path, "index accessor is not SCALAR");
    int size = tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(acc.componentType));
    if (acc.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
        acc.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        acc.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
        bad(path, "index accessor must be unsigned byte, short or int");
    const size_t element = static_cast<size_t>(size);
    size_t stride = element;
    const uint8_t* base = accessor_bytes(model, acc, element, stride, path, "indices");
    std::vector<uint32_t> out(acc.count, 0);
    if (base) {
        for (size_t i = 0; i < acc.count; ++i)
            out[i] =
                static_cast<uint32_t>(read_component(base + i * stride, acc.componentType, false));
    }
    return out;
}

}  // namespace facet::gltf_detail
