#pragma once
// The terms of the `pbr` model's BRDF (shade/brdf.hpp gives the whole):
// the constants, GGX's distribution and Smith term, the DFG and sheen
// tables, the sheen's lobe, and the records a point's inputs and its
// worked-out terms travel in (SurfaceTerms, PbrPoint). docs/pbr.md gives
// every formula and its source.
#include <algorithm>
#include <array>
#include <cmath>

#include <glm/vec3.hpp>

#include "core/simd_math.hpp"

#include "shade/fresnel.hpp"
#include "shade/lanes.hpp"

namespace facet::pbr {

constexpr float kPi = 3.14159265358979323846f;

// The smallest perceptual roughness used. Below it GGX's peak
// 1 / (pi alpha^2) grows without bound (a mirror needs a delta function),
// and float n.h, accurate to about 6e-8 near 1, can no longer resolve the
// peak's width. 0.045 (alpha^2 = 4.1e-6) is Filament's clamp for float
// shaders ("Physically Based Rendering in Filament", "Roughness remapping
// and clamping").
constexpr float kMinRoughness = 0.045f;

// The smallest n.v used: a view along the surface would make V's and the
// compensation's terms divide by zero (Filament clamps n.v the same way).
constexpr float kMinNdotV = 1e-4f;

// The index of refraction of the glTF core material (Appendix B.2.2 and
// KHR_materials_ior's default): F0 = 0.04.
constexpr float kDefaultIor = 1.5f;

// alpha = roughness^2, the mapping to GGX's width that Burley 2012 made
// perceptually linear and glTF adopts (Appendix B.2.3). The roughness is
// first clamped to [kMinRoughness, 1].
template <typename T>
[[gnu::always_inline]] inline T alpha_from_roughness(T roughness) {
    using lanes::select, lanes::splat;
    const T low = splat<T>(kMinRoughness), one = splat<T>(1.0f);
    const T r = select(roughness < low, low, select(one < roughness, one, roughness));
    return r * r;
}

// The half vector h = normalise(l + v) as the BRDF uses it. All three
// are symmetric in l and v to the bit (l + v = v + l, and v.h = l.h is
// taken as |l + v| / 2, which holds for unit l and v), so the BRDF is
// exactly reciprocal.
template <typename T>
struct HalfVector {
    T n_dot_h = lanes::splat<T>(0.0f);
    // |n x h|^2 = 1 - (n.h)^2, from the cross product: as 1 - (n.h)^2 in
    // float it would carry an error of about 1e-7, more than alpha^2 of a
    // smooth surface (6e-6 at roughness 0.05), and bias GGX's peak (Filament
    // computes D from n x h for the same reason).
    T n_cross_h_squared = lanes::splat<T>(1.0f);
    T v_dot_h = lanes::splat<T>(0.0f);
};

// Zero n.h and v.h (and |n x h|^2 one) where v = -l (no half vector).
template <typename T>
[[gnu::always_inline]] inline HalfVector<T> half_vector(const lanes::Vec3<T>& n,
                                                        const lanes::Vec3<T>& v,
                                                        const lanes::Vec3<T>& l) {
    using lanes::select, lanes::splat;
    const lanes::Vec3<T> s = {l[0] + v[0], l[1] + v[1], l[2] + v[2]};
    const T s2 = lanes::dot(s, s);
    const lanes::Mask<T> ok = s2 > splat<T>(1e-12f);
    const T safe = select(ok, s2, splat<T>(1.0f));
    const T length = lanes::square_root(safe);
    const lanes::Vec3<T> n_cross_s = {n[1] * s[2] - n[2] * s[1], n[2] * s[0] - n[0] * s[2],
                                      n[0] * s[1] - n[1] * s[0]};
    return {select(ok, lanes::dot(n, s) / length, splat<T>(0.0f)),
            select(ok, lanes::dot(n_cross_s, n_cross_s) / safe, splat<T>(1.0f)),
            select(ok, 0.5f * length, splat<T>(0.0f))};
}
inline HalfVector<float> half_vector(const glm::vec3& n, const glm::vec3& v, const glm::vec3& l) {
    return half_vector<float>({n.x, n.y, n.z}, {v.x, v.y, v.z}, {l.x, l.y, l.z});
}

// The GGX / Trowbridge-Reitz normal distribution (Walter et al. 2007, eq.
// 33; Trowbridge & Reitz 1975), as glTF Appendix B.3.2 writes it:
//   D(h) = alpha^2 chi+(n.h) / (pi ((n.h)^2 (alpha^2 - 1) + 1)^2)
// in 1/sr, normalised so that the integral of D(h)(n.h) over the
// hemisphere is 1. The denominator's (n.h)^2 (alpha^2 - 1) + 1 is computed
// as (n.h)^2 alpha^2 + |n x h|^2 (HalfVector says why).
template <typename T>
[[gnu::always_inline]] inline T ggx_distribution(T n_dot_h, T n_cross_h_squared, T alpha) {
    const T a2 = alpha * alpha;
    const T d = n_dot_h * n_dot_h * a2 + n_cross_h_squared;
    return lanes::select(n_dot_h > lanes::splat<T>(0.0f), a2 / (kPi * d * d),
                         lanes::splat<T>(0.0f));
}

// sqrt((n.x)^2 (1 - alpha^2) + alpha^2): one side's root of the
// height-correlated Smith term below, computed once for the view.
template <typename T>
[[gnu::always_inline]] inline T smith_root(T n_dot_x, T alpha) {
    const T a2 = alpha * alpha;
    return lanes::square_root(n_dot_x * n_dot_x * (1.0f - a2) + a2);
}

// The height-correlated Smith masking-shadowing function for GGX (Heitz
// 2014, "Understanding the Masking-Shadowing Function in Microfacet-Based
// BRDFs"), already divided by the microfacet denominator 4 |n.l| |n.v|
// (glTF Appendix B.3.2's visibility nu; Filament's V):
//   V = 1 / (2 (n.v sqrt(alpha^2 + (1 - alpha^2)(n.l)^2)
//             + n.l sqrt(alpha^2 + (1 - alpha^2)(n.v)^2)))
// for n.l > 0 and n.v > 0 (the caller checks). In double too, for the DFG
// table's integration.
template <typename Real>
inline Real smith_ggx_correlated_visibility(Real n_dot_l, Real n_dot_v, Real alpha) {
    const Real a2 = alpha * alpha;
    const Real view_root = std::sqrt(n_dot_v * n_dot_v * (Real(1) - a2) + a2);
    const Real light_root = std::sqrt(n_dot_l * n_dot_l * (Real(1) - a2) + a2);
    return Real(0.5) / (n_dot_l * view_root + n_dot_v * light_root);
}

// The single-scattering specular microfacet BRDF without its Fresnel
// factor, glTF Appendix B.3.2's specular_brdf(alpha) = V * D, in 1/sr,
// with the view's Smith root given (smith_root(n.v, alpha)).
template <typename T>
[[gnu::always_inline]] inline T specular_brdf(const HalfVector<T>& h, T n_dot_l, T n_dot_v,
                                              T view_root, T alpha) {
    const T distribution = ggx_distribution(h.n_dot_h, h.n_cross_h_squared, alpha);
    const T light_root = smith_root(n_dot_l, alpha);
    return distribution * (0.5f / (n_dot_l * view_root + n_dot_v * light_root));
}
inline float specular_brdf(const HalfVector<float>& h, float n_dot_l, float n_dot_v, float alpha) {
    return specular_brdf(h, n_dot_l, n_dot_v, smith_root(n_dot_v, alpha), alpha);
}

// The directional albedo of the specular lobe, split as Karis 2013 ("Real
// Shading in Unreal Engine 4", the split sum) does: for Schlick's F with
// F90 = 1,
//   E(f0) = integral of specular_brdf * F * (n.l) over l = f0 * scale + bias
// with scale = integral of D V (1 - (1 - v.h)^5) (n.l) and
// bias = integral of D V (1 - v.h)^5 (n.l). scale + bias is the albedo of
// the lobe with F = 1.
struct DfgTerms {
    float scale = 0.0f;
    float bias = 0.0f;
    float albedo() const { return scale + bias; }
};

// DfgTerms on a kSize x kSize grid of (n.v, roughness), bilinearly
// interpolated. Grid node (i, j) is at n.v = i / (kSize - 1) (at least
// kMinNdotV) and perceptual roughness kMinRoughness + (1 - kMinRoughness) *
// j / (kSize - 1), so both ends of both ranges are nodes. Environment
// lighting needs scale and bias; the energy compensation the albedo.
struct DfgTable {
    static constexpr int kSize = 32;
    // Hammersley points per node (a power of two: the radical inverse then
    // stratifies them evenly).
    static constexpr int kSamples = 1024;
    std::array<DfgTerms, kSize * kSize> terms;  // terms[j * kSize + i]

