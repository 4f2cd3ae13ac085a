#include "render/alpha_coverage.hpp"

namespace facet {
namespace {

// Thresholds of the 4 x 4 Bayer matrix, (rank + 0.5) / 16: every alpha
// keeps round(16 alpha) samples of each 4 x 4 block, spread evenly.
constexpr float kBayer4[4][4] = {
    {0.5f / 16, 8.5f / 16, 2.5f / 16, 10.5f / 16},
    {12.5f / 16, 4.5f / 16, 14.5f / 16, 6.5f / 16},
    {3.5f / 16, 11.5f / 16, 1.5f / 16, 9.5f / 16},
    {15.5f / 16, 7.5f / 16, 13.5f / 16, 5.5f / 16},
};

}  // namespace

std::vector<uint8_t> coverage_tested_triangles(const World& world) {
    std::vector<uint8_t> tested;
    for (const Draw& d : world.draws) {
        if (world.materials[d.material].alpha_mode == AlphaMode::opaque) continue;
        if (tested.empty()) tested.assign(world.triangle_count(), 0);
        std::fill_n(tested.begin() + d.first_triangle, d.triangle_count, 1);
    }
    return tested;
}

bool AlphaCoverage::keep(const void* self, uint32_t triangle, float b1, float b2, int x, int y) {
    const AlphaCoverage& c = *static_cast<const AlphaCoverage*>(self);
    const World& world = c.world_;
    const Draw& draw = world.draws[world.triangle_draw[triangle]];
    const Material& m = c.materials_[draw.material];
    float alpha = m.alpha;
    if (m.base_color_map && draw.has_uvs) {
        const std::array<glm::vec2, 3> c = world.corner_uvs(triangle, m.base_color_map);
        const glm::vec2 uv = (1 - b1 - b2) * c[0] + b1 * c[1] + b2 * c[2];
        // The finest level: a cut-out's edge stays where the texture draws it.
        alpha *= m.base_color_map.texture->sample(uv, 0.0f).a;
    }
    if (m.alpha_mode == AlphaMode::mask) return alpha >= m.alpha_cutoff;
    return alpha > kBayer4[y & 3][x & 3];
}

}  // namespace facet
