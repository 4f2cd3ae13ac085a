#include "llvmpipe_pbr.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/gtc/type_ptr.hpp>

#include "anim/track.hpp"
#include "assets/mesh.hpp"
#include "core/display_transform.hpp"
#include "render/shade_lights.hpp"
#include "shade/brdf.hpp"
#include "shade/environment_map.hpp"
#include "shade/lanes.hpp"
#include "shade/model_pbr.hpp"

namespace facet_bench {
namespace {

// Texture units: the reference's base colour texture is on 0 and its
// shadow map on 1.
constexpr int kDfgUnit = 2;
constexpr int kEnvironmentUnit = 3;
constexpr int kSheenUnit = 4;
static_assert(PbrPeer::kBackdropUnit > kSheenUnit);

// The surface at a fragment and the BRDF under one light: point_at and
// light_response of src/shade/model_pbr.cpp with brdf.hpp's formulas
// (docs/pbr.md), in the same order of operations. No clear coat and no
// maps: the set-up refuses materials with them. DfgTable::lookup reads the
// table's four nodes round (n.v, roughness) with texelFetch and blends
// them as facet does, inputs clamped to the grid; SheenTable::lookup the
// same from its own table. The sheen (brdf_layers.hpp's with_sheen and
// with_sheen_environment) is compiled in only when a material has one,
// as a GL programmer would; so is the transmission (TRANSMISSION, the
// glass draws' program only).
const char* kSurfaceGlsl = R"(
const float kPi = 3.14159265358979323846;
const float kMinRoughness = 0.045;
const float kMinNdotV = 1e-4;
const int kDfgLast = DFG_SIZE - 1;
uniform vec3 u_eye;
uniform vec2 u_metallic_roughness;
uniform vec3 u_f0;  // the dielectric's: from the ior and KHR_materials_specular
uniform float u_f90;
uniform sampler2D u_dfg;  // (scale, bias): column n.v, row roughness
#ifdef SHEEN
uniform vec3 u_sheen_color;
uniform float u_sheen_roughness;
uniform sampler2D u_sheen;  // E_s: column n.v, row sheen roughness
#endif
#ifdef TRANSMISSION
uniform float u_transmission;
uniform float u_ior;
#endif

struct Surface {
    vec3 position, n, v, base, f0;
    float n_dot_v, metallic, roughness, alpha, f90;
    vec2 dfg;  // scale, bias
    vec3 metal_compensation, dielectric_compensation;
    vec3 diffuse_albedo;  // the base's diffuse share: all of it, 1 - t of it under a transmission
#ifdef TRANSMISSION
    float transmission, transmission_roughness, transmission_alpha;
#endif
#ifdef SHEEN
    vec3 sheen_color;
    float sheen_max, sheen_roughness, sheen_alpha, lambda_v, albedo_v, keeps_v;
    float a, b, c, d, e, l_half;  // the masking fit's coefficients, and l(0.5)
#endif
};

vec2 table_lookup(sampler2D table, float n_dot_v, float roughness) {
    float x = clamp(n_dot_v, 0.0, 1.0) * float(kDfgLast);
    float y = (clamp(roughness, kMinRoughness, 1.0) - kMinRoughness) / (1.0 - kMinRoughness) *
              float(kDfgLast);
    int i = min(int(x), kDfgLast - 1);
    int j = min(int(y), kDfgLast - 1);
    float tx = x - float(i), ty = y - float(j);
    vec2 t00 = texelFetch(table, ivec2(i, j), 0).rg;
    vec2 t10 = texelFetch(table, ivec2(i + 1, j), 0).rg;
    vec2 t01 = texelFetch(table, ivec2(i, j + 1), 0).rg;
    vec2 t11 = texelFetch(table, ivec2(i + 1, j + 1), 0).rg;
    vec2 low = t00 + (t10 - t00) * tx;
    vec2 high = t01 + (t11 - t01) * tx;
    return low + (high - low) * ty;
}

#ifdef SHEEN
// The Charlie distribution, its masking fit and Lambda (brdf_terms.hpp).
float sheen_l(Surface s, float x) {
    return s.a / (1.0 + s.b * pow(x, s.c)) + s.d * x + s.e;
}
float sheen_lambda(Surface s, float cosine) {
    return cosine < 0.5 ? exp(sheen_l(s, cosine)) : exp(2.0 * s.l_half - sheen_l(s, 1.0 - cosine));
}
void prepare_sheen(inout Surface s) {
    s.sheen_color = clamp(u_sheen_color, 0.0, 1.0);
    s.sheen_max = max(s.sheen_color.r, max(s.sheen_color.g, s.sheen_color.b));
    s.keeps_v = 1.0;
    if (!(s.sheen_max > 0.0)) return;
    s.sheen_roughness = clamp(u_sheen_roughness, 0.0, 1.0);
    float r = clamp(s.sheen_roughness, kMinRoughness, 1.0);
    s.sheen_alpha = r * r;
    float t = (1.0 - s.sheen_alpha) * (1.0 - s.sheen_alpha);
    s.a = mix(21.5473, 25.3245, t);
    s.b = mix(3.82987, 3.32435, t);
    s.c = mix(0.19823, 0.16801, t);
    s.d = mix(-1.97760, -1.27393, t);
    s.e = mix(-4.32054, -4.85967, t);
    s.l_half = sheen_l(s, 0.5);
    s.lambda_v = sheen_lambda(s, s.n_dot_v);
    s.albedo_v = table_lookup(u_sheen, s.n_dot_v, s.sheen_roughness).r;
    s.keeps_v = 1.0 - s.sheen_max * s.albedo_v;
}
// The base keeps 1 - max(colour) max(E(n.v), E(n.l)); the lobe adds.
vec3 with_sheen(Surface s, float n_cross_h2, float n_dot_l, vec3 result) {
    if (!(s.sheen_max > 0.0)) return result;
    float cosine = max(n_dot_l, kMinNdotV);
    float keeps = min(s.keeps_v, 1.0 - s.sheen_max *
                                           table_lookup(u_sheen, cosine, s.sheen_roughness).r);
    float inverse = 1.0 / s.sheen_alpha;
    float charlie = (2.0 + inverse) * pow(min(n_cross_h2, 1.0), 0.5 * inverse) * (0.5 / kPi);
    float lobe = charlie / ((1.0 + s.lambda_v + sheen_lambda(s, cosine)) * (4.0 * s.n_dot_v));
    return result * keeps + s.sheen_color * lobe;
}
#endif

#ifdef TRANSMISSION
// brdf_layers.hpp's prepare_transmission_terms: the diffuse keeps 1 - t,
// and the refraction's lobe is the surface's with its roughness scaled by
// clamp(2 ior - 2, 0, 1) (an index of 1 bends nothing, so blurs nothing).
void prepare_transmission(inout Surface s) {
    s.transmission = clamp(u_transmission, 0.0, 1.0);
    s.diffuse_albedo = s.diffuse_albedo * (1.0 - s.transmission);
    s.transmission_roughness = s.roughness * clamp(2.0 * u_ior - 2.0, 0.0, 1.0);
    float r = clamp(s.transmission_roughness, kMinRoughness, 1.0);
    s.transmission_alpha = r * r;
}
#endif

Surface surface_at(vec3 position, vec3 n, vec3 base) {
    Surface s;
    s.position = position;
    s.n = n;
    vec3 to_eye = u_eye - position;
    float len = length(to_eye);
    s.v = len > 0.0 ? to_eye * (1.0 / len) : n;
    s.n_dot_v = max(dot(s.n, s.v), kMinNdotV);
    s.base = base;
    s.metallic = clamp(u_metallic_roughness.x, 0.0, 1.0);
    s.roughness = clamp(u_metallic_roughness.y, 0.0, 1.0);
    float r = clamp(s.roughness, kMinRoughness, 1.0);
    s.alpha = r * r;
    s.f0 = u_f0;
    s.f90 = u_f90;
    s.dfg = table_lookup(u_dfg, s.n_dot_v, s.roughness);
    float k = 1.0 / (s.dfg.x + s.dfg.y) - 1.0;
    s.metal_compensation = vec3(1.0) + s.base * k;
    s.dielectric_compensation = vec3(1.0) + s.f0 * k;
    s.diffuse_albedo = base;
#ifdef SHEEN
    prepare_sheen(s);
#endif
#ifdef TRANSMISSION
    prepare_transmission(s);
#endif
    return s;
}

// The symmetric half vector l + v: n.h, |n x h|^2 and v.h.
struct HalfVector {
    float n_dot_h, n_cross_h2, v_dot_h;
};
HalfVector half_vector(vec3 n, vec3 v, vec3 l) {
    vec3 sum = l + v;
    float s2 = dot(sum, sum);
    HalfVector h = HalfVector(0.0, 1.0, 0.0);
    if (s2 > 1e-12) {
        float sum_length = sqrt(s2);
        vec3 n_cross_s = cross(n, sum);
        h.n_dot_h = dot(n, sum) / sum_length;
        h.n_cross_h2 = dot(n_cross_s, n_cross_s) / s2;
        h.v_dot_h = 0.5 * sum_length;
    }
    return h;
}

// GGX with the denominator from |n x h|^2 times height-correlated Smith.
float specular_lobe(HalfVector h, float n_dot_l, float n_dot_v, float alpha) {
    float a2 = alpha * alpha;
    float d = h.n_dot_h * h.n_dot_h * a2 + h.n_cross_h2;
    float distribution = h.n_dot_h > 0.0 ? a2 / (kPi * d * d) : 0.0;
    float view_root = sqrt(n_dot_v * n_dot_v * (1.0 - a2) + a2);
    float light_root = sqrt(n_dot_l * n_dot_l * (1.0 - a2) + a2);
    return distribution * (0.5 / (n_dot_l * view_root + n_dot_v * light_root));
}

float schlick_weight(float v_dot_h) {
    float m = 1.0 - clamp(v_dot_h, 0.0, 1.0);
    float m2 = m * m;
    return m2 * m2 * m;
}

#ifdef TRANSMISSION
uniform vec3 u_transmittance;  // what the volume leaves across its thickness (Beer-Lambert)

// A light behind the surface through the specular BTDF, the light mirrored
// to the viewer's side (brdf_layers.hpp's with_transmission):
//   (1 - metallic) t T base (1 - F(v.h')) D(h') V(n.l', n.v) |n.l|
vec3 light_behind(Surface s, vec3 l, float n_dot_l) {
    if (!(s.transmission > 0.0)) return vec3(0.0);
    vec3 mirrored = l - 2.0 * n_dot_l * s.n;
    float cosine = -n_dot_l;
    HalfVector h = half_vector(s.n, s.v, mirrored);
    float lobe = specular_lobe(h, cosine, s.n_dot_v, s.transmission_alpha);
    vec3 fd = s.f0 + (vec3(s.f90) - s.f0) * schlick_weight(h.v_dot_h);
    float share = (1.0 - s.metallic) * s.transmission * lobe * cosine;
    return (vec3(1.0) - fd) * share * s.base * u_transmittance;
}
#endif

// The base's BRDF under one light, the sheen over it, and under a
// transmission the light from behind.
vec3 light_response(Surface s, vec3 l) {
    float n_dot_l = dot(s.n, l);
#ifdef TRANSMISSION
    if (n_dot_l < 0.0) return light_behind(s, l, n_dot_l);
#endif
    if (!(n_dot_l > 0.0)) return vec3(0.0);
    HalfVector h = half_vector(s.n, s.v, l);
    float n_cross_h2 = h.n_cross_h2;
    float specular = specular_lobe(h, n_dot_l, s.n_dot_v, s.alpha);
    float w = schlick_weight(h.v_dot_h);
    vec3 fd = s.f0 + (vec3(s.f90) - s.f0) * w;
    vec3 dielectric = (vec3(1.0) - fd) * (1.0 / kPi) * s.diffuse_albedo +
                      fd * specular * s.dielectric_compensation;
    vec3 metal = (s.base + (vec3(1.0) - s.base) * w) * specular * s.metal_compensation;
    vec3 result = ((1.0 - s.metallic) * dielectric + s.metallic * metal) * n_dot_l;
#ifdef SHEEN
    result = with_sheen(s, n_cross_h2, n_dot_l, result);
#endif
    return result;
}

// The split sum for diffuse radiance E(n)/pi and prefiltered specular
// radiance: model_pbr.cpp's environment_response without the coat.
vec3 environment_response(Surface s, vec3 diffuse, vec3 specular) {
    vec3 dielectric_lobe =
        (s.f0 * s.dfg.x + vec3(s.f90 * s.dfg.y)) * s.dielectric_compensation;
    vec3 metal_lobe = (s.base * s.dfg.x + vec3(s.dfg.y)) * s.metal_compensation;
    vec3 dielectric = (vec3(1.0) - min(dielectric_lobe, vec3(1.0))) * s.diffuse_albedo * diffuse +
                      dielectric_lobe * specular;
    vec3 result = (1.0 - s.metallic) * dielectric + s.metallic * metal_lobe * specular;
#ifdef SHEEN
    if (s.sheen_max > 0.0) result = result * s.keeps_v + s.sheen_color * s.albedo_v * diffuse;
#endif
    return result;
}

#ifdef TRANSMISSION
// What the surface passes of the radiance behind it (brdf.hpp's
// transmitted_response): the dielectric's share t, tinted by the base
// colour and the volume, weighted by what its specular lobe leaves, under
// the sheen as the environment's diffuse light.
vec3 transmitted_response(Surface s, vec3 behind) {
    vec3 lobe = (s.f0 * s.dfg.x + vec3(s.f90 * s.dfg.y)) * s.dielectric_compensation;
    vec3 result = (1.0 - s.metallic) * (vec3(1.0) - min(lobe, vec3(1.0))) * s.transmission *
                  u_transmittance * s.base * behind;
#ifdef SHEEN
    if (s.sheen_max > 0.0) result *= s.keeps_v;
#endif
    return result;
}
#endif
)";

// The glass's view of what lies behind it (shade/transmission_backdrop.cpp's
// radiance_behind): the opaque pass's linear colour, resolved into a
// half-float texture with its 2x2 box mip chain, clamped to its edges and
// read trilinearly where the view refracted by refract(-v, n, 1 / ior)
// leaves the volume, position + thickness * that direction, at level
// log2(width) * the refraction's roughness. With dispersion each channel
// takes its own index, ior -+ (ior - 1) 0.025 dispersion. GL's texture
// rows run bottom-up, so v is 0.5 (y / w + 1) where facet's image rows,
// top-down, take 0.5 (1 - y / w): the same place.
const char* kBackdropGlsl = R"(
uniform sampler2D u_backdrop;
uniform mat4 u_view_projection;
uniform float u_thickness;  // world units: the material's times the object's scale
#ifdef DISPERSION
uniform float u_dispersion;
#endif

vec2 backdrop_uv(vec3 point, vec3 fallback) {
    vec4 clip = u_view_projection * vec4(point, 1.0);
    if (!(clip.w > 0.0)) clip = u_view_projection * vec4(fallback, 1.0);
    if (!(clip.w > 0.0)) return vec2(0.5);
    return 0.5 * (clip.xy / clip.w) + 0.5;
}

vec4 backdrop_along(Surface s, float ior, float lod) {
    // Entering a denser medium the view always refracts.
    vec3 direction = refract(-s.v, s.n, 1.0 / max(ior, 1.0));
    vec3 exit = s.position + u_thickness * direction;
    return textureLod(u_backdrop, backdrop_uv(exit, s.position), lod);
}

vec3 radiance_behind(Surface s) {
    float lod = kBackdropLevelScale * s.transmission_roughness;
#ifdef DISPERSION
    float spread = (u_ior - 1.0) * 0.025 * u_dispersion;
    return vec3(backdrop_along(s, u_ior - spread, lod).r, backdrop_along(s, u_ior, lod).g,
                backdrop_along(s, u_ior + spread, lod).b);
#else
    return backdrop_along(s, u_ior, lod).rgb;
#endif
}
)";

