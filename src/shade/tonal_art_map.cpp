#include "shade/tonal_art_map.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "core/error.hpp"
#include "core/integer_hash.hpp"
#include "shade/paper_grain.hpp"

namespace facet {

TamParams TamParams::pencil() {
    TamParams p;
    p.max_darkness = 0.65f;  // graphite never gets as dark as ink
    p.stroke_width = 1.0f;
    p.edge_softness = 1.5f;
    p.pressure_min = 0.35f;
    p.pressure_max = 0.7f;
    p.length_jitter = 0.4f;
    p.taper = 0.25f;
    p.angle_jitter = 8.0f;
    p.grain = 0.7f;
    p.grain_cells = 32;
    p.paper_shading = 0.12f;
    return p;
}

namespace {

// Caps the stroke list if a target cannot be reached (a darkness the
// strokes cannot build up, e.g. pencil on grain with zero-height pits).
constexpr size_t kMaxStrokes = 200000;
constexpr uint32_t kStrokeStream = 0x5354524bU;  // "STRK"
constexpr uint32_t kPaperStream = 0x50415052U;   // "PAPR"

bool is_power_of_two(int v) {
    return v > 0 && (v & (v - 1)) == 0;
}

void check(bool ok, const char* what) {
    if (!ok) throw Error(ExitCode::invalid_input, std::string("tonal art map: ") + what);
}

void validate(const TamParams& p) {
    check(p.levels >= 1 && p.levels <= 64, "levels must be in [1, 64]");
    check(is_power_of_two(p.size) && p.size >= 16 && p.size <= 2048,
          "size must be a power of two in [16, 2048]");
    check(p.max_darkness > 0.0f && p.max_darkness < 1.0f, "max_darkness must be in (0, 1)");
    check(p.stroke_width > 0.0f, "stroke_width must be > 0");
    check(p.edge_softness >= 0.0f, "edge_softness must be >= 0");
    check(p.stroke_length > 0.0f && p.stroke_length <= 1.0f, "stroke_length must be in (0, 1]");
    check(p.length_jitter >= 0.0f && p.length_jitter < 1.0f, "length_jitter must be in [0, 1)");
    check(p.taper >= 0.0f && p.taper <= 0.5f, "taper must be in [0, 0.5]");
    check(p.curvature >= 0.0f && p.curvature <= 0.25f, "curvature must be in [0, 0.25]");
    check(p.pressure_min > 0.0f && p.pressure_min <= p.pressure_max && p.pressure_max <= 1.0f,
          "pressures must satisfy 0 < min <= max <= 1");
    check(p.candidates >= 1, "candidates must be >= 1");
    check(p.min_stroke_size >= 1, "min_stroke_size must be >= 1");
    check(p.grain >= 0.0f && p.grain <= 1.0f, "grain must be in [0, 1]");
    check(p.paper_shading >= 0.0f && p.paper_shading <= 1.0f, "paper_shading must be in [0, 1]");
    check(p.grain == 0.0f || (is_power_of_two(p.grain_cells) && p.grain_cells <= p.size),
          "grain_cells must be a power of two no larger than size");
}

// sin and cos by Taylor series on [−π, π] (error below 1e-10): only IEEE
// operations, unlike std::sin, whose last bit may differ between C libraries.
void sin_cos(double radians, double& s, double& c) {
    const double two_pi = 2.0 * std::numbers::pi;
    const double x = radians - two_pi * std::floor(radians / two_pi + 0.5);
    const double x2 = x * x;
    double sin_sum = 0.0, cos_sum = 0.0;
    // Horner from the highest term: sin to x^23, cos to x^22.
    for (int k = 11; k >= 0; --k) {
        const double sin_den = (2.0 * k + 2.0) * (2.0 * k + 3.0);
        const double cos_den = (2.0 * k + 1.0) * (2.0 * k + 2.0);
        sin_sum = 1.0 - x2 * sin_sum / sin_den;
        cos_sum = 1.0 - x2 * cos_sum / cos_den;
    }
    s = x * sin_sum;
    c = cos_sum;
}

// A stroke is a quadratic Bézier curve from `start` through `bend` to
// `start + chord`, flattened into kStrokeSegments straight pieces.
constexpr int kStrokeSegments = 4;

struct Stroke {
    float x0, y0;  // start, in tiles
    float dx, dy;  // start to end, in tiles
    float bend;    // the control point's offset from the chord's middle, along
                   // its left normal, as a fraction of the chord's length
    float pressure;

