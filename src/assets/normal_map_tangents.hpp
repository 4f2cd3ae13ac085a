#pragma once
// The step that gives tangent frames to the mesh parts that need them: the
// parts whose material has a normal map and that have no tangents (a glTF
// file's TANGENT is used as given). Every mesh passes through it twice:
// when loaded (load_mesh, with the file's materials) and when the world is
// built (with the scene's, which may add a normal map to any mesh).
#include <memory>
#include <vector>

#include "assets/mesh.hpp"
#include "core/diagnostics.hpp"

namespace facet {

enum class TangentNeed {
    none,            // no normal map, or tangents already
    missing,         // a normal map, texture coordinates, and no tangents yet
    no_coordinates,  // a normal map, but none of the coordinates it reads
};

TangentNeed tangent_need(const MeshPart& part, const Material& material);

// Gives each part of `mesh` that `materials` (one per mesh.materials, the
// part's drawn with materials[part.material]) leave missing tangents its
// MikkTSpace frames (assets/tangent_frames.hpp). A glTF rig follows: its
// part gets the same vertex split, and the tangents in its mesh space. A
// part without the coordinates its normal map reads gets a warning that
// names it and says the normal map is lost. `keep_vertices`: frames
// without splitting any vertex (a cloth, whose solver owns its vertices).
void add_normal_map_tangents(Mesh& mesh, const std::vector<Material>& materials, Warnings& warnings,
                             bool keep_vertices = false);

// `mesh` itself when no part is missing tangents, else a copy with them
// added as above; the warnings come either way.
std::shared_ptr<const Mesh> with_normal_map_tangents(std::shared_ptr<const Mesh> mesh,
                                                     const std::vector<Material>& materials,
                                                     Warnings& warnings,
                                                     bool keep_vertices = false);

}  // namespace facet