// The environment: PrefilteredEnvironment::diffuse (the 9 coefficients,
// spherical_harmonics.cpp's basis and cosine factors, clamped at 0) and
// ::specular (level from roughness, bilinear within a level over the
// copied border as OctahedralMap::sample reads it, a blend between two
// levels), with octahedral_encode, looked up in the map's frame
// (EnvironmentLighting::to_map). The levels lie one above the other in one
// float texture, each with its border, read with texelFetch.
const char* kEnvironmentGlsl = R"(
uniform sampler2D u_environment;
uniform int u_level_row[LEVELS];   // first row of each level, border included
uniform int u_level_size[LEVELS];  // texels a side, border excluded
uniform vec3 u_sh[9];
uniform vec2 u_rotation;  // cos, sin
uniform float u_intensity;

vec3 to_map(vec3 d) {
    return vec3(u_rotation.x * d.x - u_rotation.y * d.z, d.y,
                u_rotation.y * d.x + u_rotation.x * d.z);
}

vec2 octahedral_encode(vec3 d) {
    float l1 = abs(d.x) + abs(d.y) + abs(d.z);
    if (!(l1 > 0.0 && l1 <= 3.40282347e38)) return vec2(0.0);
    float inverse = 1.0 / l1;
    float x = d.x * inverse, z = d.z * inverse;
    if (d.y >= 0.0) return vec2(x, z);
    float sign_x = x >= 0.0 ? 1.0 : -1.0, sign_z = z >= 0.0 ? 1.0 : -1.0;
    return vec2((1.0 - abs(z)) * sign_x, (1.0 - abs(x)) * sign_z);
}

