#include "render/normal_map_lookup.hpp"

#include "shade/normal_map.hpp"
#include "shade/texture_lod.hpp"

namespace facet {

bool draws_normal_map(const World& world, const TransformedVertices& vertices, const Material& m,
                      uint32_t triangle) {
    return m.normal_map && !vertices.world_tangent.empty() &&
           world.draws[world.triangle_draw[triangle]].has_tangents;
}

glm::vec3 normal_from_map(const World& world, const TransformedVertices& vertices,
                          const Material& m, const SurfaceSample& pixel, const glm::vec3& front) {
    const uint32_t* c = &world.indices[3 * static_cast<size_t>(pixel.triangle)];
    const glm::vec4 tangent = pixel.bary[0] * vertices.world_tangent[c[0]] +
                              pixel.bary[1] * vertices.world_tangent[c[1]] +
                              pixel.bary[2] * vertices.world_tangent[c[2]];
    const TextureSlot& slot = m.normal_map;
    const std::array<glm::vec2, 3> uv = world.corner_uvs(pixel.triangle, slot);
    const TextureLookup t = texture_lookup(uv[0], uv[1], uv[2], pixel,
                                           glm::vec2(slot.texture->width, slot.texture->height));
    const glm::vec3 texel(slot.texture->sample(t.uv, t.lod));
    return mapped_normal(front, tangent, pixel.back_facing, texel, m.normal_scale);
}

}  // namespace facet