    // Point i of the flattened curve (0 .. kStrokeSegments), in tiles.
    void point(int i, float& x, float& y) const {
        const float t = static_cast<float>(i) / kStrokeSegments;
        // B(t) = chord·t + 2t(1 − t)·offset, the offset at the chord's middle.
        const float arc = 2.0f * t * (1.0f - t) * bend;
        x = x0 + dx * t - dy * arc;
        y = y0 + dy * t + dx * arc;
    }
};

// Cells per side of the coarse density grid that candidates are judged on.
constexpr int kDensityCells = 16;

// One mip of the level being built: float coverage, its running sum, and
// the sums per density cell.
struct WorkImage {
    int size = 0;
    std::vector<float> coverage;
    std::vector<float> deposit;  // graphite taken per unit of stroke: 1, or grain-weighted
    double sum = 0.0;
    size_t strokes = 0;            // the prefix of the stroke list drawn so far
    int cell = 1;                  // texels per density cell side
    std::vector<double> cell_sum;  // coverage summed per cell

    void reset(int texels) {
        size = texels;
        coverage.assign(static_cast<size_t>(size) * size, 0.0f);
        deposit.assign(coverage.size(), 1.0f);
        cell = std::max(1, size / kDensityCells);
        cell_sum.assign(static_cast<size_t>(size / cell) * (size / cell), 0.0);
    }
    double mean() const { return sum / (static_cast<double>(size) * size); }
    size_t cell_of(size_t texel) const {
        const int x = static_cast<int>(texel % size), y = static_cast<int>(texel / size);
        return static_cast<size_t>(y / cell) * (size / cell) + x / cell;
    }
    double cell_density(size_t texel) const {
        return cell_sum[cell_of(texel)] / (static_cast<double>(cell) * cell);
    }
};

// Calls visit(texel index, alpha) for every texel the stroke touches at a
// mip of `size` texels: the texels within half the stroke's width of the
// curve, with an anti-aliased edge, faded at both ends, wrapped around the
// tile. Each texel counts once, at its distance from the nearest segment,
// so the joints between segments are not darker than the rest.
template <typename Visit>
void for_each_stroke_texel(const Stroke& s, int size, const TamParams& p, Visit&& visit) {
    const float r = static_cast<float>(size);
    float px[kStrokeSegments + 1], py[kStrokeSegments + 1];
    float lo_x = 1e30f, hi_x = -1e30f, lo_y = 1e30f, hi_y = -1e30f;
    for (int i = 0; i <= kStrokeSegments; ++i) {
        s.point(i, px[i], py[i]);
        px[i] *= r;
        py[i] *= r;
        lo_x = std::min(lo_x, px[i]), hi_x = std::max(hi_x, px[i]);
        lo_y = std::min(lo_y, py[i]), hi_y = std::max(hi_y, py[i]);
    }
    const float half = 0.5f * p.stroke_width;
    const float soft = p.edge_softness;
    const float reach = half + 0.5f * soft;  // no coverage beyond this distance
    const int mask = size - 1;
    const int row_lo = static_cast<int>(std::floor(lo_y - reach));
    const int row_hi = static_cast<int>(std::ceil(hi_y + reach));
    for (int row = row_lo; row <= row_hi; ++row) {
        const float cy = static_cast<float>(row) + 0.5f;
        // The parts of the segments within `reach` of this row bound the columns.
        float col_min = 1e30f, col_max = -1e30f;
        for (int k = 0; k < kStrokeSegments; ++k) {
            const float ay = py[k], sy = py[k + 1] - py[k];
            float t_lo = 0.0f, t_hi = 1.0f;
            if (std::fabs(sy) > 1e-6f) {
                const float ta = (cy - reach - ay) / sy, tb = (cy + reach - ay) / sy;
                t_lo = std::max(std::min(ta, tb), 0.0f);
                t_hi = std::min(std::max(ta, tb), 1.0f);
                if (t_lo > t_hi) continue;
            } else if (std::fabs(cy - ay) > reach) {
                continue;
            }
            const float xa = px[k] + t_lo * (px[k + 1] - px[k]);
            const float xb = px[k] + t_hi * (px[k + 1] - px[k]);
            col_min = std::min(col_min, std::min(xa, xb));
            col_max = std::max(col_max, std::max(xa, xb));
        }
        if (col_min > col_max) continue;
        const int col_lo = static_cast<int>(std::floor(col_min - reach - 0.5f));
        const int col_hi = static_cast<int>(std::ceil(col_max + reach));
        for (int col = col_lo; col <= col_hi; ++col) {
            const float cx = static_cast<float>(col) + 0.5f;
            float best = 1e30f, along = 0.0f;  // squared distance, curve parameter there
            for (int k = 0; k < kStrokeSegments; ++k) {
                const float sx = px[k + 1] - px[k], sy = py[k + 1] - py[k];
                const float len2 = sx * sx + sy * sy;
                float t = len2 > 0.0f ? ((cx - px[k]) * sx + (cy - py[k]) * sy) / len2 : 0.0f;
                t = std::clamp(t, 0.0f, 1.0f);
                const float ox = px[k] + t * sx - cx, oy = py[k] + t * sy - cy;
                const float d2 = ox * ox + oy * oy;
                if (d2 < best) best = d2, along = (static_cast<float>(k) + t) / kStrokeSegments;
            }
            const float d = std::sqrt(best);
            const float edge = soft > 0.0f ? std::clamp((reach - d) / soft, 0.0f, 1.0f)
                                           : (d <= half ? 1.0f : 0.0f);
            const float ends =
                p.taper > 0.0f ? std::min(1.0f, std::min(along, 1.0f - along) / p.taper) : 1.0f;
            const float alpha = s.pressure * edge * ends;
            if (alpha > 0.0f) visit(static_cast<size_t>(row & mask) * size + (col & mask), alpha);
        }
    }
}

// Graphite (or ink) over what is there: c + a·(1 − c). Never lowers a
// texel, so adding strokes keeps every earlier stroke (the nesting).
void draw_stroke(const Stroke& s, WorkImage& img, const TamParams& p) {
    for_each_stroke_texel(s, img.size, p, [&](size_t i, float alpha) {
        const float before = img.coverage[i];
        const float after = before + alpha * img.deposit[i] * (1.0f - before);
        img.coverage[i] = after;
        const double delta = static_cast<double>(after) - static_cast<double>(before);
        img.sum += delta;
        img.cell_sum[img.cell_of(i)] += delta;
    });
}

// How well a stroke would fill the image: Praun et al. pick, among
// candidates, the stroke that best moves the tone towards its target. The
// darkening it adds counts by how far its neighbourhood (a cell of a
// coarse grid) still is from the target, and not at all where the cell is
// there already: thin strokes rarely overlap, so judged texel by texel all
// candidates look alike and blank patches survive.
double stroke_gain(const Stroke& s, const WorkImage& img, double target, const TamParams& p) {
    double gain = 0.0;
    for_each_stroke_texel(s, img.size, p, [&](size_t i, float alpha) {
        const double darkening = alpha * img.deposit[i] * (1.0f - img.coverage[i]);
        gain += darkening * std::max(0.0, 1.0 - img.cell_density(i) / target);
    });
    return gain;
}

Stroke random_stroke(const TamParams& p, uint32_t candidate, bool cross) {
    const uint32_t h = hash32(p.seed, kStrokeStream, candidate);
    auto unit = [h](uint32_t field) { return hash_unit(hash32(h, field)); };
    const float centre_u = unit(0), centre_v = unit(1);
    const float length = p.stroke_length * (1.0f + p.length_jitter * (2.0f * unit(2) - 1.0f));
    const float degrees =
        p.hatch_angle + (cross ? p.cross_angle : 0.0f) + p.angle_jitter * (2.0f * unit(3) - 1.0f);
    double s, c;
    sin_cos(static_cast<double>(degrees) * (std::numbers::pi / 180.0), s, c);
    const float dx = static_cast<float>(c) * length, dy = static_cast<float>(s) * length;
    const float pressure = p.pressure_min + (p.pressure_max - p.pressure_min) * unit(4);
    // The curve's middle lies halfway between the chord's and the control
    // point, so a bow of `curvature` needs twice that offset.
    const float bend = 2.0f * p.curvature * (2.0f * unit(5) - 1.0f);
    // Centred on the curve's middle, not the chord's.
    const float mid_x = centre_u + 0.5f * dy * bend, mid_y = centre_v - 0.5f * dx * bend;
    return {mid_x - 0.5f * dx, mid_y - 0.5f * dy, dx, dy, bend, pressure};
}

uint8_t to_byte(float v) {
    return static_cast<uint8_t>(std::clamp(v, 0.0f, 1.0f) * 255.0f + 0.5f);
}

TamImage quantise(const std::vector<float>& values, int size) {
    TamImage img{size, std::vector<uint8_t>(values.size())};
    for (size_t i = 0; i < values.size(); ++i) img.texels[i] = to_byte(values[i]);
    return img;
}

// 2x2 box filter. Integer, so it keeps the nesting: a texel-wise larger
// image stays texel-wise larger.
TamImage halve(const TamImage& fine) {
    const int size = fine.size / 2;
    TamImage img{size, std::vector<uint8_t>(static_cast<size_t>(size) * size)};
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const int sum = fine.at(2 * x, 2 * y) + fine.at(2 * x + 1, 2 * y) +
                            fine.at(2 * x, 2 * y + 1) + fine.at(2 * x + 1, 2 * y + 1);
            img.texels[static_cast<size_t>(y) * size + x] = static_cast<uint8_t>((sum + 2) / 4);
        }
    return img;
}

std::vector<float> halve(const std::vector<float>& fine, int fine_size) {
    const int size = fine_size / 2;
    std::vector<float> out(static_cast<size_t>(size) * size);
    auto at = [&](int x, int y) { return fine[static_cast<size_t>(y) * fine_size + x]; };
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x)
            out[static_cast<size_t>(y) * size + x] =
                ((at(2 * x, 2 * y) + at(2 * x + 1, 2 * y)) +
                 (at(2 * x, 2 * y + 1) + at(2 * x + 1, 2 * y + 1))) *
                0.25f;
    return out;
}