float level_coordinate(float along, float size) {
    return max(0.5, min((along * 0.5 + 0.5) * size + 0.5, size + 0.5));
}

vec3 level_sample(int k, vec2 p) {
    int size = u_level_size[k];
    float x = level_coordinate(p.x, float(size)), y = level_coordinate(p.y, float(size));
    int column = min(int(x), size), row = min(int(y), size);
    float tx = x - float(column), ty = y - float(row);
    ivec2 at = ivec2(column, u_level_row[k] + row);
    vec3 u0 = texelFetch(u_environment, at, 0).rgb;
    vec3 u1 = texelFetch(u_environment, at + ivec2(1, 0), 0).rgb;
    vec3 l0 = texelFetch(u_environment, at + ivec2(0, 1), 0).rgb;
    vec3 l1 = texelFetch(u_environment, at + ivec2(1, 1), 0).rgb;
    vec3 upper = u0 + (u1 - u0) * tx;
    vec3 lower = l0 + (l1 - l0) * tx;
    return upper + (lower - upper) * ty;
}

vec3 environment_specular(vec3 reflected, float roughness) {
    float position = max(0.0, min(roughness, 1.0)) * float(LEVELS - 1);
    int k = min(int(position), LEVELS - 1);
    float t = position - float(k);
    vec2 p = octahedral_encode(reflected);
    vec3 lower = level_sample(k, p);
    if (t == 0.0) return lower;
    vec3 upper = level_sample(k + 1, p);
    return lower + (upper - lower) * t;
}

