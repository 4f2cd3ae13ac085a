#pragma once
// Square images over the whole sphere of directions, by the octahedral
// mapping (Cigolle et al. 2014, "A Survey of Efficient Representations for
// Independent Unit Vectors", JCGT 3 (2)): the environment's prefiltered
// radiance maps are stored this way because finding a direction's texel
// then costs one division and a few adds, where an equirectangular image
// needs an arc tangent and an arc cosine. docs/pbr.md, "Environment
// lighting: the prefiltered maps", draws the layout.
//
// A direction d is first projected onto the octahedron |x| + |y| + |z| = 1.
// The upper half (y >= 0) is seen from above: p = (x, z) / (|x| + |y| + |z|)
// lies in the diamond |p.x| + |p.y| <= 1. The lower half is folded out over
// the diamond's edges into the square's four corners:
//   p = ((1 - |p.y|) sign(p.x), (1 - |p.x|) sign(p.y))   when y < 0
// so +Y is the square's centre, the horizon the diamond, and -Y the four
// corners. The square's edges are mirrored about their midpoints (the
// points (s, 1) and (-s, 1) are one direction), which is what lets a map
// keep a border of texels copied across the fold, and filter bilinearly
// over it with no test for the edge.
//
// Only IEEE-exact operations (add, multiply, divide, sqrt, compare), so
// every lookup has the same bits on every CPU. No global mutable state.
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstddef>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/simd_math.hpp"

namespace facet::pbr {

// The point of the square [-1, 1]^2 for the direction d, any length. A
// direction that is zero, infinite or NaN gives the centre (+Y) rather than
// a point outside the square. Inline, as is OctahedralMap::sample: every
// specular lookup and every prefiltering sample makes one.
inline glm::vec2 octahedral_encode(const glm::vec3& d) {
    const float l1 = std::abs(d.x) + std::abs(d.y) + std::abs(d.z);
    if (!(l1 > 0.0f && l1 <= FLT_MAX)) return glm::vec2(0.0f);
    const float inverse = 1.0f / l1;
    const float x = d.x * inverse, z = d.z * inverse;
    if (d.y >= 0.0f) return {x, z};
    // A point on an axis folds to either side, which are one direction:
    // zero counts as positive, always.
    const float sign_x = x >= 0.0f ? 1.0f : -1.0f, sign_z = z >= 0.0f ? 1.0f : -1.0f;
    return {(1.0f - std::abs(z)) * sign_x, (1.0f - std::abs(x)) * sign_z};
}

// octahedral_encode for eight directions at once, to the bit: the points'
// coordinates in `x` and `y`.
[[gnu::always_inline]] inline void octahedral_encode(simd::vf dx, simd::vf dy, simd::vf dz,
                                                     simd::vf& x, simd::vf& y) {
    using simd::splat;
    using simd::vf;
    using simd::vi;
    const auto abs = [](vf v) { return (vf)((vi)v & 0x7fffffff); };
    const vf l1 = abs(dx) + abs(dy) + abs(dz);
    const vi valid = (l1 > splat(0.0f)) & (l1 <= splat(FLT_MAX));
    const vf inverse = 1.0f / (valid ? l1 : splat(1.0f));
    const vf px = dx * inverse, pz = dz * inverse;
    const vf sign_x = px >= splat(0.0f) ? splat(1.0f) : splat(-1.0f);
    const vf sign_z = pz >= splat(0.0f) ? splat(1.0f) : splat(-1.0f);
    const vi upper = dy >= splat(0.0f);
    x = upper ? px : (1.0f - abs(pz)) * sign_x;
    y = upper ? pz : (1.0f - abs(px)) * sign_z;
    x = valid ? x : splat(0.0f);
    y = valid ? y : splat(0.0f);
}

// The unit direction at the point p of [-1, 1]^2: octahedral_encode's
// inverse. In double, for building maps.
glm::dvec3 octahedral_decode(const glm::dvec2& p);

// A size x size octahedral image of linear RGB radiance. Texel (column,
// row) covers the square's cell whose centre is
//   p = ((column + 0.5) / size * 2 - 1, (row + 0.5) / size * 2 - 1)
// so row 0 is at the -Z edge and column 0 at the -X edge. The texels are
// kept with a one-texel border that copies them across the folded edges
// (fill_border), which bilinear filtering reads instead of the edge tests.
class OctahedralMap {
  public:
    OctahedralMap() = default;
    // Every texel, and the border, `fill`. `size` is a power of two (1, 2,
    // 4, ...); std::invalid_argument otherwise.
    explicit OctahedralMap(int size, const glm::vec3& fill = glm::vec3(0.0f));

