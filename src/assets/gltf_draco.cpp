#include "assets/gltf_draco.hpp"

#include <draco/compression/decode.h>

#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstring>
#include <memory>
#include <optional>

#include "assets/gltf_accessors.hpp"
#include "core/limits.hpp"

namespace facet::gltf_detail {
namespace {

constexpr const char* kExtension = "KHR_draco_mesh_compression";
// The decoded data of one primitive may be as large as the largest file
// facet reads, no more (as for EXT_meshopt_compression).
constexpr uint64_t kMaxDecodedBytes = kMaxImageFileBytes;

// The attribute's values for every point, converted to T, `components` per
// point, appended to `out` as bytes.
template <typename T>
bool append_values(const draco::PointAttribute& attribute, const draco::Mesh& mesh, int components,
                   std::vector<unsigned char>& out) {
    T value[4] = {};
    for (draco::PointIndex p(0); p < mesh.num_points(); ++p) {
        if (!attribute.ConvertValue<T>(attribute.mapped_index(p), static_cast<int8_t>(components),
                                       value))
            return false;
        const auto* bytes = reinterpret_cast<const unsigned char*>(value);
        out.insert(out.end(), bytes, bytes + sizeof(T) * static_cast<size_t>(components));
    }
    return true;
}

bool append_attribute(const draco::PointAttribute& attribute, const draco::Mesh& mesh,
                      int component_type, int components, std::vector<unsigned char>& out) {
    switch (component_type) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT:
            return append_values<float>(attribute, mesh, components, out);
        case TINYGLTF_COMPONENT_TYPE_BYTE:
            return append_values<int8_t>(attribute, mesh, components, out);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return append_values<uint8_t>(attribute, mesh, components, out);
        case TINYGLTF_COMPONENT_TYPE_SHORT:
            return append_values<int16_t>(attribute, mesh, components, out);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            return append_values<uint16_t>(attribute, mesh, components, out);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
            return append_values<uint32_t>(attribute, mesh, components, out);
        default:
            return false;
    }
}

// A new tightly packed buffer, view and accessor for `bytes`, copying the
// file accessor's type, component type, normalisation and bounds.
int add_plain_accessor(tinygltf::Model& model, const tinygltf::Accessor& like,
                       std::vector<unsigned char> bytes, size_t count) {
    tinygltf::Buffer buffer;
    buffer.data = std::move(bytes);
    tinygltf::BufferView view;
    view.buffer = static_cast<int>(model.buffers.size());
    view.byteLength = buffer.data.size();
    model.buffers.push_back(std::move(buffer));
    tinygltf::Accessor accessor = like;
    accessor.bufferView = static_cast<int>(model.bufferViews.size());
    accessor.byteOffset = 0;
    accessor.count = count;
    accessor.sparse = {};
    model.bufferViews.push_back(view);
    model.accessors.push_back(accessor);
    return static_cast<int>(model.accessors.size() - 1);
}

int whole_number(const tinygltf::Value& object, const char* key) {
    if (!object.Has(key) || !object.Get(key).IsNumber()) return -1;
    const double d = object.Get(key).GetNumberAsDouble();
    return d >= 0 && d < 2.0e9 && d == static_cast<double>(static_cast<int>(d))
               ? static_cast<int>(d)
               : -1;
}

std::unique_ptr<draco::Mesh> decode_mesh(const tinygltf::Model& model, int view_index,
                                         const std::string& path, const std::string& what) {
    if (view_index < 0 || static_cast<size_t>(view_index) >= model.bufferViews.size())
        bad(path, what + ": no such bufferView");
    const tinygltf::BufferView& view = model.bufferViews[static_cast<size_t>(view_index)];
    if (view.buffer < 0 || static_cast<size_t>(view.buffer) >= model.buffers.size())
        bad(path, what + ": its bufferView has no buffer");
    const auto& data = model.buffers[static_cast<size_t>(view.buffer)].data;
    if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset)
        bad(path, what + ": its compressed bytes lie outside their buffer");
    draco::DecoderBuffer buffer;
    buffer.Init(reinterpret_cast<const char*>(data.data() + view.byteOffset), view.byteLength);
    draco::Decoder decoder;
    auto decoded = decoder.DecodeMeshFromBuffer(&buffer);
    if (!decoded.ok())
        bad(path, what + ": the compressed data does not decode (" +
                      decoded.status().error_msg_string() + ")");
    std::unique_ptr<draco::Mesh> mesh = std::move(decoded).value();
    if (!mesh) bad(path, what + ": the compressed data holds no mesh");
    return mesh;
}

// The primitive's triangles as a new UNSIGNED_INT index accessor.
int decoded_indices(tinygltf::Model& model, const draco::Mesh& mesh,
                    const tinygltf::Accessor* like) {
    std::vector<unsigned char> bytes;
    bytes.reserve(static_cast<size_t>(mesh.num_faces()) * 12);
    for (draco::FaceIndex f(0); f < mesh.num_faces(); ++f)
        for (const draco::PointIndex& corner : mesh.face(f)) {
            const uint32_t index = corner.value();
            const auto* b = reinterpret_cast<const unsigned char*>(&index);
            bytes.insert(bytes.end(), b, b + 4);
        }
    tinygltf::Accessor accessor;
    if (like) accessor = *like;
    accessor.type = TINYGLTF_TYPE_SCALAR;
    accessor.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    accessor.normalized = false;
    accessor.minValues.clear();
    accessor.maxValues.clear();
    return add_plain_accessor(model, accessor, std::move(bytes),
                              static_cast<size_t>(mesh.num_faces()) * 3);
}

