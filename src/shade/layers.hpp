#pragma once
// Layers drawn over a shading model's colour (docs/styles.md, "Layers"):
// hatching strokes from a tonal art map, then wireframe lines.
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "shade/hatch_mapping.hpp"
#include "shade/style_state.hpp"

namespace facet {

// What the layers need at one point besides its colour.
// No default values: the shading stage keeps eight of these per batch and
// fills them only for styles with layers.
struct LayerInputs {
    glm::vec3 albedo;      // the object colour, for the default ink
    HatchFootprint hatch;  // where the strokes are read (styles with hatching)
    HatchFootprint paper;  // where the paper grain is read (pencil)
    float hatch_tone;      // hatch_tone() of the point (styles with hatching)
    float wire;            // wireframe line coverage, 0..1
};

inline bool has_layers(const StyleState& style) {
    return style.hatching.has_value() || style.wireframe;
}

// The tone a point is hatched at, 1 (white, no strokes) .. 0. `palette_tone`
// is the palette model's cel tone (>= 0), which hatches by cels as seed 000
// does; other models hatch by the lightness the shading shows (-1): the
// CIE lightness L* / 100 (tone as the eye judges it) of its luminance
// times 2^exposure, clipped at 1, over the style's white point. A dark
// object gets dense strokes, a fully lit white one none.
float hatch_tone(const StyleState& style, glm::vec3 color, float palette_tone);

// The layers over a shading model's colour.
glm::vec3 apply_layers(const StyleState& style, glm::vec3 color, const LayerInputs& in);

}  // namespace facet
