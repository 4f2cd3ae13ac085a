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
//
// In three files, by stage: shade/brdf_terms.hpp the terms and the records
// a point travels in, shade/brdf_layers.hpp the layers over the base, and
// this one a point's assembly (prepare_point, brdf_cosine,
// environment_response).
#include <glm/vec3.hpp>

#include "shade/brdf_layers.hpp"

namespace facet::pbr {

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
    prepare_transmission(s, p);
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
    if (p.any_transmission) result = with_transmission(p, l, n_dot_l, result);
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

// What the surface passes of the radiance `behind` it, seen along the
// refracted view (KHR_materials_transmission with the split sum, as the
// Khronos sample viewer's getIBLVolumeRefraction): the dielectric's share
// t, tinted by the base colour and the volume (T), weighted by what its
// specular lobe leaves,
//   (1 - metallic) (1 - (f0 scale + f90 bias)) t T base behind
// then under the sheen and the coat as the environment's diffuse light.
template <typename T>
lanes::Vec3<T> transmitted_response(const PbrPoint<T>& p, const lanes::Vec3<T>& behind) {
    using lanes::select, lanes::splat;
    const LobeFresnel<T>& f0 = p.environment_f0;
    lanes::Vec3<T> result;
    for (int c = 0; c < 3; ++c) {
        const T lobe =
            (f0.dielectric[c] * p.dfg_scale + p.f90 * p.dfg_bias) * p.dielectric_compensation[c];
        result[c] = (1.0f - p.metallic) * (1.0f - lanes::min_of(lobe, splat<T>(1.0f))) *
                    p.transmission * p.transmittance[c] * p.base[c] * behind[c];
    }
    if (p.any_sheen) {
        const lanes::Mask<T> sheened = p.sheen_max > splat<T>(0.0f);
        for (T& channel : result) channel = select(sheened, channel * p.sheen_keeps_v, channel);
    }
    if (p.any_coat) {
        const lanes::Mask<T> coated = p.coat > splat<T>(0.0f);
        const T transmission = coat_transmission(p);
        for (T& channel : result) channel = select(coated, channel * transmission, channel);
    }
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
