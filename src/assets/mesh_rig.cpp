// Keeping a MeshRig's per-vertex data in step with the baked parts when
// their vertices are split (normals from faces, tangent frames).
#include "assets/mesh_rig.hpp"

#include <type_traits>

namespace facet {

void reorder_rig_part_vertices(RigPart& part, const std::vector<uint32_t>& source_vertex) {
    std::vector<bool> from_faces(part.positions.size(), false);
    for (uint32_t v : part.normals_from_faces) from_faces[v] = true;
    auto reorder = [&](auto& list, size_t per_vertex) {
        if (list.empty()) return;
        std::remove_reference_t<decltype(list)> out;
        out.reserve(source_vertex.size() * per_vertex);
        for (uint32_t v : source_vertex)
            for (size_t k = 0; k < per_vertex; ++k) out.push_back(list[v * per_vertex + k]);
        list = std::move(out);
    };
    reorder(part.positions, 1);
    reorder(part.normals, 1);
    reorder(part.tangents, 1);
    reorder(part.joints, part.influences);
    reorder(part.weights, part.influences);
    for (auto& target : part.morph_targets) {
        reorder(target.position_deltas, 1);
        reorder(target.normal_deltas, 1);
        reorder(target.tangent_deltas, 1);
    }
    part.normals_from_faces.clear();
    for (size_t i = 0; i < source_vertex.size(); ++i)
        if (from_faces[source_vertex[i]])
            part.normals_from_faces.push_back(static_cast<uint32_t>(i));
}

}  // namespace facet
