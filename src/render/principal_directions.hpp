#pragma once
// The direction hatching strokes follow on a curved surface: per vertex,
// the principal direction of least curvature (along a tube, not round it:
// the lines an engraver draws to follow a form; the cross strokes of dark
// tones then run round it), in model space.
#include <vector>

#include <glm/vec3.hpp>

#include "assets/mesh.hpp"

namespace facet {

// One vector per vertex of the part, tangent to the surface. Its length is
// the confidence in [0, 1]: 1 where the two principal curvatures clearly
// differ (a cylinder, a saddle), falling to 0 where they are alike (a plane,
// a sphere), where no direction is better than another. The sign is
// arbitrary: a direction and its opposite are the same stroke.
//
// The normal curvature along each edge to a neighbour, κ = 2 n·e / |e|²
// (Taubin 1995, "Estimating the Tensor of Curvature of a Surface from a
// Polyhedral Approximation"), is fitted by least squares with a second
// fundamental form II, κ ≈ tᵀ·II·t for the edge's tangent direction t (as
// in Rusinkiewicz 2004, "Estimating Curvatures and Their Derivatives on
// Triangle Meshes", per vertex here); II's eigenvectors are the principal
// directions and its eigenvalues the curvatures. The tensors are averaged
// with the neighbours' twice first, which steadies the field on coarse
// meshes.
// Vertices are taken as the part has them: copies split for flat shading
// see only their own face, which is flat, so a cube's faces get no
// curvature from its corners.
std::vector<glm::vec3> principal_directions(const MeshPart& part);

}  // namespace facet
