#pragma once
// The glTF 2.0 metallic-roughness BRDF, as the glTF 2.0 specification's
// Appendix B ("BRDF Implementation") gives it, with energy compensation for
// the light that a single-scattering microfacet model loses on rough
// surfaces. docs/pbr.md gives every formula, its symbols and its source.
//
//   material   = (1 - metallic) * dielectric + metallic * metal
//   metal      = F(f0 = base colour) * specular          (conductor_fresnel)
//   dielectric = (1 - F(f0 from ior)) * base colour / pi
//                + F(f0 from ior) * specular             (fresnel_mix)
//   specular   = D * V, with alpha = roughness^2 (GGX D, height-correlated
//                Smith V, Schlick F with F90 = 1)
//
// Each specular lobe can be scaled by 1 + f0 * (1/E - 1), E the lobe's
// directional albedo from a table computed once (compute_dfg_table), so
// that a white rough metal reflects all the light it receives. A sheen
// (KHR_materials_sheen) lies over that, and a clear coat
// (KHR_materials_clearcoat) over everything.
//
// Per shading point, once:
//   const PbrPoint<T> p = prepare_point(n, v, terms, MultipleScattering::compensated, table);
// per light (l towards the light, radiance arriving at the point):
//   colour += radiance * brdf_cosine(p, l);
// and for light from every direction, environment_response.
//
// n, v and l are unit vectors; v points towards the viewer. Every term is a
// template on the number type T (shade/lanes.hpp): float for one point,
// simd::vf for the renderer's eight, so a point's result is lane 0 of the
// eight-point one, to the bit, and the formulas documented here are the
// ones that render. They take dot products (and one cross product) and
// select where a branch would diverge. Only IEEE-exact operations (add,
// mul, div, sqrt, compares) are used, so results have the same bits on
// every x86-64, like core/simd_math.hpp. No global mutable state: the table
// is an object the caller owns, or dfg_table()'s function-local static.
#include <algorithm>
#include <array>
#include <cmath>

#include <glm/vec3.hpp>

#include "core/simd_math.hpp"

#include "shade/fresnel.hpp"
#include "shade/lanes.hpp"
#include "shade/thin_film.hpp"

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
};

// KHR_materials_iridescence: each lobe's Fresnel moves towards the thin
// film's over the lobe's own reflectance (thin_film_fresnel), by the
// film's strength k: F = F_base + k (F_film - F_base), at the cosine
// `cosine` (v.h for a light, n.v for the environment). Out of line, as
// with_sheen: few points have a film, and inlined its code crowded the
// registers of the common path; values in and out, so that the common
// path's terms stay in registers.

template <typename T>
[[gnu::noinline]] LobeFresnel<T> with_thin_film(const PbrPoint<T>& p, T cosine, LobeFresnel<T> f) {
    const lanes::Vec3<T> film_d =
        thin_film_fresnel(cosine, p.iridescence_ior, p.iridescence_thickness, p.f0);
    const lanes::Vec3<T> film_m =
        thin_film_fresnel(cosine, p.iridescence_ior, p.iridescence_thickness, p.base);
    for (int c = 0; c < 3; ++c) {
        f.dielectric[c] = f.dielectric[c] + p.iridescence * (film_d[c] - f.dielectric[c]);
        f.metal[c] = f.metal[c] + p.iridescence * (film_m[c] - f.metal[c]);
    }
    return f;
}

// The sheen's part of prepare_point: whether a lane has one, inline; its
// terms out of line, as the lobe's own code (few points have a sheen).
template <typename T>
[[gnu::noinline]] void prepare_sheen_terms(const SurfaceTerms<T>& s, PbrPoint<T>& p);

template <typename T>
[[gnu::always_inline]] inline void prepare_sheen(const SurfaceTerms<T>& s, PbrPoint<T>& p) {
    using lanes::clamp01, lanes::max_of, lanes::splat;
    for (int c = 0; c < 3; ++c) p.sheen_color[c] = clamp01(s.sheen_color[c]);
    p.sheen_max = max_of(p.sheen_color[0], max_of(p.sheen_color[1], p.sheen_color[2]));
    p.any_sheen = lanes::any(p.sheen_max > splat<T>(0.0f));
    p.sheen_keeps_v = splat<T>(1.0f);
    if (p.any_sheen) prepare_sheen_terms(s, p);
}

