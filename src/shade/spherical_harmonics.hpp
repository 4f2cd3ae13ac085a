#pragma once
// Diffuse light from an environment, through the 9 real spherical
// harmonics of bands 0 to 2 (Ramamoorthi & Hanrahan 2001, "An Efficient
// Representation for Irradiance Environment Maps", SIGGRAPH 2001).
// docs/pbr.md, "Diffuse light from an environment", gives every formula,
// its symbols and its source.
//
//   L_lm = integral of L(d) Y_lm(d) over the sphere     (project_*)
//   E(n) = sum over l, m of A_l L_lm Y_lm(n)            (irradiance)
//   A_0 = pi, A_1 = 2 pi / 3, A_2 = pi / 4               (the clamped cosine)
//
// Once per environment:
//   const RadianceSh sh = project_equirect(image);
// per shading point (n unit):
//   colour += albedo * diffuse_radiance(sh, n);   // Lambert: albedo E / pi
//
// Radiance is linear RGB in the scene's units; irradiance E is radiance
// times steradians. Directions are in world space: right-handed, +Y up
// (docs/scene-format.md). The projection sums in double, in a fixed order on
// one thread, and takes its sines and cosines from a series of IEEE-exact
// operations, so its bits do not depend on threads or CPU. No global
// mutable state.
#include <array>
#include <type_traits>
#include <vector>

#include <glm/vec3.hpp>

#include "core/simd_math.hpp"

namespace facet::pbr {

// Bands 0, 1 and 2: 1 + 3 + 5 functions.
constexpr int kShCount = 9;

// The normalisation constants of R&H 2001's eq. 3, exact:
//   Y_00 = 1 / (2 sqrt(pi))                        = 0.282095
//   Y_1m = sqrt(3 / (4 pi))                        = 0.488603
//   Y_2-2, Y_2-1, Y_21 = sqrt(15 / (4 pi))         = 1.092548
//   Y_20 = sqrt(5 / (16 pi)) (times 3z^2 - 1)      = 0.315392
//   Y_22 = sqrt(15 / (16 pi)) (times x^2 - y^2)    = 0.546274
constexpr double kSh0 = 0.28209479177387814;
constexpr double kSh1 = 0.48860251190291992;
constexpr double kSh2 = 1.09254843059207907;
constexpr double kSh20 = 0.31539156525252001;
constexpr double kSh22 = 0.54627421529603954;

// The convolution of each band with the clamped cosine max(0, cos),
// R&H 2001 eq. 8 (A-hat_l): the factor that turns radiance coefficients
// into irradiance coefficients.
constexpr double kShCosineBand0 = 3.14159265358979323846;              // pi
constexpr double kShCosineBand1 = 2.0 * 3.14159265358979323846 / 3.0;  // 2 pi / 3
constexpr double kShCosineBand2 = 3.14159265358979323846 / 4.0;        // pi / 4

// The 9 basis functions at the unit direction (x, y, z), R&H 2001 eq. 3, in
// the order (l, m) = (0,0), (1,-1), (1,0), (1,1), (2,-2), (2,-1), (2,0),
// (2,1), (2,2). Written, as in the paper, with z as the polar axis; which
// world axis is polar does not matter here, since irradiance sums whole
// bands, and every band is closed under rotation.
// A constant as Real: the float or double itself, or eight lanes of the
// float (simd::vf has no conversion from a number).
template <typename Real>
Real sh_constant(double c) {
    if constexpr (std::is_same_v<Real, simd::vf>)
        return simd::splat(static_cast<float>(c));
    else
        return Real(c);
}

template <typename Real>
std::array<Real, kShCount> sh_basis(Real x, Real y, Real z) {
    const auto k = [](double c) { return sh_constant<Real>(c); };
    return {k(kSh0),
            k(kSh1) * y,
            k(kSh1) * z,
            k(kSh1) * x,
            k(kSh2) * x * y,
            k(kSh2) * y * z,
            k(kSh20) * (k(3) * z * z - k(1)),
            k(kSh2) * x * z,
            k(kSh22) * (x * x - y * y)};
}

// The coefficients L_lm of an environment's radiance, one RGB triple per
// basis function, in sh_basis's order.
struct RadianceSh {
    std::array<glm::vec3, kShCount> coefficients{};
};

// An equirectangular (latitude-longitude) radiance image, filled by the
// caller. Row 0 is the top. Texel (row, column) covers
//   u in [column / width, (column + 1) / width), v in [row / height, (row + 1) / height)
// and (u, v) is the direction
//   theta = pi v             (angle from +Y: v = 0 is straight up)
//   phi   = 2 pi (u - 1/2)   (about +Y)
//   d     = (sin theta sin phi, cos theta, -sin theta cos phi)
// so the image's centre is -Z (where the default camera looks), u = 3/4 is
// +X and the left and right edges are +Z. Seen from inside the sphere, with
// +Y up, the image is not mirrored. Rotating the environment by a about +Y
// (right-handed) moves phi to phi + a: width/4 columns to the right for 90
// degrees.
struct EquirectRadiance {
    int width = 0;
    int height = 0;
    std::vector<float> rgb;  // width * height * 3 linear RGB floats, row-major
};

// The direction of (u, v) as EquirectRadiance maps it, unit, in double.
glm::dvec3 equirect_direction(double u, double v);

// The solid angle of every texel in `row`, exactly:
//   (2 pi / width) (cos theta_0 - cos theta_1)
// with theta_0 and theta_1 the row's top and bottom edges. The rows' total
// is 4 pi.
double equirect_texel_solid_angle(int width, int height, int row);

// Projects the image onto the 9 basis functions: each texel adds its
// radiance times its solid angle times the basis at its centre's direction.
// Sums in double, row by row in order (each row summed on its own first),
// on the calling thread. Throws std::invalid_argument when the sizes do not
// match the data.
RadianceSh project_equirect(const EquirectRadiance& image);

// The coefficients of a uniform environment of radiance `radiance`, exactly:
// L_00 = 4 pi Y_00 L = 2 sqrt(pi) L, the rest 0.
RadianceSh project_uniform(const glm::vec3& radiance);

// The coefficients of a light so small that it is one direction d (unit):
// radiance L over a solid angle w, L_lm = (L w) Y_lm(d). `radiance_times_solid_angle`
// is L w, the irradiance the light gives on a plane facing it.
RadianceSh project_direction(const glm::vec3& direction,
                             const glm::vec3& radiance_times_solid_angle);

// The irradiance E(n) on a plane of unit normal n, R&H 2001 eq. 7 truncated
// to bands 0 to 2: sum of A_l L_lm Y_lm(n). Radiance times steradians. The
// truncation can make it slightly negative for a strongly directional
// environment; it is not clamped here.
glm::vec3 irradiance(const RadianceSh& sh, const glm::vec3& n);
// The same for eight normals at once, to the bit: the shading model's form.
void irradiance(const RadianceSh& sh, const simd::vf (&n)[3], simd::vf (&e)[3]);

// The radiance a white Lambertian surface of normal n reflects, E(n) / pi:
// multiplied by an albedo, the diffuse colour the shading model will use.
glm::vec3 diffuse_radiance(const RadianceSh& sh, const glm::vec3& n);
void diffuse_radiance(const RadianceSh& sh, const simd::vf (&n)[3], simd::vf (&radiance)[3]);

}  // namespace facet::pbr
