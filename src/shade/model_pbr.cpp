#include "shade/model_pbr.hpp"

#include <array>

#include "core/exact_trig.hpp"
#include "shade/brdf.hpp"
#include "shade/environment_map.hpp"
#include "shade/light_lanes.hpp"
#include "shade/shading_models.hpp"

namespace facet {
namespace {

// Eight points at a time, lane by lane the formulas of shade/brdf.hpp (and
// in the same order of operations, so that a lane gives the bits the
// one-point functions give; tests/test_pbr_shading.cpp checks it).

using pbr::kPi;
using simd::splat;
using simd::vf;
using simd::vi;
using Lanes3 = std::array<vf, 3>;

// A clear coat is a dielectric of ior 1.5 (KHR_materials_clearcoat).
constexpr float kCoatF0 = 0.04f;

[[gnu::always_inline]] inline vf dot(const Lanes3& a, const Lanes3& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// normalise_or (shade/light_sample.hpp) over lanes.
[[gnu::always_inline]] inline Lanes3 normalise_or(const Lanes3& v, const Lanes3& fallback) {
    const vf length = simd::vsqrt(dot(v, v));
    const vi ok = length > splat(0.0f);
    const vf inverse = 1.0f / (ok ? length : splat(1.0f));
    return {ok ? v[0] * inverse : fallback[0], ok ? v[1] * inverse : fallback[1],
            ok ? v[2] * inverse : fallback[2]};
}

[[gnu::always_inline]] inline vf clamp01(vf x) {  // std::clamp's order
    return x < splat(0.0f) ? splat(0.0f) : (splat(1.0f) < x ? splat(1.0f) : x);
}

Lanes3 lanes3(const vf (&v)[3]) {
    return {v[0], v[1], v[2]};
}

// pbr::alpha_from_roughness over lanes.
vf alpha_from_roughness(vf roughness) {
    const vf low = splat(pbr::kMinRoughness);
    const vf r = roughness < low ? low : (splat(1.0f) < roughness ? splat(1.0f) : roughness);
    return r * r;
}

// The points, with everything that does not depend on the light.
struct PbrPoints {
    Lanes3 position, n, v, coat_n;
    vf n_dot_v, coat_n_dot_v;
    Lanes3 base;  // the base colour: a dielectric's albedo, a metal's f0
    vf metallic, roughness, alpha, occlusion;
    Lanes3 f0;  // the dielectric's
    vf f90;
    vf coat, coat_roughness, coat_alpha;
    bool any_coat;
    pbr::DfgTable::Lanes dfg, coat_dfg;  // directional albedo terms at n.v
    // Energy compensation of each specular lobe (brdf.hpp).
    Lanes3 metal_compensation, dielectric_compensation;
    // sqrt((n.v)^2 (1 - alpha^2) + alpha^2), Smith's view term, for each lobe.
    vf view_root, coat_view_root;
};

vf smith_view_root(vf n_dot_v, vf alpha) {
    const vf a2 = alpha * alpha;
    return simd::vsqrt(n_dot_v * n_dot_v * (1.0f - a2) + a2);
}

PbrPoints points_of(const SurfaceLanes& in, const glm::vec3& eye) {
    const SurfaceBatch& s = in.surface;
    const PbrLanes& l = in.pbr;
    PbrPoints p;
    p.position = {s.px, s.py, s.pz};
    p.n = normalise_or({s.nx, s.ny, s.nz}, {splat(0.0f), splat(1.0f), splat(0.0f)});
    p.v = normalise_or({eye.x - s.px, eye.y - s.py, eye.z - s.pz}, p.n);
    p.n_dot_v = simd::vmax(dot(p.n, p.v), splat(pbr::kMinNdotV));
    p.base = lanes3(in.albedo);
    p.metallic = clamp01(l.metallic);
    p.roughness = clamp01(l.roughness);
    p.alpha = alpha_from_roughness(p.roughness);
    p.occlusion = clamp01(l.occlusion);
    p.f0 = lanes3(l.f0);
    p.f90 = l.f90;
    p.coat = clamp01(l.clearcoat);
    p.coat_roughness = clamp01(l.clearcoat_roughness);
    p.coat_alpha = alpha_from_roughness(p.coat_roughness);
    const pbr::DfgTable& table = pbr::dfg_table();
    p.dfg = table.lookup(p.n_dot_v, p.roughness);
    const vi coated = p.coat > splat(0.0f);
    p.any_coat = simd::movemask(coated) != 0;
    p.coat_dfg = {splat(0.0f), splat(0.0f)};
    p.coat_n = p.n;
    p.coat_n_dot_v = p.n_dot_v;
    if (p.any_coat) {
        p.coat_n = normalise_or(lanes3(l.coat_normal), p.n);
        p.coat_n_dot_v = simd::vmax(dot(p.coat_n, p.v), splat(pbr::kMinNdotV));
        const pbr::DfgTable::Lanes terms = table.lookup(p.coat_n_dot_v, p.coat_roughness);
        p.coat_dfg = {coated ? terms.scale : splat(0.0f), coated ? terms.bias : splat(0.0f)};
    }
    const vf k = 1.0f / (p.dfg.scale + p.dfg.bias) - 1.0f;  // pbr::energy_compensation
    for (int c = 0; c < 3; ++c) {
        p.metal_compensation[c] = 1.0f + p.base[c] * k;
        p.dielectric_compensation[c] = 1.0f + p.f0[c] * k;
    }
    p.view_root = smith_view_root(p.n_dot_v, p.alpha);
    p.coat_view_root = p.any_coat ? smith_view_root(p.coat_n_dot_v, p.coat_alpha) : p.view_root;
    return p;
}

// pbr::HalfVector over lanes: n.h, |n x h|^2 and v.h, with zeros where v = -l.
struct HalfVectors {
    vf n_dot_h, n_cross_h_squared, v_dot_h;
};

[[gnu::always_inline]] inline HalfVectors half_vectors(const Lanes3& n, const Lanes3& v,
                                                       const Lanes3& l) {
    const Lanes3 s = {l[0] + v[0], l[1] + v[1], l[2] + v[2]};
    const vf s2 = dot(s, s);
    const vi ok = s2 > splat(1e-12f);
    const vf safe = ok ? s2 : splat(1.0f);
    const vf length = simd::vsqrt(safe);
    const Lanes3 n_cross_s = {n[1] * s[2] - n[2] * s[1], n[2] * s[0] - n[0] * s[2],
                              n[0] * s[1] - n[1] * s[0]};
    return {ok ? dot(n, s) / length : splat(0.0f),
            ok ? dot(n_cross_s, n_cross_s) / safe : splat(1.0f), ok ? 0.5f * length : splat(0.0f)};
}

// pbr::specular_brdf over lanes, Smith's view term given.
[[gnu::always_inline]] inline vf specular_brdf(const HalfVectors& h, vf n_dot_l, vf n_dot_v,
                                               vf view_root, vf alpha) {
    const vf a2 = alpha * alpha;
    const vf d = h.n_dot_h * h.n_dot_h * a2 + h.n_cross_h_squared;
    const vf distribution = h.n_dot_h > splat(0.0f) ? a2 / (kPi * d * d) : splat(0.0f);
    const vf light_root = simd::vsqrt(n_dot_l * n_dot_l * (1.0f - a2) + a2);
    return distribution * (0.5f / (n_dot_l * view_root + n_dot_v * light_root));
}

// pbr::schlick_weight over lanes.
[[gnu::always_inline]] inline vf schlick_weight(vf v_dot_h) {
    const vf m = 1.0f - clamp01(v_dot_h);
    const vf m2 = m * m;
    return m2 * m2 * m;
}

// The coat's share of what reaches the base: 1 - coat * E_coat (its
// directional albedo), the same for lights and the environment, so a
// white coated surface under a white environment still reflects 1. Exactly
// 1 without a coat (its terms are zero there).
vf coat_transmission(const PbrPoints& p) {
    return 1.0f - p.coat * (kCoatF0 * p.coat_dfg.scale + p.coat_dfg.bias);
}

// glTF Appendix B.3.5 for one light direction, times n.l; with
// KHR_materials_specular's f0 and f90 for the dielectric, and the coat.
Lanes3 light_response(const PbrPoints& p, const Lanes3& l) {
    const vf n_dot_l = dot(p.n, l);
    const vi lit = n_dot_l > splat(0.0f);
    Lanes3 result = {splat(0.0f), splat(0.0f), splat(0.0f)};
    if (simd::movemask(lit) != 0) {
        const HalfVectors h = half_vectors(p.n, p.v, l);
        const vf specular = specular_brdf(h, n_dot_l, p.n_dot_v, p.view_root, p.alpha);
        const vf w = schlick_weight(h.v_dot_h);
        for (int c = 0; c < 3; ++c) {
            const vf fd = p.f0[c] + (p.f90 - p.f0[c]) * w;
            const vf dielectric = (1.0f - fd) * (1.0f / kPi) * p.base[c] +
                                  fd * specular * p.dielectric_compensation[c];
            const vf metal =
                (p.base[c] + (1.0f - p.base[c]) * w) * specular * p.metal_compensation[c];
            const vf sum = ((1.0f - p.metallic) * dielectric + p.metallic * metal) * n_dot_l;
            result[c] = lit ? sum : splat(0.0f);
        }
    }
    if (!p.any_coat) return result;
    const vf transmission = coat_transmission(p);
    const vf coat_n_dot_l = dot(p.coat_n, l);
    const vi coat_lit = (coat_n_dot_l > splat(0.0f)) & (p.coat > splat(0.0f));
    const HalfVectors h = half_vectors(p.coat_n, p.v, l);
    const vf f = kCoatF0 + (1.0f - kCoatF0) * schlick_weight(h.v_dot_h);
    const vf coat = p.coat * f *
                    specular_brdf(h, coat_n_dot_l, p.coat_n_dot_v, p.coat_view_root, p.coat_alpha) *
                    coat_n_dot_l;
    for (int c = 0; c < 3; ++c) {
        result[c] *= transmission;
        result[c] = coat_lit ? result[c] + coat : result[c];
    }
    return result;
}

// Punctual lights: pi times their radiance (facet's intensities are
// irradiance over pi, see the header), times shadow visibility. Ambient
// lights light the point from every direction alike: a uniform
// environment, added to `uniform`.
Lanes3 direct_light(const PbrPoints& p, const SurfaceBatch& surface, vi active,
                    std::span<const ShadeLight> lights, glm::vec3& uniform) {
    Lanes3 sum = {splat(0.0f), splat(0.0f), splat(0.0f)};
    for (const ShadeLight& light : lights) {
        if (light.is_ambient) {
            uniform += light.radiance;
            continue;
        }
        IncomingLight in = incoming_light(light, surface);
        const Lanes3 l = {in.lx, in.ly, in.lz};
        vi arrives = in.usable & active & (dot(p.n, l) > splat(0.0f));
        if (p.any_coat) arrives |= in.usable & active & (dot(p.coat_n, l) > splat(0.0f));
        if (simd::movemask(arrives) == 0) continue;
        if (light.shadow) apply_shadow(*light.shadow, surface, p.n[0], p.n[1], p.n[2], arrives, in);
        const Lanes3 response = light_response(p, l);
        const Lanes3 radiance = {in.rr, in.rg, in.rb};
        for (int c = 0; c < 3; ++c)
            sum[c] = arrives ? sum[c] + kPi * radiance[c] * response[c] : sum[c];
    }
    return sum;
}

// The split sum for an environment whose diffuse radiance E(n)/pi is
// `diffuse` and whose specular lobes read `specular` and `coat_specular`:
// metal and dielectric lobes weighted by their directional albedo and
// compensated, the dielectric's diffuse by what its lobe leaves (Fdez-Aguera
// 2019), then the coat over both.
Lanes3 environment_response(const PbrPoints& p, const Lanes3& diffuse, const Lanes3& specular,
                            const Lanes3& coat_specular) {
    const vf coat_albedo = p.coat * (kCoatF0 * p.coat_dfg.scale + p.coat_dfg.bias);
    const vf transmission = coat_transmission(p);
    const vi coated = p.coat > splat(0.0f);
    Lanes3 result;
    for (int c = 0; c < 3; ++c) {
        // lobe albedo f0 * scale + f90 * bias (Karis 2013's split sum)
        const vf dielectric_lobe =
            (p.f0[c] * p.dfg.scale + p.f90 * p.dfg.bias) * p.dielectric_compensation[c];
        const vf metal_lobe = (p.base[c] * p.dfg.scale + p.dfg.bias) * p.metal_compensation[c];
        const vf dielectric =
            (1.0f - simd::vmin(dielectric_lobe, splat(1.0f))) * p.base[c] * diffuse[c] +
            dielectric_lobe * specular[c];
        result[c] = (1.0f - p.metallic) * dielectric + p.metallic * metal_lobe * specular[c];
        if (p.any_coat)
            result[c] =
                coated ? result[c] * transmission + coat_albedo * coat_specular[c] : result[c];
    }
    return result;
}

Lanes3 reflect_view(const Lanes3& n, const Lanes3& v) {
    const vf twice = 2.0f * dot(n, v);
    return {twice * n[0] - v[0], twice * n[1] - v[1], twice * n[2] - v[2]};
}

Lanes3 to_map(const EnvironmentLighting& e, const Lanes3& d) {
    const vf in[3] = {d[0], d[1], d[2]};
    vf out[3];
    e.to_map(in, out);
    return lanes3(out);
}

Lanes3 environment_light(const PbrPoints& p, const EnvironmentLighting& environment) {
    const pbr::PrefilteredEnvironment& map = *environment.map;
    vf diffuse[3], specular[3], coat[3] = {splat(0.0f), splat(0.0f), splat(0.0f)};
    const Lanes3 n = to_map(environment, p.n);
    map.diffuse({n[0], n[1], n[2]}, diffuse);
    const Lanes3 r = to_map(environment, reflect_view(p.n, p.v));
    map.specular({r[0], r[1], r[2]}, p.roughness, specular);
    if (p.any_coat) {
        const Lanes3 coat_r = to_map(environment, reflect_view(p.coat_n, p.v));
        map.specular({coat_r[0], coat_r[1], coat_r[2]}, p.coat_roughness, coat);
    }
    return environment_response(p, lanes3(diffuse), lanes3(specular), lanes3(coat));
}

Lanes3 indirect_light(const PbrPoints& p, const EnvironmentLighting* environment,
                      const glm::vec3& uniform) {
    Lanes3 sum = {splat(0.0f), splat(0.0f), splat(0.0f)};
    if (uniform != glm::vec3(0.0f)) {
        const Lanes3 u = {splat(uniform.x), splat(uniform.y), splat(uniform.z)};
        sum = environment_response(p, u, u, u);
    }
    if (environment && environment->map && environment->intensity > 0.0f) {
        const Lanes3 light = environment_light(p, *environment);
        for (int c = 0; c < 3; ++c) sum[c] += environment->intensity * light[c];
    }
    for (vf& channel : sum) channel *= p.occlusion;
    return sum;
}

}  // namespace

EnvironmentLighting environment_at(const pbr::PrefilteredEnvironment* map, float intensity,
                                   float rotation_degrees) {
    EnvironmentLighting e;
    e.map = map;
    e.intensity = intensity;
    const double turns = static_cast<double>(rotation_degrees) / 360.0;
    e.cos_rotation = static_cast<float>(cos_turns(turns));
    e.sin_rotation = static_cast<float>(sin_turns(turns));
    return e;
}

void shade_pbr(const SurfaceLanes& in, const ShadingContext& context, ShadedLanes& out) {
    // Lanes past `count` hold whatever the batch held before: computed
    // alongside (the lookups clamp what they read) and never shown, but
    // kept out of the shadow maps, the costly part.
    vi active;
    for (int i = 0; i < simd::kLanes; ++i) active[i] = i < in.count ? -1 : 0;
    const PbrPoints p = points_of(in, context.eye);
    glm::vec3 uniform(0.0f);
    const Lanes3 direct = direct_light(p, in.surface, active, context.lights, uniform);
    const Lanes3 indirect = indirect_light(p, context.environment, uniform);
    for (int c = 0; c < 3; ++c) out.color[c] = direct[c] + indirect[c];
}

}  // namespace facet