template <typename T>
[[gnu::noinline]] void prepare_sheen_terms(const SurfaceTerms<T>& s, PbrPoint<T>& p) {
    using lanes::clamp01;
    p.sheen_roughness = clamp01(s.sheen_roughness);
    p.sheen_alpha = alpha_from_roughness(p.sheen_roughness);
    p.sheen_masking = sheen_masking(p.sheen_alpha);
    p.sheen_lambda_v = sheen_lambda(p.sheen_masking, p.n_dot_v);
    p.sheen_table = &sheen_table();
    p.sheen_albedo_v = p.sheen_table->lookup(p.n_dot_v, p.sheen_roughness);
    p.sheen_keeps_v = 1.0f - p.sheen_max * p.sheen_albedo_v;
}

// --- KHR_materials_anisotropy: the lobe of brushed metal ---

// The anisotropy's part of prepare_point, out of line as the sheen's. Its
// frame: t the direction made perpendicular to n, b = n x t (a direction
// along n leaves the lane isotropic). Its widths (the extension's
// specification): alpha_t = mix(alpha, 1, strength^2) along t, alpha_b =
// alpha along b. For the environment, the bent normal of the
// specification's sample implementation: the normal of the plane through
// b that faces v, n_a = (b x v) x b, mixed with n by
// (1 - strength (1 - roughness))^4, so that a strong anisotropy on a
// smooth surface reflects the environment stretched along b's plane.
template <typename T>
[[gnu::noinline]] void prepare_anisotropy_terms(const SurfaceTerms<T>& s, PbrPoint<T>& p) {
    using lanes::select, lanes::splat;
    const lanes::Vec3<T>& n = p.n;
    const lanes::Vec3<T>& d = s.anisotropy_direction;
    const T along = lanes::dot(n, d);
    const lanes::Vec3<T> in_plane = {d[0] - n[0] * along, d[1] - n[1] * along, d[2] - n[2] * along};
    const lanes::Mask<T> framed = lanes::dot(in_plane, in_plane) > splat<T>(1e-12f);
    const lanes::Vec3<T> zero = {splat<T>(0.0f), splat<T>(0.0f), splat<T>(0.0f)};
    const T strength = select(framed, lanes::clamp01(s.anisotropy), splat<T>(0.0f));
    const lanes::Mask<T> anisotropic = strength > splat<T>(0.0f);
    p.anisotropy = strength;
    p.anisotropy_t = lanes::normalise_or(in_plane, zero);
    p.anisotropy_b = lanes::cross(n, p.anisotropy_t);
    p.anisotropy_alpha_t = p.alpha + (1.0f - p.alpha) * (strength * strength);
    const T tv = p.anisotropy_alpha_t * lanes::dot(p.anisotropy_t, p.v);
    const T bv = p.alpha * lanes::dot(p.anisotropy_b, p.v);
    p.anisotropy_view_root = lanes::square_root(tv * tv + bv * bv + p.n_dot_v * p.n_dot_v);
    const lanes::Vec3<T>& b = p.anisotropy_b;
    const lanes::Vec3<T> facing = lanes::cross(lanes::cross(b, p.v), b);
    const T bend = 1.0f - strength * (1.0f - p.roughness);
    const T keep = (bend * bend) * (bend * bend);
    const lanes::Vec3<T> bent = lanes::normalise_or<T>(
        {facing[0] + keep * (n[0] - facing[0]), facing[1] + keep * (n[1] - facing[1]),
         facing[2] + keep * (n[2] - facing[2])},
        n);
    for (int c = 0; c < 3; ++c) p.reflection_normal[c] = select(anisotropic, bent[c], n[c]);
}

