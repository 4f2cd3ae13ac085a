#include "shade/lighting_batch.hpp"

#include <cmath>

#include <glm/trigonometric.hpp>

#include "shade/light_sample.hpp"

namespace facet {

using simd::splat;
using simd::vf;
using simd::vi;

void set_spot_cone(ShadeLight& light, float inner_degrees, float outer_degrees) {
    const float cos_outer = std::cos(glm::radians(outer_degrees));
    const float cos_inner = std::cos(glm::radians(std::min(inner_degrees, outer_degrees)));
    light.is_spot = true;
    light.spot_scale = 1.0f / std::max(0.001f, cos_inner - cos_outer);
    light.spot_offset = -cos_outer * light.spot_scale;
}

void pad_batch(SurfaceBatch& s, int count) {
    for (int i = count; i < simd::kLanes; ++i)
        for (vf* v : {&s.px, &s.py, &s.pz, &s.nx, &s.ny, &s.nz, &s.ambient, &s.diffuse, &s.specular,
                      &s.shininess, &s.receives_shadow, &s.ambient_specular})
            (*v)[i] = (*v)[0];
}

namespace {

using Vec3 = lanes::Vec3<vf>;

// Per lane, the unit normal (n; a zero one becomes +Y) and the unit vector
// to the eye (e).
struct UnitVectors {
    Vec3 n, e;
};

// The cosine the highlight's power raises: of the half vector and the
// normal (Blinn), or of the reflected light and the eye vector (Phong).
[[gnu::always_inline]] inline vf highlight_cosine(Highlight highlight, const UnitVectors& s,
                                                  const Vec3& l) {
    const vf zero = splat(0.0f);
    if (highlight == Highlight::blinn) {
        const Vec3 h = {l[0] + s.e[0], l[1] + s.e[1], l[2] + s.e[2]};
        const vf len = simd::vsqrt(lanes::dot(h, h));
        const vi ok = len > zero;
        const vf cosine = lanes::dot(s.n, h) / (ok ? len : splat(1.0f));
        return ok ? cosine : zero;
    }
    return lanes::dot(lanes::reflect(s.n, l), s.e);
}

// Adds one light's diffuse and highlight to `out`.
[[gnu::always_inline]] inline void add_light(const ShadeLight& light, const SurfaceBatch& p,
                                             const UnitVectors& s, Highlight highlight,
                                             LightingBatch& out) {
    const vf zero = splat(0.0f);
    const Vec3 position = {p.px, p.py, p.pz};
    IncomingLight<vf> in = incoming_light<vf>(light, position);
    const vf n_dot_l = lanes::dot(s.n, in.to_light);
    const vi lit = in.usable & (n_dot_l > zero);
    if (light.shadow)
        apply_shadow(*light.shadow, position, s.n, lit & (p.receives_shadow > zero), in);
    const vf d = lit ? p.diffuse * n_dot_l : zero;
    out.dr += d * in.radiance[0];
    out.dg += d * in.radiance[1];
    out.db += d * in.radiance[2];

    const vf cosine = highlight_cosine(highlight, s, in.to_light);
    const vi highlighted = lit & (cosine > zero) & (p.specular > zero);
    const vf power = simd::vpow_unit(simd::vmin(cosine, splat(1.0f)), p.shininess);
    const vf k = highlighted ? p.specular * power : zero;
    out.sr += k * in.radiance[0];
    out.sg += k * in.radiance[1];
    out.sb += k * in.radiance[2];
}

}  // namespace

LightingBatch light_surface_batch(const SurfaceBatch& surface, const glm::vec3& eye,
                                  std::span<const ShadeLight> lights, Highlight highlight) {
    UnitVectors s;
    s.n = lanes::normalise_or<vf>({surface.nx, surface.ny, surface.nz},
                                  {splat(0.0f), splat(1.0f), splat(0.0f)});
    // A point at the eye keeps its zero vector.
    const Vec3 to_eye = {eye.x - surface.px, eye.y - surface.py, eye.z - surface.pz};
    s.e = lanes::normalise_or(to_eye, to_eye);
    const SurfaceBatch& p = surface;
    LightingBatch out;
    const glm::vec3 ambient = ambient_light(lights);
    out.dr = p.ambient * ambient.x;
    out.dg = p.ambient * ambient.y;
    out.db = p.ambient * ambient.z;
    out.sr = p.ambient_specular * ambient.x;
    out.sg = p.ambient_specular * ambient.y;
    out.sb = p.ambient_specular * ambient.z;
    for (const ShadeLight& light : lights) {
        if (light.is_ambient) continue;
        add_light(light, p, s, highlight, out);
    }
    return out;
}

}  // namespace facet
