#pragma once
// Polygons of mesh files (OBJ faces of more than three corners) split into
// triangles.
#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace facet {

// Splits a planar polygon into corners.size() - 2 triangles (indices into
// `corners`) wound like the polygon:
// 1. the polygon's plane from Newell's method, robust for concave outlines
//    (Newell, as given in Sutherland, Sproull and Schumacker, "A
//    Characterization of Ten Hidden-Surface Algorithms", 1974);
// 2. a quad along its shorter diagonal, unless that leaves the quad;
// 3. a convex outline as a fan, in O(n);
// 4. anything else by ear clipping (Meisters, "Polygons have ears", 1975),
//    with a budget of 8 n^2 corner tests, after which each triangle is cut
//    at the most convex corner: O(n^2) for any outline, even a hostile one.
// `work`, when given, gains the number of corner tests and scans made, so
// tests can hold the bound.
std::vector<std::array<size_t, 3>> triangulate_polygon(const std::vector<glm::dvec3>& corners,
                                                       uint64_t* work = nullptr);

}  // namespace facet
