#pragma once
// Fresnel's reflectance as the `pbr` model uses it: at normal incidence
// from an index of refraction, and Schlick's approximation at other
// angles. Templates on the number type (shade/lanes.hpp), shared by the
// BRDF (shade/brdf.hpp) and the thin film (shade/thin_film.hpp).
#include "shade/lanes.hpp"

namespace facet::pbr {

// Reflectance at normal incidence of a dielectric of index `ior` in air:
// ((ior - 1) / (ior + 1))^2, from Fresnel's equations at normal incidence
// (glTF Appendix B.3.4, fresnel_mix). 1.5 gives 0.04.
// ((n_t - n_i) / (n_t + n_i))^2: the reflectance at normal incidence
// between media of indices n_i (incident) and n_t (transmitted).
template <typename T>
[[gnu::always_inline]] inline T reflectance_at_normal(T transmitted, T incident) {
    const T r = (transmitted - incident) / (transmitted + incident);
    return r * r;
}

inline float f0_from_ior(float ior) {
    return reflectance_at_normal(ior, 1.0f);
}

// Schlick 1994's weight (1 - v.h)^5, the part of F that depends on the
// angle. v.h is clamped to [0, 1].
template <typename T>
[[gnu::always_inline]] inline T schlick_weight(T v_dot_h) {
    const T m = 1.0f - lanes::clamp01(v_dot_h);
    const T m2 = m * m;
    return m2 * m2 * m;
}

// Schlick 1994's Fresnel F = F0 + (F90 - F0)(1 - v.h)^5, as glTF Appendix
// B.3.4 writes it for conductor_fresnel and fresnel_mix (F90 = 1) and
// KHR_materials_specular (F90 its weight). `weight` is schlick_weight(v.h),
// computed once for all channels.
template <typename T>
[[gnu::always_inline]] inline T schlick_fresnel(T f0, T weight, T f90 = lanes::splat<T>(1.0f)) {
    return f0 + (f90 - f0) * weight;
}

}  // namespace facet::pbr
