#pragma once
// Procedural meshes. All are centred on the origin, +Y up, counter-clockwise
// front faces, with UVs (docs/scene-format.md, "Primitives").
#include <optional>
#include <string>

#include <glm/vec3.hpp>

#include "assets/mesh.hpp"

namespace facet {

struct PrimitiveSpec {
    // plane, cube, box, sphere, cylinder, cone, tetrahedron, octahedron,
    // icosahedron, dodecahedron, prism, antiprism, pyramid, icosphere, torus,
    // flagpole (radius, height: the whole pole, its hemispherical tip of
    // radius 2 x radius included; height > 2 x radius), platform (size, thickness, hole_radius <
    // size / 2, segments)
    std::string type;
    float size = 1;  // plane and cube edge length
    // Circumradius (sphere, Platonic solids, icosphere; the base polygon of a
    // prism, antiprism or pyramid; the circle of a cylinder or cone); the
    // major radius of a torus.
    float radius = 0.5f;
    float height = 1;
    int segments = 32;               // divisions around the axis
    int rings = 16;                  // sphere latitude bands; divisions around a torus's tube
    glm::vec3 box_size = {1, 1, 1};  // box extents along x, y, z
    int sides = 6;                   // prism, antiprism and pyramid base polygon
    // Prism and pyramid: the circumradius of the top polygon, which makes a
    // frustum (seed 001's "upper circumradius"). Unset: `radius` for a prism,
    // 0 (an apex) for a pyramid.
    std::optional<float> top_radius;
    float tube = 0.25f;        // torus minor radius, less than `radius`
    int subdivisions = 2;      // icosphere: 0 is the icosahedron
    float thickness = 0.1f;    // platform: the slab's height
    float hole_radius = 0.1f;  // platform: the pole's hole, less than size / 2
    // Round primitives (sphere, icosphere, torus, cylinder, cone, flagpole,
    // and the platform's hole) are smooth unless this is false; the faceted
    // ones accept only false (or unset).
    std::optional<bool> smooth;
};

// Limits make_primitive enforces (the scene parser checks tighter ones).
constexpr int kMaxPrimitiveSides = 65536;
constexpr int kMaxIcosphereSubdivisions = 7;

// Throws facet::Error (invalid_input) for an unknown type or bad parameters,
// naming the parameter and its allowed range.
Mesh make_primitive(const PrimitiveSpec& spec);

}  // namespace facet
