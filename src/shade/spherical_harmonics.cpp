#include "shade/spherical_harmonics.hpp"

#include <cmath>
#include <cstddef>
#include <stdexcept>

#include "core/exact_trig.hpp"

namespace facet::pbr {

namespace {

constexpr double kPiDouble = 3.14159265358979323846;

// The direction of (u, v), EquirectRadiance's mapping: theta = pi v is
// half a turn times v, phi + pi = 2 pi u, so sin phi = -sin(2 pi u) and
// cos phi = -cos(2 pi u).
glm::dvec3 direction_from_turns(double u, double v) {
    const double sin_theta = sin_turns(0.5 * v), cos_theta = cos_turns(0.5 * v);
    return {-sin_theta * sin_turns(u), cos_theta, sin_theta * cos_turns(u)};
}

// A-hat_l for each coefficient, in sh_basis's order.
constexpr std::array<float, kShCount> kCosineFactors = {
    float(kShCosineBand0), float(kShCosineBand1), float(kShCosineBand1),
    float(kShCosineBand1), float(kShCosineBand2), float(kShCosineBand2),
    float(kShCosineBand2), float(kShCosineBand2), float(kShCosineBand2)};

}  // namespace

glm::dvec3 equirect_direction(double u, double v) {
    return direction_from_turns(u, v);
}

double equirect_texel_solid_angle(int width, int height, int row) {
    const double top = cos_turns(0.5 * row / height);
    const double bottom = cos_turns(0.5 * (row + 1) / height);
    return 2.0 * kPiDouble / width * (top - bottom);
}

RadianceSh project_equirect(const EquirectRadiance& image) {
    if (image.width <= 0 || image.height <= 0 ||
        image.rgb.size() != static_cast<std::size_t>(image.width) * image.height * 3)
        throw std::invalid_argument("equirect radiance: width * height * 3 floats expected");
    std::array<glm::dvec3, kShCount> total{};
    for (int row = 0; row < image.height; ++row) {
        const double v = (row + 0.5) / image.height;
        const double solid_angle = equirect_texel_solid_angle(image.width, image.height, row);
        std::array<glm::dvec3, kShCount> row_sum{};
        for (int column = 0; column < image.width; ++column) {
            const glm::dvec3 d = direction_from_turns((column + 0.5) / image.width, v);
            const float* texel =
                &image.rgb[(static_cast<std::size_t>(row) * image.width + column) * 3];
            const glm::dvec3 radiance(texel[0], texel[1], texel[2]);
            const std::array<double, kShCount> y = sh_basis(d.x, d.y, d.z);
            for (int i = 0; i < kShCount; ++i) row_sum[i] += radiance * y[i];
        }
        // The solid angle is the same along a row: multiplied once, per row.
        for (int i = 0; i < kShCount; ++i) total[i] += row_sum[i] * solid_angle;
    }
    RadianceSh sh;
    for (int i = 0; i < kShCount; ++i) sh.coefficients[i] = glm::vec3(total[i]);
    return sh;
}

RadianceSh project_uniform(const glm::vec3& radiance) {
    RadianceSh sh;
    sh.coefficients[0] = glm::vec3(glm::dvec3(radiance) * (4.0 * kPiDouble * kSh0));
    return sh;
}

RadianceSh project_direction(const glm::vec3& direction,
                             const glm::vec3& radiance_times_solid_angle) {
    const glm::dvec3 d(direction);
    const std::array<double, kShCount> y = sh_basis(d.x, d.y, d.z);
    RadianceSh sh;
    for (int i = 0; i < kShCount; ++i)
        sh.coefficients[i] = glm::vec3(glm::dvec3(radiance_times_solid_angle) * y[i]);
    return sh;
}

// The scalar forms are lane 0 of the eight-lane ones: one formula.
glm::vec3 irradiance(const RadianceSh& sh, const glm::vec3& n) {
    const simd::vf lanes[3] = {simd::splat(n.x), simd::splat(n.y), simd::splat(n.z)};
    simd::vf e[3];
    irradiance(sh, lanes, e);
    return {e[0][0], e[1][0], e[2][0]};
}

void irradiance(const RadianceSh& sh, const simd::vf (&n)[3], simd::vf (&e)[3]) {
    const std::array<simd::vf, kShCount> y = sh_basis(n[0], n[1], n[2]);
    for (int c = 0; c < 3; ++c) e[c] = simd::splat(0.0f);
    for (int i = 0; i < kShCount; ++i) {
        const simd::vf weighted = kCosineFactors[i] * y[i];
        for (int c = 0; c < 3; ++c) e[c] += sh.coefficients[i][c] * weighted;
    }
}

glm::vec3 diffuse_radiance(const RadianceSh& sh, const glm::vec3& n) {
    return irradiance(sh, n) / static_cast<float>(kPiDouble);
}

void diffuse_radiance(const RadianceSh& sh, const simd::vf (&n)[3], simd::vf (&radiance)[3]) {
    irradiance(sh, n, radiance);
    for (simd::vf& channel : radiance) channel = channel / static_cast<float>(kPiDouble);
}

}  // namespace facet::pbr