float bilinear(const TamImage& img, glm::vec2 uv) {
    if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) uv = glm::vec2(0.0f);
    const int mask = img.size - 1;
    const float r = static_cast<float>(img.size);
    const float x = (uv.x - std::floor(uv.x)) * r - 0.5f;
    const float y = (uv.y - std::floor(uv.y)) * r - 0.5f;
    const float fx0 = std::floor(x), fy0 = std::floor(y);
    const float tx = x - fx0, ty = y - fy0;
    const int x0 = static_cast<int>(fx0) & mask, y0 = static_cast<int>(fy0) & mask;
    const int x1 = (x0 + 1) & mask, y1 = (y0 + 1) & mask;
    const float top = img.at(x0, y0) + (img.at(x1, y0) - img.at(x0, y0)) * tx;
    const float bottom = img.at(x0, y1) + (img.at(x1, y1) - img.at(x0, y1)) * tx;
    return (top + (bottom - top) * ty) * (1.0f / 255.0f);
}

float trilinear(const std::vector<TamImage>& mips, glm::vec2 uv, float lod) {
    const float last = static_cast<float>(mips.size() - 1);
    const float l = lod > 0.0f ? std::min(lod, last) : 0.0f;  // NaN: the finest mip
    const float base = std::floor(l);
    const int m0 = static_cast<int>(base);
    const float f = l - base;
    const float a = bilinear(mips[m0], uv);
    if (!(f > 0.0f)) return a;
    return a + (bilinear(mips[m0 + 1], uv) - a) * f;
}

}  // namespace

