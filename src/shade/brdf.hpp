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
// that a white rough metal reflects all the light it receives.
//
// Per shading point, once:
//   const ShadingPoint p = prepare_shading_point(n, v, material, MultipleScattering::compensated);
// per light (l towards the light, radiance arriving at the point):
//   colour += radiance * brdf_cosine(p, l);
//
// n, v and l are unit vectors; v points towards the viewer. Scalar code for
// now: the renderer's eight-lane version is meant to overload the same
// names on simd::vf, so the formulas take dot products (and one cross
// product) and avoid branches where a select will do. Only IEEE-exact
// operations (add, mul, div, sqrt, compares) are used, so results have the
// same bits on every x86-64, like core/simd_math.hpp. No global mutable
// state: the table is an object the caller owns, or dfg_table()'s
// function-local static.
#include <algorithm>
#include <array>
#include <cmath>

#include <glm/vec3.hpp>

#include "core/simd_math.hpp"

#include "shade/light_sample.hpp"  // dot3

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

// The glTF metallic-roughness inputs at one point.
struct Material {
    glm::vec3 base_color{1.0f};  // linear RGB: a dielectric's albedo, a metal's F0
    float metallic = 1.0f;       // 0 dielectric .. 1 metal (glTF's default is 1)
    float roughness = 1.0f;      // perceptual roughness 0..1 (glTF's default is 1)
    float ior = kDefaultIor;     // the dielectric's index of refraction
};

// alpha = roughness^2, the mapping to GGX's width that Burley 2012 made
// perceptually linear and glTF adopts (Appendix B.2.3). The roughness is
// first clamped to [kMinRoughness, 1].
inline float alpha_from_roughness(float roughness) {
    const float r = std::clamp(roughness, kMinRoughness, 1.0f);
    return r * r;
}

// Reflectance at normal incidence of a dielectric of index `ior` in air:
// ((ior - 1) / (ior + 1))^2, from Fresnel's equations at normal incidence
// (glTF Appendix B.3.4, fresnel_mix). 1.5 gives 0.04.
inline float f0_from_ior(float ior) {
    const float r = (ior - 1.0f) / (ior + 1.0f);
    return r * r;
}

// Schlick 1994's weight (1 - v.h)^5, the part of F that depends on the
// angle. v.h is clamped to [0, 1].
inline float schlick_weight(float v_dot_h) {
    const float m = 1.0f - std::clamp(v_dot_h, 0.0f, 1.0f);
    const float m2 = m * m;
    return m2 * m2 * m;
}

// Schlick 1994's Fresnel F = F0 + (1 - F0)(1 - v.h)^5 with F90 = 1, as
// glTF Appendix B.3.4 writes it for conductor_fresnel and fresnel_mix.
// `weight` is schlick_weight(v.h), computed once for all channels.
inline float schlick_fresnel(float f0, float weight) {
    return f0 + (1.0f - f0) * weight;
}
inline glm::vec3 schlick_fresnel(const glm::vec3& f0, float weight) {
    return {schlick_fresnel(f0.x, weight), schlick_fresnel(f0.y, weight),
            schlick_fresnel(f0.z, weight)};
}

// The half vector h = normalise(l + v) as the BRDF uses it. All three
// are symmetric in l and v to the bit (l + v = v + l, and v.h = l.h is
// taken as |l + v| / 2, which holds for unit l and v), so the BRDF is
// exactly reciprocal.
struct HalfVector {
    float n_dot_h = 0.0f;
    // |n x h|^2 = 1 - (n.h)^2, from the cross product: as 1 - (n.h)^2 in
    // float it would carry an error of about 1e-7, more than alpha^2 of a
    // smooth surface (6e-6 at roughness 0.05), and bias GGX's peak (Filament
    // computes D from n x h for the same reason).
    float n_cross_h_squared = 1.0f;
    float v_dot_h = 0.0f;
};
// Zero n.h and v.h when v = -l (no half vector).
inline HalfVector half_vector(const glm::vec3& n, const glm::vec3& v, const glm::vec3& l) {
    const glm::vec3 s = l + v;
    const float s2 = dot3(s, s);
    if (!(s2 > 1e-12f)) return {};
    const float length = std::sqrt(s2);
    const glm::vec3 n_cross_s(n.y * s.z - n.z * s.y, n.z * s.x - n.x * s.z, n.x * s.y - n.y * s.x);
    return {dot3(n, s) / length, dot3(n_cross_s, n_cross_s) / s2, 0.5f * length};
}

// The GGX / Trowbridge-Reitz normal distribution (Walter et al. 2007, eq.
// 33; Trowbridge & Reitz 1975), as glTF Appendix B.3.2 writes it:
//   D(h) = alpha^2 chi+(n.h) / (pi ((n.h)^2 (alpha^2 - 1) + 1)^2)
// in 1/sr, normalised so that the integral of D(h)(n.h) over the
// hemisphere is 1. The denominator's (n.h)^2 (alpha^2 - 1) + 1 is computed
// as (n.h)^2 alpha^2 + |n x h|^2 (HalfVector says why).
inline float ggx_distribution(float n_dot_h, float n_cross_h_squared, float alpha) {
    if (!(n_dot_h > 0.0f)) return 0.0f;
    const float a2 = alpha * alpha;
    const float d = n_dot_h * n_dot_h * a2 + n_cross_h_squared;
    return a2 / (kPi * d * d);
}

