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

TransmissionStage::TransmissionStage(std::span<const uint8_t> transmitting,
                                     std::span<const uint8_t> alpha_tested)
    : transmitting_(transmitting), alpha_tested_(alpha_tested) {}

void TransmissionStage::begin_frame(const Rasterizer& raster) {
    raster_ = &raster;
    const size_t tiles = static_cast<size_t>(raster.tile_count());
    for (std::vector<uint8_t>& shown : shown_) shown.assign(tiles, 0);
    for (auto& layer : ids_) layer.resize(tiles);
    for (auto& layer : depths_) layer.resize(tiles);
    if (transmitting_.empty()) return;
    asked_.assign(static_cast<size_t>(raster.width()) * raster.height(), 0);
    most_glass_.assign(tiles, 0);
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
            // Only this tile's thread writes its bytes.
            const size_t sample = static_cast<size_t>(y) * t.raster->width() + x;
            uint8_t& asked = stage.asked_[sample];
            asked = static_cast<uint8_t>(std::min(asked + 1, 255));
            uint8_t& most = stage.most_glass_[static_cast<size_t>(tile)];
            most = std::max(most, asked);
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

std::span<const uint8_t> TransmissionStage::tiles_of(int layer) {
    const std::vector<uint8_t>& before = shown_[layer - 1];
    wanted_.resize(before.size());
    for (size_t t = 0; t < before.size(); ++t)
        wanted_[t] = before[t] && most_glass_[t] >= layer ? 1 : 0;
    return wanted_;
}

bool TransmissionStage::any_in(int layer) const {
    const std::vector<uint8_t>& shown = shown_[layer];
    return std::find(shown.begin(), shown.end(), 1) != shown.end();
}

void TransmissionStage::keep_layer(int layer, const TileVisibility& tile,
                                   const Rasterizer& raster) {
    const size_t index = static_cast<size_t>(raster.tile_index(tile.x0, tile.y0));
    std::vector<uint32_t>& ids = ids_[layer - 1][index];
    std::vector<float>& depths = depths_[layer - 1][index];
    ids.assign(static_cast<size_t>(kTileSize) * kTileSize, kNoTriangle);
    depths.assign(ids.size(), 0.0f);
    bool any = false;
    for (int y = 0; y < tile.height; ++y)
        for (int x = 0; x < tile.width; ++x) {
            const size_t at = static_cast<size_t>(y * kTileSize + x);
            const uint32_t id = tile.id[at];
            if (id == kNoTriangle || !transmitting_[raster.shade_setup(id).source_triangle])
                continue;
            ids[at] = id;
            depths[at] = tile.depth[at];
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
            depths_[layer - 1][static_cast<size_t>(tile_index)].data(),
            ids_[layer - 1][static_cast<size_t>(tile_index)].data()};
}

const TransmissionBackdrop& TransmissionStage::backdrop(const HalfColorImage& color,
                                                        const CameraMatrices& camera,
                                                        ThreadPool& pool) {
    backdrop_.image.build(color, pool);
    backdrop_.view_projection = camera.view_projection;
    return backdrop_;
}

}  // namespace facet
