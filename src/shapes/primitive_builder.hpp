#pragma once
// Internal to the assets module: the vertex and triangle builder the
// procedural primitives share (primitives.cpp, polyhedra.cpp).
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "assets/mesh.hpp"

namespace facet::detail {

constexpr float kPi = 3.14159265358979323846f;

struct Builder {
    MeshPart part;
    uint32_t vertex(glm::vec3 p, glm::vec3 n, glm::vec2 uv);
    void triangle(uint32_t a, uint32_t b, uint32_t c) {
        part.indices.insert(part.indices.end(), {a, b, c});
    }
    // Quad a-b-c-d counter-clockwise seen from the front.
    void quad(uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
        triangle(a, b, c);
        triangle(a, c, d);
    }
    // A planar convex polygon of a convex solid around the origin: its own
    // corners with its flat normal, wound to face away from the origin, and
    // triangulated as a fan from the first corner. Without `uvs` the polygon's
    // circumcircle maps onto the unit square's inscribed circle.
    void face(std::vector<glm::vec3> corners, std::vector<glm::vec2> uvs = {});
};

// The faceted solids (polyhedra.cpp).
void add_box(Builder& b, glm::vec3 size);
// tetrahedron, octahedron, icosahedron or dodecahedron of circumradius `radius`.
void add_platonic(Builder& b, const std::string& type, float radius);
// A prism (top == bottom), a pyramid (top == 0) or a frustum between them:
// `sides` planar side faces between two regular polygons of circumradii
// `bottom` and `top`, lined up corner over corner.
void add_frustum(Builder& b, int sides, float bottom, float top, float height);
void add_antiprism(Builder& b, int sides, float radius, float height);
// Geodesic sphere: the icosahedron with each triangle split in four
// `subdivisions` times, corners pushed onto the sphere; smooth normals.
void add_icosphere(Builder& b, float radius, int subdivisions);

// The flag scene's solids (flag_primitives.cpp). The flagpole: a cylinder
// with a hemispherical tip of its radius, `height` in all, centred on the
// origin, closed at the foot, smooth. The platform: a size x thickness x
// size slab with a round hole of `hole_radius` through its centre, its rim
// the same polygon as a pole of that radius and segments; flat faces, a
// smooth hole wall.
void add_flagpole(Builder& b, float radius, float height, int segments, int rings);
void add_platform(Builder& b, float size, float thickness, float hole_radius, int segments);

// Gives every triangle its own three corners with its flat normal.
void make_faceted(MeshPart& part);

}  // namespace facet::detail
