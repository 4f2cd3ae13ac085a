#include "render/transmission_stage.hpp"

#include <algorithm>
#include <cmath>

namespace facet {

std::vector<uint8_t> transmitting_triangles(const World& world, const StylePlan& plan) {
    std::vector<uint8_t> transmitting;
    for (const Draw& d : world.draws) {
        // object_normal_mapped: the object's style is `pbr`.
        if (!(world.materials[d.material].transmission > 0.0f) ||
            !plan.object_normal_mapped[d.object])
            continue;
        if (transmitting.empty()) transmitting.assign(world.triangle_count(), 0);
        std::fill_n(transmitting.begin() + d.first_triangle, d.triangle_count, 1);
    }
    return transmitting;
}

float shadow_pass(const Material& m) {
    const float ratio = m.thickness > 0.0f ? m.thickness / m.attenuation_distance : 0.0f;
    float sum = 0.0f;
    for (int c = 0; c < 3; ++c)
        sum += std::clamp(m.color[c], 0.0f, 1.0f) *
               std::pow(std::clamp(m.attenuation_color[c], 0.0f, 1.0f), ratio);
    return std::clamp((1.0f - m.metallic) * m.transmission * sum / 3.0f, 0.0f, 1.0f);
}

TransmissionStage::TransmissionStage(const World& world, const StylePlan& plan)
    : transmitting_(transmitting_triangles(world, plan)),
      alpha_tested_(coverage_tested_triangles(world)) {}

void TransmissionStage::begin_frame(const Rasterizer& raster) {
    raster_ = &raster;
    const size_t tiles = static_cast<size_t>(raster.tile_count());
    for (std::vector<uint8_t>& shown : shown_) shown.assign(tiles, 0);
    for (auto& layer : ids_) layer.resize(tiles);
}

CoverageTest TransmissionStage::test(int layer, const AlphaCoverage& alpha) {
    test_ = {this, &alpha, raster_, layer};
    return {&test_, &keep};
}

bool TransmissionStage::keep(const void* context, uint32_t triangle, float b1, float b2, int x,
                             int y) {
    const Test& t = *static_cast<const Test*>(context);
    TransmissionStage& stage = *t.stage;
    if (!stage.transmitting_.empty() && stage.transmitting_[triangle]) {
        const int tile = t.raster->tile_index(x, y);
        if (t.layer == 0) {
            // Only this tile's thread writes its byte.
            stage.shown_[0][static_cast<size_t>(tile)] = 1;
            return false;
        }
        const int size = t.raster->tile_size();
        const size_t at = static_cast<size_t>((y % size) * kTileSize + x % size);
        for (int peeled = 1; peeled < t.layer; ++peeled) {
            const uint32_t id = stage.ids_[peeled - 1][static_cast<size_t>(tile)][at];
            if (id != kNoTriangle && t.raster->shade_setup(id).source_triangle == triangle)
                return false;
        }
    }
    if (stage.alpha_tested_.empty() || !stage.alpha_tested_[triangle]) return true;
    const CoverageTest alpha = t.alpha->test();
    return alpha.keep(alpha.context, triangle, b1, b2, x, y);
}

bool TransmissionStage::any_in(int layer) const {
    const std::vector<uint8_t>& shown = shown_[layer];
    return std::find(shown.begin(), shown.end(), 1) != shown.end();
}

void TransmissionStage::keep_layer(int layer, const TileVisibility& tile,
                                   const Rasterizer& raster) {
    const size_t index = static_cast<size_t>(raster.tile_index(tile.x0, tile.y0));
    std::vector<uint32_t>& ids = ids_[layer - 1][index];
    ids.assign(static_cast<size_t>(kTileSize) * kTileSize, kNoTriangle);
    bool any = false;
    for (int y = 0; y < tile.height; ++y)
        for (int x = 0; x < tile.width; ++x) {
            const size_t at = static_cast<size_t>(y * kTileSize + x);
            const uint32_t id = tile.id[at];
            if (id == kNoTriangle || !transmitting_[raster.shade_setup(id).source_triangle])
                continue;
            ids[at] = id;
            any = true;
        }
    shown_[layer][index] = any ? 1 : 0;
}

TileVisibility TransmissionStage::layer_tile(int layer, int tile_index,
                                             const Rasterizer& raster) const {
    const int size = raster.tile_size();
    const int tiles_x = (raster.width() + size - 1) / size;
    const int x0 = (tile_index % tiles_x) * size, y0 = (tile_index / tiles_x) * size;
    return {x0,
            y0,
            std::min(size, raster.width() - x0),
            std::min(size, raster.height() - y0),
            nullptr,
            ids_[layer - 1][static_cast<size_t>(tile_index)].data()};
}

TransmissionBackdrop make_backdrop(const HalfColorImage& color, const CameraMatrices& camera) {
    TransmissionBackdrop backdrop;
    backdrop.image = Texture::from_half(
        color.width, color.height, std::vector<Rgba16F>(color.pixels.begin(), color.pixels.end()));
    backdrop.image.sampler.wrap_s = backdrop.image.sampler.wrap_t = Wrap::clamp;
    backdrop.view_projection = camera.view_projection;
    return backdrop;
}

}  // namespace facet
