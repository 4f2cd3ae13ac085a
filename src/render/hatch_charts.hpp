#pragma once
// Part of the shading stage: where one point of a hatched surface reads its
// strokes. The style's layout space gives the point's charts (the object's
// planes, its UVs or the screen) and the direction field the strokes' angle
// in each; shade/hatch_mapping.hpp turns those into tonal-art-map taps.
#include <cstdint>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "render/world.hpp"
#include "shade/hatch_mapping.hpp"
#include "shade/style_state.hpp"

namespace facet {

struct HatchPoint {
    uint32_t triangle;   // World's triangle order
    glm::vec3 bary;      // weights of the triangle's vertices
    glm::vec3 ddx, ddy;  // their derivatives per output pixel
    glm::vec2 pixel;     // where, in output pixels
    bool has_uvs;
};

// The footprints asked for (null: not wanted), from one gathering of the
// point's triangle: the strokes', which follow the direction field, and the
// paper grain's (pencil), laid out the same way but never turned, so it
// does not change where strokes begin.
void hatch_footprints(const World& world, const HatchingState& style, const HatchPoint& point,
                      HatchFootprint* strokes, HatchFootprint* paper);

}  // namespace facet