void decode_primitive(tinygltf::Model& model, tinygltf::Primitive& prim, const std::string& path,
                      const std::string& what) {
    const tinygltf::Value e = prim.extensions.at(kExtension);
    if (!e.IsObject() || !e.Has("attributes") || !e.Get("attributes").IsObject())
        bad(path, what + ": " + kExtension + " needs a bufferView and attributes");
    if (prim.mode >= 0 && prim.mode != TINYGLTF_MODE_TRIANGLES)
        bad(path, what + ": compressed primitives must be triangle lists");
    const std::unique_ptr<draco::Mesh> mesh =
        decode_mesh(model, whole_number(e, "bufferView"), path, what);
    const size_t points = mesh->num_points();
    // Every attribute is checked, and the whole size bounded, before
    // anything is converted.
    struct Planned {
        std::string name;
        const draco::PointAttribute* attribute;
        tinygltf::Accessor like;
        int components;
    };
    std::vector<Planned> planned;
    uint64_t bytes = static_cast<uint64_t>(mesh->num_faces()) * 12;
    const tinygltf::Value& attributes = e.Get("attributes");
    for (const std::string& name : attributes.Keys()) {
        const auto it = prim.attributes.find(name);
        if (it == prim.attributes.end())
            bad(path, what + ": compressed attribute " + name + " is not one of the primitive's");
        const tinygltf::Value& id = attributes.Get(name);
        const double unique_id = id.IsNumber() ? id.GetNumberAsDouble() : -1;
        const draco::PointAttribute* attribute =
            unique_id >= 0 && unique_id < 65536
                ? mesh->GetAttributeByUniqueId(static_cast<uint32_t>(unique_id))
                : nullptr;
        if (!attribute) bad(path, what + ": compressed attribute " + name + " is not in the data");
        const tinygltf::Accessor like = accessor_at(model, it->second, path, what + " " + name);
        const int components = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(like.type));
        if (components < 1 || components > 4 || like.count != points)
            bad(path, what + " " + name + ": the accessor's count or type (" +
                          std::to_string(like.count) + ") disagrees with the compressed data (" +
                          std::to_string(points) + " points)");
        const int size =
            tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(like.componentType));
        if (size <= 0) bad(path, what + " " + name + ": unknown component type");
        bytes += static_cast<uint64_t>(points) * static_cast<uint64_t>(components * size);
        planned.push_back({name, attribute, like, components});
    }
    if (bytes > kMaxDecodedBytes) bad(path, what + ": decodes to more than the limit for a buffer");
    for (const Planned& a : planned) {
        std::vector<unsigned char> data;
        data.reserve(points * static_cast<size_t>(a.components) * 4);
        if (!append_attribute(*a.attribute, *mesh, a.like.componentType, a.components, data))
            bad(path, what + " " + a.name +
                          ": the compressed values do not convert to the accessor's type");
        prim.attributes[a.name] = add_plain_accessor(model, a.like, std::move(data), points);
    }
    std::optional<tinygltf::Accessor> index_like;
    if (prim.indices >= 0) index_like = accessor_at(model, prim.indices, path, what + " indices");
    prim.indices = decoded_indices(model, *mesh, index_like ? &*index_like : nullptr);
    prim.extensions.erase(kExtension);
}

}  // namespace

std::string with_placeholder_views(const std::string& json, int& placeholder_view) {
    placeholder_view = -1;
    nlohmann::json doc = nlohmann::json::parse(json, nullptr, false);
    if (doc.is_discarded() || !doc.is_object() || !doc.contains("accessors") ||
        !doc["accessors"].is_array() || !doc.contains("buffers") || !doc["buffers"].is_array() ||
        doc["buffers"].empty())
        return json;  // tinygltf reports what is wrong
    nlohmann::json& views = doc["bufferViews"];
    if (!views.is_array() && !views.is_null()) return json;
    bool changed = false;
    const int index = views.is_array() ? static_cast<int>(views.size()) : 0;
    for (auto& accessor : doc["accessors"]) {
        if (!accessor.is_object() || accessor.contains("bufferView") || accessor.contains("sparse"))
            continue;
        accessor["bufferView"] = index;
        changed = true;
    }
    if (!changed) return json;
    views.push_back({{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 1}});
    placeholder_view = index;
    return doc.dump();
}

void decode_draco_primitives(tinygltf::Model& model, const std::string& path,
                             int placeholder_view) {
    for (size_t m = 0; m < model.meshes.size(); ++m)
        for (size_t p = 0; p < model.meshes[m].primitives.size(); ++p) {
            tinygltf::Primitive& prim = model.meshes[m].primitives[p];
            if (!prim.extensions.count(kExtension)) continue;
            decode_primitive(model, prim, path,
                             "mesh '" + model.meshes[m].name + "' primitive " + std::to_string(p));
        }
    if (placeholder_view < 0) return;
    for (tinygltf::Accessor& accessor : model.accessors)
        if (accessor.bufferView == placeholder_view) accessor.bufferView = -1;
}

}  // namespace facet::gltf_detail
