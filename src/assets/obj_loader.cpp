// Wavefront OBJ + MTL through tinyobjloader.
#include <algorithm>
#include <filesystem>
#include <map>
#include <tuple>

#include <glm/geometric.hpp>
#include <tiny_obj_loader.h>

#include "assets/mesh.hpp"
#include "core/error.hpp"

namespace facet {
namespace {

// OBJ files rarely say which edges are sharp; this angle separates the
// edges of a cube from the facets of a tessellated sphere.
constexpr float kObjCreaseDegrees = 60.0f;

std::vector<std::string> split_lines(const std::string& text, const std::string& prefix) {
    std::vector<std::string> out;
    size_t start = 0;
    while (start < text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        if (end > start) out.push_back(prefix + text.substr(start, end - start));
        start = end + 1;
    }
    return out;
}

}  // namespace

Mesh load_obj(const std::string& path) {
    tinyobj::ObjReaderConfig config;
    config.triangulate = true;
    config.vertex_color = false;
    config.mtl_search_path = std::filesystem::path(path).parent_path().string();
    tinyobj::ObjReader reader;
    bool ok = reader.ParseFromFile(path, config);
    if (!ok) {
        std::string why = reader.Error();
        while (!why.empty() && (why.back() == '\n' || why.back() == ' ')) why.pop_back();
        throw Error(ExitCode::invalid_input, path + ": cannot read OBJ: " + (why.empty() ? "unknown error" : why));
    }

    Mesh mesh;
    mesh.source = path;
    mesh.warnings = split_lines(reader.Warning(), "");
    const auto& attrib = reader.GetAttrib();
    const auto& shapes = reader.GetShapes();
    const auto& obj_materials = reader.GetMaterials();
    const std::string dir = config.mtl_search_path;

    std::map<std::string, std::shared_ptr<const Texture>> textures;
    for (const auto& m : obj_materials) {
        Material mat;
        mat.name = m.name;
        mat.color = {m.diffuse[0], m.diffuse[1], m.diffuse[2]};
        float ks = (m.specular[0] + m.specular[1] + m.specular[2]) / 3.0f;
        mat.specular = ks;
        if (m.shininess > 0) mat.shininess = m.shininess;
        if (!m.diffuse_texname.empty()) {
            // Files written on Windows often name textures with backslashes.
            std::string name = m.diffuse_texname;
            std::replace(name.begin(), name.end(), '\\', '/');
            std::string tex_path = (std::filesystem::path(dir) / name).lexically_normal().string();
            auto& slot = textures[tex_path];
            if (!slot) {
                try {
                    slot = std::make_shared<Texture>(load_texture(tex_path));
                } catch (const Error& e) {
                    throw Error(ExitCode::invalid_input,
                                path + ": material '" + m.name + "': map_Kd: " + e.what());
                }
            }
            mat.texture = slot;
            // map_Kd replaces Kd in most exporters' intent; many write Kd 0 0 0 with a map.
            if (mat.color == glm::vec3(0)) mat.color = glm::vec3(1);
        }
        mesh.materials.push_back(mat);
    }
    const uint32_t default_material = static_cast<uint32_t>(mesh.materials.size());
    bool used_default = false;

    const size_t position_count = attrib.vertices.size() / 3;
    const size_t normal_count = attrib.normals.size() / 3;
    const size_t uv_count = attrib.texcoords.size() / 2;

    // One part per material; vertices are unique per (position, normal, uv) index triple.
    struct Building {
        MeshPart part;
        std::map<std::tuple<int, int, int>, uint32_t> unique;
        bool missing_normals = false;
        bool any_uv = false;
    };
    std::map<uint32_t, Building> parts;
    for (const auto& shape : shapes) {
        const auto& m = shape.mesh;
        size_t offset = 0;
        for (size_t face = 0; face < m.num_face_vertices.size(); ++face) {
            size_t count = m.num_face_vertices[face];
            if (count != 3) {  // triangulation failed for this face: skip it
                offset += count;
                continue;
            }
            int mat_id = face < m.material_ids.size() ? m.material_ids[face] : -1;
            uint32_t material = (mat_id >= 0 && static_cast<size_t>(mat_id) < mesh.materials.size())
                                    ? static_cast<uint32_t>(mat_id)
                                    : default_material;
            used_default = used_default || material == default_material;
            Building& b = parts[material];
            b.part.material = material;
            for (size_t k = 0; k < 3; ++k) {
                const tinyobj::index_t& idx = m.indices[offset + k];
                if (idx.vertex_index < 0 || static_cast<size_t>(idx.vertex_index) >= position_count)
                    throw Error(ExitCode::invalid_input,
                                path + ": shape '" + shape.name + "' face " + std::to_string(face + 1) +
                                    " refers to vertex " + std::to_string(idx.vertex_index + 1) +
                                    " but the file has " + std::to_string(position_count));
                int n = idx.normal_index;
                if (n >= 0 && static_cast<size_t>(n) >= normal_count) n = -1;
                int t = idx.texcoord_index;
                if (t >= 0 && static_cast<size_t>(t) >= uv_count) t = -1;
                if (n < 0) b.missing_normals = true;
                if (t >= 0) b.any_uv = true;
                auto key = std::make_tuple(idx.vertex_index, n, t);
                auto [it, added] = b.unique.emplace(key, static_cast<uint32_t>(b.part.positions.size()));
                if (added) {
                    size_t v = static_cast<size_t>(idx.vertex_index);
                    b.part.positions.push_back({attrib.vertices[3 * v], attrib.vertices[3 * v + 1],
                                                attrib.vertices[3 * v + 2]});
                    b.part.normals.push_back(n >= 0 ? glm::vec3(attrib.normals[3 * n],
                                                                attrib.normals[3 * n + 1],
                                                                attrib.normals[3 * n + 2])
                                                    : glm::vec3(0));
                    // OBJ puts v = 0 at the bottom of the image; facet samples from the top.
                    b.part.uvs.push_back(t >= 0 ? glm::vec2(attrib.texcoords[2 * t],
                                                            1.0f - attrib.texcoords[2 * t + 1])
                                                : glm::vec2(0));
                }
                b.part.indices.push_back(it->second);
            }
            offset += 3;
        }
    }
    if (used_default) {
        Material fallback;
        fallback.name = "default";
        mesh.materials.push_back(fallback);
    }
    for (auto& [material, b] : parts) {
        if (!b.any_uv) b.part.uvs.clear();
        if (b.missing_normals) compute_normals(b.part, kObjCreaseDegrees);
        for (auto& n : b.part.normals) {
            float len = glm::length(n);
            n = len > 0 ? n / len : glm::vec3(0, 1, 0);
        }
        validate_part(b.part, path);
        mesh.parts.push_back(std::move(b.part));
    }
    if (mesh.triangle_count() == 0) throw Error(ExitCode::invalid_input, path + ": the OBJ file has no faces");
    return mesh;
}

}  // namespace facet