vec3 environment_diffuse(vec3 n) {
    const float band0 = 3.14159265358979323846;
    const float band1 = 2.09439510239319549231;
    const float band2 = 0.78539816339744830962;
    vec3 e = vec3(0.0);
    e += u_sh[0] * (band0 * 0.28209479177387814);
    e += u_sh[1] * (band1 * (0.48860251190291992 * n.y));
    e += u_sh[2] * (band1 * (0.48860251190291992 * n.z));
    e += u_sh[3] * (band1 * (0.48860251190291992 * n.x));
    e += u_sh[4] * (band2 * (1.09254843059207907 * n.x * n.y));
    e += u_sh[5] * (band2 * (1.09254843059207907 * n.y * n.z));
    e += u_sh[6] * (band2 * (0.31539156525252001 * (3.0 * n.z * n.z - 1.0)));
    e += u_sh[7] * (band2 * (1.09254843059207907 * n.x * n.z));
    e += u_sh[8] * (band2 * (0.54627421529603954 * (n.x * n.x - n.y * n.y)));
    return max(e / kPi, vec3(0.0));
}
)";

// Khronos PBR Neutral, display_transform.cpp's khronos_neutral.
const char* kNeutralGlsl = R"(
vec3 neutral(vec3 c) {
    const float start_compression = 0.8 - 0.04, desaturation = 0.15;
    float lowest = min(c.r, min(c.g, c.b));
    float offset = lowest < 0.08 ? lowest - 6.25 * lowest * lowest : 0.04;
    c -= offset;
    float peak = max(c.r, max(c.g, c.b));
    if (peak < start_compression) return c;
    const float d = 1.0 - start_compression;
    float new_peak = 1.0 - d * d / (peak + d - start_compression);
    c *= new_peak / peak;
    float g = 1.0 - 1.0 / (desaturation * (peak - new_peak) + 1.0);
    return c + (vec3(new_peak) - c) * g;
}
)";

