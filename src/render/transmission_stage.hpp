#pragma once
// Stage 12 of a frame: glass (KHR_materials_transmission under `pbr`),
// drawn as real-time renderers draw it, over the finished opaque image.
//
// 1. The opaque pass leaves transmitting triangles out (they are
//    coverage-tested, and the opaque pass's test refuses them), and notes
//    the tiles where one would have shown.
// 2. Depth peeling (Everitt 2001, "Interactive Order-Independent
//    Transparency"), by triangle rather than by depth: layer k keeps, per
//    sample, the nearest transmitting triangle that layers 1..k-1 did not
//    keep there, so it is the k-th nearest glass surface at that sample,
//    with the opaque surfaces still hiding glass behind them. Exact, and
//    the same for any thread count. Up to kMaxGlassLayers layers.
// 3. The layers are shaded back to front: each reads a mip chain of the
//    image so far (shade/transmission_backdrop.hpp) along its refracted
//    view, so glass seen through glass shows it.
#include <cstdint>
#include <span>
#include <vector>

#include "raster/rasterizer.hpp"
#include "render/alpha_coverage.hpp"
#include "render/frame_inputs.hpp"
#include "render/world.hpp"
#include "shade/transmission_backdrop.hpp"

namespace facet {

// Per triangle of the world: 1 where a transmitting material is drawn by
// `pbr`, the one model that draws glass (the others draw it opaque, and a
// warning says so); empty when none is.
std::vector<uint8_t> transmitting_triangles(const World& world, const StylePlan& plan);

// The share of a light's beam that glass of material `m` lets through to
// its shadow, one number for the whole material (its maps and colour's
// hue left out): what is not metal, times the transmission, times the
// mean over the channels of the base colour and of what the volume leaves
// across its thickness (Beer-Lambert).
float shadow_pass(const Material& m);

// Glass seen through more glass than this is drawn as far as this many
// surfaces (a closed bottle shows two: its front and its back).
constexpr int kMaxGlassLayers = 4;

class TransmissionStage {
  public:
    // Reads the run's per-triangle flags, RenderPlan::transmitting and
    // RenderPlan::alpha_tested, which must outlive the stage.
    TransmissionStage(std::span<const uint8_t> transmitting, std::span<const uint8_t> alpha_tested);

    // What the stage holds for a frame of `pixels` and `samples`: the
    // backdrop's pyramid; per sample the count of glass asked about, and
    // (at most, for every sample) each layer's triangle id and depth.
    static uint64_t bytes(uint64_t pixels, uint64_t samples) {
        return BackdropPyramid::bytes(pixels) +
               samples * (sizeof(uint8_t) + kMaxGlassLayers * (sizeof(uint32_t) + sizeof(float)));
    }

    // Before a frame's opaque pass, for `raster`'s tiles.
    void begin_frame(const Rasterizer& raster);

    // The coverage test of layer `layer` (0: the opaque pass), deciding
    // alpha-tested triangles by `alpha`. Valid until the next call.
    CoverageTest test(int layer, const AlphaCoverage& alpha);

    // The tiles layer `layer` draws (a byte per tile): those where the
    // layer before it showed glass and the opaque pass saw at least
    // `layer` glass triangles over a sample. All 0 once there is none.
    std::span<const uint8_t> tiles_of(int layer);
    // The tiles where layer `layer` has glass (a byte per tile), after its pass.
    std::span<const uint8_t> glass_tiles(int layer) const { return shown_[layer]; }
    bool any_in(int layer) const;

    // Layer `layer`'s pass over one tile: keeps its glass samples.
    void keep_layer(int layer, const TileVisibility& tile, const Rasterizer& raster);

    // The backdrop of a layer: `color` (the frame so far, linear RGBA,
    // premultiplied) as a pyramid, for `camera`, made on `pool`. Valid
    // until the next call.
    const TransmissionBackdrop& backdrop(const HalfColorImage& color, const CameraMatrices& camera,
                                         ThreadPool& pool);

    // Layer `layer`'s glass in a tile `tile_index` where glass_tiles(layer)
    // holds it (ids kNoTriangle elsewhere, row stride kTileSize).
    TileVisibility layer_tile(int layer, int tile_index, const Rasterizer& raster) const;

  private:
    struct Test {
        TransmissionStage* stage;
        const AlphaCoverage* alpha;
        const Rasterizer* raster;
        int layer;
    };
    static bool keep(const void* context, uint32_t triangle, float b1, float b2, int x, int y);

    std::span<const uint8_t> transmitting_;
    std::span<const uint8_t> alpha_tested_;
    // shown_[k][tile]: layer k (0: the opaque pass) had glass in the tile.
    std::vector<uint8_t> shown_[kMaxGlassLayers + 1];
    // ids_[k - 1][tile] and depths_[k - 1][tile]: layer k's triangle ids
    // and depths in the tile, where shown.
    std::vector<std::vector<uint32_t>> ids_[kMaxGlassLayers];
    std::vector<std::vector<float>> depths_[kMaxGlassLayers];
    // The opaque pass counts, per sample, the glass triangles asked about:
    // each glass surface a layer can show there was asked about (it was
    // nearer than anything drawn before it), so a tile needs no more
    // layers than its largest count (most_glass_).
    std::vector<uint8_t> asked_;
    std::vector<uint8_t> most_glass_;
    std::vector<uint8_t> wanted_;  // tiles_of's
    const Rasterizer* raster_ = nullptr;
    Test test_{};
    TransmissionBackdrop backdrop_;
};

}  // namespace facet
