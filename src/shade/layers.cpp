#include "shade/layers.hpp"

#include <algorithm>

#include "core/color.hpp"

namespace facet {

float hatch_tone(const StyleState& style, glm::vec3 color, float palette_tone) {
    if (palette_tone >= 0) return palette_hatch_tone(style.palette, palette_tone);
    const HatchingState& h = *style.hatching;
    const float light =
        std::max(rec709_luminance(color.x, color.y, color.z), 0.0f) * h.exposure_scale;
    return std::clamp(cie_lightness(light) / h.white, 0.0f, 1.0f);
}

glm::vec3 apply_layers(const StyleState& style, glm::vec3 color, const LayerInputs& in) {
    if (style.hatching) {
        const HatchingState& h = *style.hatching;
        const float coverage = hatch_coverage(*h.tam, in.hatch_tone, in.hatch) * h.strength;
        // A wash: the paper tinted by the object's colour, flat, so the
        // strokes alone say how much light falls (as in a pen drawing
        // coloured with watercolour).
        if (h.wash) color = h.paper * (glm::vec3(1.0f) + (in.albedo - glm::vec3(1.0f)) * *h.wash);
        if (h.pencil) color *= hatch_paper_shade(*h.tam, in.paper);
        const glm::vec3 ink = h.ink ? *h.ink : palette_ink(style.palette, in.albedo);
        color =
            h.additive ? add_hatching(color, ink, coverage) : apply_hatching(color, ink, coverage);
    }
    if (in.wire > 0) color += (style.wire.color - color) * in.wire;
    return color;
}

}  // namespace facet