// The lights (the scene's directional, point and spot lights), then the
// environment, then the ambient lights as a uniform environment, times
// the exposure, through the tone curve; the framebuffer encodes sRGB. In a
// scene with glass (LINEAR_OUTPUT) the draws leave linear light, as facet's
// frame holds it, for the glass to read and add to; the present pass
// applies exposure and tone curve after them.
const char* kMainGlsl = R"(
in vec3 v_world;
in vec3 v_normal;
in vec2 v_uv;
uniform vec3 u_albedo;
uniform vec2 u_uv_scale;
#ifdef TEXTURED
uniform sampler2D u_texture;
#endif
out vec4 frag_color;

vec3 indirect_light(Surface s) {
    vec3 sum = vec3(0.0);
#ifdef AMBIENT
    sum += environment_response(s, u_ambient_light, u_ambient_light);
#endif
#ifdef ENVIRONMENT
    vec3 diffuse = environment_diffuse(to_map(s.n));
    vec3 r = 2.0 * dot(s.n, s.v) * s.n - s.v;
    vec3 specular = environment_specular(to_map(r), s.roughness);
    sum += u_intensity * environment_response(s, diffuse, specular);
#endif
    return sum;  // times the occlusion, which is 1 without an occlusion map
}

void main() {
    vec3 base = u_albedo;
#ifdef TEXTURED
    base *= texture(u_texture, v_uv * u_uv_scale).rgb;
#endif
    float len = length(v_normal);
    vec3 n = len > 0.0 ? v_normal * (1.0 / len) : vec3(0.0, 1.0, 0.0);
    if (!gl_FrontFacing) n = -n;
    Surface s = surface_at(v_world, n, base);
#ifdef LINEAR_OUTPUT
    vec3 colour = direct_light(s) + indirect_light(s);
#ifdef TRANSMISSION
    colour += transmitted_response(s, radiance_behind(s));
#endif
#else
    vec3 colour = (direct_light(s) + indirect_light(s)) * kExposureGain;
#ifdef NEUTRAL
    colour = neutral(colour);
#endif
#endif
    frag_color = vec4(colour, 1.0);
}
)";

// A light's kind, compiled into the program.
struct LightKind {
    bool point, ranged, spot;
};

// The scene's lights as the reference's draw loop uploads them (at most 8,
// ambient ones apart), from the first frame: their kinds do not change.
std::vector<LightKind> light_kinds(const facet::SceneDesc& scene, const facet::World& world) {
    const facet::FrameState state =
        facet::evaluate_frame(scene, world.object_bounds, scene.output.frames.front());
    std::vector<LightKind> kinds;
    for (const facet::ShadeLight& l : facet::make_shade_lights(state.lights))
        if (!l.is_ambient && kinds.size() < 8)
            kinds.push_back({l.is_point, l.is_point && l.inv_range > 0.0f, l.is_spot});
    return kinds;
}

// direct_light, unrolled over the scene's lights: pi times each light's
// radiance (facet's intensities are irradiance over pi), its shadow for
// the shadow light, times the BRDF and cosine. `behind_too`: the light
// also arrives from behind (a transmission), its shadow looked up on that
// side, as model_pbr.cpp's direct_light does.
std::string direct_light_glsl(const std::vector<LightKind>& kinds, int shadow_index,
                              bool behind_too) {
    auto flag = [](bool b) { return b ? "true" : "false"; };
    std::string glsl =
        "vec3 direct_light(Surface s) {\n    vec3 sum = vec3(0.0);\n    vec3 l, radiance;\n";
    for (size_t i = 0; i < kinds.size(); ++i) {
        glsl += "    radiance = light_arriving(" + std::to_string(i) + ", s.position, " +
                flag(kinds[i].point) + ", " + flag(kinds[i].ranged) + ", " + flag(kinds[i].spot) +
                ", l);\n";
        if (static_cast<int>(i) == shadow_index)
            glsl += behind_too
                        ? "    radiance *= shadow(s.position, dot(s.n, l) < 0.0 ? -s.n : s.n);\n"
                        : "    if (dot(s.n, l) > 0.0) radiance *= shadow(s.position, s.n);\n";
        glsl += "    sum += kPi * radiance * light_response(s, l);\n";
    }
    return glsl + "    return sum;\n}\n";
}

