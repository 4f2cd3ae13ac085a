#pragma once
// The layers of the `pbr` model over its base (shade/brdf.hpp gives the
// whole): the thin film, the sheen, the anisotropy and the diffuse
// transmission (KHR_materials_iridescence, _sheen, _anisotropy,
// _diffuse_transmission). Each has an inline part that asks whether any
// lane has it and an out-of-line part that does its work, so that a
// batch without it keeps its bits and its registers. docs/pbr.md gives
// every formula and its source.
#include "shade/brdf_terms.hpp"
#include "shade/thin_film.hpp"

namespace facet::pbr {

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

// A light l behind the surface mirrored to the viewer's side,
// l' = l - 2 (n.l) n: both transmissions evaluate their Fresnel term (and
// the specular BTDF its lobe) at it, as the Khronos sample viewer does.
template <typename T>
[[gnu::always_inline]] inline lanes::Vec3<T> mirrored_light(const lanes::Vec3<T>& n,
                                                            const lanes::Vec3<T>& l, T n_dot_l) {
    const T twice = 2.0f * n_dot_l;
    return {l[0] - twice * n[0], l[1] - twice * n[1], l[2] - twice * n[2]};
}

// KHR_materials_transmission: the dielectric's base is
//   mix(diffuse, specular BTDF * base colour, t)
// so the diffuse terms (and a diffuse transmission's) keep 1 - t of
// theirs. KHR_materials_volume: light crossing the volume keeps
//   T = attenuation_color ^ (thickness / attenuation_distance)
// (Beer-Lambert, the path taken as the thickness, as the Khronos sample
// viewer does). The refraction's lobe is the surface's GGX, its alpha
// scaled by clamp(2 ior - 2, 0, 1) (at least the smallest alpha), and the
// backdrop's blur its perceptual roughness scaled alike: an index of 1
// bends nothing, so blurs nothing (the sample viewer's applyIorToRoughness,
// on alphaRoughness for the lobe and on the roughness for the blur).
template <typename T>
[[gnu::noinline]] void prepare_transmission_terms(const SurfaceTerms<T>& s, PbrPoint<T>& p) {
    using lanes::clamp01, lanes::splat;
    const T keep = 1.0f - p.transmission;
    for (int c = 0; c < 3; ++c) p.diffuse_albedo[c] = p.diffuse_albedo[c] * keep;
    p.diffuse_transmission = p.diffuse_transmission * keep;
    // A distance of 0 is none the files or scenes give (they refuse it).
    const T exponent = lanes::select(
        s.attenuation_distance > splat<T>(0.0f),
        lanes::max_of(s.thickness, splat<T>(0.0f)) / s.attenuation_distance, splat<T>(0.0f));
    for (int c = 0; c < 3; ++c)
        p.transmittance[c] = lanes::power_unit(clamp01(s.attenuation_color[c]), exponent);
    const T bends = clamp01(2.0f * s.ior - 2.0f);
    p.transmission_roughness = p.roughness * bends;
    p.transmission_alpha = lanes::max_of(p.alpha * bends, splat<T>(kMinRoughness * kMinRoughness));
    p.transmission_view_root = smith_root(p.n_dot_v, p.transmission_alpha);
}

template <typename T>
[[gnu::always_inline]] inline void prepare_transmission(const SurfaceTerms<T>& s, PbrPoint<T>& p) {
    p.transmission = lanes::clamp01(s.transmission);
    p.any_transmission = lanes::any(p.transmission > lanes::splat<T>(0.0f));
    if (p.any_transmission) prepare_transmission_terms(s, p);
}

// A light behind the surface (n.l < 0) through the transmission: the
// specification's specular BTDF with the light mirrored to the viewer's
// side, l' = l - 2 (n.l) n (as the Khronos sample viewer evaluates it),
//   (1 - metallic) t T base (1 - F(v.h')) D(h') V(n.l', n.v) |n.l|
// with the refraction's lobe (prepare_transmission). Lanes without one,
// or lit from the front, keep their bits.
template <typename T>
[[gnu::noinline]] lanes::Vec3<T> with_transmission(const PbrPoint<T>& p, const lanes::Vec3<T>& l,
                                                   T n_dot_l, lanes::Vec3<T> result) {
    using lanes::select, lanes::splat;
    const T zero = splat<T>(0.0f);
    const lanes::Mask<T> behind = (n_dot_l < zero) & (p.transmission > zero);
    if (!lanes::any(behind)) return result;
    const T cosine = zero - n_dot_l;
    const HalfVector<T> h = half_vector(p.n, p.v, mirrored_light(p.n, l, n_dot_l));
    const T lobe =
        specular_brdf(h, cosine, p.n_dot_v, p.transmission_view_root, p.transmission_alpha);
    const T w = schlick_weight(h.v_dot_h);
    const T share = (1.0f - p.metallic) * p.transmission * lobe * cosine;
    for (int c = 0; c < 3; ++c) {
        const T through =
            (1.0f - schlick_fresnel(p.f0[c], w, p.f90)) * share * p.base[c] * p.transmittance[c];
        result[c] = select(behind, result[c] + through, result[c]);
    }
    return result;
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
    const T w = schlick_weight(half_vector(p.n, p.v, mirrored_light(p.n, l, n_dot_l)).v_dot_h);
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

}  // namespace facet::pbr
