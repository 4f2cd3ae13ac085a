#include "render/tile_fragments.hpp"

namespace facet {
namespace {

void single_sample_fragments(const TileVisibility& tile, TileFragments& out) {
    for (int y = 0; y < tile.height; ++y) {
        const uint32_t* ids = tile.id + y * kTileSize;
        const float fy = static_cast<float>(tile.y0 + y) + 0.5f;
        for (int x = 0; x < tile.width; ++x) {
            const uint16_t pixel = static_cast<uint16_t>(y * tile.width + x);
            if (ids[x] == kNoTriangle) {
                out.empty[pixel] = 1;
                continue;
            }
            out.empty[pixel] = 0;
            const int f = out.count++;
            out.x[f] = static_cast<float>(tile.x0 + x) + 0.5f;
            out.y[f] = fy;
            out.id[f] = ids[x];
            out.pixel[f] = pixel;
            out.pixel_x[f] = static_cast<uint16_t>(x);
            out.pixel_y[f] = static_cast<uint16_t>(y);
            out.samples[f] = 1;
        }
    }
}

}  // namespace

// One pixel's k x k samples into fragments: a short list of distinct ids,
// each with its sample count and the sum of its sample centres.
void add_pixel_fragments(const TileVisibility& tile, int px, int py, TileFragments& out) {
    const int side = out.side;
    const uint16_t pixel = static_cast<uint16_t>(py * out.pixels_x + px);
    const int first = out.count;
    int empty = 0;
    float sum_x[25], sum_y[25];  // k <= 5
    for (int sy = 0; sy < side; ++sy) {
        const int y = py * side + sy;
        const uint32_t* ids = tile.id + y * kTileSize;
        for (int sx = 0; sx < side; ++sx) {
            const int x = px * side + sx;
            const uint32_t id = ids[x];
            if (id == kNoTriangle) {
                ++empty;
                continue;
            }
            int f = first;
            while (f < out.count && out.id[f] != id) ++f;
            if (f == out.count) {
                ++out.count;
                out.id[f] = id;
                out.pixel[f] = pixel;
                out.pixel_x[f] = static_cast<uint16_t>(px);
                out.pixel_y[f] = static_cast<uint16_t>(py);
                out.samples[f] = 0;
                sum_x[f - first] = 0;
                sum_y[f - first] = 0;
            }
            ++out.samples[f];
            sum_x[f - first] += static_cast<float>(tile.x0 + x) + 0.5f;
            sum_y[f - first] += static_cast<float>(tile.y0 + y) + 0.5f;
        }
    }
    for (int f = first; f < out.count; ++f) {
        const float n = static_cast<float>(out.samples[f]);
        out.x[f] = sum_x[f - first] / n;
        out.y[f] = sum_y[f - first] / n;
    }
    out.empty[pixel] = static_cast<uint8_t>(empty);
}

uint32_t pixel_id(const TileVisibility& tile, int side, int px, int py) {
    const uint32_t first = tile.id[py * side * kTileSize + px * side];
    for (int sy = 0; sy < side; ++sy) {
        const uint32_t* ids = tile.id + (py * side + sy) * kTileSize + px * side;
        for (int sx = 0; sx < side; ++sx)
            if (ids[sx] != first) return kMixedPixel;
    }
    return first;
}

void begin_tile_fragments(const TileVisibility& tile, int side, TileFragments& out) {
    out.count = 0;
    out.side = side;
    out.pixels_x = tile.width / side;
    out.pixels_y = tile.height / side;
}

void build_tile_fragments(const TileVisibility& tile, int side, bool mixed_only,
                          TileFragments& out) {
    begin_tile_fragments(tile, side, out);
    if (side == 1 && mixed_only) return;
    if (side == 1) return single_sample_fragments(tile, out);
    for (int py = 0; py < out.pixels_y; ++py)
        for (int px = 0; px < out.pixels_x; ++px) {
            if (mixed_only && pixel_id(tile, side, px, py) != kMixedPixel) continue;
            add_pixel_fragments(tile, px, py, out);
        }
}

}  // namespace facet