// The height-correlated Smith masking-shadowing function for GGX (Heitz
// 2014, "Understanding the Masking-Shadowing Function in Microfacet-Based
// BRDFs"), already divided by the microfacet denominator 4 |n.l| |n.v|
// (glTF Appendix B.3.2's visibility nu; Filament's V):
//   V = 1 / (2 (n.v sqrt(alpha^2 + (1 - alpha^2)(n.l)^2)
//             + n.l sqrt(alpha^2 + (1 - alpha^2)(n.v)^2)))
// for n.l > 0 and n.v > 0 (the caller checks). Templated on the float type
// so that the DFG table can integrate it in double.
template <typename Real>
inline Real smith_ggx_correlated_visibility(Real n_dot_l, Real n_dot_v, Real alpha) {
    const Real a2 = alpha * alpha;
    const Real view_root = std::sqrt(n_dot_v * n_dot_v * (Real(1) - a2) + a2);
    const Real light_root = std::sqrt(n_dot_l * n_dot_l * (Real(1) - a2) + a2);
    return Real(0.5) / (n_dot_l * view_root + n_dot_v * light_root);
}

// The single-scattering specular microfacet BRDF without its Fresnel
// factor, glTF Appendix B.3.2's specular_brdf(alpha) = V * D, in 1/sr.
inline float specular_brdf(const HalfVector& h, float n_dot_l, float n_dot_v, float alpha) {
    return ggx_distribution(h.n_dot_h, h.n_cross_h_squared, alpha) *
           smith_ggx_correlated_visibility(n_dot_l, n_dot_v, alpha);
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

// The multiplier that restores the energy a single-scattering lobe of
// directional albedo E loses to multiple scattering between microfacets:
//   1 + f0 (1/E - 1)
// (Turquin 2019, "Practical multiple scattering compensation for microfacet
// models"; the same scaling of the split sum by Fdez-Aguera 2019, as
// Filament applies it, "Energy loss in specular reflectance", 4.7.2; an
// approximation of Kulla & Conty 2017's extra lobe). A white metal (f0 = 1)
// then reflects everything: E * (1/E) = 1.
inline glm::vec3 energy_compensation(const glm::vec3& f0, float albedo) {
    const float k = 1.0f / albedo - 1.0f;
    return glm::vec3(1.0f) + f0 * k;
}
inline float energy_compensation(float f0, float albedo) {
    return 1.0f + f0 * (1.0f / albedo - 1.0f);
}

// Whether the specular lobes get the energy compensation. `ignored` is the
// specification's single-scattering BRDF exactly.
enum class MultipleScattering { ignored, compensated };

// Everything at one shading point that does not depend on the light: worked
// out once, then used for every light.
struct ShadingPoint {
    glm::vec3 n{0.0f, 1.0f, 0.0f}, v{0.0f, 1.0f, 0.0f};  // unit
    float n_dot_v = 1.0f;  // at least kMinNdotV (a shading normal may face away)
    float alpha = 1.0f;
    float metallic = 1.0f;                 // clamped to [0, 1]
    glm::vec3 base_color{1.0f};            // also the metal's f0
    float dielectric_f0 = 0.04f;           // f0_from_ior(ior)
    glm::vec3 metal_compensation{1.0f};    // energy_compensation(base_color, E)
    float dielectric_compensation = 1.0f;  // energy_compensation(dielectric_f0, E)
};

ShadingPoint prepare_shading_point(const glm::vec3& n, const glm::vec3& v, const Material& material,
                                   MultipleScattering multiple_scattering);

// The glTF BRDF times the cosine, f(v, l) (n.l), for one light direction l
// (unit, towards the light), in 1/sr: times the irradiance a light gives
// on a plane facing it (a punctual light's colour times intensity at the
// point) it is the radiance reflected towards v. Zero when the light is
// below the surface (n.l <= 0). This is the
// glTF Appendix B.3.5 sum
//   (1 - metallic) * mix(base/pi, specular, F_dielectric)
//   + metallic * F_metal * specular
// with each specular lobe times its compensation (1 when ignored).
glm::vec3 brdf_cosine(const ShadingPoint& point, const glm::vec3& l);

// The same in one call, for tests and one-off use.
inline glm::vec3 brdf_cosine(const glm::vec3& n, const glm::vec3& v, const glm::vec3& l,
                             const Material& material, MultipleScattering multiple_scattering) {
    return brdf_cosine(prepare_shading_point(n, v, material, multiple_scattering), l);
}

}  // namespace facet::pbr
