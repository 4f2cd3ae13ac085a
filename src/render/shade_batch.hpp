#pragma once
// Part of the shading stage (render/shade_stage.cpp): eight points of one
// style, from the triangle each shows and where, to their colours. The
// surface is reconstructed (raster/surface_sample.hpp), the triangle's
// vertices and material gathered, the steps its features ask for run
// (shade/material_terms.hpp), and the style's model called
// (shade/shading_models.hpp).
//
// One surface path, a template instantiated twice: the general one runs
// each step whose feature a batch has; the plain one is the same code with
// every step compiled out, for batches with no feature under a Phong,
// Blinn-Phong or unlit style without layers. Features are settled once per
// draw, style and frame (FrameInputs::draw_features); a batch only ORs its
// triangles' sets.
#include <cstdint>

#include <glm/vec3.hpp>

#include "core/simd_math.hpp"
#include "raster/rasterizer.hpp"
#include "render/shade_stage.hpp"

namespace facet {

// What the caller asks: read only.
struct ShadeRequest {
    int count = 0;              // lanes >= count repeat lane 0
    uint32_t id[simd::kLanes];  // the rasterizer's triangle id
    simd::vf x, y;              // where each point is, in the rasterizer's sample units
    bool want_normal = false;   // fill `normal` even if the style's model needs none
    bool want_wire = false;     // fill `wire` and `wire_color` (the lines pass)
    // > 0: `pixel_depth` is the depth of the nearest of each lane's
    // pixel_side x pixel_side samples round (x, y), all of the same triangle.
    int pixel_side = 0;
};

// What shade_batch gives back: every field, from every path.
struct ShadeResult {
    simd::vf color[3];  // linear RGB over the background
    // How much of the background the lane hides: 1, but for shadow
    // catchers the shadow's strength (their colour is then the background
    // darkened by it), and less where a material fades. The alpha pass
    // shows color - background * (1 - coverage).
    simd::vf coverage;
    simd::vf depth;        // linear view depth at (x, y)
    simd::vf pixel_depth;  // as ShadeRequest::pixel_side says; `depth` when it is 0
    // On the viewer's side, any length, as the G-buffer keeps it; zero
    // where neither the model nor the request needs it.
    simd::vf normal[3];
    uint32_t object[simd::kLanes];
    float wire[simd::kLanes];  // wireframe line coverage drawn over each lane, 0..1
    glm::vec3 wire_color{0.0f};
};

// Shades the request's points with in.frame.styles[style]. True when the
// plain path shaded them.
bool shade_batch(const ShadeInputs& in, const Rasterizer& raster, uint32_t style,
                 const ShadeRequest& request, ShadeResult& result);

}  // namespace facet
