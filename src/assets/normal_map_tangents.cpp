// Tangent frames for the parts whose material has a normal map (the base's
// or the clear coat's) or an anisotropy.
#include "assets/normal_map_tangents.hpp"

#include "assets/gltf_pose.hpp"
#include "assets/tangent_frames.hpp"

namespace facet {
namespace {

Warning lost_normal_map(const Mesh& mesh, size_t part, const Material& material) {
    return file_warning(mesh.source,
                        "part " + std::to_string(part) + " (material '" + material.name +
                            "') has no texture coordinates (set " +
                            std::to_string(*material.tangent_uv_set()) +
                            ") for its tangent frames, so it is drawn without its normal maps "
                            "and anisotropy");
}

}  // namespace

TangentNeed tangent_need(const MeshPart& part, const Material& material) {
    if (!material.tangent_uv_set() || !part.tangents.empty()) return TangentNeed::none;
    return tangent_uvs(part, *material.tangent_uv_set()).empty() ? TangentNeed::no_coordinates
                                                                 : TangentNeed::missing;
}

void add_normal_map_tangents(Mesh& mesh, const std::vector<Material>& materials, Warnings& warnings,
                             bool keep_vertices) {
    std::shared_ptr<MeshRig> rig;  // a copy of mesh.rig, made when a rigged part splits
    for (size_t p = 0; p < mesh.parts.size(); ++p) {
        MeshPart& part = mesh.parts[p];
        if (part.material >= materials.size()) continue;
        const Material& material = materials[part.material];
        const TangentNeed need = tangent_need(part, material);
        if (need == TangentNeed::no_coordinates)
            warnings.push_back(lost_normal_map(mesh, p, material));
        if (need != TangentNeed::missing) continue;
        if (keep_vertices) {
            add_tangent_frames_in_place(part, *material.tangent_uv_set());
            continue;
        }
        std::vector<uint32_t> source_vertex;
        add_tangent_frames(part, *material.tangent_uv_set(), &source_vertex);
        if (!mesh.rig) continue;
        if (!rig) {
            rig = std::make_shared<MeshRig>(*mesh.rig);
            mesh.rig = rig;
        }
        reorder_rig_part_vertices(rig->parts[p], source_vertex);
        rig->parts[p].tangents = rest_tangents_in_mesh_space(mesh, p, part.tangents);
    }
}

std::shared_ptr<const Mesh> with_normal_map_tangents(std::shared_ptr<const Mesh> mesh,
                                                     const std::vector<Material>& materials,
                                                     Warnings& warnings, bool keep_vertices) {
    bool missing = false;
    for (size_t p = 0; p < mesh->parts.size(); ++p) {
        const MeshPart& part = mesh->parts[p];
        if (part.material >= materials.size()) continue;
        const TangentNeed need = tangent_need(part, materials[part.material]);
        missing = missing || need == TangentNeed::missing;
        if (need == TangentNeed::no_coordinates)
            warnings.push_back(lost_normal_map(*mesh, p, materials[part.material]));
    }
    if (!missing) return mesh;
    auto copy = std::make_shared<Mesh>(*mesh);
    Warnings repeated;  // the no_coordinates warnings again, already given above
    add_normal_map_tangents(*copy, materials, repeated, keep_vertices);
    return copy;
}

}  // namespace facet