// The shadow light's index among the uploaded lights: scene order, ambient
// lights left out (as the reference's set_lights counts).
int uploaded_index(const facet::SceneDesc& scene, int scene_light) {
    if (scene_light < 0) return -1;
    int index = 0;
    for (int i = 0; i < scene_light; ++i)
        if (scene.lights[static_cast<size_t>(i)].type != facet::LightType::ambient) ++index;
    return index;
}

// What the port leaves out, named, for a material that has it: maps,
// emission, alpha, and the layers other than a sheen and a transmission of
// constants.
void check_material(const facet::Material& m) {
    const char* missing = m.clearcoat > 0.0f              ? "a clear coat"
                          : m.iridescence > 0.0f          ? "a thin film"
                          : m.anisotropy > 0.0f           ? "an anisotropy"
                          : m.diffuse_transmission > 0.0f ? "a diffuse transmission"
                          : (m.features() & facet::kPhysicalMaps) || m.normal_map ? "a map"
                          : m.emissive_map || m.emissive != glm::vec3(0.0f)       ? "emission"
                          : m.alpha_mode != facet::AlphaMode::opaque              ? "alpha"
                                                                                  : nullptr;
    if (missing)
        throw std::runtime_error("the llvmpipe pbr port does not draw " + std::string(missing) +
                                 " (material " + m.name + ")");
}

// What the port leaves out of glass: its inner surfaces, which facet
// peels and shows through the front ones, and its shadow, which facet
// makes lighter by what the glass lets through (the port's map is depth
// only, so its glass would cast a black one).
void check_glass(const facet::World& world, const facet::Draw& d, int shadow_light) {
    const facet::Material& m = world.materials[d.material];
    const char* missing = m.double_sided ? "double-sided glass"
                          : shadow_light >= 0 && world.casts_shadows[d.object] ? "a glass's shadow"
                                                                               : nullptr;
    if (missing)
        throw std::runtime_error("the llvmpipe pbr port does not draw " + std::string(missing) +
                                 " (material " + m.name + ")");
}

// The full-screen pass that ends a frame with glass: the frame's linear
// light, resolved, times the exposure, through the tone curve, into the
// sRGB framebuffer; one triangle covering the viewport.
const char* kPresentVertexGlsl = R"(
void main() {
    gl_Position = vec4(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0, 0.0, 1.0);
}
)";
const char* kPresentFragmentGlsl = R"(
uniform sampler2D u_frame;
out vec4 frag_color;
void main() {
    vec3 colour = texelFetch(u_frame, ivec2(gl_FragCoord.xy), 0).rgb * kExposureGain;
#ifdef NEUTRAL
    colour = neutral(colour);
#endif
    frag_color = vec4(colour, 1.0);
}
)";

}  // namespace

PbrPeer::PbrPeer(const Gl& gl, const facet::SceneDesc& scene, const facet::World& world,
                 int shadow_light)
    : gl_(gl), scene_(scene), world_(world) {
    for (const facet::Draw& d : world.draws) {
        const facet::Material& m = world.materials[d.material];
        check_material(m);
        sheen_ = sheen_ || m.sheen_color != glm::vec3(0.0f);
        if (!transmits(m)) continue;
        check_glass(world, d, shadow_light);
        glass_ = true;
        dispersion_ = dispersion_ || m.dispersion > 0.0f;
    }
    const facet::Tonemap tonemap = scene.output.display.tonemap;
    if (tonemap != facet::Tonemap::none && tonemap != facet::Tonemap::neutral)
        throw std::runtime_error(std::string("the llvmpipe pbr port has no tone curve ") +
                                 facet::c_name_of(facet::kTonemaps, tonemap));
    bool ambient = false;
    for (const facet::LightDesc& l : scene.lights)
        ambient = ambient || l.type == facet::LightType::ambient;
    char gain[64];
    std::snprintf(gain, sizeof gain, "const float kExposureGain = %.9g;\n",
                  facet::exposure_gain(scene.output.display));
    const bool neutral = tonemap == facet::Tonemap::neutral;
    tone_ =
        (neutral ? "#define NEUTRAL\n" : "") + std::string(gain) + (neutral ? kNeutralGlsl : "");
    defines_ = "#define DFG_SIZE " + std::to_string(facet::pbr::DfgTable::kSize) + "\n" +
               "#define LEVELS " + std::to_string(facet::pbr::kEnvironmentLevels) + "\n" +
               (world.environment ? "#define ENVIRONMENT\n" : "") +
               (ambient ? "#define AMBIENT\n" : "") + (sheen_ ? "#define SHEEN\n" : "");
    const std::vector<LightKind> kinds = light_kinds(scene, world);
    const int shadow_index = uploaded_index(scene, shadow_light);
    direct_light_ = direct_light_glsl(kinds, shadow_index, false);
    if (glass_) glass_direct_light_ = direct_light_glsl(kinds, shadow_index, true);
    upload_dfg_table();
    if (sheen_) upload_sheen_table();
    if (world.environment) upload_environment();
}

