#include "shade/model_pbr.hpp"

#include <algorithm>
#include <cmath>

#include "core/exact_trig.hpp"
#include "shade/brdf.hpp"
#include "shade/environment_map.hpp"
#include "shade/light_sample.hpp"
#include "shade/shading_models.hpp"
#include "shade/shadow_map.hpp"

namespace facet {
namespace {

using pbr::kPi;

// A clear coat is a dielectric of ior 1.5 (KHR_materials_clearcoat).
constexpr float kCoatF0 = 0.04f;

// One lane's point, with everything that does not depend on the light.
struct PbrPoint {
    glm::vec3 position, n, v, coat_n;
    float n_dot_v, coat_n_dot_v;
    glm::vec3 base;  // the base colour: a dielectric's albedo, a metal's f0
    float metallic, roughness, alpha, occlusion;
    glm::vec3 f0;  // the dielectric's
    float f90;
    float coat, coat_roughness, coat_alpha;
    pbr::DfgTerms dfg, coat_dfg;  // directional albedo terms at n.v
    // Energy compensation of each specular lobe (brdf.hpp).
    glm::vec3 metal_compensation, dielectric_compensation;
    bool receives_shadow;
};

glm::vec3 lane3(const simd::vf (&v)[3], int i) {
    return {v[0][i], v[1][i], v[2][i]};
}

PbrPoint point_at(const SurfaceLanes& in, int i, const glm::vec3& eye) {
    const SurfaceBatch& s = in.surface;
    const PbrLanes& l = in.pbr;
    PbrPoint p;
    p.position = {s.px[i], s.py[i], s.pz[i]};
    p.n = normalise_or({s.nx[i], s.ny[i], s.nz[i]}, glm::vec3(0, 1, 0));
    p.v = normalise_or(eye - p.position, p.n);
    p.coat_n = normalise_or(lane3(l.coat_normal, i), p.n);
    p.n_dot_v = std::max(dot3(p.n, p.v), pbr::kMinNdotV);
    p.coat_n_dot_v = std::max(dot3(p.coat_n, p.v), pbr::kMinNdotV);
    p.base = in.albedo_at(i);
    p.metallic = std::clamp(l.metallic[i], 0.0f, 1.0f);
    p.roughness = std::clamp(l.roughness[i], 0.0f, 1.0f);
    p.alpha = pbr::alpha_from_roughness(p.roughness);
    p.occlusion = std::clamp(l.occlusion[i], 0.0f, 1.0f);
    p.f0 = lane3(l.f0, i);
    p.f90 = l.f90[i];
    p.coat = std::clamp(l.clearcoat[i], 0.0f, 1.0f);
    p.coat_roughness = std::clamp(l.clearcoat_roughness[i], 0.0f, 1.0f);
    p.coat_alpha = pbr::alpha_from_roughness(p.coat_roughness);
    const pbr::DfgTable& table = pbr::dfg_table();
    p.dfg = table.lookup(p.n_dot_v, p.roughness);
    p.coat_dfg = p.coat > 0.0f ? table.lookup(p.coat_n_dot_v, p.coat_roughness) : pbr::DfgTerms{};
    const float albedo = p.dfg.albedo();
    p.metal_compensation = pbr::energy_compensation(p.base, albedo);
    p.dielectric_compensation = pbr::energy_compensation(p.f0, albedo);
    p.receives_shadow = s.receives_shadow[i] > 0;
    return p;
}

// The directional albedo of a Schlick lobe with reflectances f0 and f90:
// f0 * scale + f90 * bias (Karis 2013's split sum).
glm::vec3 lobe_albedo(const glm::vec3& f0, float f90, const pbr::DfgTerms& dfg) {
    return f0 * dfg.scale + glm::vec3(f90 * dfg.bias);
}

// The coat's share of what reaches the base: 1 - coat * E_coat (its
// directional albedo), the same for lights and the environment, so a
// white coated surface under a white environment still reflects 1.
float coat_transmission(const PbrPoint& p) {
    return 1.0f - p.coat * (kCoatF0 * p.coat_dfg.scale + p.coat_dfg.bias);
}

// glTF Appendix B.3.5 for one light direction, times n.l; with
// KHR_materials_specular's f0 and f90 for the dielectric, and the coat.
glm::vec3 light_response(const PbrPoint& p, const glm::vec3& l) {
    glm::vec3 result(0.0f);
    const float n_dot_l = dot3(p.n, l);
    if (n_dot_l > 0.0f) {
        const pbr::HalfVector h = pbr::half_vector(p.n, p.v, l);
        const float specular = pbr::specular_brdf(h, n_dot_l, p.n_dot_v, p.alpha);
        const float w = pbr::schlick_weight(h.v_dot_h);
        const glm::vec3 fd = p.f0 + (glm::vec3(p.f90) - p.f0) * w;
        const glm::vec3 dielectric = (glm::vec3(1.0f) - fd) * (1.0f / kPi) * p.base +
                                     fd * specular * p.dielectric_compensation;
        const glm::vec3 metal = pbr::schlick_fresnel(p.base, w) * specular * p.metal_compensation;
        result = ((1.0f - p.metallic) * dielectric + p.metallic * metal) * n_dot_l;
    }
    if (!(p.coat > 0.0f)) return result;
    result *= coat_transmission(p);
    const float coat_n_dot_l = dot3(p.coat_n, l);
    if (coat_n_dot_l > 0.0f) {
        const pbr::HalfVector h = pbr::half_vector(p.coat_n, p.v, l);
        const float f = pbr::schlick_fresnel(kCoatF0, pbr::schlick_weight(h.v_dot_h));
        result += glm::vec3(p.coat * f *
                            pbr::specular_brdf(h, coat_n_dot_l, p.coat_n_dot_v, p.coat_alpha) *
                            coat_n_dot_l);
    }
    return result;
}

// Punctual lights: pi times their radiance (facet's intensities are
// irradiance over pi, see the header), times shadow visibility. Ambient
// lights light the point from every direction alike: a uniform
// environment, added to `uniform`.
glm::vec3 direct_light(const PbrPoint& p, std::span<const ShadeLight> lights, glm::vec3& uniform) {
    glm::vec3 sum(0.0f);
    for (const ShadeLight& light : lights) {
        if (light.is_ambient) {
            uniform += light.radiance;
            continue;
        }
        LightSample sample = sample_light(light, p.position);
        if (!(sample.radiance.x > 0 || sample.radiance.y > 0 || sample.radiance.z > 0)) continue;
        if (p.receives_shadow) sample.radiance *= light_visibility(light, p.position, p.n);
        sum += kPi * sample.radiance * light_response(p, sample.to_light);
    }
    return sum;
}

// The split sum for an environment whose diffuse radiance E(n)/pi is
// `diffuse` and whose specular lobes read `specular` and `coat_specular`:
// metal and dielectric lobes weighted by their directional albedo and
// compensated, the dielectric's diffuse by what its lobe leaves (Fdez-Aguera
// 2019), then the coat over both.
glm::vec3 environment_response(const PbrPoint& p, const glm::vec3& diffuse,
                               const glm::vec3& specular, const glm::vec3& coat_specular) {
    const glm::vec3 dielectric_lobe = lobe_albedo(p.f0, p.f90, p.dfg) * p.dielectric_compensation;
    const glm::vec3 metal_lobe = lobe_albedo(p.base, 1.0f, p.dfg) * p.metal_compensation;
    const glm::vec3 dielectric =
        (glm::vec3(1.0f) - glm::min(dielectric_lobe, glm::vec3(1.0f))) * p.base * diffuse +
        dielectric_lobe * specular;
    glm::vec3 result = (1.0f - p.metallic) * dielectric + p.metallic * metal_lobe * specular;
    if (p.coat > 0.0f)
        result = result * coat_transmission(p) +
                 p.coat * (kCoatF0 * p.coat_dfg.scale + p.coat_dfg.bias) * coat_specular;
    return result;
}

glm::vec3 reflect_view(const glm::vec3& n, const glm::vec3& v) {
    return 2.0f * dot3(n, v) * n - v;
}

glm::vec3 indirect_light(const PbrPoint& p, const EnvironmentLighting* environment,
                         const glm::vec3& uniform) {
    glm::vec3 sum(0.0f);
    if (uniform != glm::vec3(0.0f)) sum += environment_response(p, uniform, uniform, uniform);
    if (environment && environment->map && environment->intensity > 0.0f) {
        const pbr::PrefilteredEnvironment& map = *environment->map;
        const glm::vec3 diffuse = map.diffuse(environment->to_map(p.n));
        const glm::vec3 specular =
            map.specular(environment->to_map(reflect_view(p.n, p.v)), p.roughness);
        const glm::vec3 coat =
            p.coat > 0.0f
                ? map.specular(environment->to_map(reflect_view(p.coat_n, p.v)), p.coat_roughness)
                : glm::vec3(0.0f);
        sum += environment->intensity * environment_response(p, diffuse, specular, coat);
    }
    return sum * p.occlusion;
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
    for (int i = 0; i < in.count; ++i) {
        const PbrPoint p = point_at(in, i, context.eye);
        glm::vec3 uniform(0.0f);
        const glm::vec3 direct = direct_light(p, context.lights, uniform);
        out.set(i, direct + indirect_light(p, context.environment, uniform));
    }
}

}  // namespace facet
