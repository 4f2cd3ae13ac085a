#include "shade/environment_prefilter.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "core/exact_trig.hpp"
#include "shade/hammersley.hpp"

namespace facet::pbr {

namespace {

constexpr double kPiDouble = 3.14159265358979323846;

// The smallest and largest maps of the chain. The octahedral mapping bends
// along the axis planes and the horizon, so bilinear filtering of even a
// smooth, broad lobe errs most there, and a crease shows on rough metal:
// for a cosine lobe over a gradient, at worst 11 % (mean 0.8 %) with 16
// texels a side, 5 % (0.2 %) with 32, 2.4 % (0.06 %) with 64. 32 is where
// the rough levels' error is no longer the map's but the sampling's. Above
// 2048, the sharp map would outgrow what a lookup needs while costing
// 50 MB. The largest prefiltered level, 256 (the first), and the next
// hold most of the filtering's cost.
constexpr int kMinLevelSize = 32;
constexpr int kMaxSharpSize = 2048;
constexpr int kMaxPrefilteredSize = 256;

// A prefiltered level's size is the power of two nearest 11 / alpha. A
// texel of a size-N map spans about sqrt(4 pi) / N = 3.5 / N radians, so
// the lobe's half width at half maximum, 1.29 alpha, spans about four:
// enough for bilinear filtering to keep a small light's reflection round
// (at two, it came out 14 % out of round and 16 % too dim at its peak).
constexpr double kTexelsPerAlpha = 11.0;

// Krivanek & Colbert 2008 read each sample one mip level coarser than its
// solid angle asks (a bias of 1), to hide the sampling pattern. Half a
// level was as smooth on a noisy map (within 0.5 % rms of a 65 k-sample
// reference, levels 2 to 4) and kept a small sun's glossy peak at 83 %
// of the reference rather than 68 %.
constexpr double kLodBias = 0.5;

// log2(x) for x > 0 from IEEE-exact operations: frexp splits x exactly into
// m 2^e with m in [1/2, 1), and ln m = 2 atanh(z) with z = (m - 1) / (m + 1)
// in [-1/3, 0), whose series z + z^3/3 + ... converges to 1e-18 in 20
// terms. The C library's log2 may differ in its last bits by CPU.
double exact_log2(double x) {
    constexpr double kLn2 = 0.69314718055994530942;
    int exponent = 0;
    const double m = std::frexp(x, &exponent);
    const double z = (m - 1.0) / (m + 1.0), z2 = z * z;
    double power = z, sum = z;
    for (int k = 1; k < 20; ++k) {
        power *= z2;
        sum += power / static_cast<double>(2 * k + 1);
    }
    return exponent + 2.0 * sum / kLn2;
}

// The power of two nearest `target` in ratio (at or above target / sqrt 2),
// between `low` and `high`, both powers of two.
int nearest_power_of_two(double target, int low, int high) {
    int size = low;
    while (size < high && size * 1.4142135623730951 < target) size *= 2;
    return size;
}

// Hammersley points per texel for a level of `size`: 8 M samples a level
// for the two largest (128 a texel at 256 x 256, 512 at 128 x 128), and
// 1024 a texel for the small rough ones. With each sample read from the mip
// level its solid angle asks for, a few dozen already filter without
// fireflies, but the coarse mip levels that few samples ask for blur more
// than the lobe: with 256, the studio's roughest level came out up to 17 %
// too bright in its darkest parts; with 1024, 6 % (1 % rms), against a
// reference of 65 536 samples.
int samples_for_level(int size) {
    const int64_t texels = static_cast<int64_t>(size) * size;
    return static_cast<int>(std::clamp<int64_t>((int64_t(1) << 23) / texels, 64, 1024));
}

// One sample of a lobe, in the frame of the texel's direction n = +z: its
// direction l, its weight n.l, and the mip level its density asks for.
struct LobeSample {
    glm::vec3 direction;
    double weight = 0.0;
    int mip = 0;
    float mip_fraction = 0.0f;  // towards mip + 1
};

// Karis 2013's prefiltering assumes n = v = r, so the lobe is the same for
// every texel: its samples are worked out once per level. h is drawn from
// D(h)(n.h) as the DFG table draws it (brdf.cpp), l = 2 (n.h) h - n, and
// the density of l is D (n.h) / (4 v.h) = D / 4. A sample standing for a
// solid angle 1 / (count * pdf) reads the mip level whose texels are that
// large, plus kLodBias (Krivanek & Colbert 2008): the source's texels there
// are already the average the sample stands for, so a bright small light
// is spread instead of hit or missed.
std::vector<LobeSample> lobe_samples(double alpha, int count, int sharp_size, int mip_count) {
    const double a2 = alpha * alpha;
    const double texel_solid_angle = 4.0 * kPiDouble / (double(sharp_size) * sharp_size);
    std::vector<LobeSample> samples;
    for (int i = 0; i < count; ++i) {
        const double u = radical_inverse_base2(static_cast<uint32_t>(i));
        const double turns = static_cast<double>(i) / count;
        const double denominator = 1.0 + (a2 - 1.0) * u;
        const double cos_h = std::sqrt((1.0 - u) / denominator);
        const double sin_h = std::sqrt(a2 * u / denominator);  // not 1 - cos^2: no cancelling
        const double n_dot_l = 2.0 * cos_h * cos_h - 1.0;
        if (!(n_dot_l > 0.0)) continue;
        const double d = cos_h * cos_h * a2 + sin_h * sin_h;  // (n.h)^2 (a2 - 1) + 1
        const double pdf = a2 / (kPiDouble * d * d) / 4.0;
        const double sample_solid_angle = 1.0 / (count * pdf);
        const double lod =
            std::max(0.0, 0.5 * exact_log2(sample_solid_angle / texel_solid_angle) + kLodBias);
        LobeSample sample;
        const double spread = 2.0 * cos_h * sin_h;
        sample.direction = glm::vec3(spread * cos_turns(turns), spread * sin_turns(turns), n_dot_l);
        sample.weight = n_dot_l;
        sample.mip = std::min(static_cast<int>(lod), mip_count - 1);
        sample.mip_fraction =
            sample.mip == mip_count - 1 ? 0.0f : static_cast<float>(lod - sample.mip);
        samples.push_back(sample);
    }
    return samples;
}

// Duff et al. 2017, "Building an Orthonormal Basis, Revisited" (JCGT 6 (1)):
// two unit tangents of the unit n, from arithmetic alone. The frame turns
// where n.z changes sign, and the sample pattern with it; the lobe is
// symmetric about n, so the filtered value hardly notices.
void tangent_frame(const glm::dvec3& n, glm::dvec3& tangent, glm::dvec3& bitangent) {
    const double sign = n.z >= 0.0 ? 1.0 : -1.0;
    const double a = -1.0 / (sign + n.z);
    const double b = n.x * n.y * a;
    tangent = {1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x};
    bitangent = {b, sign + n.y * n.y * a, -n.y};
}

glm::vec3 sample_pyramid(const std::vector<OctahedralMap>& pyramid, const glm::vec2& p, int mip,
                         float fraction) {
    const glm::vec3 fine = pyramid[static_cast<size_t>(mip)].sample(p);
    if (fraction == 0.0f) return fine;
    const glm::vec3 coarse = pyramid[static_cast<size_t>(mip) + 1].sample(p);
    return fine + (coarse - fine) * fraction;
}

// One texel of a prefiltered level: the weighted mean of the lobe's
// samples around the texel's direction, summed in double in sample order.
glm::vec3 prefilter_texel(const std::vector<OctahedralMap>& pyramid,
                          const std::vector<LobeSample>& lobe, double total_weight,
                          const glm::dvec3& n) {
    glm::dvec3 tangent_double, bitangent_double;
    tangent_frame(n, tangent_double, bitangent_double);
    // The sample directions only pick texels: float is plenty, and faster.
    const glm::vec3 tangent(tangent_double), bitangent(bitangent_double), normal(n);
    glm::dvec3 sum(0.0);
    for (const LobeSample& s : lobe) {
        const glm::vec3 l =
            tangent * s.direction.x + bitangent * s.direction.y + normal * s.direction.z;
        sum += glm::dvec3(sample_pyramid(pyramid, octahedral_encode(l), s.mip, s.mip_fraction)) *
               s.weight;
    }
    return glm::vec3(sum / total_weight);
}

// The equirect image's bilinear value at (u, v): the columns wrap round,
// the rows are clamped at the poles.
glm::dvec3 equirect_bilinear(const EquirectRadiance& image, double u, double v) {
    const double x = u * image.width - 0.5;
    const double y = std::clamp(v * image.height - 0.5, 0.0, image.height - 1.0);
    const double column_floor = std::floor(x), row_floor = std::floor(y);
    const double tx = x - column_floor, ty = y - row_floor;
    const int64_t width = image.width;
    // u is in [0, 1], so column_floor is in [-1, width - 1]: one wrap at most.
    int64_t c0 = static_cast<int64_t>(column_floor);
    if (c0 < 0) c0 += width;
    if (c0 >= width) c0 -= width;
    const int64_t c1 = c0 + 1 == width ? 0 : c0 + 1;
    const int64_t r0 = static_cast<int64_t>(row_floor);
    const int64_t r1 = std::min<int64_t>(r0 + 1, image.height - 1);
    const auto texel = [&](int64_t column, int64_t row) {
        const float* t = &image.rgb[static_cast<size_t>((row * width + column) * 3)];
        return glm::dvec3(t[0], t[1], t[2]);
    };
    const glm::dvec3 upper = texel(c0, r0) + (texel(c1, r0) - texel(c0, r0)) * tx;
    const glm::dvec3 lower = texel(c0, r1) + (texel(c1, r1) - texel(c0, r1)) * tx;
    return upper + (lower - upper) * ty;
}

// EquirectRadiance's (u, v) of the unit direction d: phi = atan2(x, -z),
// u = phi / 2 pi + 1/2, and theta = atan2(sqrt(x^2 + z^2), y), v = theta / pi.
glm::dvec2 equirect_coordinates(const glm::dvec3& d) {
    const double u = atan2_turns(d.x, -d.z) + 0.5;
    const double v = 2.0 * atan2_turns(std::sqrt(d.x * d.x + d.z * d.z), d.y);
    return {u, v};
}

}  // namespace

int sharp_map_size(int image_height) {
    int size = kMinLevelSize;
    while (size < kMaxSharpSize && size < image_height) size *= 2;
    return size;
}

int prefiltered_level_size(double roughness, int sharp_size) {
    const double alpha = roughness * roughness;
    return std::min(sharp_size, nearest_power_of_two(kTexelsPerAlpha / alpha, kMinLevelSize,
                                                     kMaxPrefilteredSize));
}

void resample_equirect_row(const EquirectRadiance& image, int row, OctahedralMap& sharp) {
    const double size = sharp.size();
    for (int column = 0; column < sharp.size(); ++column) {
        glm::dvec3 sum(0.0);
        for (int quarter = 0; quarter < 4; ++quarter) {
            const glm::dvec2 p((column + 0.25 + 0.5 * (quarter & 1)) / size * 2.0 - 1.0,
                               (row + 0.25 + 0.5 * (quarter >> 1)) / size * 2.0 - 1.0);
            const glm::dvec2 uv = equirect_coordinates(octahedral_decode(p));
            sum += equirect_bilinear(image, uv.x, uv.y);
        }
        sharp.set_texel(column, row, glm::vec3(sum * 0.25));
    }
}

std::vector<OctahedralMap> prefilter_chain(OctahedralMap sharp, int level_count, ThreadPool& pool) {
    const int sharp_size = sharp.size();
    std::vector<OctahedralMap> pyramid;
    pyramid.push_back(std::move(sharp));
    while (pyramid.back().size() > 1) pyramid.push_back(pyramid.back().half_size());
    const int mip_count = static_cast<int>(pyramid.size());

    std::vector<OctahedralMap> levels(static_cast<size_t>(level_count));
    std::vector<std::vector<LobeSample>> lobes(static_cast<size_t>(level_count));
    std::vector<double> total_weights(static_cast<size_t>(level_count), 0.0);
    // Every row of every level is one task: the big first level then
    // spreads over the threads like the small ones.
    std::vector<std::pair<int, int>> tasks;  // (level, row)
    for (int k = 1; k < level_count; ++k) {
        const double roughness = static_cast<double>(k) / (level_count - 1);
        const int size = prefiltered_level_size(roughness, sharp_size);
        levels[static_cast<size_t>(k)] = OctahedralMap(size);
        lobes[static_cast<size_t>(k)] =
            lobe_samples(roughness * roughness, samples_for_level(size), sharp_size, mip_count);
        for (const LobeSample& s : lobes[static_cast<size_t>(k)])
            total_weights[static_cast<size_t>(k)] += s.weight;
        for (int row = 0; row < size; ++row) tasks.emplace_back(k, row);
    }
    pool.parallel_for(tasks.size(), [&](size_t task) {
        const auto [k, row] = tasks[task];
        OctahedralMap& level = levels[static_cast<size_t>(k)];
        for (int column = 0; column < level.size(); ++column)
            level.set_texel(column, row,
                            prefilter_texel(pyramid, lobes[static_cast<size_t>(k)],
                                            total_weights[static_cast<size_t>(k)],
                                            level.texel_direction(column, row)));
    });
    for (int k = 1; k < level_count; ++k) levels[static_cast<size_t>(k)].fill_border();
    levels[0] = std::move(pyramid[0]);
    return levels;
}

}  // namespace facet::pbr