    // The terms at any n.v and perceptual roughness, each clamped to the
    // table's range.
    DfgTerms lookup(float n_dot_v, float roughness) const;
    // The same for eight points at once, to the bit (the scalar form is its
    // lane 0). A NaN reads the table's low end, never beyond it.
    struct Lanes {
        simd::vf scale, bias;
    };
    Lanes lookup(simd::vf n_dot_v, simd::vf roughness) const;
};

// Computes the table by quasi-Monte Carlo integration: kSamples Hammersley
// points (Hammersley 1960; the radical inverse in base 2) importance-sample
// GGX's D(h)(n.h) at every node, as Karis 2013 does, with every sum in
// double. Fixed points, one thread, IEEE-exact operations only: the same
// bits on every run and machine. About 1 M samples: some 40 ms.
DfgTable compute_dfg_table();

// The table, computed on first use and then shared (a function-local
// static const: thread-safe, never modified).
const DfgTable& dfg_table();

// --- KHR_materials_sheen: the lobe of cloth's fibres ---

// The "Charlie" distribution of Conty Estevez & Kulla 2017 ("Production
// Friendly Microfacet Sheen BRDF"), as KHR_materials_sheen gives it:
//   D(h) = (2 + 1/alpha) sin(theta_h)^(1/alpha) / (2 pi)
// with alpha = sheen roughness^2 and sin^2 theta_h = |n x h|^2
// (HalfVector), so sin^(1/alpha) = (|n x h|^2)^(1/(2 alpha)). Most of its
// mass lies where h is along the surface: light grazing the fibres.
template <typename T>
[[gnu::always_inline]] inline T charlie_distribution(T n_cross_h_squared, T alpha) {
    const T inverse = 1.0f / alpha;
    return (2.0f + inverse) *
           lanes::power_unit(lanes::min_of(n_cross_h_squared, lanes::splat<T>(1.0f)),
                             0.5f * inverse) *
           (0.5f / kPi);
}

// The same paper's fit of the sheen's masking: l(x) = a / (1 + b x^c) +
// d x + e, its five coefficients interpolated between their values at
// alpha = 1 and alpha = 0 by (1 - alpha)^2, then
//   Lambda(cos) = exp(l(cos))                 for cos < 0.5
//               = exp(2 l(0.5) - l(1 - cos))  otherwise.
template <typename T>
struct SheenMasking {
    T a, b, c, d, e;
    T l_half;  // l(0.5)
};

template <typename T>
[[gnu::always_inline]] inline T sheen_l(const SheenMasking<T>& m, T x) {
    return m.a / (1.0f + m.b * lanes::power_unit(x, m.c)) + m.d * x + m.e;
}

template <typename T>
[[gnu::always_inline]] inline SheenMasking<T> sheen_masking(T alpha) {
    const T t = (1.0f - alpha) * (1.0f - alpha);
    const auto mix = [&](float at_rough, float at_smooth) {
        return at_rough + (at_smooth - at_rough) * t;
    };
    SheenMasking<T> m = {mix(21.5473f, 25.3245f),   mix(3.82987f, 3.32435f),
                         mix(0.19823f, 0.16801f),   mix(-1.97760f, -1.27393f),
                         mix(-4.32054f, -4.85967f), lanes::splat<T>(0.0f)};
    m.l_half = sheen_l(m, lanes::splat<T>(0.5f));
    return m;
}

// Lambda at a cosine in (0, 1]. exp(y) is 2^(y log2 e); y stays below 21.
template <typename T>
[[gnu::always_inline]] inline T sheen_lambda(const SheenMasking<T>& m, T cosine) {
    const lanes::Mask<T> low = cosine < lanes::splat<T>(0.5f);
    const T l = sheen_l(m, lanes::select(low, cosine, 1.0f - cosine));
    const T y = lanes::select(low, l, 2.0f * m.l_half - l);
    return lanes::exp2(y * 1.44269504f);
}

// The sheen lobe with a white colour, times n.l, for n.l > 0 (the caller
// checks): D V (n.l) with the paper's visibility
//   V = 1 / ((1 + Lambda(n.v) + Lambda(n.l)) 4 (n.v) (n.l))
// so n.l cancels. `lambda_v` is Lambda(n.v), worked out once.
template <typename T>
[[gnu::always_inline]] inline T sheen_brdf_cosine(T n_cross_h_squared, T n_dot_l, T n_dot_v,
                                                  T lambda_v, T alpha,
                                                  const SheenMasking<T>& masking) {
    const T lambda_l = sheen_lambda(masking, n_dot_l);
    return charlie_distribution(n_cross_h_squared, alpha) /
           ((1.0f + lambda_v + lambda_l) * (4.0f * n_dot_v));
}

// The sheen lobe's directional albedo E_s with a white colour (the
// integral of sheen_brdf_cosine over the light's hemisphere), on
// DfgTable's grid of (n.v, roughness), the roughness read as the sheen's:
// KHR_materials_sheen's E(x) of its albedo scaling. A table of its own, so
// that scenes without a sheen do not compute it.
struct SheenTable {
    std::array<float, DfgTable::kSize * DfgTable::kSize> albedo;  // albedo[j * kSize + i]

