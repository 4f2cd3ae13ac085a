#pragma once
// Tangent frames for normal maps, made the way MikkTSpace makes them, so
// that a normal map baked by Blender, Substance or xNormal against
// MikkTSpace tangents (what glTF 2.0 assumes when a file has no TANGENT)
// shades as its author saw it. Written from the published description:
// Morten S. Mikkelsen, "Simulation of wrinkled surfaces revisited", MSc
// thesis, University of Copenhagen, 2008, and the documented behaviour of
// its reference implementation (mikktspace.h).
//
// The convention is glTF's: a tangent is xyz, the unit direction of
// increasing u, and w = +1 or -1, so that the bitangent w (n x t) points
// up the texture. facet's coordinates put v = 0 at the top of the image
// (as glTF does), so up is the direction of decreasing v.
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "assets/mesh.hpp"

namespace facet {

// Gives `part` one tangent per vertex (MeshPart::tangents) from its
// texture coordinate set `uv_set` (0 or 1, as TextureSlot::uv_set; a part
// without set 1 uses set 0, as World::corner_uvs does):
// 1. per triangle, the direction of increasing u from the derivatives of
//    position over (u, up), and its orientation, the sign of the triangle's
//    area in texture space: -1 where the texture is mirrored;
// 2. corners weld when their position, normal and coordinates are equal to
//    the bit, whatever their vertex index;
// 3. round each welded vertex, the corners form groups: those of triangles
//    sharing an edge there and having the same orientation, so the two
//    sides of a mirrored chart never average together;
// 4. each group's tangent is the sum of its corners' triangle directions,
//    each made perpendicular to the vertex normal (Gram-Schmidt), made
//    unit, and weighted by the corner's angle; w is the group's orientation;
// 5. a triangle with no area in texture space or in space has no direction
//    and takes the group of a neighbour round the vertex; a vertex with no
//    usable triangle at all (or a sum that cancels) gets a fixed direction
//    perpendicular to its normal, w = +1;
// 6. a vertex whose corners came out with different frames is split into
//    one copy per frame: the first keeps its index, the others are appended
//    and the indices rewritten.
// Every tangent is finite and unit length, whatever the input. O(n log n)
// in the corners. When `source_vertex` is given, it receives for each
// vertex of the result the vertex it was copied from (the identity for
// those that kept their index), so that data kept beside the part (a glTF
// skin, morph targets) can follow the split.
void add_tangent_frames(MeshPart& part, int uv_set, std::vector<uint32_t>* source_vertex = nullptr);

// Tangents of a part whose vertices must not split (a simulated cloth,
// whose solver owns them): steps 1, 4 and 5 per vertex index, the
// orientation of each vertex the one most of its corners' angle has.
void add_tangent_frames_in_place(MeshPart& part, int uv_set);

// Recomputes the directions of tangents that a deforming surface carries
// (a cloth, every frame) from its moved positions and normals, keeping
// each vertex's w: steps 1, 4 and 5 over the corners whose orientation
// agrees with w. `indices` index `positions` after `index_base` is taken
// off (the world's concatenated arrays).
void refresh_tangent_directions(std::span<const glm::vec3> positions,
                                std::span<const glm::vec3> normals, std::span<const glm::vec2> uvs,
                                std::span<const uint32_t> indices, uint32_t index_base,
                                std::span<glm::vec4> tangents);

// The coordinate set of `part` that a map reading `uv_set` uses: set 1,
// else set 0 (empty when the part has neither).
const std::vector<glm::vec2>& tangent_uvs(const MeshPart& part, int uv_set);

// A unit vector perpendicular to `normal` chosen from it alone: the
// coordinate axis least along it, made perpendicular. The frame of a
// vertex whose texture coordinates give no direction.
glm::vec3 any_perpendicular(const glm::vec3& normal);

}  // namespace facet