// The anisotropic GGX lobe without its Fresnel factor (the extension's
// specification; Burley 2012, Appendix B.2; Heitz 2014 for the
// height-correlated Smith term), for unit l with n.l > 0:
//   D = 1 / (pi a_t a_b ((t.h / a_t)^2 + (b.h / a_b)^2 + (n.h)^2)^2)
//   V = 1 / (2 (n.l |(a_t t.v, a_b b.v, n.v)| + n.v |(a_t t.l, a_b b.l, n.l)|))
// D written as the specification does, a^2 w^2 w^2 / pi with a^2 = a_t a_b
// and w^2 = a^2 / |(a_b t.h, a_t b.h, a^2 n.h)|^2. Lanes without an
// anisotropy keep `isotropic`, to the bit.
template <typename T>
[[gnu::noinline]] T with_anisotropy(const PbrPoint<T>& p, const lanes::Vec3<T>& l, T n_dot_l,
                                    T isotropic) {
    using lanes::select, lanes::splat;
    const lanes::Vec3<T> sum = {l[0] + p.v[0], l[1] + p.v[1], l[2] + p.v[2]};
    const lanes::Vec3<T> h = lanes::normalise_or(sum, p.n);
    const T at = p.anisotropy_alpha_t, ab = p.alpha;
    const T n_dot_h = lanes::dot(p.n, h);
    const T a2 = at * ab;
    const T ft = ab * lanes::dot(p.anisotropy_t, h), fb = at * lanes::dot(p.anisotropy_b, h),
            fn = a2 * n_dot_h;
    const T w2 = a2 / (ft * ft + fb * fb + fn * fn);
    const T distribution =
        select(n_dot_h > splat<T>(0.0f), a2 * w2 * w2 * (1.0f / kPi), splat<T>(0.0f));
    const T tl = at * lanes::dot(p.anisotropy_t, l), bl = ab * lanes::dot(p.anisotropy_b, l);
    const T light_root = lanes::square_root(tl * tl + bl * bl + n_dot_l * n_dot_l);
    const T visibility = 0.5f / (n_dot_l * p.anisotropy_view_root + p.n_dot_v * light_root);
    return select(p.anisotropy > splat<T>(0.0f), distribution * visibility, isotropic);
}

template <typename T>
[[gnu::always_inline]] inline void prepare_anisotropy(const SurfaceTerms<T>& s, PbrPoint<T>& p) {
    p.reflection_normal = p.n;
    p.any_anisotropy = lanes::any(s.anisotropy > lanes::splat<T>(0.0f));
    if (p.any_anisotropy) prepare_anisotropy_terms(s, p);
}

// --- KHR_materials_diffuse_transmission: light through lampshades and leaves ---

// Its part of prepare_point, out of line as the other layers'.
template <typename T>
[[gnu::noinline]] void prepare_diffuse_transmission_terms(const SurfaceTerms<T>& s,
                                                          PbrPoint<T>& p) {
    const lanes::Mask<T> through = p.diffuse_transmission > lanes::splat<T>(0.0f);
    for (int c = 0; c < 3; ++c) {
        p.diffuse_transmission_color[c] = lanes::clamp01(s.diffuse_transmission_color[c]);
        p.diffuse_albedo[c] =
            lanes::select(through, p.base[c] * (1.0f - p.diffuse_transmission), p.base[c]);
    }
}

template <typename T>
[[gnu::always_inline]] inline void prepare_diffuse_transmission(const SurfaceTerms<T>& s,
                                                                PbrPoint<T>& p) {
    p.diffuse_albedo = p.base;
    p.diffuse_transmission = lanes::clamp01(s.diffuse_transmission);
    p.any_diffuse_transmission = lanes::any(p.diffuse_transmission > lanes::splat<T>(0.0f));
    if (p.any_diffuse_transmission) prepare_diffuse_transmission_terms(s, p);
}

