#include "shade/octahedral_map.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace facet::pbr {

namespace {

double sign_not_zero(double value) {
    return value >= 0.0 ? 1.0 : -1.0;
}

}  // namespace

glm::dvec3 octahedral_decode(const glm::dvec2& p) {
    const double y = 1.0 - std::abs(p.x) - std::abs(p.y);
    glm::dvec3 d(p.x, y, p.y);
    if (y < 0.0) {
        d.x = (1.0 - std::abs(p.y)) * sign_not_zero(p.x);
        d.z = (1.0 - std::abs(p.x)) * sign_not_zero(p.y);
    }
    return d / std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
}

OctahedralMap::OctahedralMap(int size, const glm::vec3& fill)
    : size_(size), texels_(static_cast<size_t>(size + 2) * (size + 2), fill) {
    // half_size halves exactly, so every texel of a level covers whole
    // texels of the level above.
    if (size < 1 || (size & (size - 1)) != 0)
        throw std::invalid_argument("octahedral map: the size must be a power of two");
}

void OctahedralMap::sample(const OctahedralMap* const (&maps)[simd::kLanes], simd::vf px,
                           simd::vf py, simd::vf (&out)[3]) {
    using simd::splat;
    using simd::vf;
    using simd::vi;
    vi sizes;
    for (int lane = 0; lane < simd::kLanes; ++lane) sizes[lane] = maps[lane]->size_;
    const vf size = __builtin_convertvector(sizes, vf);
    // As sample() does with std::max and std::min, in the same order, so
    // that a NaN becomes the low end here too.
    const auto std_min = [](vf a, vf b) { return b < a ? b : a; };
    const auto std_max = [](vf a, vf b) { return a < b ? b : a; };
    const auto coordinate = [&](vf along) {
        return std_max(splat(0.5f), std_min((along * 0.5f + 0.5f) * size + 0.5f, size + 0.5f));
    };
    const vf x = coordinate(px), y = coordinate(py);
    vi column = __builtin_convertvector(x, vi), row = __builtin_convertvector(y, vi);
    column = column < sizes ? column : sizes;
    row = row < sizes ? row : sizes;
    const vf tx = x - __builtin_convertvector(column, vf);
    const vf ty = y - __builtin_convertvector(row, vf);
    vf texel[4][3];  // upper left, upper right, lower left, lower right
    for (int lane = 0; lane < simd::kLanes; ++lane) {
        const OctahedralMap& map = *maps[lane];
        const glm::vec3* upper = &map.texels_[static_cast<size_t>(row[lane]) * map.stride() +
                                              static_cast<size_t>(column[lane])];
        const glm::vec3* corners[4] = {upper, upper + 1, upper + map.stride(),
                                       upper + map.stride() + 1};
        for (int k = 0; k < 4; ++k)
            for (int c = 0; c < 3; ++c) texel[k][c][lane] = (*corners[k])[c];
    }
    for (int c = 0; c < 3; ++c) {
        const vf top = texel[0][c] + (texel[1][c] - texel[0][c]) * tx;
        const vf bottom = texel[2][c] + (texel[3][c] - texel[2][c]) * tx;
        out[c] = top + (bottom - top) * ty;
    }
}

void OctahedralMap::fill_border() {
    const int last = size_ - 1;
    // Beyond an edge, the texel at distance k from the edge's midpoint on
    // one side is the texel at distance k on the other side, one row in.
    for (int i = 0; i < size_; ++i) {
        set_texel(-1, i, texel(0, last - i));
        set_texel(size_, i, texel(last, last - i));
        set_texel(i, -1, texel(last - i, 0));
        set_texel(i, size_, texel(last - i, last));
    }
    // A corner is -Y: diagonally across it lies the opposite corner.
    set_texel(-1, -1, texel(last, last));
    set_texel(size_, -1, texel(0, last));
    set_texel(-1, size_, texel(last, 0));
    set_texel(size_, size_, texel(0, 0));
}

glm::dvec3 OctahedralMap::texel_direction(int column, int row) const {
    return octahedral_decode({(column + 0.5) / size_ * 2.0 - 1.0, (row + 0.5) / size_ * 2.0 - 1.0});
}

double OctahedralMap::texel_solid_angle_weight(int column, int row) const {
    const glm::dvec3 d = texel_direction(column, row);
    const double l1 = std::abs(d.x) + std::abs(d.y) + std::abs(d.z);
    return l1 * l1 * l1;
}

OctahedralMap OctahedralMap::half_size() const {
    if (size_ == 1) return *this;
    OctahedralMap half(size_ / 2);
    for (int row = 0; row < half.size_; ++row)
        for (int column = 0; column < half.size_; ++column) {
            glm::dvec3 sum(0.0);
            double total_weight = 0.0;
            for (int child = 0; child < 4; ++child) {
                const int c = 2 * column + (child & 1), r = 2 * row + (child >> 1);
                const double weight = texel_solid_angle_weight(c, r);
                sum += glm::dvec3(texel(c, r)) * weight;
                total_weight += weight;
            }
            half.set_texel(column, row, glm::vec3(sum / total_weight));
        }
    half.fill_border();
    return half;
}

}  // namespace facet::pbr
