#pragma once
// Stage 7 of a frame (deferred shading): every pixel of a rasterized tile,
// from the triangle id and depth the tile stage left in the visibility
// buffer. Each visible point is shaded once, by the style of the object it
// shows (shade/shading_models.hpp); background pixels get the background.
// The stage also fills the G-buffer the outline stage reads.
#include <span>

#include "core/image.hpp"
#include "post/outlines.hpp"
#include "raster/rasterizer.hpp"
#include "render/frame_inputs.hpp"
#include "render/vertex_stage.hpp"
#include "render/world.hpp"
#include "shade/lighting.hpp"

namespace facet {

struct ShadeInputs {
    const World& world;
    const FrameInputs& frame;
    const StylePlan& plan;
    const TransformedVertices& vertices;
    std::span<const ShadeLight> lights;
    int samples_per_side;  // wire widths and screen-space strokes scale with it
};

// The images the stage writes, at the rasterizer's (sample) resolution.
struct ShadeTarget {
    ColorImage& color;        // linear RGBA
    DepthImage& depth;        // linear view depth, +inf for background
    OutlineBuffers* gbuffer;  // depth, normal and object id; null when no outlines
};

// Shades one tile; `raster` resolves the tile's triangle ids. Called for
// different tiles on several threads at once: writes only the tile's pixels.
void shade_tile(const TileVisibility& tile, const Rasterizer& raster, const ShadeInputs& in,
                const ShadeTarget& out);

}  // namespace facet
