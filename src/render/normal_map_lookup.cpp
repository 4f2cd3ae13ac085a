#include "render/normal_map_lookup.hpp"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "shade/normal_map.hpp"
#include "shade/texture_lod.hpp"

namespace facet {
namespace {

// A texel's direction, stored in the frame of the coordinates the map is
// read at (after KHR_texture_transform or uv_scale), turned into the frame
// of the mesh's own coordinates, which the tangents follow. A rotated or
// mirrored map would otherwise light its relief from the wrong side. Only
// the direction is kept: a normal's tilt does not depend on how often the
// map repeats. x runs along +u and y up the image (-v), in both frames.
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

}  // namespace

bool draws_normal_map(const World& world, const TransformedVertices& vertices,
                      const TextureSlot& map, uint32_t triangle) {
    return map && !vertices.world_tangent.empty() &&
           world.draws[world.triangle_draw[triangle]].has_tangents;
}

glm::vec3 normal_from_map(const World& world, const TransformedVertices& vertices,
                          const TextureSlot& slot, float scale, const SurfaceSample& pixel,
                          const glm::vec3& front) {
    const uint32_t* c = &world.indices[3 * static_cast<size_t>(pixel.triangle)];
    const glm::vec4 tangent = pixel.bary[0] * vertices.world_tangent[c[0]] +
                              pixel.bary[1] * vertices.world_tangent[c[1]] +
                              pixel.bary[2] * vertices.world_tangent[c[2]];
    const std::array<glm::vec2, 3> uv = world.corner_uvs(pixel.triangle, slot);
    const TextureLookup t = texture_lookup(uv[0], uv[1], uv[2], pixel,
                                           glm::vec2(slot.texture->width, slot.texture->height));
    const glm::vec3 texel =
        texel_in_mesh_frame(glm::vec3(slot.texture->sample(t.uv, t.lod)), slot.transform);
    return mapped_normal(front, tangent, pixel.back_facing, texel, scale);
}

}  // namespace facet