    // Bilinear, clamped as DfgTable::lookup; the scalar form is lane 0.
    simd::vf lookup(simd::vf n_dot_v, simd::vf sheen_roughness) const;
    float lookup(float n_dot_v, float sheen_roughness) const {
        return lookup(simd::splat(n_dot_v), simd::splat(sheen_roughness))[0];
    }
};

// Each node a midpoint sum over a grid of light directions (n.l and the
// azimuth), the lobe evaluated by the eight-lane code that renders:
// IEEE-exact operations only, the same bits on every run and machine.
SheenTable compute_sheen_table();

// The table, computed on first use (the first sheen a frame shades) and
// then shared, as dfg_table().
const SheenTable& sheen_table();

// Whether the specular lobes get the energy compensation below. `ignored`
// is the specification's single-scattering BRDF exactly.
enum class MultipleScattering { ignored, compensated };

// A clear coat is a dielectric of ior 1.5 (KHR_materials_clearcoat).
constexpr float kCoatF0 = 0.04f;

// The `pbr` model's inputs at a point, textures applied.
template <typename T>
struct SurfaceTerms {
    lanes::Vec3<T> base;  // linear RGB: a dielectric's albedo, a metal's F0
    T metallic, roughness;
    T occlusion;  // of indirect light: 1 none, 0 all
    // The dielectric's reflectance at normal incidence (from the ior, times
    // KHR_materials_specular's colour and weight) and at grazing (the weight).
    lanes::Vec3<T> f0;
    T f90;
    T coat, coat_roughness;  // KHR_materials_clearcoat's factor and roughness
    // The coat's normal: the surface's before its normal map (the coat is
    // smooth lacquer over the relief), on the viewer's side, any length.
    lanes::Vec3<T> coat_normal;
    // KHR_materials_sheen's colour and roughness: no sheen where the colour is black.
    lanes::Vec3<T> sheen_color;
    T sheen_roughness;
    // KHR_materials_iridescence: the thin film's strength (0: none), index
    // of refraction and thickness in nm.
    T iridescence, iridescence_ior, iridescence_thickness;
    // KHR_materials_anisotropy: the strength (0: none) and the direction
    // along which the lobe is rougher, in the tangent plane (any length;
    // made perpendicular to the shading normal here).
    T anisotropy;
    lanes::Vec3<T> anisotropy_direction;
    // KHR_materials_diffuse_transmission: the share of the dielectric's
    // diffuse light that passes through (0: none) and its colour.
    T diffuse_transmission;
    lanes::Vec3<T> diffuse_transmission_color;
    // KHR_materials_transmission, _volume and _dispersion: the share of the
    // dielectric's diffuse light that refraction replaces (0: none), the
    // index of refraction, the volume's thickness in world units (0: a
    // thin wall), its Beer-Lambert tint (light keeps attenuation_color
    // after attenuation_distance) and the dispersion (20 / Abbe number).
    T transmission, ior, thickness;
    lanes::Vec3<T> attenuation_color;
    T attenuation_distance, dispersion;
};

// Each lobe's Fresnel term, or its f0: the dielectric's and the metal's.
template <typename T>
struct LobeFresnel {
    lanes::Vec3<T> dielectric, metal;
};

// Everything at a point that does not depend on the light: worked out once,
// then used for every light and the environment.
template <typename T>
struct PbrPoint {
    lanes::Vec3<T> n, v, coat_n;  // unit
    T n_dot_v, coat_n_dot_v;      // at least kMinNdotV (a shading normal may face away)
    lanes::Vec3<T> base;
    T metallic, roughness, alpha, occlusion;  // clamped to [0, 1]; alpha from roughness
    lanes::Vec3<T> f0;
    T f90;
    T coat, coat_roughness, coat_alpha;
    bool any_coat;  // a lane has a coat: the coat's terms are worked out
    T dfg_scale, dfg_bias, coat_dfg_scale, coat_dfg_bias;  // DfgTable's terms at n.v (0: no coat)
    // The multiplier that restores the energy a single-scattering lobe of
    // directional albedo E loses to multiple scattering between microfacets:
    //   1 + f0 (1/E - 1)
    // (Turquin 2019, "Practical multiple scattering compensation for
    // microfacet models"; the same scaling of the split sum by Fdez-Aguera
    // 2019, as Filament applies it, "Energy loss in specular reflectance",
    // 4.7.2; an approximation of Kulla & Conty 2017's extra lobe). A white
    // metal (f0 = 1) then reflects everything: E * (1/E) = 1.
    lanes::Vec3<T> metal_compensation, dielectric_compensation;
    // smith_root(n.v, alpha) of each lobe.
    T view_root, coat_view_root;
    // The sheen (worked out only where a lane has one: any_sheen): its
    // colour, roughness and alpha, Lambda(n.v), its albedo E(n.v) with a
    // white colour, and what it leaves the layers below towards the view,
    // 1 - max(colour) E(n.v).
    bool any_sheen;
    lanes::Vec3<T> sheen_color;
    T sheen_max, sheen_roughness, sheen_alpha, sheen_lambda_v, sheen_albedo_v, sheen_keeps_v;
    SheenMasking<T> sheen_masking;
    const SheenTable* sheen_table;  // for the sheen's albedo towards each light (any_sheen)
    // The thin film (any_iridescence): strength, index and thickness.
    bool any_iridescence;
    T iridescence, iridescence_ior, iridescence_thickness;
    // The split sum's f0 of each lobe: the surface's, moved by a thin film
    // towards the film's reflectance at n.v (the environment reads it for
    // every light from every direction, so it is worked out here, once).
    LobeFresnel<T> environment_f0;
    // The anisotropy (any_anisotropy): its strength (0 where the lane has
    // none), its unit tangent t (rougher) and bitangent b = n x t, alpha
    // along t, and the view's root of the anisotropic Smith term.
    bool any_anisotropy;
    T anisotropy, anisotropy_alpha_t, anisotropy_view_root;
    lanes::Vec3<T> anisotropy_t, anisotropy_b;
    // The normal the environment's specular lobe reflects the view about:
    // n, or the anisotropy's bent normal.
    lanes::Vec3<T> reflection_normal;
    // The dielectric's diffuse albedo, the base colour less what a diffuse
    // transmission (any_diffuse_transmission) passes through: base (1 - t).
    lanes::Vec3<T> diffuse_albedo;
    bool any_diffuse_transmission;
    T diffuse_transmission;
    lanes::Vec3<T> diffuse_transmission_color;
    // The transmission (any_transmission): its share t (0 where the lane
    // has none; the diffuse terms above keep 1 - t), what the volume leaves
    // of light crossing its thickness (Beer-Lambert), and the refraction's
    // blur and lobe: the surface's perceptual roughness and alpha, each
    // scaled by clamp(2 ior - 2, 0, 1), and the view's Smith root.
    bool any_transmission;
    T transmission;
    lanes::Vec3<T> transmittance;
    T transmission_roughness, transmission_alpha, transmission_view_root;
};

}  // namespace facet::pbr
