#pragma once
// Stage 7b of a frame, when the scene asks for them: the passes that
// describe the surface each pixel shows rather than its colour (normal,
// object and material ids, uv, world position, motion; docs/passes.md),
// from the same visibility buffer the shading stage reads, tile by tile.
//
// Each pixel's samples fall into fragments, one per triangle
// (render/tile_fragments.hpp). Normal, uv and position are the
// coverage-weighted sum of the fragments' values, the background counting
// as zero, so they are anti-aliased as the colour is. Ids and motion come
// from the fragment that covers most samples (the nearer on a tie), or are
// 0 where the background covers more: ids are never blended.
#include <cstdint>
#include <span>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "core/image.hpp"
#include "output/passes.hpp"
#include "raster/rasterizer.hpp"
#include "render/frame_inputs.hpp"
#include "render/vertex_stage.hpp"
#include "render/world.hpp"

namespace facet {

// The output-size images of the surface passes; only those asked for are
// filled (the others keep their size 0).
struct SurfacePassImages {
    Image<glm::vec3> normal;      // unit (shorter at edges), world or camera space
    Image<uint32_t> object_id;    // scene object index + 1; 0 is the background
    Image<uint32_t> material_id;  // World::materials index + 1; 0 is the background
    Image<glm::vec2> uv;          // the mesh's first texture coordinates
    Image<glm::vec3> position;    // world space
    Image<glm::vec2> motion;      // pixels to where the point was one frame earlier, y up
};

struct SurfacePassInputs {
    const World& world;
    const FrameInputs& frame;
    const TransformedVertices& vertices;
    // Every vertex in clip space one frame earlier (the motion pass), else empty.
    std::span<const glm::vec4> previous_clip;
    int samples_per_side;
    PassSet passes;
    bool normals_in_camera_space;
    int width, height;  // the output's pixels
    // Per scene object: whether its style draws normal maps (`pbr`), so
    // the normal pass shows the mapped normal.
    std::span<const uint8_t> normal_mapped;
};

// Gives each asked-for image of `images` the output size, reusing buffers.
void fit_surface_passes(const SurfacePassInputs& in, SurfacePassImages& images);

// Bytes per pixel of `pass` in SurfacePassImages; 0 for a pass not kept there.
uint64_t surface_pass_pixel_bytes(Pass pass);

// Writes the tile's pixels of every asked-for pass. Called for different
// tiles on several threads at once: writes only the tile's own pixels.
void write_surface_passes(const TileVisibility& tile, const Rasterizer& raster,
                          const SurfacePassInputs& in, SurfacePassImages& out);

// True when any pass this stage writes is asked for.
inline bool wants_surface_passes(PassSet passes) {
    return passes.any_of(
        {Pass::normal, Pass::object_id, Pass::material_id, Pass::uv, Pass::position, Pass::motion});
}

}  // namespace facet