TonalArtMap generate_tonal_art_map(const TamParams& p) {
    validate(p);
    TonalArtMap tam;
    tam.params = p;

    int mip_count = 0, drawn = 0;
    for (int s = p.size; s >= 1; s /= 2, ++mip_count)
        if (s >= p.min_stroke_size) ++drawn;
    drawn = std::max(drawn, 1);

    // Per drawn mip: the work image, and the grain that weights deposits.
    std::vector<WorkImage> work(drawn);
    std::vector<float> paper;
    if (p.grain > 0.0f)
        paper = make_paper_grain({p.size, p.grain_cells, 3, hash32(p.seed, kPaperStream)});
    std::vector<float> paper_mip = paper;
    for (int m = 0, s = p.size; m < mip_count; ++m, s /= 2) {
        if (!paper.empty()) {
            if (m > 0) paper_mip = halve(paper_mip, s * 2);
            tam.paper.push_back(quantise(paper_mip, s));
        }
        if (m >= drawn) continue;
        WorkImage& w = work[m];
        w.reset(s);
        if (!paper.empty())
            for (size_t i = 0; i < w.deposit.size(); ++i)
                w.deposit[i] = 1.0f - p.grain * (1.0f - paper_mip[i]);
    }

    std::vector<Stroke> strokes;
    uint32_t candidate = 0;
    tam.levels.resize(p.levels);
    for (int level = 0; level < p.levels; ++level) {
        const double target = static_cast<double>(p.max_darkness) * (level + 1) / p.levels;
        const bool crossing = level >= p.cross_from_level;
        int added_in_level = 0;
        size_t in_coarser = 0;  // strokes in this level's next coarser mip
        std::vector<TamImage>& mips = tam.levels[level];
        mips.resize(mip_count);
        // Coarsest drawn mip first (Praun et al. fill each tone column from
        // the top row down), so each finer mip starts from its strokes.
        for (int m = drawn - 1; m >= 0; --m) {
            WorkImage& w = work[m];
            while (w.strokes < in_coarser) draw_stroke(strokes[w.strokes++], w, p);
            while (w.mean() < target) {
                if (w.strokes == strokes.size()) {
                    if (strokes.size() >= kMaxStrokes) break;
                    // Alternate hatching and cross strokes in the dark levels,
                    // so both directions thicken together.
                    const bool cross = crossing && added_in_level % 2 == 0;
                    Stroke best = random_stroke(p, candidate++, cross);
                    double best_gain = stroke_gain(best, w, target, p);
                    for (int c = 1; c < p.candidates; ++c) {
                        const Stroke s = random_stroke(p, candidate++, cross);
                        const double gain = stroke_gain(s, w, target, p);
                        if (gain > best_gain) best = s, best_gain = gain;
                    }
                    strokes.push_back(best);
                    ++added_in_level;
                }
                draw_stroke(strokes[w.strokes++], w, p);
            }
            in_coarser = w.strokes;
            mips[m] = quantise(w.coverage, w.size);
        }
        for (int m = drawn; m < mip_count; ++m) mips[m] = halve(mips[m - 1]);
        tam.level_darkness.push_back(static_cast<float>(work[0].mean()));
        tam.level_strokes.push_back(static_cast<int>(work[0].strokes));
    }
    return tam;
}

