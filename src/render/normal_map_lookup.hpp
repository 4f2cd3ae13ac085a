#pragma once
// A material's normal map at one surface sample, read the same way by the
// shading stage (render/shade_batch.cpp) and the normal pass
// (render/surface_pass_stage.cpp): the vertices' tangent frame interpolated,
// the map sampled with the pixel's footprint, and the two combined by
// shade/normal_map.hpp. The anisotropy's direction follows the same frame.
#include <glm/vec3.hpp>

#include "raster/surface_sample.hpp"
#include "render/vertex_stage.hpp"
#include "render/world.hpp"

namespace facet {

// Whether the triangle's draw has tangent frames (texture coordinates to
// make them from).
bool has_tangent_frames(const World& world, const TransformedVertices& vertices, uint32_t triangle);

// Whether `map` (a material's normal_map or clearcoat_normal_map) turns the
// normals of `triangle`: it is set and the triangle has tangent frames.
bool draws_normal_map(const World& world, const TransformedVertices& vertices,
                      const TextureSlot& map, uint32_t triangle);

// The normal `map` gives, tilted by `scale`, unit, on the viewer's side.
// `pixel` carries the derivatives of one output pixel; `front` is the
// interpolated vertex normal of the triangle's front side, unit.
glm::vec3 normal_from_map(const World& world, const TransformedVertices& vertices,
                          const TextureSlot& map, float scale, const SurfaceSample& pixel,
                          const glm::vec3& front);

// KHR_materials_anisotropy's direction at a sample of a triangle with
// tangent frames: `in_frame` (x along the tangent, y along the bitangent,
// as the texel of the material's anisotropy map gives it after
// texel_in_mesh_frame) in world space, in the plane of `front`.
// Zero where the frame has no tangent.
glm::vec3 anisotropy_direction(const World& world, const TransformedVertices& vertices,
                               const glm::vec2& in_frame, const SurfaceSample& pixel,
                               const glm::vec3& front);

// A texel's direction, stored in the frame of the coordinates the map is
// read at (after KHR_texture_transform or uv_scale), turned into the frame
// of the mesh's own coordinates, which the tangents follow: RG as a
// direction ((c + 1) / 2), B as it is.
glm::vec3 texel_in_mesh_frame(const glm::vec3& texel, const UvTransform& transform);

}  // namespace facet
