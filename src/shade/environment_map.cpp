#include "shade/environment_map.hpp"

#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>

#include <glm/common.hpp>

#include "core/thread_pool.hpp"
#include "shade/environment_prefilter.hpp"

namespace facet::pbr {

PrefilteredEnvironment::PrefilteredEnvironment(const RadianceSh& sh,
                                               std::vector<OctahedralMap> levels)
    : sh_(sh), levels_(std::move(levels)) {
    if (levels_.size() != static_cast<size_t>(kEnvironmentLevels))
        throw std::invalid_argument(
            "prefiltered environment: " + std::to_string(kEnvironmentLevels) + " levels expected");
    for (const OctahedralMap& level : levels_)
        if (level.size() < 1) throw std::invalid_argument("prefiltered environment: empty level");
}

float PrefilteredEnvironment::level_roughness(int k) {
    return static_cast<float>(k) / static_cast<float>(kEnvironmentLevels - 1);
}

glm::vec3 PrefilteredEnvironment::diffuse(const glm::vec3& n) const {
    return glm::max(diffuse_radiance(sh_, n), glm::vec3(0.0f));
}

glm::vec3 PrefilteredEnvironment::specular(const glm::vec3& reflected,
                                           float perceptual_roughness) const {
    // In this order a NaN roughness becomes 0.
    const float roughness = std::max(0.0f, std::min(perceptual_roughness, 1.0f));
    const float position = roughness * static_cast<float>(kEnvironmentLevels - 1);
    const int k = std::min(static_cast<int>(position), kEnvironmentLevels - 1);
    const float t = position - static_cast<float>(k);
    const glm::vec2 p = octahedral_encode(reflected);
    const glm::vec3 lower = levels_[static_cast<size_t>(k)].sample(p);
    // On a level (roughness 0, 1/7, ..., 1) that level alone: no second
    // read, and no rounding from a blend.
    if (t == 0.0f) return lower;
    const glm::vec3 upper = levels_[static_cast<size_t>(k) + 1].sample(p);
    return lower + (upper - lower) * t;
}

void PrefilteredEnvironment::diffuse(const simd::vf (&n)[3], simd::vf (&radiance)[3]) const {
    diffuse_radiance(sh_, n, radiance);
    for (simd::vf& channel : radiance)  // glm::max's order: a NaN stays
        channel = channel < simd::splat(0.0f) ? simd::splat(0.0f) : channel;
}

void PrefilteredEnvironment::specular(const simd::vf (&reflected)[3], simd::vf perceptual_roughness,
                                      simd::vf (&radiance)[3]) const {
    using simd::splat;
    using simd::vf;
    using simd::vi;
    // As the one-point form, with std::max and std::min's order: NaN is 0.
    const vf clamped_high = splat(1.0f) < perceptual_roughness ? splat(1.0f) : perceptual_roughness;
    const vf roughness = splat(0.0f) < clamped_high ? clamped_high : splat(0.0f);
    const vf position = roughness * static_cast<float>(kEnvironmentLevels - 1);
    const vi last = simd::splat_i(kEnvironmentLevels - 1);
    vi k = __builtin_convertvector(position, vi);
    k = last < k ? last : k;
    const vf t = position - __builtin_convertvector(k, vf);
    vf px, py;
    octahedral_encode(reflected[0], reflected[1], reflected[2], px, py);
    const OctahedralMap* lower_maps[simd::kLanes];
    const OctahedralMap* upper_maps[simd::kLanes];
    for (int lane = 0; lane < simd::kLanes; ++lane) {
        lower_maps[lane] = &levels_[static_cast<size_t>(k[lane])];
        upper_maps[lane] = &levels_[static_cast<size_t>(std::min(k[lane] + 1, last[lane]))];
    }
    OctahedralMap::sample(lower_maps, px, py, radiance);
    const vi on_level = t == splat(0.0f);
    if (simd::movemask(on_level) == 0xffu) return;
    vf upper[3];
    OctahedralMap::sample(upper_maps, px, py, upper);
    for (int c = 0; c < 3; ++c)
        radiance[c] = on_level ? radiance[c] : radiance[c] + (upper[c] - radiance[c]) * t;
}

SharedEnvironment build_environment(const EquirectRadiance& image, unsigned threads) {
    if (image.width <= 0 || image.height <= 0 ||
        image.rgb.size() != static_cast<size_t>(image.width) * image.height * 3)
        throw std::invalid_argument("environment: width * height * 3 floats expected");
    ThreadPool pool(threads);
    OctahedralMap sharp(sharp_map_size(image.height));
    RadianceSh sh;
    // The projection onto the harmonics runs on one thread (its sum has a
    // fixed order): as task 0, handed out first, it runs beside the rows.
    pool.parallel_for(static_cast<size_t>(sharp.size()) + 1, [&](size_t task) {
        if (task == 0)
            sh = project_equirect(image);
        else
            resample_equirect_row(image, static_cast<int>(task) - 1, sharp);
    });
    sharp.fill_border();
    return std::make_shared<const PrefilteredEnvironment>(
        sh, prefilter_chain(std::move(sharp), kEnvironmentLevels, pool));
}

SharedEnvironment uniform_environment(const glm::vec3& radiance) {
    // One texel a level (and its border, filled alike) is enough: bilinear
    // filtering and the blend between levels return equal values unchanged.
    std::vector<OctahedralMap> levels(kEnvironmentLevels, OctahedralMap(1, radiance));
    return std::make_shared<const PrefilteredEnvironment>(project_uniform(radiance),
                                                          std::move(levels));
}

}  // namespace facet::pbr
