// Diffuse environment light from 9 spherical-harmonic coefficients
// (shade/spherical_harmonics.hpp, docs/pbr.md "Diffuse light from an
// environment") against closed forms: the equirect mapping and its solid
// angles, the basis's orthonormality, a uniform environment, a single bright
// direction (with the 9 terms' known error against the true cosine), a
// rotation about +Y.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <stdexcept>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "shade/spherical_harmonics.hpp"

using namespace facet;

namespace {

constexpr double kPi = 3.14159265358979323846;

// An equirect image whose texels hold radiance(direction at the texel's centre).
pbr::EquirectRadiance make_image(int width, int height,
                                 const std::function<glm::vec3(const glm::dvec3&)>& radiance) {
    pbr::EquirectRadiance image{width, height, std::vector<float>(width * height * 3)};
    for (int row = 0; row < height; ++row)
        for (int column = 0; column < width; ++column) {
            const glm::vec3 l =
                radiance(pbr::equirect_direction((column + 0.5) / width, (row + 0.5) / height));
            for (int c = 0; c < 3; ++c) image.rgb[(row * width + column) * 3 + c] = l[c];
        }
    return image;
}

// Some unit normals all round the sphere, axes and diagonals included.
std::vector<glm::vec3> test_normals() {
    std::vector<glm::vec3> normals = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                      {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
    for (int i = 0; i < 12; ++i) {
        const double a = 0.7 * i, b = 1.3 * i + 0.2;
        normals.push_back(
            glm::vec3(std::sin(a) * std::cos(b), std::cos(a), std::sin(a) * std::sin(b)));
    }
    return normals;
}

double relative_error(const glm::vec3& value, const glm::vec3& expected) {
    double worst = 0.0;
    for (int c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(double(value[c]) - expected[c]) / std::abs(expected[c]));
    return worst;
}

// The 9-term irradiance of a direction light of unit L w, as a function of
// the angle gamma between n and d. By the addition theorem, the sum over m
// of Y_lm(d) Y_lm(n) is (2l + 1)/(4 pi) P_l(cos gamma), so
//   E_9 = pi/(4 pi) + (2 pi/3)(3/(4 pi)) cos + (pi/4)(5/(4 pi)) (3 cos^2 - 1)/2
//       = 1/4 + cos/2 + (5/32)(3 cos^2 - 1).
// Written from the Legendre polynomials, not from the code's basis.
double nine_term_cosine(double cos_gamma) {
    return 0.25 + 0.5 * cos_gamma + 5.0 / 32.0 * (3.0 * cos_gamma * cos_gamma - 1.0);
}

}  // namespace

TEST_CASE("spherical harmonics: the equirect mapping puts -Z at the centre, +X right of it, +Y up",
          "[shade][harmonics]") {
    const auto near = [](const glm::dvec3& a, const glm::dvec3& b) {
        return glm::length(a - b) < 1e-12;
    };
    CHECK(near(pbr::equirect_direction(0.5, 0.5), {0, 0, -1}));
    CHECK(near(pbr::equirect_direction(0.75, 0.5), {1, 0, 0}));
    CHECK(near(pbr::equirect_direction(0.25, 0.5), {-1, 0, 0}));
    CHECK(near(pbr::equirect_direction(0.0, 0.5), {0, 0, 1}));
    CHECK(near(pbr::equirect_direction(0.3, 0.0), {0, 1, 0}));
    CHECK(near(pbr::equirect_direction(0.3, 1.0), {0, -1, 0}));
    // The texels' solid angles add up to the sphere's 4 pi.
    double total = 0.0;
    for (int row = 0; row < 32; ++row) total += 64 * pbr::equirect_texel_solid_angle(64, 32, row);
    CHECK(total == Approx(4.0 * kPi).epsilon(1e-14));
}

TEST_CASE("spherical harmonics: the 9 basis functions are orthonormal by quadrature",
          "[shade][harmonics]") {
    // Midpoints uniform in t = cos theta about +Y (uniform in area) and in
    // phi: exact in phi for these trigonometric polynomials, error ~1e-5 in t.
    constexpr int kSteps = 256;
    double gram[pbr::kShCount][pbr::kShCount] = {};
    const double weight = (2.0 / kSteps) * (2.0 * kPi / (2 * kSteps));
    for (int i = 0; i < kSteps; ++i) {
        const double t = -1.0 + 2.0 * (i + 0.5) / kSteps, s = std::sqrt(1.0 - t * t);
        for (int k = 0; k < 2 * kSteps; ++k) {
            const double phi = 2.0 * kPi * (k + 0.5) / (2 * kSteps);
            const auto y = pbr::sh_basis(s * std::cos(phi), t, s * std::sin(phi));
            for (int a = 0; a < pbr::kShCount; ++a)
                for (int b = 0; b < pbr::kShCount; ++b) gram[a][b] += weight * y[a] * y[b];
        }
    }
    double worst = 0.0;
    for (int a = 0; a < pbr::kShCount; ++a)
        for (int b = 0; b < pbr::kShCount; ++b)
            worst = std::max(worst, std::abs(gram[a][b] - (a == b ? 1.0 : 0.0)));
    CHECK(worst < 1e-4);
}

TEST_CASE("spherical harmonics: a uniform environment L gives E = pi L for every normal",
          "[shade][harmonics]") {
    const glm::vec3 radiance(0.25f, 1.0f, 3.0f);
    const pbr::RadianceSh exact = pbr::project_uniform(radiance);
    // A 64 x 32 image of the same: the solid angles add up to 4 pi, and the
    // texel-centre directions leave L_20 and L_22 at under 1e-3 of L_00,
    // which moves E by up to 5e-4.
    const pbr::RadianceSh image =
        pbr::project_equirect(make_image(64, 32, [&](const glm::dvec3&) { return radiance; }));
    double worst_image = 0.0;
    for (const glm::vec3& n : test_normals()) {
        CHECK(relative_error(pbr::irradiance(exact, n), float(kPi) * radiance) < 1e-4);
        CHECK(relative_error(pbr::diffuse_radiance(exact, n), radiance) < 1e-4);
        worst_image =
            std::max(worst_image, relative_error(pbr::irradiance(image, n), float(kPi) * radiance));
    }
    CHECK(worst_image < 1e-3);
    CHECK(relative_error(image.coefficients[0], exact.coefficients[0]) < 1e-6);
}

TEST_CASE("spherical harmonics: a single direction's irradiance is the 9-term clamped cosine",
          "[shade][harmonics]") {
    const glm::vec3 d = glm::normalize(glm::vec3(0.3f, 0.8f, -0.5f));
    const float flux = 2.0f;  // L w, the irradiance on a plane facing d
    const pbr::RadianceSh sh = pbr::project_direction(d, glm::vec3(flux));
    for (const glm::vec3& n : test_normals()) {
        const double expected = flux * nine_term_cosine(glm::dot(n, d));
        const glm::vec3 e = pbr::irradiance(sh, n);
        for (int c = 0; c < 3; ++c) CHECK(std::abs(e[c] - expected) < 1e-5 * flux);
    }
    // The 9 terms against the true max(0, n.d) L w: 6.25 % too bright facing
    // the light (1.0625 for 1), 0.094 at 90 degrees where the truth is 0,
    // 0.0625 facing away, and 0.461 for 0.5 at 60 degrees: a single bright
    // light is the 9 terms' worst case (docs/pbr.md, "Error of 9 terms").
    const glm::vec3 side = glm::normalize(glm::cross(d, glm::vec3(0, 0, 1)));
    const glm::vec3 sixty = 0.5f * d + std::sqrt(0.75f) * side;
    CHECK(pbr::irradiance(sh, d).x / flux == Approx(1.0625).margin(1e-5));
    CHECK(pbr::irradiance(sh, side).x / flux == Approx(0.09375).margin(1e-5));
    CHECK(pbr::irradiance(sh, -d).x / flux == Approx(0.0625).margin(1e-5));
    CHECK(pbr::irradiance(sh, sixty).x / flux == Approx(0.4609375).margin(1e-5));
    // Its minimum, at cos gamma = -8/15 (122.2 degrees), is negative: E is not clamped.
    const glm::vec3 past = -8.0f / 15.0f * d + std::sqrt(1.0f - 64.0f / 225.0f) * side;
    CHECK(pbr::irradiance(sh, past).x / flux == Approx(-0.0395833).margin(1e-5));
}

TEST_CASE("spherical harmonics: one bright texel projects as a direction of its solid angle",
          "[shade][harmonics]") {
    constexpr int kWidth = 64, kHeight = 32, kRow = 9, kColumn = 41;
    const glm::vec3 radiance(50.0f, 20.0f, 5.0f);
    pbr::EquirectRadiance image{kWidth, kHeight, std::vector<float>(kWidth * kHeight * 3, 0.0f)};
    for (int c = 0; c < 3; ++c) image.rgb[(kRow * kWidth + kColumn) * 3 + c] = radiance[c];
    const double solid_angle = pbr::equirect_texel_solid_angle(kWidth, kHeight, kRow);
    const glm::vec3 d(pbr::equirect_direction((kColumn + 0.5) / kWidth, (kRow + 0.5) / kHeight));
    const pbr::RadianceSh projected = pbr::project_equirect(image);
    const pbr::RadianceSh expected =
        pbr::project_direction(d, radiance * static_cast<float>(solid_angle));
    for (int i = 0; i < pbr::kShCount; ++i)
        for (int c = 0; c < 3; ++c)
            CHECK(projected.coefficients[i][c] ==
                  Approx(expected.coefficients[i][c]).margin(1e-6 * radiance[c]));
    // Facing the texel: the 9-term 1.0625 L w, against the true L w.
    const glm::vec3 e = pbr::irradiance(projected, d);
    for (int c = 0; c < 3; ++c)
        CHECK(e[c] / (radiance[c] * solid_angle) == Approx(1.0625).epsilon(1e-4));
}

TEST_CASE("spherical harmonics: rotating the environment 90 degrees about +Y rotates E",
          "[shade][harmonics]") {
    constexpr int kWidth = 64, kHeight = 32;
    const glm::dvec3 key = glm::normalize(glm::dvec3(1.0, 0.5, -0.3));
    const pbr::EquirectRadiance image = make_image(kWidth, kHeight, [&](const glm::dvec3& d) {
        const double lobe = std::max(0.0, glm::dot(d, key));
        return glm::vec3(1.0 + 3.0 * lobe * lobe, 0.5 + d.x * d.x, 0.2 + 0.5 * (d.z + 1.0));
    });
    // Rotating by a about +Y moves phi to phi + a: for 90 degrees, texel
    // column j of the rotated image is column j + width/4 of the original.
    pbr::EquirectRadiance rotated = image;
    for (int row = 0; row < kHeight; ++row)
        for (int column = 0; column < kWidth; ++column)
            for (int c = 0; c < 3; ++c)
                rotated.rgb[(row * kWidth + column) * 3 + c] =
                    image.rgb[(row * kWidth + (column + kWidth / 4) % kWidth) * 3 + c];
    const pbr::RadianceSh original = pbr::project_equirect(image);
    const pbr::RadianceSh turned = pbr::project_equirect(rotated);
    // The right-handed 90-degree rotation about +Y: (x, y, z) -> (z, y, -x).
    const auto rotate = [](const glm::vec3& n) { return glm::vec3(n.z, n.y, -n.x); };
    double worst = 0.0, unrotated_difference = 0.0;
    for (const glm::vec3& n : test_normals()) {
        const glm::vec3 e = pbr::irradiance(original, n);
        worst = std::max(worst, relative_error(pbr::irradiance(turned, rotate(n)), e));
        unrotated_difference =
            std::max(unrotated_difference, relative_error(pbr::irradiance(turned, n), e));
    }
    CHECK(worst < 1e-5);
    CHECK(unrotated_difference > 0.1);  // the environment is not symmetric about +Y
}

TEST_CASE("spherical harmonics: an image whose data does not match its size is refused",
          "[shade][harmonics]") {
    pbr::EquirectRadiance image{8, 4, std::vector<float>(8 * 4 * 3 - 1)};
    CHECK_THROWS_AS(pbr::project_equirect(image), std::invalid_argument);
    image.rgb.push_back(0.0f);
    CHECK_NOTHROW(pbr::project_equirect(image));
}
