#pragma once
// A material's normal map at one surface sample, read the same way by the
// shading stage (render/shade_batch.cpp) and the normal pass
// (render/surface_pass_stage.cpp): the vertices' tangent frame interpolated,
// the map sampled with the pixel's footprint, and the two combined by
// shade/normal_map.hpp.
#include <glm/vec3.hpp>

#include "raster/surface_sample.hpp"
#include "render/vertex_stage.hpp"
#include "render/world.hpp"

namespace facet {

// Whether `map` (a material's normal_map or clearcoat_normal_map) turns the
// normals of `triangle`: it is set and the triangle's draw has tangents
// (texture coordinates to make them from).
bool draws_normal_map(const World& world, const TransformedVertices& vertices,
                      const TextureSlot& map, uint32_t triangle);

// The normal `map` gives, tilted by `scale`, unit, on the viewer's side.
// `pixel` carries the derivatives of one output pixel; `front` is the
// interpolated vertex normal of the triangle's front side, unit.
glm::vec3 normal_from_map(const World& world, const TransformedVertices& vertices,
                          const TextureSlot& map, float scale, const SurfaceSample& pixel,
                          const glm::vec3& front);

}  // namespace facet