float tam_level_coverage(const TonalArtMap& tam, int level, glm::vec2 uv, float lod) {
    return trilinear(tam.levels[level], uv, lod);
}

float tam_coverage(const TonalArtMap& tam, float tone, glm::vec2 uv, float lod) {
    const int levels = static_cast<int>(tam.levels.size());
    const float darkness = 1.0f - std::clamp(tone, 0.0f, 1.0f);
    // Level i is darkness (i+1)/K of max_darkness; position −1 is the blank page.
    const float position =
        std::min(darkness / tam.params.max_darkness * static_cast<float>(levels) - 1.0f,
                 static_cast<float>(levels - 1));
    if (!(position > -1.0f)) return 0.0f;
    const float base = std::floor(position);
    const int lower = static_cast<int>(base);
    const float f = position - base;
    const float a = lower >= 0 ? tam_level_coverage(tam, lower, uv, lod) : 0.0f;
    if (!(f > 0.0f)) return a;
    return a + (tam_level_coverage(tam, lower + 1, uv, lod) - a) * f;
}

float tam_paper_shade(const TonalArtMap& tam, glm::vec2 uv, float lod) {
    if (tam.paper.empty()) return 1.0f;
    return 1.0f - tam.params.paper_shading * (1.0f - trilinear(tam.paper, uv, lod));
}

}  // namespace facet
