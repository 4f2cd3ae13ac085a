#pragma once
// The shading models, as the shading stage calls them: up to eight visible
// points of one style at a time. One switch picks the model; each model
// lives in its own file (model_*.hpp, and palette_style.hpp, gooch_style.hpp
// and toon_style.hpp for the stylised ones), and layers (hatching,
// wireframe) are applied afterwards by shade/layers.hpp.
#include <span>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "assets/mesh.hpp"
#include "shade/brdf.hpp"
#include "shade/lighting.hpp"
#include "shade/lighting_batch.hpp"
#include "shade/model_pbr.hpp"
#include "shade/style_state.hpp"

namespace facet {

struct TransmissionBackdrop;  // shade/transmission_backdrop.hpp

// The points: SurfaceBatch holds position, the normal on the viewer's side
// (any length; the face normal for flat shading), the material's terms and
// whether shadows darken the point.
struct SurfaceLanes {
    int count = 0;
    SurfaceBatch surface;
    simd::vf albedo[3];  // object colour (linear RGB), texture applied
    // The Phong family's highlight colour: white, or a metal-rough
    // material's specular colour (shade/metal_rough_phong.hpp).
    simd::vf specular_color[3];
    simd::vf depth;  // linear view depth
    // Gouraud: the vertex lighting interpolated, diffuse and specular RGB.
    simd::vf vertex_diffuse[3], vertex_specular[3];
    // The `pbr` model's terms, textures applied; `base` is left to the
    // model, which takes it from `albedo`.
    pbr::SurfaceTerms<simd::vf> pbr;

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
    // What transmitting surfaces see through themselves; null outside the
    // glass layers' pass (shade/transmission_backdrop.hpp).
    const TransmissionBackdrop* backdrop = nullptr;
};

void shade_lanes(const StyleState& style, const ShadingContext& context, SurfaceLanes& in,
                 ShadedLanes& out);

// shade_lanes for the plain styles' models (plain_style: Phong,
// Blinn-Phong, unlit), which leave palette_tone alone.
void shade_plain_model(const StyleState& style, const ShadingContext& context, SurfaceLanes& in,
                       ShadedLanes& out);

// What a style's model reads besides the barycentrics and the albedo.
struct ModelNeeds {
    bool position;      // world position (and shadows, emission and catchers' light)
    bool normal;        // the normal on the viewer's side
    bool light_terms;   // the material's Phong terms and the lights
    bool vertex_light;  // Gouraud's light from the vertices
    // Per batch: its `pbr` materials have a sheen, a thin film or an anisotropy
    // (kExtraLobes); without, their terms are zero for the whole batch.
    bool extra_lobes = false;
};
ModelNeeds needs_of(ShadingModel model);

// The features only the `pbr` model draws: its maps and its extra lobes.
constexpr uint32_t kPbrOnlyFeatures = kPhysicalMaps | kNormalMaps | kExtraLobes;

// Whether `model` is of the Phong family, which reads a metal-rough
// material through shade/metal_rough_phong.hpp.
bool phong_family(ShadingModel model);

// Of a material's and mesh part's features (MaterialFeature,
// assets/mesh.hpp), those `style` draws: its own base colour replaces the
// maps and vertex colours (and the reading of metal and roughness), only
// `pbr` reads its maps, only the Phong family reads metal and roughness,
// and only the models that light a surface add emission. Asked once per
// draw, style and frame.
uint32_t drawn_features(const StyleState& style, uint32_t features);
// The same rule for a style's model and whether it gives its own base
// colour, before any frame (the world's warnings of what is lost).
uint32_t drawn_features(ShadingModel model, bool style_base_color, uint32_t features);

// Whether `style`'s batches with no drawn feature take the plain path, the
// surface path compiled without any (render/shade_batch.cpp): a Phong,
// Blinn-Phong or unlit model without layers.
bool plain_style(const StyleState& style);

}  // namespace facet
