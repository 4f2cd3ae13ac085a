#pragma once
// Which samples the triangles of cut-out and transparent materials cover
// (glTF alphaMode MASK and BLEND), as the rasterizer's CoverageTest.
//
// MASK keeps a sample where the alpha (the material's times its texture's)
// reaches the cutoff. BLEND is order-independent: it keeps a share of the
// samples equal to the alpha, those whose threshold in a 4 x 4 ordered
// (Bayer) pattern over the sample grid lies below it, so surfaces behind
// show through the rest, and resolving anti-aliased samples blends them.
// This is screen-door transparency, in the manner of alpha-to-coverage and
// of hashed alpha testing (Wyman and McGuire 2017), with a fixed pattern so
// that every run and thread count gives the same bytes. With 16 samples
// per pixel a 2 x 2 pixel block shows 64 levels of alpha; with one, the
// pattern itself shows.
#include <cstdint>
#include <vector>

#include "raster/rasterizer.hpp"
#include "render/world.hpp"

namespace facet {

// Per triangle of the world: 1 where its material's alpha mode is mask or
// blend; empty when no material is.
std::vector<uint8_t> coverage_tested_triangles(const World& world);

// The test for one frame: `materials` are the frame's (World::materials
// with animated values), and must outlive the draw.
class AlphaCoverage {
  public:
    AlphaCoverage(const World& world, const std::vector<Material>& materials)
        : world_(world), materials_(materials) {}
    CoverageTest test() const { return {this, &keep}; }

  private:
    static bool keep(const void* self, uint32_t triangle, float b1, float b2, int x, int y);

    const World& world_;
    const std::vector<Material>& materials_;
};

}  // namespace facet
