#include "shade/lighting_batch.hpp"

#include <cmath>

#include <glm/trigonometric.hpp>

#include "shade/shadow_map.hpp"

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

LightingBatch light_surface_batch(const SurfaceBatch& surface, const glm::vec3& eye,
                                  std::span<const ShadeLight> lights, Highlight highlight) {
    struct Unit {
        vf nx, ny, nz, ex, ey, ez;
    };
    // Unit normal (a zero one becomes +Y) and unit vector to the eye.
    auto normalise = [](vf x, vf y, vf z, Unit& u, bool eye_vector) {
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
    };
    Unit s;
    normalise(surface.nx, surface.ny, surface.nz, s, false);
    normalise(eye.x - surface.px, eye.y - surface.py, eye.z - surface.pz, s, true);
    const SurfaceBatch& p = surface;
    LightingBatch out;
    const glm::vec3 ambient = ambient_light(lights);
    out.dr = p.ambient * ambient.x;
    out.dg = p.ambient * ambient.y;
    out.db = p.ambient * ambient.z;
    out.sr = out.sg = out.sb = splat(0.0f);
    const vf zero = splat(0.0f);
    for (const ShadeLight& light : lights) {
        if (light.is_ambient) continue;
        vf lx, ly, lz, rr, rg, rb;
        vi usable = simd::splat_i(-1);
        if (light.is_point) {
            vf dx = light.position.x - p.px, dy = light.position.y - p.py,
               dz = light.position.z - p.pz;
            vf dist2 = dx * dx + dy * dy + dz * dz;
            usable = dist2 > zero;
            vf safe = usable ? dist2 : splat(1.0f);
            vf inv_len = 1.0f / simd::vsqrt(safe);
            lx = dx * inv_len;
            ly = dy * inv_len;
            lz = dz * inv_len;
            vf falloff = 1.0f / safe;  // inverse-square
            if (light.inv_range > 0.0f) falloff *= range_window(dist2, light.inv_range);
            if (light.is_spot)
                falloff *= spot_cone(
                    lx * light.direction.x + ly * light.direction.y + lz * light.direction.z,
                    light);
            usable &= falloff > zero;
            rr = light.radiance.x * falloff;
            rg = light.radiance.y * falloff;
            rb = light.radiance.z * falloff;
        } else {
            lx = splat(light.direction.x);
            ly = splat(light.direction.y);
            lz = splat(light.direction.z);
            rr = splat(light.radiance.x);
            rg = splat(light.radiance.y);
            rb = splat(light.radiance.z);
        }
        vf n_dot_l = s.nx * lx + s.ny * ly + s.nz * lz;
        vi lit = usable & (n_dot_l > zero);
        if (light.shadow) {
            // Shadow-map lookups one lane at a time, only where the light
            // arrives and the surface receives shadows.
            vf visible = splat(1.0f);
            for (int i = 0; i < simd::kLanes; ++i)
                if (lit[i] && p.receives_shadow[i] > 0.0f)
                    visible[i] = shadow_visibility(*light.shadow, {p.px[i], p.py[i], p.pz[i]},
                                                   {s.nx[i], s.ny[i], s.nz[i]});
            rr *= visible;
            rg *= visible;
            rb *= visible;
        }
        vf d = lit ? p.diffuse * n_dot_l : zero;
        out.dr += d * rr;
        out.dg += d * rg;
        out.db += d * rb;

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
        vi highlighted = lit & (cosine > zero) & (p.specular > zero);
        vf power = simd::vpow_unit(simd::vmin(cosine, splat(1.0f)), p.shininess);
        vf k = highlighted ? p.specular * power : zero;
        out.sr += k * rr;
        out.sg += k * rg;
        out.sb += k * rb;
    }
    return out;
}

}  // namespace facet
