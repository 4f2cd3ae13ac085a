#pragma once
// Part of the shading stage (render/shade_stage.cpp): eight points of one
// style, from the triangle each shows and where, to their colours. The
// surface is reconstructed (raster/surface_sample.hpp), the triangle's
// vertices and material gathered, textures and layers applied, and the
// style's model run (shade/shading_models.hpp).
#include <cstdint>

#include <glm/vec3.hpp>

#include "core/simd_math.hpp"
#include "raster/rasterizer.hpp"
#include "raster/surface_sample.hpp"
#include "render/shade_stage.hpp"
#include "shade/shading_models.hpp"

namespace facet {

struct ShadeBatch {
    // Set by the caller. Lanes >= count repeat lane 0.
    int count = 0;
    uint32_t id[simd::kLanes];  // the rasterizer's triangle id
    simd::vf x, y;              // where each point is, in the rasterizer's sample units
    bool want_normal = false;   // fill `normal` even if the style's model needs none
    bool want_wire = false;     // fill `wire` and `wire_color` (the lines pass)
    // > 0: fill `pixel_depth` with the depth of the nearest of each lane's
    // pixel_side x pixel_side samples round (x, y), all of the same triangle.
    int pixel_side = 0;

    // Set by shade_batch.
    const ShadeSetup* setup[simd::kLanes];
    uint32_t object[simd::kLanes];
    SurfaceSamples sample;  // callers read its w, each lane's depth (the plain path sets no more)
    simd::vf normal[3];     // on the viewer's side, any length, as the G-buffer keeps it
    simd::vf color[3];      // linear RGB over the background, the result
    // How much of the background the lane hides: 1, but for shadow
    // catchers the shadow's strength (their colour is then the background
    // darkened by it). The alpha pass shows color - background * (1 - coverage).
    simd::vf coverage;
    simd::vf pixel_depth;
    float wire[simd::kLanes];  // wireframe line coverage drawn over each lane, 0..1
    glm::vec3 wire_color{0.0f};

    // Scratch.
    const Material* material[simd::kLanes];
    bool has_uvs[simd::kLanes];
    bool has_colors[simd::kLanes];
    bool any_texture, any_vertex_colors, any_emission, any_shadow_catcher, any_fade;
    bool any_physical_map;  // the `pbr` model's maps
    SurfaceLanes lanes;
};

// Whether a batch whose lanes show triangles of `draw` (one mesh part of
// one object), of material `m`, takes the plain path under `style`
// (ShadingPaths::specialised): a Phong, Blinn-Phong or unlit style without
// layers, and a material that only its constants colour (no base colour
// texture or vertex colours unless the style sets the colour, no emission,
// shadow catcher or fade).
bool takes_plain_path(const StyleState& style, const Draw& draw, const Material& m);

// Shades the batch with in.frame.styles[style]; writes the fields marked
// "set by shade_batch". True when the plain path shaded it.
bool shade_batch(const ShadeInputs& in, const Rasterizer& raster, uint32_t style, ShadeBatch& b);

}  // namespace facet