// The point for unit n and v and the surface's terms.
template <typename T>
PbrPoint<T> prepare_point(const lanes::Vec3<T>& n, const lanes::Vec3<T>& v,
                          const SurfaceTerms<T>& s, MultipleScattering multiple_scattering,
                          const DfgTable& table) {
    using lanes::clamp01, lanes::select, lanes::splat;
    PbrPoint<T> p;
    p.n = n;
    p.v = v;
    p.n_dot_v = lanes::max_of(lanes::dot(n, v), splat<T>(kMinNdotV));
    p.base = s.base;
    p.metallic = clamp01(s.metallic);
    p.roughness = clamp01(s.roughness);
    p.alpha = alpha_from_roughness(p.roughness);
    p.occlusion = clamp01(s.occlusion);
    p.f0 = s.f0;
    p.f90 = s.f90;
    p.coat = clamp01(s.coat);
    p.coat_roughness = clamp01(s.coat_roughness);
    p.coat_alpha = alpha_from_roughness(p.coat_roughness);
    const auto dfg = table.lookup(p.n_dot_v, p.roughness);
    p.dfg_scale = dfg.scale, p.dfg_bias = dfg.bias;
    const lanes::Mask<T> coated = p.coat > splat<T>(0.0f);
    p.any_coat = lanes::any(coated);
    p.coat_dfg_scale = p.coat_dfg_bias = splat<T>(0.0f);
    p.coat_n = p.n;
    p.coat_n_dot_v = p.n_dot_v;
    if (p.any_coat) {
        p.coat_n = lanes::normalise_or(s.coat_normal, p.n);
        p.coat_n_dot_v = lanes::max_of(lanes::dot(p.coat_n, v), splat<T>(kMinNdotV));
        const auto terms = table.lookup(p.coat_n_dot_v, p.coat_roughness);
        p.coat_dfg_scale = select(coated, T(terms.scale), splat<T>(0.0f));
        p.coat_dfg_bias = select(coated, T(terms.bias), splat<T>(0.0f));
    }
    const bool compensated = multiple_scattering == MultipleScattering::compensated;
    const T k = 1.0f / (p.dfg_scale + p.dfg_bias) - 1.0f;
    for (int c = 0; c < 3; ++c) {
        p.metal_compensation[c] = compensated ? 1.0f + p.base[c] * k : splat<T>(1.0f);
        p.dielectric_compensation[c] = compensated ? 1.0f + p.f0[c] * k : splat<T>(1.0f);
    }
    p.view_root = smith_root(p.n_dot_v, p.alpha);
    p.coat_view_root = p.any_coat ? smith_root(p.coat_n_dot_v, p.coat_alpha) : p.view_root;
    prepare_sheen(s, p);
    prepare_anisotropy(s, p);
    prepare_diffuse_transmission(s, p);
    p.iridescence = clamp01(s.iridescence);
    p.any_iridescence = lanes::any(p.iridescence > splat<T>(0.0f));
    p.iridescence_ior = s.iridescence_ior;
    p.iridescence_thickness = lanes::max_of(s.iridescence_thickness, splat<T>(0.0f));
    p.environment_f0 = {p.f0, p.base};
    if (p.any_iridescence) p.environment_f0 = with_thin_film(p, p.n_dot_v, p.environment_f0);
    return p;
}

// The coat's share of what reaches the base: 1 - coat * E_coat (its
// directional albedo), the same for lights and the environment, so a
// white coated surface under a white environment still reflects 1. Exactly
// 1 without a coat (its terms are zero there).
template <typename T>
[[gnu::always_inline]] inline T coat_transmission(const PbrPoint<T>& p) {
    return 1.0f - p.coat * (kCoatF0 * p.coat_dfg_scale + p.coat_dfg_bias);
}