std::string PbrPeer::fragment_shader(PbrOutput output) const {
    const std::string environment = world_.environment ? kEnvironmentGlsl : "";
    if (output == PbrOutput::displayed)
        return defines_ + tone_ + kSurfaceGlsl + environment + direct_light_ + kMainGlsl;
    if (output == PbrOutput::linear)
        return defines_ + "#define LINEAR_OUTPUT\n" + kSurfaceGlsl + environment + direct_light_ +
               kMainGlsl;
    // The glass reads the backdrop's levels up to log2 of its width.
    char scale[64];
    std::snprintf(scale, sizeof scale, "const float kBackdropLevelScale = %.9g;\n",
                  std::log2(static_cast<float>(scene_.output.width)));
    return defines_ + "#define LINEAR_OUTPUT\n#define TRANSMISSION\n" +
           (dispersion_ ? "#define DISPERSION\n" : "") + scale + kSurfaceGlsl + environment +
           kBackdropGlsl + glass_direct_light_ + kMainGlsl;
}

ShaderSources PbrPeer::present_shaders() const {
    return {kPresentVertexGlsl, tone_ + kPresentFragmentGlsl};
}

void PbrPeer::upload_dfg_table() {
    const facet::pbr::DfgTable& table = facet::pbr::dfg_table();
    std::vector<float> scale_bias;
    for (const facet::pbr::DfgTerms& t : table.terms) {
        scale_bias.push_back(t.scale);
        scale_bias.push_back(t.bias);
    }
    gl_.ActiveTexture(GL_TEXTURE0 + kDfgUnit);
    glGenTextures(1, &dfg_texture_);
    glBindTexture(GL_TEXTURE_2D, dfg_texture_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RG32F, facet::pbr::DfgTable::kSize,
                 facet::pbr::DfgTable::kSize, 0, GL_RG, GL_FLOAT, scale_bias.data());
    // texelFetch does not filter, but a texture without mipmaps must not
    // ask for them to be complete.
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl_.ActiveTexture(GL_TEXTURE0);
}

