#pragma once
// The shading models, as the shading stage calls them: up to eight visible
// points of one style at a time. One switch picks the model; each model
// lives in its own file (model_*.hpp, and palette_style.hpp, gooch_style.hpp
// and toon_style.hpp for the stylised ones), and layers (hatching,
// wireframe) are applied afterwards by shade/layers.hpp.
#include <span>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "shade/lighting.hpp"
#include "shade/lighting_batch.hpp"
#include "shade/style_state.hpp"

namespace facet {

// The points: SurfaceBatch holds position, the normal on the viewer's side
// (any length; the face normal for flat shading), the material's terms and
// whether shadows darken the point.
struct SurfaceLanes {
    int count = 0;
    SurfaceBatch surface;
    glm::vec3 albedo[simd::kLanes];             // object colour, texture applied
    float depth[simd::kLanes];                  // linear view depth
    LightingResult vertex_light[simd::kLanes];  // Gouraud: the interpolated vertex lighting
};

struct ShadedLanes {
    glm::vec3 color[simd::kLanes];  // linear RGB
    // Palette only: the tone of the cel for hatching (seed 000), else -1.
    float palette_tone[simd::kLanes];
};

struct ShadingContext {
    glm::vec3 eye;                       // camera position, world space
    std::span<const ShadeLight> lights;  // lights[0] is the stylised models' key light
    glm::vec2 depth_range;               // the depth view's near..far
};

void shade_lanes(const StyleState& style, const ShadingContext& context, SurfaceLanes& in,
                 ShadedLanes& out);

}  // namespace facet