// The sheen over the base, for one light (KHR_materials_sheen, "albedo
// scaling"): the base keeps 1 - max(colour) max(E(n.v), E(n.l)) of its
// light, and the sheen lobe, times its colour, adds to it. Lanes without
// a sheen keep their bits.
template <typename T>
[[gnu::noinline]] lanes::Vec3<T> with_sheen(const PbrPoint<T>& p, const HalfVector<T>& h, T n_dot_l,
                                            lanes::Mask<T> lit, lanes::Vec3<T> result) {
    using lanes::select, lanes::splat;
    const lanes::Mask<T> sheened = lit & (p.sheen_max > splat<T>(0.0f));
    const T cosine = lanes::max_of(n_dot_l, splat<T>(kMinNdotV));
    const T keeps = lanes::min_of(
        p.sheen_keeps_v, 1.0f - p.sheen_max * p.sheen_table->lookup(cosine, p.sheen_roughness));
    const T lobe = sheen_brdf_cosine(h.n_cross_h_squared, cosine, p.n_dot_v, p.sheen_lambda_v,
                                     p.sheen_alpha, p.sheen_masking);
    for (int c = 0; c < 3; ++c)
        result[c] = select(sheened, result[c] * keeps + p.sheen_color[c] * lobe, result[c]);
    return result;
}

// The sheen over the base's response to an environment: the base keeps
// 1 - max(colour) E(n.v), and the sheen adds colour E(n.v) times the
// diffuse radiance (its lobe is broad).
template <typename T>
[[gnu::noinline]] lanes::Vec3<T> with_sheen_environment(const PbrPoint<T>& p,
                                                        const lanes::Vec3<T>& diffuse,
                                                        lanes::Vec3<T> result) {
    const lanes::Mask<T> sheened = p.sheen_max > lanes::splat<T>(0.0f);
    for (int c = 0; c < 3; ++c)
        result[c] = lanes::select(
            sheened, result[c] * p.sheen_keeps_v + p.sheen_color[c] * p.sheen_albedo_v * diffuse[c],
            result[c]);
    return result;
}

// A light behind the surface (n.l < 0) through a diffuse transmission
// (KHR_materials_diffuse_transmission): the dielectric's diffuse share t
// passes as a Lambertian BTDF of its colour c_t, weighted as the reflected
// diffuse is by what the specular layer leaves, with F at the light
// mirrored to the viewer's side, l' = l - 2 (n.l) n:
//   (1 - metallic) (1 - F(v.h')) t c_t / pi |n.l|
// Lanes without one, or lit from the front, keep their bits.
template <typename T>
[[gnu::noinline]] lanes::Vec3<T> with_diffuse_transmission(const PbrPoint<T>& p,
                                                           const lanes::Vec3<T>& l, T n_dot_l,
                                                           lanes::Vec3<T> result) {
    using lanes::select, lanes::splat;
    const T zero = splat<T>(0.0f);
    const lanes::Mask<T> behind = (n_dot_l < zero) & (p.diffuse_transmission > zero);
    if (!lanes::any(behind)) return result;
    const T twice = 2.0f * n_dot_l;
    const lanes::Vec3<T> mirrored = {l[0] - twice * p.n[0], l[1] - twice * p.n[1],
                                     l[2] - twice * p.n[2]};
    const T w = schlick_weight(half_vector(p.n, p.v, mirrored).v_dot_h);
    const T share = (1.0f - p.metallic) * p.diffuse_transmission * (1.0f / kPi) * (zero - n_dot_l);
    for (int c = 0; c < 3; ++c) {
        const T through =
            (1.0f - schlick_fresnel(p.f0[c], w, p.f90)) * share * p.diffuse_transmission_color[c];
        result[c] = select(behind, result[c] + through, result[c]);
    }
    return result;
}

// The same for light from every direction: the diffuse radiance arriving
// from behind, `back` (E(-n)/pi), passes through by t c_t, weighted as the
// reflected diffuse by what the dielectric's lobe leaves.
template <typename T>
[[gnu::noinline]] lanes::Vec3<T> with_diffuse_transmission_environment(const PbrPoint<T>& p,
                                                                       const lanes::Vec3<T>& back,
                                                                       lanes::Vec3<T> result) {
    using lanes::select, lanes::splat;
    const lanes::Mask<T> through = p.diffuse_transmission > splat<T>(0.0f);
    const LobeFresnel<T>& f0 = p.environment_f0;
    for (int c = 0; c < 3; ++c) {
        const T lobe =
            (f0.dielectric[c] * p.dfg_scale + p.f90 * p.dfg_bias) * p.dielectric_compensation[c];
        const T passed = (1.0f - p.metallic) * (1.0f - lanes::min_of(lobe, splat<T>(1.0f))) *
                         p.diffuse_transmission * p.diffuse_transmission_color[c] * back[c];
        result[c] = select(through, result[c] + passed, result[c]);
    }
    return result;
}

