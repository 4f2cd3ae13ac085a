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
#include "shade/model_pbr.hpp"
#include "shade/style_state.hpp"

namespace facet {

// The points: SurfaceBatch holds position, the normal on the viewer's side
// (any length; the face normal for flat shading), the material's terms and
// whether shadows darken the point.
struct SurfaceLanes {
    int count = 0;
    SurfaceBatch surface;
    simd::vf albedo[3];  // object colour (linear RGB), texture applied
    simd::vf depth;      // linear view depth
    // Gouraud: the vertex lighting interpolated, diffuse and specular RGB.
    simd::vf vertex_diffuse[3], vertex_specular[3];
    PbrLanes pbr;  // the `pbr` model only

    glm::vec3 albedo_at(int lane) const {
        return {albedo[0][lane], albedo[1][lane], albedo[2][lane]};
    }
};

struct ShadedLanes {
    simd::vf color[3];  // linear RGB
    // Palette only: the tone of the cel for hatching (seed 000), else -1.
    float palette_tone[simd::kLanes];

    glm::vec3 color_at(int lane) const { return {color[0][lane], color[1][lane], color[2][lane]}; }
    void set(int lane, const glm::vec3& c) {
        color[0][lane] = c.x, color[1][lane] = c.y, color[2][lane] = c.z;
    }
};

struct ShadingContext {
    glm::vec3 eye;                       // camera position, world space
    std::span<const ShadeLight> lights;  // lights[0] is the stylised models' key light
    glm::vec2 depth_range;               // the depth view's near..far
    const EnvironmentLighting* environment = nullptr;  // the `pbr` model's indirect light
};

void shade_lanes(const StyleState& style, const ShadingContext& context, SurfaceLanes& in,
                 ShadedLanes& out);

}  // namespace facet
