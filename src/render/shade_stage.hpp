#pragma once
// Stage 7 of a frame (deferred shading): the fragments of a rasterized tile
// (render/tile_fragments.hpp), from the triangle ids and depths the tile
// stage left in the visibility buffer. Each fragment is shaded once, by the
// style of the object it shows (shade/shading_models.hpp), eight fragments
// of one style at a time. Background pixels get the background.
//
// The stage writes either the finished pixels (each the coverage-weighted
// sum of its fragments) or, when screen-space stages follow at the sample
// resolution, every sample with its fragment's colour and the G-buffer
// those stages read: the frame's targets decide (render/frame_targets.hpp).
#include <span>

#include "core/half.hpp"
#include "core/image.hpp"
#include "post/outlines.hpp"
#include "raster/rasterizer.hpp"
#include "render/frame_inputs.hpp"
#include "render/frame_targets.hpp"
#include "render/vertex_stage.hpp"
#include "render/world.hpp"
#include "shade/lighting.hpp"

namespace facet {

// `specialised`: plain batches (none of their draws' features drawn by
// their style, a Phong, Blinn-Phong or unlit one without layers) take the
// surface path's plain instantiation, which writes the same bits as the
// general one (render/shade_batch.cpp); `general_only`: every batch takes
// the general instantiation, for tests and the bench to compare.
enum class ShadingPaths { specialised, general_only };

struct ShadeInputs {
    const World& world;
    const FrameInputs& frame;
    const StylePlan& plan;
    const TransformedVertices& vertices;
    std::span<const ShadeLight> lights;
    // The lights that cast shadows, with their maps (Gouraud looks their
    // shadows up per pixel).
    std::span<const ShadeLight> shadow_lights;
    int samples_per_side;  // k: the rasterizer runs at k times the output's width and height
    // Per triangle, this frame's wireframe edges (render/feature_edge_stage.hpp);
    // empty without wireframes.
    std::span<const uint8_t> edge_mask;
    ShadingPaths paths = ShadingPaths::specialised;
    // In the glass layers' pass, what transmitting surfaces see through
    // themselves (render/transmission_stage.hpp); else null.
    const TransmissionBackdrop* backdrop = nullptr;
};

// Where a tile's shading goes, as the frame's targets say
// (render/frame_targets.hpp). At `pixels`: `pixels`, and `depth` of the
// output's size, and the G-buffer and surface share when ambient occlusion
// reads them. At `samples`: `samples`, `depth` of the rasterizer's size, and
// the G-buffer and line samples when later stages read them.
struct ShadeTarget {
    ShadeResolution resolution;
    HalfColorImage* pixels;  // linear RGBA, half floats, premultiplied
    ColorImage* samples;     // rgb the sample's colour, a its coverage (post/resolve.hpp)
    DepthImage& depth;       // linear view depth, +inf for background
    // Per sample or pixel (as `resolution`): depth, normal, object id; null
    // when not needed. A pixel's are those of its nearest sample's
    // triangle, the depth on that triangle's plane at the pixel's centre.
    OutlineBuffers* gbuffer;
    // At `pixels`, for the alpha pass: the same pixels over nothing (no
    // background), premultiplied; null when not asked for.
    HalfColorImage* pixels_over_nothing;
    // At `samples`: each sample's wireframe stroke alone, premultiplied;
    // null when not needed.
    ColorImage* line_samples;
    // At `pixels` with a G-buffer: the share of each pixel's samples that
    // show a surface, so that occlusion leaves the background's share alone.
    Image<float>* surface_share;
    // Samples without a triangle keep what the target holds instead of
    // taking the background, and a pixel's depth is the nearer of the two:
    // a glass layer drawn over the frame (render/transmission_stage.hpp).
    bool over_existing = false;
};

// How many batches of eight points shading ran, and how many of them took
// the plain path (render/shade_batch.cpp).
struct ShadeCounts {
    uint64_t batches = 0, plain = 0;
    void add(bool was_plain) { ++batches, plain += was_plain ? 1 : 0; }
};

// Shades one tile; `raster` resolves its triangle ids. Called for different
// tiles on several threads at once: writes only the tile's own pixels.
ShadeCounts shade_tile(const TileVisibility& tile, const Rasterizer& raster, const ShadeInputs& in,
                       const ShadeTarget& out);

}  // namespace facet