    int size() const { return size_; }
    const glm::vec3& texel(int column, int row) const {
        return texels_[static_cast<size_t>(row + 1) * stride() + (column + 1)];
    }
    void set_texel(int column, int row, const glm::vec3& value) {
        texels_[static_cast<size_t>(row + 1) * stride() + (column + 1)] = value;
    }
    // Copies the edge texels into the border, mirrored as the fold requires.
    // Call after the last set_texel and before sample.
    void fill_border();

    // The unit direction at texel (column, row)'s centre.
    glm::dvec3 texel_direction(int column, int row) const;

    // Bilinear filtering at the point p of [-1, 1]^2 (octahedral_encode's):
    // four texels, border included, weighted by p's distance to their
    // centres. Texels of equal value give that value exactly.
    glm::vec3 sample(const glm::vec2& p) const {
        // Texel (c, r)'s centre is at border-included coordinate c + 1: the
        // point's coordinate minus a half, plus one for the border. Clamped
        // so that a point a rounding error outside the square still reads
        // the border, never beyond it; in this order, NaN becomes the low end.
        const float size = static_cast<float>(size_);
        const auto coordinate = [size](float along) {
            return std::max(0.5f, std::min((along * 0.5f + 0.5f) * size + 0.5f, size + 0.5f));
        };
        const float x = coordinate(p.x), y = coordinate(p.y);
        const int column = std::min(static_cast<int>(x), size_);  // x > 0: truncation is floor
        const int row = std::min(static_cast<int>(y), size_);
        const float tx = x - static_cast<float>(column), ty = y - static_cast<float>(row);
        const glm::vec3* upper = &texels_[static_cast<size_t>(row) * stride() + column];
        const glm::vec3* lower = upper + stride();
        return lerp(lerp(upper[0], upper[1], tx), lerp(lower[0], lower[1], tx), ty);
    }

    // sample() at eight points, lane i's in *maps[i] (maps may repeat), to
    // the bit: the coordinates over lanes, the four texels one lane at a time.
    static void sample(const OctahedralMap* const (&maps)[simd::kLanes], simd::vf px, simd::vf py,
                       simd::vf (&out)[3]);

    // The solid angle of texel (column, row), up to a factor common to
    // every texel of the map: the square's area element maps to the solid
    // angle dA / |q|^3, q the point on the octahedron (|q|_1 = 1), so texels
    // near the faces' centres (|q| = 1/sqrt 3) cover 3 sqrt 3 = 5.2 times
    // the solid angle of those at the vertices (+-X, +-Y, +-Z, |q| = 1).
    // For the unit d at the texel's centre, 1/|q|^3 = |d|_1^3.
    double texel_solid_angle_weight(int column, int row) const;

    // The map of half the size (at least 1), each texel the mean radiance
    // of the 2 x 2 texels it covers, weighted by their solid angles and
    // summed in double: the next level of a mip pyramid. A plain average
    // would misplace energy by up to the factor of 5.2 above.
    OctahedralMap half_size() const;

  private:
    int stride() const { return size_ + 2; }
    // a + (b - a) t, which is exactly a when a == b: a uniform map's
    // lookups return its value to the bit.
    static glm::vec3 lerp(const glm::vec3& a, const glm::vec3& b, float t) {
        return {a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t, a.z + (b.z - a.z) * t};
    }

    int size_ = 0;
    std::vector<glm::vec3> texels_;  // (size + 2)^2, row by row, border included
};

}  // namespace facet::pbr
