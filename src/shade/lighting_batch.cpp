#include "shade/lighting_batch.hpp"

#include <cmath>

#include <glm/trigonometric.hpp>

#include "shade/light_lanes.hpp"

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
                      &s.shininess, &s.receives_shadow})
            (*v)[i] = (*v)[0];
}

namespace {

// Per lane, the unit normal (n) and the unit vector to the eye (e).
struct UnitVectors {
    vf nx, ny, nz, ex, ey, ez;
};

// Unit normal (a zero one becomes +Y) and unit vector to the eye.
[[gnu::always_inline]] inline void normalise(vf x, vf y, vf z, UnitVectors& u, bool eye_vector) {
    vf len = simd::vsqrt(x * x + y * y + z * z);
    vi ok = len > splat(0.0f);
    vf inv = 1.0f / (ok ? len : splat(1.0f));
    if (eye_vector) {
        u.ex = x * inv;
        u.ey = y * inv;
        u.ez = z * inv;
    } else {
        u.nx = ok ? x * inv : splat(0.0f);
        u.ny = ok ? y * inv : splat(1.0f);
        u.nz = ok ? z * inv : splat(0.0f);
    }
}

// The cosine the highlight's power raises: of the half vector and the
// normal (Blinn), or of the reflected light and the eye vector (Phong).
[[gnu::always_inline]] inline vf highlight_cosine(Highlight highlight, const UnitVectors& s,
                                                  const IncomingLight& in, vf n_dot_l) {
    const vf zero = splat(0.0f);
    const vf lx = in.lx, ly = in.ly, lz = in.lz;
    vf cosine;
    if (highlight == Highlight::blinn) {
        vf hx = lx + s.ex, hy = ly + s.ey, hz = lz + s.ez;
        vf len2 = hx * hx + hy * hy + hz * hz;
        vf len = simd::vsqrt(len2);
        vi ok = len > zero;
        cosine = (s.nx * hx + s.ny * hy + s.nz * hz) / (ok ? len : splat(1.0f));
        cosine = ok ? cosine : zero;
    } else {
        vf twice = 2.0f * n_dot_l;
        vf rx = twice * s.nx - lx, ry = twice * s.ny - ly, rz = twice * s.nz - lz;
        cosine = rx * s.ex + ry * s.ey + rz * s.ez;
    }
    return cosine;
}

// Adds one light's diffuse and highlight to `out`.
[[gnu::always_inline]] inline void add_light(const ShadeLight& light, const SurfaceBatch& p,
                                             const UnitVectors& s, Highlight highlight,
                                             LightingBatch& out) {
    const vf zero = splat(0.0f);
    IncomingLight in = incoming_light(light, p);
    vf n_dot_l = s.nx * in.lx + s.ny * in.ly + s.nz * in.lz;
    vi lit = in.usable & (n_dot_l > zero);
    if (light.shadow) apply_shadow(*light.shadow, p, s.nx, s.ny, s.nz, lit, in);
    vf d = lit ? p.diffuse * n_dot_l : zero;
    out.dr += d * in.rr;
    out.dg += d * in.rg;
    out.db += d * in.rb;

    vf cosine = highlight_cosine(highlight, s, in, n_dot_l);
    vi highlighted = lit & (cosine > zero) & (p.specular > zero);
    vf power = simd::vpow_unit(simd::vmin(cosine, splat(1.0f)), p.shininess);
    vf k = highlighted ? p.specular * power : zero;
    out.sr += k * in.rr;
    out.sg += k * in.rg;
    out.sb += k * in.rb;
}

}  // namespace

LightingBatch light_surface_batch(const SurfaceBatch& surface, const glm::vec3& eye,
                                  std::span<const ShadeLight> lights, Highlight highlight) {
    UnitVectors s;
    normalise(surface.nx, surface.ny, surface.nz, s, false);
    normalise(eye.x - surface.px, eye.y - surface.py, eye.z - surface.pz, s, true);
    const SurfaceBatch& p = surface;
    LightingBatch out;
    const glm::vec3 ambient = ambient_light(lights);
    out.dr = p.ambient * ambient.x;
    out.dg = p.ambient * ambient.y;
    out.db = p.ambient * ambient.z;
    out.sr = out.sg = out.sb = splat(0.0f);
    for (const ShadeLight& light : lights) {
        if (light.is_ambient) continue;
        add_light(light, p, s, highlight, out);
    }
    return out;
}

}  // namespace facet
