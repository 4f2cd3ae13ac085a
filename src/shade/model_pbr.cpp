#include "shade/model_pbr.hpp"

#include <type_traits>

#include "core/exact_trig.hpp"
#include "shade/brdf.hpp"
#include "shade/environment_map.hpp"
#include "shade/light_sample.hpp"
#include "shade/shading_models.hpp"
#include "shade/transmission_backdrop.hpp"

namespace facet {
namespace {

// One point (float) or eight (simd::vf) through the same template, over
// shade/brdf.hpp's terms and shade/light_sample.hpp's lights:
// shade_pbr_point is lane 0 of shade_pbr, to the bit
// (tests/test_pbr_lanes.cpp).

using lanes::select;
using lanes::splat;
using lanes::Vec3;
using pbr::kPi;

// The environment's map lookups, for one point and for eight.
Vec3<float> map_diffuse(const pbr::PrefilteredEnvironment& map, const Vec3<float>& n) {
    const glm::vec3 e = map.diffuse(glm::vec3(n[0], n[1], n[2]));
    return {e.x, e.y, e.z};
}
Vec3<simd::vf> map_diffuse(const pbr::PrefilteredEnvironment& map, const Vec3<simd::vf>& n) {
    simd::vf out[3];
    map.diffuse({n[0], n[1], n[2]}, out);
    return {out[0], out[1], out[2]};
}
Vec3<float> map_specular(const pbr::PrefilteredEnvironment& map, const Vec3<float>& r,
                         float roughness) {
    const glm::vec3 e = map.specular(glm::vec3(r[0], r[1], r[2]), roughness);
    return {e.x, e.y, e.z};
}
Vec3<simd::vf> map_specular(const pbr::PrefilteredEnvironment& map, const Vec3<simd::vf>& r,
                            simd::vf roughness) {
    simd::vf out[3];
    map.specular({r[0], r[1], r[2]}, roughness, out);
    return {out[0], out[1], out[2]};
}

// A world direction turned into the map's frame (EnvironmentLighting::to_map).
template <typename T>
Vec3<T> to_map(const EnvironmentLighting& e, const Vec3<T>& d) {
    return {e.cos_rotation * d[0] - e.sin_rotation * d[2], d[1],
            e.sin_rotation * d[0] + e.cos_rotation * d[2]};
}

// Punctual lights: pi times their radiance (facet's intensities are
// irradiance over pi, see the header), times shadow visibility, at the
// points in `active`. Ambient lights light the point from every direction
// alike: a uniform environment, added to `uniform`.
template <typename T>
Vec3<T> direct_light(const pbr::PbrPoint<T>& p, const Vec3<T>& position, lanes::Mask<T> active,
                     lanes::Mask<T> receives_shadow, std::span<const ShadeLight> lights,
                     glm::vec3& uniform) {
    const T zero = splat<T>(0.0f);
    Vec3<T> sum = {zero, zero, zero};
    for (const ShadeLight& light : lights) {
        if (light.is_ambient) {
            uniform += light.radiance;
            continue;
        }
        IncomingLight<T> in = incoming_light<T>(light, position);
        const Vec3<T>& l = in.to_light;
        const T n_dot_l = lanes::dot(p.n, l);
        lanes::Mask<T> arrives = in.usable & active & (n_dot_l > zero);
        if (p.any_coat) arrives |= in.usable & active & (lanes::dot(p.coat_n, l) > zero);
        // Either transmission lets light in from behind too; its shadow is
        // looked up on that side.
        Vec3<T> facing = p.n;
        if (p.any_diffuse_transmission || p.any_transmission) {
            arrives |=
                in.usable & active & ((p.diffuse_transmission > zero) | (p.transmission > zero));
            const lanes::Mask<T> behind = n_dot_l < zero;
            for (int c = 0; c < 3; ++c) facing[c] = select(behind, zero - p.n[c], p.n[c]);
        }
        if (!lanes::any(arrives)) continue;
        if (light.shadow)
            apply_shadow(*light.shadow, position, facing, arrives & receives_shadow, in);
        const Vec3<T> response = pbr::brdf_cosine(p, l);
        for (int c = 0; c < 3; ++c)
            sum[c] = select(arrives, sum[c] + kPi * in.radiance[c] * response[c], sum[c]);
    }
    return sum;
}

template <typename T>
Vec3<T> environment_light(const pbr::PbrPoint<T>& p, const EnvironmentLighting& environment) {
    const pbr::PrefilteredEnvironment& map = *environment.map;
    const Vec3<T> diffuse = map_diffuse(map, to_map(environment, p.n));
    const Vec3<T> specular = map_specular(
        map, to_map(environment, lanes::reflect(p.reflection_normal, p.v)), p.roughness);
    Vec3<T> coat = {splat<T>(0.0f), splat<T>(0.0f), splat<T>(0.0f)};
    if (p.any_coat)
        coat =
            map_specular(map, to_map(environment, lanes::reflect(p.coat_n, p.v)), p.coat_roughness);
    Vec3<T> back = diffuse;
    if (p.any_diffuse_transmission)
        back = map_diffuse(map, to_map(environment, Vec3<T>{-p.n[0], -p.n[1], -p.n[2]}));
    return pbr::environment_response(p, diffuse, specular, coat, back);
}

template <typename T>
Vec3<T> indirect_light(const pbr::PbrPoint<T>& p, const EnvironmentLighting* environment,
                       const glm::vec3& uniform) {
    Vec3<T> sum = {splat<T>(0.0f), splat<T>(0.0f), splat<T>(0.0f)};
    if (uniform != glm::vec3(0.0f)) {
        const Vec3<T> u = {splat<T>(uniform.x), splat<T>(uniform.y), splat<T>(uniform.z)};
        sum = pbr::environment_response(p, u, u, u);
    }
    if (environment && environment->map && environment->intensity > 0.0f) {
        const Vec3<T> light = environment_light(p, *environment);
        for (int c = 0; c < 3; ++c) sum[c] += environment->intensity * light[c];
    }
    for (T& channel : sum) channel *= p.occlusion;
    return sum;
}

// The radiance behind each point along its refracted view
// (shade/transmission_backdrop.hpp), point by point: a backdrop is read
// texel by texel, as textures are.
inline RefractedView refracted_view(const pbr::PbrPoint<float>& p, const Vec3<float>& position,
                                    const pbr::SurfaceTerms<float>& s, int) {
    return {{position[0], position[1], position[2]},
            {p.n[0], p.n[1], p.n[2]},
            {p.v[0], p.v[1], p.v[2]},
            s.ior,
            lanes::max_of(s.thickness, 0.0f),
            p.transmission_roughness,
            s.dispersion};
}
inline RefractedView refracted_view(const pbr::PbrPoint<simd::vf>& p,
                                    const Vec3<simd::vf>& position,
                                    const pbr::SurfaceTerms<simd::vf>& s, int i) {
    return {{position[0][i], position[1][i], position[2][i]},
            {p.n[0][i], p.n[1][i], p.n[2][i]},
            {p.v[0][i], p.v[1][i], p.v[2][i]},
            s.ior[i],
            lanes::max_of(s.thickness[i], 0.0f),
            p.transmission_roughness[i],
            s.dispersion[i]};
}

template <typename T>
Vec3<T> radiance_behind(const pbr::PbrPoint<T>& p, const Vec3<T>& position,
                        const pbr::SurfaceTerms<T>& s, lanes::Mask<T> active,
                        const ShadingContext& context) {
    Vec3<T> behind = {splat<T>(0.0f), splat<T>(0.0f), splat<T>(0.0f)};
    if constexpr (std::is_same_v<T, float>) {
        if (!(active && p.transmission > 0.0f)) return behind;
        const glm::vec3 r = radiance_behind(refracted_view(p, position, s, 0), context.backdrop,
                                            context.environment);
        return {r.x, r.y, r.z};
    } else {
        for (int i = 0; i < simd::kLanes; ++i) {
            if (!active[i] || !(p.transmission[i] > 0.0f)) continue;
            const glm::vec3 r = radiance_behind(refracted_view(p, position, s, i), context.backdrop,
                                                context.environment);
            for (int c = 0; c < 3; ++c) behind[c][i] = r[c];
        }
        return behind;
    }
}

// The model at points of position and normal (on the viewer's side, any
// length; a zero one faces +Y).
template <typename T>
Vec3<T> shade_points(const Vec3<T>& position, const Vec3<T>& normal, lanes::Mask<T> active,
                     lanes::Mask<T> receives_shadow, const pbr::SurfaceTerms<T>& terms,
                     const ShadingContext& context) {
    const Vec3<T> n = lanes::normalise_or(normal, {splat<T>(0.0f), splat<T>(1.0f), splat<T>(0.0f)});
    const glm::vec3 eye = context.eye;
    const Vec3<T> v =
        lanes::normalise_or<T>({eye.x - position[0], eye.y - position[1], eye.z - position[2]}, n);
    const pbr::PbrPoint<T> p =
        pbr::prepare_point(n, v, terms, pbr::MultipleScattering::compensated, pbr::dfg_table());
    glm::vec3 uniform(0.0f);
    const Vec3<T> direct =
        direct_light(p, position, active, receives_shadow, context.lights, uniform);
    const Vec3<T> indirect = indirect_light(p, context.environment, uniform);
    Vec3<T> color = {direct[0] + indirect[0], direct[1] + indirect[1], direct[2] + indirect[2]};
    if (p.any_transmission) {
        const Vec3<T> through =
            pbr::transmitted_response(p, radiance_behind(p, position, terms, active, context));
        for (int c = 0; c < 3; ++c) color[c] += through[c];
    }
    return color;
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
    simd::vi active;
    for (int i = 0; i < simd::kLanes; ++i) active[i] = i < in.count ? -1 : 0;
    const SurfaceBatch& s = in.surface;
    pbr::SurfaceTerms<simd::vf> terms = in.pbr;
    terms.base = {in.albedo[0], in.albedo[1], in.albedo[2]};
    const Vec3<simd::vf> color =
        shade_points<simd::vf>({s.px, s.py, s.pz}, {s.nx, s.ny, s.nz}, active,
                               s.receives_shadow > simd::splat(0.0f), terms, context);
    for (int c = 0; c < 3; ++c) out.color[c] = color[c];
}

glm::vec3 shade_pbr_point(const glm::vec3& position, const glm::vec3& normal, bool receives_shadow,
                          const pbr::SurfaceTerms<float>& terms, const ShadingContext& context) {
    const Vec3<float> color =
        shade_points<float>({position.x, position.y, position.z}, {normal.x, normal.y, normal.z},
                            true, receives_shadow, terms, context);
    return {color[0], color[1], color[2]};
}

}  // namespace facet
