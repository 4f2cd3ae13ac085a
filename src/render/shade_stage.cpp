#include "render/shade_stage.hpp"

#include <algorithm>
#include <cstring>
#include <limits>
#include <vector>

#include "render/shade_batch.hpp"
#include "render/tile_fragments.hpp"

namespace facet {
namespace {

using simd::kLanes;
using simd::vf;
using simd::vi;

constexpr float kInfinity = std::numeric_limits<float>::infinity();

// The style that shades a triangle id, remembering the last id asked for:
// neighbouring pixels mostly show the same triangle.
class StyleLookup {
  public:
    StyleLookup(const ShadeInputs& in, const Rasterizer& raster) : in_(in), raster_(raster) {}

    uint32_t operator()(uint32_t id) {
        if (in_.frame.styles.size() == 1) return 0;
        if (id != last_id_) {
            last_id_ = id;
            const uint32_t tri = raster_.shade_setup(id).source_triangle;
            const World& world = in_.world;
            last_style_ = in_.plan.object_style[world.draws[world.triangle_draw[tri]].object];
        }
        return last_style_;
    }

  private:
    const ShadeInputs& in_;
    const Rasterizer& raster_;
    uint32_t last_id_ = kNoTriangle, last_style_ = 0;
};

// Linear view depth at (x, y), in the rasterizer's sample units, on the
// plane of the triangle behind `id`.
float depth_on_triangle(const Rasterizer& raster, uint32_t id, float x, float y) {
    const ShadeSetup& s = raster.shade_setup(id);
    const float fx = x - s.x0, fy = y - s.y0;
    return 1.0f / (s.inv_w[0] + s.inv_w[1] * fx + s.inv_w[2] * fy);
}

// Linear view depth of sample (x, y) of the triangle behind `id`: the same
// operations as reconstruct_surfaces, so the same bits as its w.
float sample_depth(const Rasterizer& raster, uint32_t id, int x, int y) {
    return depth_on_triangle(raster, id, static_cast<float>(x) + 0.5f,
                             static_cast<float>(y) + 0.5f);
}

// The nearest of a pixel's samples (largest reversed-Z): the triangle it
// shows and its linear depth.
struct NearestSample {
    uint32_t id = kNoTriangle;
    float depth = kInfinity;
};

NearestSample nearest_sample(const TileVisibility& tile, const Rasterizer& raster, int side, int px,
                             int py) {
    int nearest = -1;
    float nearest_z = 0;
    for (int sy = py * side; sy < (py + 1) * side; ++sy)
        for (int sx = px * side; sx < (px + 1) * side; ++sx) {
            const int at = sy * kTileSize + sx;
            if (tile.id[at] != kNoTriangle && (nearest < 0 || tile.depth[at] > nearest_z)) {
                nearest = at;
                nearest_z = tile.depth[at];
            }
        }
    if (nearest < 0) return {};
    const uint32_t id = tile.id[nearest];
    return {id,
            sample_depth(raster, id, tile.x0 + nearest % kTileSize, tile.y0 + nearest / kTileSize)};
}

void write_gbuffer(OutlineBuffers& g, int x, int y, float depth, const glm::vec3& normal,
                   uint32_t object) {
    const size_t i = g.index(x, y);
    g.depth[i] = depth;
    g.normal[i] = normal;
    g.object_id[i] = object;
}

// --- Pixels whose samples all show one thing, eight along a row at a time ---

// Eight pixels of a row: what each shows, and the colours and depths to write.
struct RowChunk {
    int px0, py, count;   // first pixel (in the tile), row, pixels in the chunk
    uint32_t id[kLanes];  // per pixel: a triangle id, kNoTriangle or kMixedPixel
    vf color[4];          // RGBA of the pixels written here
    vf coverage;          // how much of the background each hides (ShadeResult::coverage)
    vf depth;
    // For a G-buffer at the pixels (ambient occlusion without outlines):
    // the surface at each pixel's centre.
    vf centre_depth;
    vf normal[3];
    uint32_t object[kLanes];
};

// Shades the chunk's pixels in `mine` (lanes of one style); the points are
// the pixels' centres.
[[gnu::always_inline]] inline void shade_chunk_style(const ShadeInputs& in,
                                                     const Rasterizer& raster,
                                                     const TileVisibility& tile, uint32_t style,
                                                     unsigned mine, bool want_normal,
                                                     RowChunk& chunk, ShadeCounts& counts) {
    const int side = in.samples_per_side;
    const float k = static_cast<float>(side);
    ShadeRequest b;
    b.count = chunk.count;
    b.want_normal = want_normal;
    const int first = __builtin_ctz(mine);
    if (mine == 0xffu)
        std::memcpy(b.id, chunk.id, sizeof b.id);
    else
        for (int i = 0; i < kLanes; ++i) b.id[i] = chunk.id[(mine >> i) & 1 ? i : first];
    const vf lane = {0, 1, 2, 3, 4, 5, 6, 7};
    b.x = (lane + static_cast<float>(chunk.px0)) * k + (static_cast<float>(tile.x0) + 0.5f * k);
    b.y = simd::splat(static_cast<float>(tile.y0 + chunk.py * side) + 0.5f * k);
    b.pixel_side = side > 1 ? side : 0;
    ShadeResult r;
    counts.add(shade_batch(in, raster, style, b, r));
    const vi lane_bit = {1, 2, 4, 8, 16, 32, 64, 128};
    const vi mask = (simd::splat_i(static_cast<int32_t>(mine)) & lane_bit) != simd::splat_i(0);
    for (int a = 0; a < 3; ++a) chunk.color[a] = mask ? r.color[a] : chunk.color[a];
    const float background_alpha = in.frame.background.a;
    chunk.color[3] = mask ? r.coverage + (1.0f - r.coverage) * background_alpha : chunk.color[3];
    chunk.coverage = mask ? r.coverage : chunk.coverage;
    chunk.depth = mask ? r.pixel_depth : chunk.depth;
    if (!want_normal) return;
    chunk.centre_depth = mask ? r.depth : chunk.centre_depth;
    for (int a = 0; a < 3; ++a) chunk.normal[a] = mask ? r.normal[a] : chunk.normal[a];
    for (int i = 0; i < kLanes; ++i)
        if ((mine >> i) & 1) chunk.object[i] = r.object[i];
}

// The colour a surface shows over nothing, from its colour over the
// background and how much of the background it hides.
glm::vec4 over_nothing(const glm::vec3& color, float coverage, const glm::vec4& background) {
    if (coverage == 1.0f) return {color, 1.0f};  // exactly, for opaque surfaces
    return {color - glm::vec3(background) * (1.0f - coverage), coverage};
}

// The alpha pass's copy of a chunk: the pixels that show a surface as they
// are, the background ones transparent. Mixed pixels come later.
void write_chunk_over_nothing(const ShadeTarget& out, const glm::vec4& background, int x, int y,
                              const RowChunk& chunk, unsigned shown) {
    Rgba16F* pixels = &out.pixels_over_nothing->at(x, y);
    for (int i = 0; i < chunk.count; ++i) {
        if (chunk.id[i] == kMixedPixel) continue;
        if (out.over_existing && !((shown >> i) & 1)) continue;  // keeps what it held
        const glm::vec3 color(chunk.color[0][i], chunk.color[1][i], chunk.color[2][i]);
        pixels[i] = (shown >> i) & 1 ? to_half(over_nothing(color, chunk.coverage[i], background))
                                     : to_half(glm::vec4(0.0f));
    }
}

// The G-buffer's copy of a chunk, and each pixel's share of samples that
// show a surface (1 or 0 here). Mixed pixels come later.
void write_chunk_gbuffer(const ShadeTarget& out, int x, int y, const RowChunk& chunk,
                         unsigned shown) {
    for (int i = 0; i < chunk.count; ++i) {
        if (chunk.id[i] == kMixedPixel) continue;
        const bool surface = (shown >> i) & 1;
        const glm::vec3 normal(chunk.normal[0][i], chunk.normal[1][i], chunk.normal[2][i]);
        write_gbuffer(*out.gbuffer, x + i, y, chunk.centre_depth[i],
                      surface ? normal : glm::vec3(0), surface ? chunk.object[i] : kNoObject);
        out.surface_share->at(x + i, y) = surface ? 1.0f : 0.0f;
    }
}

[[gnu::always_inline]] inline void write_chunk(const TileVisibility& tile, const ShadeTarget& out,
                                               const glm::vec4& background, int side,
                                               const RowChunk& chunk, bool any_mixed,
                                               unsigned shown) {
    const int x = tile.x0 / side + chunk.px0, y = tile.y0 / side + chunk.py;
    if (out.pixels_over_nothing) write_chunk_over_nothing(out, background, x, y, chunk, shown);
    if (out.gbuffer) write_chunk_gbuffer(out, x, y, chunk, shown);
    Rgba16F* colors = &out.pixels->at(x, y);
    float* depths = &out.depth.at(x, y);
    if (chunk.count == kLanes && !any_mixed) {
        store_half_rgba(chunk.color, colors);
        simd::store_streaming(depths, chunk.depth);
        return;
    }
    for (int i = 0; i < chunk.count; ++i) {
        if (chunk.id[i] == kMixedPixel) continue;  // written from its fragments
        colors[i] = to_half(
            glm::vec4(chunk.color[0][i], chunk.color[1][i], chunk.color[2][i], chunk.color[3][i]));
        depths[i] = chunk.depth[i];
    }
}

// What the chunk's pixels show: a triangle, the background, or a mix.
// Returns the mask of pixels that show a triangle.
[[gnu::always_inline]] inline unsigned chunk_ids(const TileVisibility& tile, int side,
                                                 RowChunk& chunk, bool& any_mixed) {
    const uint32_t* row = tile.id + chunk.py * kTileSize + chunk.px0;
    vi ids;
    if (side == 1 && chunk.count == kLanes) {
        std::memcpy(&ids, row, sizeof ids);  // one load, then one store
        std::memcpy(chunk.id, &ids, sizeof ids);
    } else if (side == 2 && chunk.count == kLanes) {  // 4 samples a pixel: the usual AA
        const uint32_t* top = tile.id + 2 * chunk.py * kTileSize + 2 * chunk.px0;
        vi t[2], b[2];
        std::memcpy(t, top, sizeof t);
        std::memcpy(b, top + kTileSize, sizeof b);
        auto even = [](vi lo, vi hi) {
            return __builtin_shufflevector(lo, hi, 0, 2, 4, 6, 8, 10, 12, 14);
        };
        auto odd = [](vi lo, vi hi) {
            return __builtin_shufflevector(lo, hi, 1, 3, 5, 7, 9, 11, 13, 15);
        };
        const vi top_left = even(t[0], t[1]);
        const vi same = (top_left == odd(t[0], t[1])) & (top_left == even(b[0], b[1])) &
                        (top_left == odd(b[0], b[1]));
        ids = same ? top_left : simd::splat_i(static_cast<int32_t>(kMixedPixel));
        std::memcpy(chunk.id, &ids, sizeof ids);
    } else {
        for (int i = 0; i < kLanes; ++i)
            chunk.id[i] = i >= chunk.count ? kNoTriangle
                          : side == 1      ? row[i]
                                           : pixel_id(tile, side, chunk.px0 + i, chunk.py);
        std::memcpy(&ids, chunk.id, sizeof ids);
    }
    // Ids count up from 0; kMixedPixel and kNoTriangle are the two largest.
    const unsigned shown =
        simd::movemask(ids + simd::splat_i(2) > simd::splat_i(1));  // wraps the two to 0, 1
    any_mixed = simd::movemask(ids == simd::splat_i(static_cast<int32_t>(kMixedPixel))) != 0;
    return shown;
}

// What the chunk's pixels hold, for a layer drawn over them
// (ShadeTarget::over_existing).
void load_existing(const TileVisibility& tile, const ShadeTarget& out, int side, RowChunk& chunk) {
    const int x = tile.x0 / side + chunk.px0, y = tile.y0 / side + chunk.py;
    for (int i = 0; i < kLanes; ++i) {
        const int at = std::min(i, chunk.count - 1);
        const glm::vec4 c = to_float(out.pixels->at(x + at, y));
        for (int a = 0; a < 4; ++a) chunk.color[a][i] = c[a];
        chunk.depth[i] = out.depth.at(x + at, y);
    }
}

// Every pixel of the tile that is background or shows one triangle.
// Pixels with samples of several things go into `mixed` as fragments.
[[gnu::always_inline]] inline void shade_simple_pixels(const TileVisibility& tile,
                                                       const Rasterizer& raster,
                                                       const ShadeInputs& in,
                                                       const ShadeTarget& out, TileFragments& mixed,
                                                       ShadeCounts& counts) {
    const int side = in.samples_per_side;
    const int pixels_x = tile.width / side, pixels_y = tile.height / side;
    const glm::vec4 bg = in.frame.background;
    const bool one_style = in.frame.styles.size() == 1;
    const bool want_normal = out.gbuffer != nullptr;
    StyleLookup style_of_id(in, raster);
    RowChunk chunk;
    for (chunk.py = 0; chunk.py < pixels_y; ++chunk.py)
        for (chunk.px0 = 0; chunk.px0 < pixels_x; chunk.px0 += kLanes) {
            chunk.count = std::min(kLanes, pixels_x - chunk.px0);
            bool any_mixed = false;
            const unsigned shown_at_start = chunk_ids(tile, side, chunk, any_mixed);
            unsigned shown = shown_at_start;
            // Over existing pixels, a chunk its surfaces cover whole need
            // not read what they held.
            const bool covered = shown == (1u << chunk.count) - 1 && !any_mixed;
            if (out.over_existing && !covered) {
                load_existing(tile, out, side, chunk);
            } else {
                for (int a = 0; a < 4; ++a) chunk.color[a] = simd::splat(bg[a]);
                chunk.depth = simd::splat(kInfinity);
            }
            chunk.coverage = simd::splat(0.0f);
            if (want_normal) {
                chunk.centre_depth = simd::splat(kInfinity);
                for (vf& n : chunk.normal) n = simd::splat(0.0f);
                std::fill(chunk.object, chunk.object + kLanes, kNoObject);
            }
            // The next chunk's triangles are most likely not in cache yet
            // (a dense mesh shows a new triangle every pixel or two): ask
            // for their setup records now, while this chunk shades.
            if (side == 1 && chunk.px0 + 2 * kLanes <= pixels_x) {
                const uint32_t* next = tile.id + chunk.py * kTileSize + chunk.px0 + kLanes;
                for (int i = 0; i < kLanes; i += 2)
                    if (next[i] < kMixedPixel) __builtin_prefetch(&raster.shade_setup(next[i]));
            }
            if (one_style && shown)
                shade_chunk_style(in, raster, tile, 0, shown, want_normal, chunk, counts);
            while (!one_style && shown) {  // one style at a time
                const uint32_t style = style_of_id(chunk.id[__builtin_ctz(shown)]);
                unsigned mine = 0;
                for (int i = 0; i < kLanes; ++i)
                    if ((shown >> i) & 1 && style_of_id(chunk.id[i]) == style) mine |= 1u << i;
                shade_chunk_style(in, raster, tile, style, mine, want_normal, chunk, counts);
                shown &= ~mine;
            }
            write_chunk(tile, out, bg, side, chunk, any_mixed, shown_at_start);
            if (any_mixed)
                for (int i = 0; i < chunk.count; ++i)
                    if (chunk.id[i] == kMixedPixel)
                        add_pixel_fragments(tile, chunk.px0 + i, chunk.py, mixed);
        }
}

// --- Fragments: pixels whose samples show several things ---

// Fragments in batches of eight of one style, each batch's colours handed
// to `write(batch, fragment indices)`, with the normal when `out` has a
// G-buffer and the wireframe when it has line samples.
template <typename Write>
void shade_fragments(const TileFragments& f, const Rasterizer& raster, const ShadeInputs& in,
                     const ShadeTarget& out, ShadeCounts& counts, Write write) {
    StyleLookup style_of_id(in, raster);
    std::vector<uint32_t> style_of(static_cast<size_t>(f.count));
    std::vector<int> order(static_cast<size_t>(f.count));
    for (int i = 0; i < f.count; ++i) style_of[i] = style_of_id(f.id[i]);
    for (int i = 0; i < f.count; ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(),
                     [&](int a, int b) { return style_of[a] < style_of[b]; });
    ShadeRequest b;
    ShadeResult r;
    b.want_normal = out.gbuffer != nullptr;
    b.want_wire = out.line_samples != nullptr;
    int fragment[kLanes];
    for (int first = 0; first < f.count;) {
        const uint32_t style = style_of[order[first]];
        b.count = 0;
        while (b.count < kLanes && first + b.count < f.count &&
               style_of[order[first + b.count]] == style) {
            fragment[b.count] = order[first + b.count];
            ++b.count;
        }
        float xs[kLanes], ys[kLanes];
        for (int i = 0; i < kLanes; ++i) {
            const int at = fragment[i < b.count ? i : 0];
            b.id[i] = f.id[at];
            xs[i] = f.x[at];
            ys[i] = f.y[at];
        }
        std::memcpy(&b.x, xs, sizeof b.x);
        std::memcpy(&b.y, ys, sizeof b.y);
        counts.add(shade_batch(in, raster, style, b, r));
        write(b, r, fragment);
        first += b.count;
    }
}

// Mixed pixels, resolved here: each the coverage-weighted sum of its
// fragments and the background, with the nearest sample's depth (and in
// the G-buffer, the nearest sample's normal and object, and the share of
// the samples that show a surface).
void shade_mixed_pixels(const TileVisibility& tile, const Rasterizer& raster, const ShadeInputs& in,
                        const ShadeTarget& out, const TileFragments& f, ShadeCounts& counts) {
    if (f.count == 0) return;
    const int side = f.side;
    const float per_sample = 1.0f / static_cast<float>(side * side);
    const glm::vec4 bg = in.frame.background;
    const size_t pixel_count = static_cast<size_t>(f.pixels_x * f.pixels_y);
    std::vector<glm::vec4> sums(pixel_count, glm::vec4(0));
    std::vector<glm::vec4> nothing_sums(out.pixels_over_nothing ? pixel_count : 0, glm::vec4(0));
    std::vector<glm::vec3> normals(out.gbuffer ? static_cast<size_t>(f.count) : 0);
    std::vector<uint32_t> objects(normals.size());
    shade_fragments(
        f, raster, in, out, counts,
        [&](const ShadeRequest& b, const ShadeResult& r, const int* fragment) {
            for (int i = 0; i < b.count; ++i) {
                const int at = fragment[i];
                const float weight = static_cast<float>(f.samples[at]) * per_sample;
                const glm::vec3 color(r.color[0][i], r.color[1][i], r.color[2][i]);
                const float coverage = r.coverage[i];
                sums[f.pixel[at]] += glm::vec4(color, coverage + (1.0f - coverage) * bg.a) * weight;
                if (out.pixels_over_nothing)
                    nothing_sums[f.pixel[at]] += over_nothing(color, coverage, bg) * weight;
                if (out.gbuffer) {
                    normals[at] = glm::vec3(r.normal[0][i], r.normal[1][i], r.normal[2][i]);
                    objects[at] = r.object[i];
                }
            }
        });
    for (int at = 0; at < f.count; ++at) {
        if (at > 0 && f.pixel[at] == f.pixel[at - 1]) continue;  // one write per pixel
        const int px = f.pixel_x[at], py = f.pixel_y[at];
        const float empty_share = static_cast<float>(f.empty[f.pixel[at]]) * per_sample;
        const int x = tile.x0 / side + px, y = tile.y0 / side + py;
        // The samples with no triangle show the background, or over
        // existing pixels what the pixel held.
        const glm::vec4 behind = out.over_existing ? to_float(out.pixels->at(x, y)) : bg;
        out.pixels->at(x, y) = to_half(sums[f.pixel[at]] + behind * empty_share);
        if (out.pixels_over_nothing) {
            const glm::vec4 alone = out.over_existing
                                        ? to_float(out.pixels_over_nothing->at(x, y)) * empty_share
                                        : glm::vec4(0.0f);
            out.pixels_over_nothing->at(x, y) = to_half(nothing_sums[f.pixel[at]] + alone);
        }
        const NearestSample nearest = nearest_sample(tile, raster, side, px, py);
        out.depth.at(x, y) =
            out.over_existing ? std::min(out.depth.at(x, y), nearest.depth) : nearest.depth;
        if (!out.gbuffer) continue;
        int shown = at;  // the pixel's fragment of the nearest sample's triangle
        while (shown + 1 < f.count && f.id[shown] != nearest.id) ++shown;
        // Its plane at the pixel's centre, where simple pixels are taken too.
        const float half_pixel = 0.5f * static_cast<float>(side);
        const float centre_depth = depth_on_triangle(
            raster, nearest.id, static_cast<float>(tile.x0 + px * side) + half_pixel,
            static_cast<float>(tile.y0 + py * side) + half_pixel);
        // A plane seen edge-on can put its centre behind the eye: then the sample.
        const bool centre_on_plane = centre_depth > 0.0f && centre_depth < kInfinity;
        write_gbuffer(*out.gbuffer, x, y, centre_on_plane ? centre_depth : nearest.depth,
                      normals[shown], objects[shown]);
        out.surface_share->at(x, y) = 1.0f - empty_share;
    }
}

// Every sample, for passes at the sample resolution: each covered sample
// gets its fragment's colour, depth, normal and object; the rest background.
void shade_every_sample(const TileVisibility& tile, const Rasterizer& raster, const ShadeInputs& in,
                        const ShadeTarget& out, TileFragments& f, ShadeCounts& counts) {
    build_tile_fragments(tile, in.samples_per_side, false, f);
    const int side = f.side;
    shade_fragments(
        f, raster, in, out, counts,
        [&](const ShadeRequest& b, const ShadeResult& r, const int* fragment) {
            for (int i = 0; i < b.count; ++i) {
                const int at = fragment[i];
                // rgb over the background, a the share of it hidden (post/resolve.hpp).
                const glm::vec4 color(r.color[0][i], r.color[1][i], r.color[2][i], r.coverage[i]);
                const glm::vec3 normal(r.normal[0][i], r.normal[1][i], r.normal[2][i]);
                const glm::vec4 stroke(r.wire_color * r.wire[i], r.wire[i]);
                for (int sy = f.pixel_y[at] * side; sy < (f.pixel_y[at] + 1) * side; ++sy)
                    for (int sx = f.pixel_x[at] * side; sx < (f.pixel_x[at] + 1) * side; ++sx) {
                        if (tile.id[sy * kTileSize + sx] != f.id[at]) continue;
                        const int x = tile.x0 + sx, y = tile.y0 + sy;
                        const float depth = sample_depth(raster, f.id[at], x, y);
                        out.samples->at(x, y) = color;
                        out.depth.at(x, y) = depth;
                        if (out.line_samples) out.line_samples->at(x, y) = stroke;
                        if (out.gbuffer)
                            write_gbuffer(*out.gbuffer, x, y, depth, normal, r.object[i]);
                    }
            }
        });
    if (out.over_existing) return;  // the samples with no triangle keep theirs
    for (int ty = 0; ty < tile.height; ++ty)
        for (int tx = 0; tx < tile.width; ++tx) {
            if (tile.id[ty * kTileSize + tx] != kNoTriangle) continue;
            const int x = tile.x0 + tx, y = tile.y0 + ty;
            // The background's colour, nothing covering it (post/resolve.hpp).
            out.samples->at(x, y) = glm::vec4(glm::vec3(in.frame.background), 0.0f);
            out.depth.at(x, y) = kInfinity;
            if (out.line_samples) out.line_samples->at(x, y) = glm::vec4(0.0f);
            if (out.gbuffer) write_gbuffer(*out.gbuffer, x, y, kInfinity, glm::vec3(0), kNoObject);
        }
}

}  // namespace

ShadeCounts shade_tile(const TileVisibility& tile, const Rasterizer& raster, const ShadeInputs& in,
                       const ShadeTarget& out) {
    ShadeCounts counts;
    if (out.resolution == ShadeResolution::samples) {
        TileFragments fragments;
        shade_every_sample(tile, raster, in, out, fragments, counts);
        return counts;
    }
    TileFragments mixed;
    begin_tile_fragments(tile, in.samples_per_side, mixed);
    shade_simple_pixels(tile, raster, in, out, mixed, counts);
    shade_mixed_pixels(tile, raster, in, out, mixed, counts);
    simd::streaming_stores_done();
    return counts;
}

}  // namespace facet