void PbrPeer::upload_sheen_table() {
    const facet::pbr::SheenTable& table = facet::pbr::sheen_table();
    gl_.ActiveTexture(GL_TEXTURE0 + kSheenUnit);
    glGenTextures(1, &sheen_texture_);
    glBindTexture(GL_TEXTURE_2D, sheen_texture_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R32F, facet::pbr::DfgTable::kSize,
                 facet::pbr::DfgTable::kSize, 0, GL_RED, GL_FLOAT, table.albedo.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl_.ActiveTexture(GL_TEXTURE0);
}

void PbrPeer::upload_environment() {
    const facet::pbr::PrefilteredEnvironment& env = *world_.environment;
    int width = 0, height = 0;
    for (int k = 0; k < facet::pbr::kEnvironmentLevels; ++k) {
        const int size = env.level(k).size();
        level_rows_.push_back(height);
        level_sizes_.push_back(size);
        width = std::max(width, size + 2);
        height += size + 2;
    }
    std::vector<float> rgb(static_cast<size_t>(width) * height * 3, 0.0f);
    for (int k = 0; k < facet::pbr::kEnvironmentLevels; ++k) {
        const facet::pbr::OctahedralMap& level = env.level(k);
        // Rows and columns -1 and size are the border that fill_border copied.
        for (int row = -1; row <= level.size(); ++row)
            for (int column = -1; column <= level.size(); ++column) {
                const glm::vec3& texel = level.texel(column, row);
                const size_t at =
                    (static_cast<size_t>(level_rows_[k] + row + 1) * width + (column + 1)) * 3;
                rgb[at] = texel.r, rgb[at + 1] = texel.g, rgb[at + 2] = texel.b;
            }
    }
    gl_.ActiveTexture(GL_TEXTURE0 + kEnvironmentUnit);
    glGenTextures(1, &environment_texture_);
    glBindTexture(GL_TEXTURE_2D, environment_texture_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB32F, width, height, 0, GL_RGB, GL_FLOAT, rgb.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl_.ActiveTexture(GL_TEXTURE0);
}

void PbrPeer::prepare(GLuint program) {
    gl_.UseProgram(program);
    auto loc = [&](const char* name) { return gl_.GetUniformLocation(program, name); };
    gl_.Uniform1i(loc("u_dfg"), kDfgUnit);
    if (sheen_) gl_.Uniform1i(loc("u_sheen"), kSheenUnit);
    // -1 outside the glass program: the GL ignores it.
    gl_.Uniform1i(loc("u_backdrop"), kBackdropUnit);
    if (world_.environment) {
        gl_.Uniform1i(loc("u_environment"), kEnvironmentUnit);
        gl_.Uniform1iv(loc("u_level_row"), facet::pbr::kEnvironmentLevels, level_rows_.data());
        gl_.Uniform1iv(loc("u_level_size"), facet::pbr::kEnvironmentLevels, level_sizes_.data());
        gl_.Uniform3fv(loc("u_sh"), facet::pbr::kShCount,
                       glm::value_ptr(world_.environment->sh().coefficients[0]));
    }
    locations_[program] = {loc("u_metallic_roughness"),
                           loc("u_f0"),
                           loc("u_f90"),
                           loc("u_rotation"),
                           loc("u_intensity"),
                           loc("u_sheen_color"),
                           loc("u_sheen_roughness"),
                           {loc("u_transmission"), loc("u_ior"), loc("u_thickness"),
                            loc("u_transmittance"), loc("u_dispersion")}};
}

void PbrPeer::set_glass(GLuint program, const facet::Material& m, float object_scale) {
    const GlassLocations& at = locations_.at(program).glass;
    gl_.Uniform1f(at.transmission, m.transmission);
    gl_.Uniform1f(at.ior, m.ior);
    // As shade/material_terms.hpp's put_extra_lobes and brdf_layers.hpp's
    // prepare_transmission_terms: lengths in the world's units, and the
    // volume's tint worked out once per draw with facet's own power (no
    // map varies it over the surface).
    const float thickness = m.thickness * object_scale;
    const float distance = m.attenuation_distance * object_scale;
    const float exponent = distance > 0.0f ? std::max(thickness, 0.0f) / distance : 0.0f;
    glm::vec3 transmittance;
    for (int c = 0; c < 3; ++c)
        transmittance[c] =
            facet::lanes::power_unit(std::clamp(m.attenuation_color[c], 0.0f, 1.0f), exponent);
    gl_.Uniform1f(at.thickness, std::max(thickness, 0.0f));
    gl_.Uniform3fv(at.transmittance, 1, glm::value_ptr(transmittance));
    gl_.Uniform1f(at.dispersion, m.dispersion);
}

void PbrPeer::set_draw(GLuint program, const facet::FrameState& state, const facet::Material& m) {
    const Locations& at = locations_.at(program);
    gl_.Uniform2fv(at.metallic_roughness, 1, glm::value_ptr(glm::vec2(m.metallic, m.roughness)));
    // render/shade_batch.cpp's put_physical_terms.
    const float f0 = facet::pbr::f0_from_ior(m.ior);
    const glm::vec3 dielectric_f0 =
        glm::min(f0 * m.specular_color, glm::vec3(1.0f)) * m.specular_weight;
    gl_.Uniform3fv(at.f0, 1, glm::value_ptr(dielectric_f0));
    gl_.Uniform1f(at.f90, m.specular_weight);
    gl_.ActiveTexture(GL_TEXTURE0 + kDfgUnit);
    glBindTexture(GL_TEXTURE_2D, dfg_texture_);
    if (sheen_) {
        gl_.Uniform3fv(at.sheen_color, 1, glm::value_ptr(m.sheen_color));
        gl_.Uniform1f(at.sheen_roughness, m.sheen_roughness);
        gl_.ActiveTexture(GL_TEXTURE0 + kSheenUnit);
        glBindTexture(GL_TEXTURE_2D, sheen_texture_);
    }
    if (world_.environment) {
        // As render/frame_inputs.cpp evaluates the environment's keys.
        const facet::FrameTime time{static_cast<double>(state.frame), state.time};
        const std::optional<facet::EnvironmentDesc>& e = scene_.environment;
        const facet::EnvironmentLighting lighting = facet::environment_at(
            world_.environment.get(), e ? facet::evaluate(e->intensity, time) : 1.0f,
            e ? facet::evaluate(e->rotation, time) : 0.0f);
        gl_.Uniform2fv(at.rotation, 1,
                       glm::value_ptr(glm::vec2(lighting.cos_rotation, lighting.sin_rotation)));
        gl_.Uniform1f(at.intensity, lighting.intensity);
        gl_.ActiveTexture(GL_TEXTURE0 + kEnvironmentUnit);
        glBindTexture(GL_TEXTURE_2D, environment_texture_);
    }
    gl_.ActiveTexture(GL_TEXTURE0);
}

std::string PbrPeer::features() const {
    std::string f = "GLSL port, lights compiled in";
    if (world_.environment)
        f += ", environment as " + std::to_string(facet::pbr::kEnvironmentLevels) +
             " float octahedral levels + SH";
    f += ", DFG table";
    if (sheen_) f += ", sheen (Charlie, its albedo table)";
    if (glass_)
        f += ", glass (linear half-float frame, the opaque pass's 2x2 box mips read along the "
             "refracted view, draws back to front, then exposure and tone in a full-screen pass)";
    if (scene_.output.display.tonemap == facet::Tonemap::neutral) f += ", PBR Neutral";
    return f;
}

}  // namespace facet_bench
