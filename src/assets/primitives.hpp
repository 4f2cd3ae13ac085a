#pragma once
// Procedural meshes. All are centred on the origin, +Y up, counter-clockwise
// front faces, with UVs.
#include <string>

#include "assets/mesh.hpp"

namespace facet {

struct PrimitiveSpec {
    std::string type;  // plane, cube, sphere, cylinder, cone
    float size = 1;    // plane and cube edge length
    float radius = 0.5f;
    float height = 1;
    int segments = 32;  // divisions around the axis
    int rings = 16;     // sphere latitude bands
};

// Throws facet::Error (invalid_input) for an unknown type or bad parameters.
Mesh make_primitive(const PrimitiveSpec& spec);

}  // namespace facet
