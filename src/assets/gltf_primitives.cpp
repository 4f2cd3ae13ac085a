#include "assets/gltf_primitives.hpp"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_inverse.hpp>

#include "assets/gltf_accessors.hpp"
#include "assets/gltf_variants.hpp"
#include "assets/tangent_frames.hpp"

namespace facet::gltf_detail {
namespace {

constexpr int kModeTriangles = 4, kModeStrip = 5, kModeFan = 6;

std::vector<uint32_t> triangle_list(int mode, const std::vector<uint32_t>& idx) {
    std::vector<uint32_t> tris;
    if (mode == kModeTriangles) {
        tris.assign(idx.begin(), idx.begin() + (idx.size() / 3) * 3);
    } else if (mode == kModeStrip) {
        for (size_t i = 2; i < idx.size(); ++i) {
            // Every other triangle of a strip is reversed to keep one winding (glTF §3.7.2.1).
            if (i % 2 == 0)
                tris.insert(tris.end(), {idx[i - 2], idx[i - 1], idx[i]});
            else
                tris.insert(tris.end(), {idx[i - 1], idx[i - 2], idx[i]});
        }
    } else if (mode == kModeFan) {
        for (size_t i = 2; i < idx.size(); ++i)
            tris.insert(tris.end(), {idx[0], idx[i - 1], idx[i]});
    }
    return tris;
}

std::vector<glm::vec3> read_vec3s(const tinygltf::Model& model, int accessor, size_t count,
                                  const std::string& path, const std::string& what,
                                  const std::string& attribute) {
    const std::vector<float> v = read_floats(model, accessor, 3, path, what + " " + attribute);
    if (v.size() / 3 != count)
        bad(path, what + ": " + attribute + " count differs from POSITION count");
    std::vector<glm::vec3> out(count);
    for (size_t i = 0; i < count; ++i) out[i] = {v[3 * i], v[3 * i + 1], v[3 * i + 2]};
    return out;
}

std::vector<glm::vec2> read_uvs(const tinygltf::Model& model, const tinygltf::Primitive& prim,
                                int set, size_t count, const std::string& path,
                                const std::string& what) {
    const std::string name = "TEXCOORD_" + std::to_string(set);
    const auto it = prim.attributes.find(name);
    if (it == prim.attributes.end()) return {};
    const std::vector<float> uv = read_floats(model, it->second, 2, path, what + " " + name);
    if (uv.size() / 2 != count)
        bad(path, what + ": " + name + " count differs from POSITION count");
    std::vector<glm::vec2> out(count);
    for (size_t i = 0; i < count; ++i) out[i] = {uv[2 * i], uv[2 * i + 1]};
    return out;
}

// COLOR_0 (glTF §3.7.2.1): linear RGB or RGBA, floats or normalised
// integers. The alpha is read past (facet's vertex colours are opaque),
// with a warning where it is not 1.
std::vector<glm::vec3> read_vertex_colors(const tinygltf::Model& model, int accessor, size_t count,
                                          const std::string& path, const std::string& what,
                                          Warnings& warnings) {
    const tinygltf::Accessor& a = accessor_at(model, accessor, path, what + " COLOR_0");
    if (a.type != TINYGLTF_TYPE_VEC3 && a.type != TINYGLTF_TYPE_VEC4)
        bad(path, what + ": COLOR_0 must be VEC3 or VEC4");
    const int components = a.type == TINYGLTF_TYPE_VEC3 ? 3 : 4;
    const std::vector<float> values =
        read_floats(model, accessor, components, path, what + " COLOR_0");
    if (values.size() / static_cast<size_t>(components) != count)
        bad(path, what + ": COLOR_0 count differs from POSITION count");
    std::vector<glm::vec3> colors(count);
    bool translucent = false;
    for (size_t i = 0; i < count; ++i) {
        const float* c = &values[i * static_cast<size_t>(components)];
        colors[i] = glm::clamp(glm::vec3(c[0], c[1], c[2]), glm::vec3(0), glm::vec3(1));
        translucent = translucent || (components == 4 && c[3] < 1.0f);
    }
    if (translucent)
        warnings.push_back(file_warning(
            path, what + ": COLOR_0's alpha is not read: the vertex colours are drawn opaque"));
    return colors;
}

// A TANGENT w this close to +1 or -1 is taken as it: some tools write the
// sign through a rounding step. Anything further names no side at all.
constexpr float kTangentSignSlack = 0.01f;

// TANGENT (glTF §3.7.2.1): VEC4 floats, or normalised bytes or shorts
// (KHR_mesh_quantization); xyz the unit tangent, w the bitangent's sign.
// Values that are not finite are refused by read_floats, naming the file
// and the attribute, as for the other attributes.
std::vector<glm::vec4> read_tangents(const tinygltf::Model& model, int accessor, size_t count,
                                     const std::string& path, const std::string& what) {
    const std::string name = what + " TANGENT";
    const tinygltf::Accessor& a = accessor_at(model, accessor, path, name);
    if (a.type != TINYGLTF_TYPE_VEC4) bad(path, name + " must be VEC4");
    const bool quantized = a.normalized && (a.componentType == TINYGLTF_COMPONENT_TYPE_BYTE ||
                                            a.componentType == TINYGLTF_COMPONENT_TYPE_SHORT);
    if (a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT && !quantized)
        bad(path, name + " must be floats, or normalised bytes or shorts (KHR_mesh_quantization)");
    const std::vector<float> values = read_floats(model, accessor, 4, path, name);
    if (values.size() / 4 != count) bad(path, name + " count differs from POSITION count");
    std::vector<glm::vec4> tangents(count);
    for (size_t i = 0; i < count; ++i) {
        const float* v = &values[4 * i];
        if (!(std::fabs(std::fabs(v[3]) - 1.0f) <= kTangentSignSlack))
            bad(path, name + ": vertex " + std::to_string(i) + " has w = " + std::to_string(v[3]) +
                          "; w must be +1 or -1 (the bitangent's sign)");
        const glm::vec3 xyz(v[0], v[1], v[2]);
        const float length = glm::length(xyz);
        tangents[i] = {length > 0 && std::isfinite(length) ? xyz / length : glm::vec3(0),
                       v[3] < 0 ? -1.0f : 1.0f};
    }
    return tangents;
}

// The file's tangents placed by `world`: xyz by its linear part (not the
// inverse transpose: a tangent lies in the surface and moves with it), w
// flipped where it mirrors, so that w (n x t) still points up the texture.
// A tangent of no length becomes a direction perpendicular to the normal.
std::vector<glm::vec4> place_tangents(const std::vector<glm::vec4>& tangents,
                                      const std::vector<glm::vec3>& normals, const glm::mat4& world,
                                      size_t& replaced) {
    const glm::mat3 linear(world);
    const float flip = glm::determinant(linear) < 0 ? -1.0f : 1.0f;
    std::vector<glm::vec4> out(tangents.size());
    replaced = 0;
    for (size_t i = 0; i < tangents.size(); ++i) {
        const glm::vec3 t = linear * glm::vec3(tangents[i]);
        const float length = glm::length(t);
        const bool usable = length > 0 && std::isfinite(length);
        if (!usable) ++replaced;
        out[i] = {usable ? t / length : any_perpendicular(normals[i]), tangents[i].w * flip};
    }
    return out;
}

std::vector<uint32_t> read_triangles(const tinygltf::Model& model, const tinygltf::Primitive& prim,
                                     int mode, size_t count, const std::string& path,
                                     const std::string& what) {
    std::vector<uint32_t> idx;
    if (prim.indices >= 0) {
        idx = read_indices(model, prim.indices, path);
    } else {
        idx.resize(count);
        for (size_t i = 0; i < count; ++i) idx[i] = static_cast<uint32_t>(i);
    }
    for (uint32_t i : idx)
        if (i >= count)
            bad(path, what + ": index " + std::to_string(i) + " is out of range (" +
                          std::to_string(count) + " vertices)");
    return triangle_list(mode, idx);
}

// Zero normals (BoxBadNormals), or ones a singular transform flattened,
// would shade as if facing an arbitrary way: the faces around the vertex
// know better.
void replace_unusable_normals(MeshPart& part, const std::vector<uint32_t>& unusable) {
    std::vector<glm::vec3> sum(part.positions.size(), glm::vec3(0));
    for (size_t t = 0; t + 2 < part.indices.size(); t += 3) {
        const uint32_t a = part.indices[t], b = part.indices[t + 1], c = part.indices[t + 2];
        const glm::vec3 face = glm::cross(part.positions[b] - part.positions[a],
                                          part.positions[c] - part.positions[a]);
        for (uint32_t v : {a, b, c}) sum[v] += face;
    }
    for (uint32_t v : unusable) {
        const float len = glm::length(sum[v]);
        part.normals[v] = len > 0 && std::isfinite(len) ? sum[v] / len : glm::vec3(0, 1, 0);
    }
}

}  // namespace

std::optional<MeshSpacePrimitive> read_primitive(const tinygltf::Model& model,
                                                 const tinygltf::Primitive& prim,
                                                 const std::string& path, const std::string& what,
                                                 uint32_t default_material, Warnings& warnings) {
    const int mode = prim.mode < 0 ? kModeTriangles : prim.mode;
    if (mode != kModeTriangles && mode != kModeStrip && mode != kModeFan) {
        warnings.push_back(file_warning(path, what + ": points and lines are not rendered"));
        return std::nullopt;
    }
    const auto position = prim.attributes.find("POSITION");
    if (position == prim.attributes.end()) {
        warnings.push_back(file_warning(path, what + ": no POSITION attribute, skipped"));
        return std::nullopt;
    }
    MeshSpacePrimitive p;
    p.what = what;
    const std::vector<float> pos =
        read_floats(model, position->second, 3, path, what + " POSITION");
    const size_t count = pos.size() / 3;
    p.positions.resize(count);
    for (size_t i = 0; i < count; ++i)
        p.positions[i] = {pos[3 * i], pos[3 * i + 1], pos[3 * i + 2]};
    if (const auto it = prim.attributes.find("NORMAL"); it != prim.attributes.end())
        p.normals = read_vec3s(model, it->second, count, path, what, "NORMAL");
    if (const auto it = prim.attributes.find("TANGENT"); it != prim.attributes.end()) {
        if (p.normals.empty())
            warnings.push_back(file_warning(
                path, what + ": TANGENT is ignored: the primitive has no NORMAL (glTF 2.0 "
                             "§3.7.2.1), so it gets flat normals and tangents made for them"));
        else
            p.tangents = read_tangents(model, it->second, count, path, what);
    }
    p.uvs = read_uvs(model, prim, 0, count, path, what);
    p.uvs1 = read_uvs(model, prim, 1, count, path, what);
    if (const auto it = prim.attributes.find("COLOR_0"); it != prim.attributes.end())
        p.colors = read_vertex_colors(model, it->second, count, path, what, warnings);
    p.material = default_material;
    if (prim.material >= 0) {
        if (static_cast<size_t>(prim.material) >= model.materials.size())
            bad(path, what + " refers to missing material " + std::to_string(prim.material));
        p.material = static_cast<uint32_t>(prim.material);
    }
    p.variant_materials = read_variant_materials(model, prim, p.material, path, what);
    p.indices = read_triangles(model, prim, mode, count, path, what);
    if (p.indices.empty()) return std::nullopt;
    return p;
}

MeshPart place_primitive(const MeshSpacePrimitive& primitive, const glm::mat4& world,
                         const std::string& path, Warnings& warnings,
                         std::vector<uint32_t>* source_vertex, ThreadPool* pool) {
    MeshPart part;
    part.material = primitive.material;
    part.variant_materials = primitive.variant_materials;
    part.positions.reserve(primitive.positions.size());
    for (const glm::vec3& p : primitive.positions)
        part.positions.push_back(glm::vec3(world * glm::vec4(p, 1)));
    part.uvs = primitive.uvs;
    part.uvs1 = primitive.uvs1;
    part.colors = primitive.colors;
    part.indices = primitive.indices;
    if (glm::determinant(glm::mat3(world)) < 0)
        for (size_t t = 0; t + 2 < part.indices.size(); t += 3)
            std::swap(part.indices[t + 1], part.indices[t + 2]);
    if (source_vertex) source_vertex->clear();
    if (primitive.normals.empty()) {
        // glTF §3.7.2.1: without normals, flat normals are used.
        compute_normals(part, 0.0f, source_vertex, nullptr, pool);
        validate_part(part, path);
        return part;
    }
    const glm::mat3 normal_matrix = glm::inverseTranspose(glm::mat3(world));
    std::vector<uint32_t> unusable;
    part.normals.reserve(primitive.normals.size());
    for (size_t i = 0; i < primitive.normals.size(); ++i) {
        const glm::vec3 n = normal_matrix * primitive.normals[i];
        const float len = glm::length(n);
        const bool usable = len > 0 && std::isfinite(len);
        part.normals.push_back(usable ? n / len : glm::vec3(0));
        if (!usable) unusable.push_back(static_cast<uint32_t>(i));
    }
    if (!unusable.empty()) {
        replace_unusable_normals(part, unusable);
        warnings.push_back(
            file_warning(path, primitive.what + ": " + std::to_string(unusable.size()) +
                                   " normals of zero length replaced by face normals"));
    }
    if (!primitive.tangents.empty()) {
        size_t replaced = 0;
        part.tangents = place_tangents(primitive.tangents, part.normals, world, replaced);
        if (replaced > 0)
            warnings.push_back(file_warning(
                path, primitive.what + ": " + std::to_string(replaced) +
                          " tangents of zero length replaced by directions across the normals"));
    }
    if (source_vertex)
        for (size_t i = 0; i < part.positions.size(); ++i)
            source_vertex->push_back(static_cast<uint32_t>(i));
    validate_part(part, path);
    return part;
}

}  // namespace facet::gltf_detail