// The glTF BRDF times the cosine, f(v, l) (n.l), for one light direction l
// (unit, towards the light), in 1/sr: times the irradiance a light gives on
// a plane facing it it is the radiance reflected towards v. Zero where the
// light is below the surface (n.l <= 0). glTF Appendix B.3.5's sum
//   (1 - metallic) * mix(base/pi, specular, F_dielectric)
//   + metallic * F_metal * specular
// with each specular lobe times its compensation, KHR_materials_specular's
// f0 and f90 for the dielectric, the sheen over them (with_sheen), and the
// coat over all:
//   below * (1 - coat * E_coat) + coat * F_coat * specular_coat.
template <typename T>
lanes::Vec3<T> brdf_cosine(const PbrPoint<T>& p, const lanes::Vec3<T>& l) {
    using lanes::select, lanes::splat;
    const T zero = splat<T>(0.0f);
    const T n_dot_l = lanes::dot(p.n, l);
    const lanes::Mask<T> lit = n_dot_l > zero;
    lanes::Vec3<T> result = {zero, zero, zero};
    if (lanes::any(lit)) {
        const HalfVector<T> h = half_vector(p.n, p.v, l);
        T specular = specular_brdf(h, n_dot_l, p.n_dot_v, p.view_root, p.alpha);
        if (p.any_anisotropy) specular = with_anisotropy(p, l, n_dot_l, specular);
        const T w = schlick_weight(h.v_dot_h);
        LobeFresnel<T> f;
        for (int c = 0; c < 3; ++c) {
            f.dielectric[c] = schlick_fresnel(p.f0[c], w, p.f90);
            f.metal[c] = schlick_fresnel(p.base[c], w);
        }
        if (p.any_iridescence) f = with_thin_film(p, h.v_dot_h, f);
        for (int c = 0; c < 3; ++c) {
            // fresnel_mix: the diffuse base under a specular layer, weighted by F.
            const T fd = f.dielectric[c];
            const T dielectric = (1.0f - fd) * (1.0f / kPi) * p.diffuse_albedo[c] +
                                 fd * specular * p.dielectric_compensation[c];
            // conductor_fresnel: the specular lobe tinted by the metal's F.
            const T metal = f.metal[c] * specular * p.metal_compensation[c];
            const T sum = ((1.0f - p.metallic) * dielectric + p.metallic * metal) * n_dot_l;
            result[c] = select(lit, sum, zero);
        }
        if (p.any_sheen) result = with_sheen(p, h, n_dot_l, lit, result);
    }
    if (p.any_diffuse_transmission) result = with_diffuse_transmission(p, l, n_dot_l, result);
    if (!p.any_coat) return result;
    const T transmission = coat_transmission(p);
    const T coat_n_dot_l = lanes::dot(p.coat_n, l);
    const lanes::Mask<T> coat_lit = (coat_n_dot_l > zero) & (p.coat > zero);
    const HalfVector<T> h = half_vector(p.coat_n, p.v, l);
    const T f = schlick_fresnel(splat<T>(kCoatF0), schlick_weight(h.v_dot_h));
    const T coat = p.coat * f *
                   specular_brdf(h, coat_n_dot_l, p.coat_n_dot_v, p.coat_view_root, p.coat_alpha) *
                   coat_n_dot_l;
    for (int c = 0; c < 3; ++c) {
        result[c] *= transmission;
        result[c] = select(coat_lit, result[c] + coat, result[c]);
    }
    return result;
}

