#include "render/normal_map_lookup.hpp"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "shade/normal_map.hpp"
#include "shade/texture_lod.hpp"

namespace facet {
namespace {

// The vertices' tangent at a sample, with its sign in w.
glm::vec4 interpolated_tangent(const World& world, const TransformedVertices& vertices,
                               const SurfaceSample& pixel) {
    const uint32_t* c = &world.indices[3 * static_cast<size_t>(pixel.triangle)];
    return pixel.bary[0] * vertices.world_tangent[c[0]] +
           pixel.bary[1] * vertices.world_tangent[c[1]] +
           pixel.bary[2] * vertices.world_tangent[c[2]];
}

}  // namespace

// A rotated or mirrored map would otherwise light its relief from the
// wrong side, or turn the anisotropy. Only the direction is kept: a
// normal's tilt does not depend on how often the map repeats. x runs along
// +u and y up the image (-v), in both frames.
glm::vec3 texel_in_mesh_frame(const glm::vec3& texel, const UvTransform& transform) {
    if (transform.identity()) return texel;
    const double det = glm::determinant(transform.linear);
    if (!(det != 0.0) || !std::isfinite(det)) return texel;
    const glm::dvec2 in_map(2.0 * texel.x - 1.0, -(2.0 * texel.y - 1.0));  // (u', v')
    const glm::dvec2 in_mesh = glm::inverse(transform.linear) * in_map;    // (u, v)
    const double length = glm::length(in_map), turned = glm::length(in_mesh);
    if (!(turned > 0.0)) return texel;
    const glm::dvec2 xy = glm::dvec2(in_mesh.x, -in_mesh.y) * (length / turned);
    return {static_cast<float>(0.5 * xy.x + 0.5), static_cast<float>(0.5 * xy.y + 0.5), texel.z};
}

bool has_tangent_frames(const World& world, const TransformedVertices& vertices,
                        uint32_t triangle) {
    return !vertices.world_tangent.empty() &&
           world.draws[world.triangle_draw[triangle]].has_tangents;
}

bool draws_normal_map(const World& world, const TransformedVertices& vertices,
                      const TextureSlot& map, uint32_t triangle) {
    return map && has_tangent_frames(world, vertices, triangle);
}

glm::vec3 anisotropy_direction(const World& world, const TransformedVertices& vertices,
                               const glm::vec2& in_frame, const SurfaceSample& pixel,
                               const glm::vec3& front) {
    const auto frame = tangent_frame(front, interpolated_tangent(world, vertices, pixel));
    return frame ? in_frame.x * frame->t + in_frame.y * frame->b : glm::vec3(0.0f);
}

glm::vec3 normal_from_map(const World& world, const TransformedVertices& vertices,
                          const TextureSlot& slot, float scale, const SurfaceSample& pixel,
                          const glm::vec3& front) {
    const glm::vec4 tangent = interpolated_tangent(world, vertices, pixel);
    const std::array<glm::vec2, 3> uv = world.corner_uvs(pixel.triangle, slot);
    const TextureFootprint footprint = texture_lookup(
        uv[0], uv[1], uv[2], pixel, glm::vec2(slot.texture->width, slot.texture->height));
    const glm::vec3 texel =
        texel_in_mesh_frame(glm::vec3(slot.texture->sample(footprint)), slot.transform);
    return mapped_normal(front, tangent, pixel.back_facing, texel, scale);
}

}  // namespace facet
