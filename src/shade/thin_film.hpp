#pragma once
// The Fresnel reflectance of a thin film over a surface, as
// KHR_materials_iridescence defines it after Belcour & Barla 2017 ("A
// Practical Extension to Microfacet Theory for the Modeling of Varying
// Iridescence"): the light reflected at the film's top and at the base
// below interferes by the optical path difference, and the interference
// is integrated against the eye's colour matching functions in closed
// form (their Gaussian fit, evaluated in Fourier space). Written once as
// a template on the number type, like shade/brdf.hpp, with IEEE-exact
// operations and core/simd_math.hpp's polynomials only, so the bits are
// the same on every CPU. docs/pbr.md, "Iridescence", gives the formulas.
#include "shade/fresnel.hpp"
#include "shade/lanes.hpp"

namespace facet::pbr {

// The Fourier transform of the colour matching functions (Belcour & Barla
// 2017's Gaussian fit, as the extension gives it), at optical path
// difference `opd` (nm) and per-channel phase shift `shift`, in linear
// Rec. 709 RGB.
template <typename T>
[[gnu::always_inline]] inline lanes::Vec3<T> thin_film_sensitivity(T opd,
                                                                   const lanes::Vec3<T>& shift) {
    constexpr float kTwoPi = 6.28318530717958647692f;
    const T phase = (kTwoPi * 1e-9f) * opd;
    const T phase2 = phase * phase;
    // val * sqrt(2 pi var), pos and var of the X, Y and Z lobes, and X's second lobe.
    constexpr float kScale[3] = {5.4856e-13f * 164901.09f, 4.4201e-13f * 241790.25f,
                                 5.2481e-13f * 203826.03f};
    constexpr float kPosition[3] = {1.6810e+06f, 1.7953e+06f, 2.2084e+06f};
    constexpr float kVariance[3] = {4.3278e+09f, 9.3046e+09f, 6.6121e+09f};
    constexpr float kLog2e = 1.44269504f;
    lanes::Vec3<T> xyz;
    for (int c = 0; c < 3; ++c)
        xyz[c] = kScale[c] * lanes::cosine(kPosition[c] * phase + shift[c]) *
                 lanes::exp2(-(kVariance[c] * kLog2e) * phase2);
    xyz[0] += (9.7470e-14f * 168675.78f) * lanes::cosine(2.2399e+06f * phase + shift[0]) *
              lanes::exp2(-(4.5282e+09f * kLog2e) * phase2);
    for (T& v : xyz) v = v * (1.0f / 1.0685e-7f);
    // XYZ to linear Rec. 709 (IEC 61966-2-1).
    return {3.2404542f * xyz[0] - 1.5371385f * xyz[1] - 0.4985314f * xyz[2],
            -0.9692660f * xyz[0] + 1.8760108f * xyz[1] + 0.0415560f * xyz[2],
            0.0556434f * xyz[0] - 0.2040259f * xyz[1] + 1.0572252f * xyz[2]};
}

// The film's Fresnel reflectance, per channel, seen from air at the
// cosine `cos_outside` (v.h), for a film of index `film_ior` and
// `thickness` nm over a base whose reflectance at normal incidence is
// `base_f0` (its index found from it, assuming air above it). Total
// internal reflection in the film gives 1.
template <typename T>
lanes::Vec3<T> thin_film_fresnel(T cos_outside, T film_ior, T thickness,
                                 const lanes::Vec3<T>& base_f0) {
    using lanes::select, lanes::splat;
    constexpr float kPi = 3.14159265358979323846f;
    const T one = splat<T>(1.0f), zero = splat<T>(0.0f);
    // The film's index falls to air's as its thickness goes to 0
    // (smoothstep over 0 .. 0.03 nm, as the extension writes it).
    const T t = lanes::clamp01(thickness * (1.0f / 0.03f));
    const T ior = 1.0f + (film_ior - 1.0f) * (t * t * (3.0f - 2.0f * t));
    // Snell: the cosine inside the film.
    const T c1 = lanes::clamp01(cos_outside);
    const T sin2_inside = (1.0f / (ior * ior)) * (1.0f - c1 * c1);
    const T cos2_inside = 1.0f - sin2_inside;
    const lanes::Mask<T> total = cos2_inside < zero;
    const T c2 = lanes::square_root(lanes::max_of(cos2_inside, zero));
    // The top interface, air to film (Schlick), and its phase shifts.
    const T r12 = schlick_fresnel(reflectance_at_normal(ior, one), schlick_weight(c1));
    const T t121 = 1.0f - r12;
    const T phi21 = select(ior < one, zero, splat<T>(kPi));  // pi - phi12
    const T opd = 2.0f * ior * thickness * c2;
    lanes::Vec3<T> r23, phi;
    for (int c = 0; c < 3; ++c) {
        // The base's index from its f0, then the film-to-base interface.
        const T root =
            lanes::square_root(lanes::min_of(lanes::clamp01(base_f0[c]), splat<T>(0.9999f)));
        const T base_ior = (1.0f + root) / (1.0f - root);
        r23[c] = schlick_fresnel(reflectance_at_normal(base_ior, ior), schlick_weight(c2));
        phi[c] = phi21 + select(base_ior < ior, splat<T>(kPi), zero);
    }
    // The Airy sum's first three terms (m = 0, 1, 2), after Belcour & Barla.
    lanes::Vec3<T> result, cm, r123;
    for (int c = 0; c < 3; ++c) {
        const T product =
            lanes::min_of(lanes::max_of(r12 * r23[c], splat<T>(1e-5f)), splat<T>(0.9999f));
        r123[c] = lanes::square_root(product);
        const T rs = t121 * t121 * r23[c] / (1.0f - product);
        result[c] = r12 + rs;
        cm[c] = rs - t121;
    }
    for (int m = 1; m <= 2; ++m) {
        const float order = static_cast<float>(m);
        const lanes::Vec3<T> shift = {order * phi[0], order * phi[1], order * phi[2]};
        const lanes::Vec3<T> s = thin_film_sensitivity(order * opd, shift);
        for (int c = 0; c < 3; ++c) {
            cm[c] = cm[c] * r123[c];
            result[c] = result[c] + cm[c] * (2.0f * s[c]);
        }
    }
    for (int c = 0; c < 3; ++c) result[c] = select(total, one, lanes::max_of(result[c], zero));
    return result;
}

}  // namespace facet::pbr