// The split sum for light from every direction: an environment whose
// diffuse radiance E(n)/pi is `diffuse` and whose specular lobes read
// `specular` and `coat_specular` (prefiltered along the reflected view).
// Metal and dielectric lobes are weighted by their directional albedo
// f0 * scale + f90 * bias (Karis 2013) and compensated, the dielectric's
// diffuse by what its lobe leaves (Fdez-Aguera 2019), then the coat over both.
// `back` is the diffuse radiance from behind, for a diffuse transmission.
template <typename T>
lanes::Vec3<T> environment_response(const PbrPoint<T>& p, const lanes::Vec3<T>& diffuse,
                                    const lanes::Vec3<T>& specular,
                                    const lanes::Vec3<T>& coat_specular,
                                    const lanes::Vec3<T>& back) {
    using lanes::select, lanes::splat;
    const T coat_albedo = p.coat * (kCoatF0 * p.coat_dfg_scale + p.coat_dfg_bias);
    const T transmission = coat_transmission(p);
    const lanes::Mask<T> coated = p.coat > splat<T>(0.0f);
    const LobeFresnel<T>& f0 = p.environment_f0;
    lanes::Vec3<T> result;
    for (int c = 0; c < 3; ++c) {
        const T dielectric_lobe =
            (f0.dielectric[c] * p.dfg_scale + p.f90 * p.dfg_bias) * p.dielectric_compensation[c];
        const T metal_lobe = (f0.metal[c] * p.dfg_scale + p.dfg_bias) * p.metal_compensation[c];
        const T dielectric = (1.0f - lanes::min_of(dielectric_lobe, splat<T>(1.0f))) *
                                 p.diffuse_albedo[c] * diffuse[c] +
                             dielectric_lobe * specular[c];
        result[c] = (1.0f - p.metallic) * dielectric + p.metallic * metal_lobe * specular[c];
    }
    if (p.any_sheen) result = with_sheen_environment(p, diffuse, result);
    if (p.any_diffuse_transmission) result = with_diffuse_transmission_environment(p, back, result);
    if (p.any_coat)
        for (int c = 0; c < 3; ++c)
            result[c] = select(coated, result[c] * transmission + coat_albedo * coat_specular[c],
                               result[c]);
    return result;
}

// An environment alike from every side (a uniform one, an ambient light):
// as much diffuse radiance from behind as in front.
template <typename T>
lanes::Vec3<T> environment_response(const PbrPoint<T>& p, const lanes::Vec3<T>& diffuse,
                                    const lanes::Vec3<T>& specular,
                                    const lanes::Vec3<T>& coat_specular) {
    return environment_response(p, diffuse, specular, coat_specular, diffuse);
}

// The glTF metallic-roughness inputs at one point, for one-off use and tests.
struct Material {
    glm::vec3 base_color{1.0f};  // linear RGB: a dielectric's albedo, a metal's F0
    float metallic = 1.0f;       // 0 dielectric .. 1 metal (glTF's default is 1)
    float roughness = 1.0f;      // perceptual roughness 0..1 (glTF's default is 1)
    float ior = kDefaultIor;     // the dielectric's index of refraction
};

// A core glTF material's terms: no coat, f90 1, no occlusion.
SurfaceTerms<float> surface_terms(const Material& material);

// The one-point forms, with unit n, v and l.
inline PbrPoint<float> prepare_shading_point(const glm::vec3& n, const glm::vec3& v,
                                             const Material& material,
                                             MultipleScattering multiple_scattering) {
    return prepare_point<float>({n.x, n.y, n.z}, {v.x, v.y, v.z}, surface_terms(material),
                                multiple_scattering, dfg_table());
}
inline glm::vec3 brdf_cosine(const PbrPoint<float>& p, const glm::vec3& l) {
    const lanes::Vec3<float> f = brdf_cosine<float>(p, {l.x, l.y, l.z});
    return {f[0], f[1], f[2]};
}
inline glm::vec3 brdf_cosine(const glm::vec3& n, const glm::vec3& v, const glm::vec3& l,
                             const Material& material, MultipleScattering multiple_scattering) {
    return brdf_cosine(prepare_shading_point(n, v, material, multiple_scattering), l);
}

}  // namespace facet::pbr
