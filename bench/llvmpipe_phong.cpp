#include "llvmpipe_phong.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "anim/frame_state.hpp"
#include "render/shade_lights.hpp"

namespace facet_bench {

// Term for term what src/shade/lighting_batch.cpp computes: inverse-square
// falloff, the range window and the spot cone for point and spot lights,
// and the shadow map's visibility for the light that has one.
const char* const kLightUniformsGlsl = R"(
const int kMaxLights = 8;
uniform int u_light_count;
uniform vec4 u_light_pos[kMaxLights];   // xyz: position, or direction to the light; w: 1 point or spot
uniform vec4 u_light_axis[kMaxLights];  // xyz: spot axis towards the light; w: 1 / range or 0
uniform vec3 u_radiance[kMaxLights];
uniform vec2 u_spot[kMaxLights];        // cone scale and offset; (0, 1) for no cone
uniform vec3 u_ambient_light;
uniform int u_shadow_light;
#ifdef SHADOWS
#ifndef SHADOW_TEXEL
uniform float u_shadow_texel;
#define SHADOW_TEXEL u_shadow_texel
#endif
uniform sampler2DShadow u_shadow_map;
uniform mat4 u_shadow_matrix;   // world -> shadow map [0, 1]^3
uniform mat3 u_shadow_view;     // world -> the sun's view: x right, y up, z towards the sun
uniform vec2 u_shadow_offsets;  // normal offset (scene units), depth bias (map depth units)
// facet's lookup (shade/shadow_map.cpp) with the GL's comparisons: the
// point moved off the surface along its unit normal n by a texel times
// sin(angle to the sun), a depth bias of half a texel plus half a texel
// per unit of the receiver's slope, and facet's box filter as SHADOW_TAPS
// bilinear comparisons a side, SHADOW_STEP (about two) texels apart, each
// covering two texels a side, against the receiver's plane at its centre
// (facet's plane is per texel).
float shadow(vec3 p, vec3 n) {
    vec3 nv = u_shadow_view * n;
    float sin_light = sqrt(max(0.0, 1.0 - nv.z * nv.z));
    vec4 s = u_shadow_matrix * vec4(p + n * (u_shadow_offsets.x * sin_light), 1.0);
    vec2 slope = clamp(nv.xy / max(nv.z, 1e-6), -10.0, 10.0);
    // The map's depth per tap step along the receiver's plane.
    vec2 step_depth = slope * (u_shadow_offsets.y * SHADOW_STEP);
    float depth = s.z - u_shadow_offsets.y * (0.5 + 0.5 * max(abs(slope.x), abs(slope.y)));
    float lit = 0.0;
    for (int j = 0; j < SHADOW_TAPS; ++j)
        for (int i = 0; i < SHADOW_TAPS; ++i) {
            vec2 k = vec2(float(i), float(j)) - 0.5 * float(SHADOW_TAPS - 1);
            lit += shadow2D(u_shadow_map, vec3(s.xy + k * (SHADOW_STEP * SHADOW_TEXEL),
                                               depth + dot(k, step_depth))).r;
        }
    return lit * (1.0 / float(SHADOW_TAPS * SHADOW_TAPS));
}
#ifdef GOURAUD
// Gouraud looks shadows up per pixel, as facet does (render/shade_batch.cpp):
// the vertices are lit without them, and light_point keeps the shadow
// light's direct diffuse and highlight here for the pixels to take out.
vec3 g_direct_diffuse, g_direct_specular;
#endif
#ifndef SHADOW_TO_LIGHT
#define SHADOW_TO_LIGHT u_light_pos[u_shadow_light].xyz
#endif
#endif
// Light i arriving at p, and l towards it. The general program passes the
// kind flags from uniforms; the others pass constants.
vec3 light_arriving(int i, vec3 p, bool point, bool ranged, bool spot, out vec3 l) {
    l = u_light_pos[i].xyz;
    if (!point) return u_radiance[i];
    vec3 d = u_light_pos[i].xyz - p;
    float dist2 = dot(d, d);
    if (dist2 <= 0.0) {  // at the light itself: no direction, no light
        l = vec3(0.0, 1.0, 0.0);
        return vec3(0.0);
    }
    l = d / sqrt(dist2);
    float falloff = 1.0 / dist2;
    if (ranged) {
        float x = dist2 * u_light_axis[i].w * u_light_axis[i].w;
        float w = clamp(1.0 - x * x, 0.0, 1.0);
        falloff *= w * w;
    }
    if (spot) {
        float t = clamp(dot(l, u_light_axis[i].xyz) * u_spot[i].x + u_spot[i].y, 0.0, 1.0);
        falloff *= t * t * (3.0 - 2.0 * t);
    }
    return u_radiance[i] * falloff;
}
)";

namespace {

// The general light loop: ambient * (sum of ambient lights, or white), then
// per light Lambert and the Phong or Blinn highlight.
const char* kGeneralLightLoopGlsl = R"(
uniform vec4 u_terms;  // ambient, diffuse, specular, shininess
void light_point(vec3 p, vec3 n, vec3 to_eye, out vec3 diffuse, out vec3 specular) {
    diffuse = u_terms.x * u_ambient_light;
    specular = vec3(0.0);
#if defined(SHADOWS) && defined(GOURAUD)
    g_direct_diffuse = vec3(0.0);
    g_direct_specular = vec3(0.0);
#endif
    for (int i = 0; i < u_light_count; ++i) {
        vec3 l;
        vec3 radiance =
            light_arriving(i, p, u_light_pos[i].w > 0.5, u_light_axis[i].w > 0.0, true, l);
        float n_dot_l = dot(n, l);
        if (n_dot_l <= 0.0) continue;
#if defined(SHADOWS) && !defined(GOURAUD)
        if (i == u_shadow_light) radiance *= shadow(p, n);
#endif
        vec3 d = u_terms.y * n_dot_l * radiance;
        diffuse += d;
        float cosine;
        if (PHONG) {
            cosine = dot(2.0 * n_dot_l * n - l, to_eye);
        } else {
            vec3 h = l + to_eye;
            float hl = length(h);
            cosine = hl > 0.0 ? dot(n, h) / hl : 0.0;
        }
#if defined(SHADOWS) && defined(GOURAUD)
        // Kept apart only where the pixels need it: llvmpipe ran the
        // general program twice as slowly on blob-5k with the highlight in
        // a variable assigned under the branch, for every scene.
        vec3 highlight = vec3(0.0);
        if (cosine > 0.0 && u_terms.z > 0.0)
            highlight = u_terms.z * pow(min(cosine, 1.0), u_terms.w) * radiance;
        specular += highlight;
        if (i == u_shadow_light) g_direct_diffuse = d, g_direct_specular = highlight;
#else
        if (cosine > 0.0 && u_terms.z > 0.0)
            specular += u_terms.z * pow(min(cosine, 1.0), u_terms.w) * radiance;
#endif
    }
}
)";

// The material's colour and texture scale: uniforms in the general program.
const char* kGeneralMaterialGlsl = R"(
uniform vec3 u_albedo;
uniform vec2 u_uv_scale;
#define ALBEDO u_albedo
#define UV_SCALE u_uv_scale
#ifdef FADE
uniform vec2 u_fade;  // start and end; far beyond every point where the material does not fade
uniform vec3 u_background;
#define FADE_START u_fade.x
#define FADE_END u_fade.y
#define BACKGROUND u_background
#endif
)";

const char* kFragmentShader = R"(
in vec3 v_world;
in vec3 v_normal;
in vec2 v_uv;
#ifdef GOURAUD
in vec3 v_diffuse;
in vec3 v_specular;
#ifdef SHADOWS
in vec3 v_direct_diffuse;
in vec3 v_direct_specular;
#endif
#endif
#ifdef FADE
in vec3 v_model;
#endif
uniform vec3 u_eye;
#ifdef TEXTURED
uniform sampler2D u_texture;
#endif
out vec4 frag_color;
void main() {
    vec3 albedo = ALBEDO;
#ifdef TEXTURED
    albedo *= texture(u_texture, v_uv * UV_SCALE).rgb;
#endif
#if defined(UNLIT)
    frag_color = vec4(albedo, 1.0);
#elif defined(GOURAUD)
    vec3 diffuse = v_diffuse, specular = v_specular;
#ifdef SHADOWS
    // facet's share: where the sun reaches the pixel's normal (turned to the
    // viewer), its direct light less what the pixel's lookup finds blocked.
    float len = length(v_normal);
    vec3 n = len > 0.0 ? v_normal / len : vec3(0.0, 1.0, 0.0);
#ifdef TWO_SIDED
    if (!gl_FrontFacing) n = -n;
#endif
    float blocked = dot(n, SHADOW_TO_LIGHT) > 0.0 ? 1.0 - shadow(v_world, n) : 0.0;
    diffuse -= blocked * v_direct_diffuse;
    specular -= blocked * v_direct_specular;
#endif
    frag_color = vec4(albedo * diffuse + specular, 1.0);
#else
    float len = length(v_normal);
    vec3 n = len > 0.0 ? v_normal / len : vec3(0.0, 1.0, 0.0);
#ifdef TWO_SIDED  // a single-sided material's back faces are culled
    if (!gl_FrontFacing) n = -n;
#endif
    vec3 diffuse, specular;
    light_point(v_world, n, normalize(u_eye - v_world), diffuse, specular);
    frag_color = vec4(albedo * diffuse + specular, 1.0);
#endif
#ifdef FADE  // into the background by the distance from the object's origin, as facet's fade
    float kept = 1.0 - smoothstep(FADE_START, FADE_END, length(v_model));
    frag_color.rgb = BACKGROUND + (frag_color.rgb - BACKGROUND) * kept;
#endif
}
)";

// GLSL float literals, exact for the float they print.
std::string literal(float v) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "%.9g", static_cast<double>(v));
    std::string s = buf;
    if (s.find_first_of(".eE") == std::string::npos) s += ".0";
    return s;
}

std::string literal(const glm::vec3& v) {
    return "vec3(" + literal(v.x) + ", " + literal(v.y) + ", " + literal(v.z) + ")";
}

std::string model_defines(facet::ShadingModel model, bool textured, bool shadows) {
    std::string d;
    if (model == facet::ShadingModel::unlit) d += "#define UNLIT\n";
    if (model == facet::ShadingModel::gouraud) d += "#define GOURAUD\n";
    d += std::string("#define PHONG ") + (model == facet::ShadingModel::phong ? "true" : "false") +
         "\n";
    if (textured) d += "#define TEXTURED\n";
    if (shadows) d += "#define SHADOWS\n";
    return d;
}

bool same_light(const facet::ShadeLight& a, const facet::ShadeLight& b) {
    return a.is_point == b.is_point && a.is_spot == b.is_spot && a.direction == b.direction &&
           a.position == b.position && a.radiance == b.radiance && a.spot_scale == b.spot_scale &&
           a.spot_offset == b.spot_offset && a.inv_range == b.inv_range;
}

// Light i's l and radiance at p, into the light_point's locals: a static
// light's position, axis, cone, range and radiance as constants, a moving
// one's from the uniforms, both with its kind compiled in.
std::string arrival_glsl(const SceneLighting& lighting, size_t i) {
    const facet::ShadeLight& light = lighting.lights[i];
    const bool ranged = light.is_point && light.inv_range > 0.0f;
    if (lighting.moving[i]) {
        auto flag = [](bool b) { return b ? "true" : "false"; };
        return "    radiance = light_arriving(" + std::to_string(i) + ", p, " +
               flag(light.is_point) + ", " + flag(ranged) + ", " + flag(light.is_spot) + ", l);\n";
    }
    if (!light.is_point)
        return "    l = " + literal(light.direction) +
               ";\n    radiance = " + literal(light.radiance) + ";\n";
    // At the light itself there is no direction and no light.
    std::string g = "    {\n        vec3 d = " + literal(light.position) +
                    " - p;\n"
                    "        float dist2 = dot(d, d);\n"
                    "        l = dist2 > 0.0 ? d / sqrt(dist2) : vec3(0.0, 1.0, 0.0);\n"
                    "        float falloff = dist2 > 0.0 ? 1.0 / dist2 : 0.0;\n";
    if (ranged)
        g += "        float x = dist2 * " + literal(light.inv_range) + " * " +
             literal(light.inv_range) +
             ";\n"
             "        float w = clamp(1.0 - x * x, 0.0, 1.0);\n"
             "        falloff *= w * w;\n";
    if (light.is_spot)
        g += "        float t = clamp(dot(l, " + literal(light.direction) + ") * " +
             literal(light.spot_scale) + " + " + literal(light.spot_offset) +
             ", 0.0, 1.0);\n"
             "        falloff *= t * t * (3.0 - 2.0 * t);\n";
    return g + "        radiance = " + literal(light.radiance) + " * falloff;\n    }\n";
}

// light_point for one material under the scene's lights, unrolled.
std::string specialised_light_point(facet::ShadingModel model, const SceneLighting& lighting,
                                    const facet::Material& m) {
    const std::string ambient =
        lighting.ambient_moving ? std::string("u_ambient_light") : literal(lighting.ambient);
    std::string g =
        "void light_point(vec3 p, vec3 n, vec3 to_eye, out vec3 diffuse, out vec3 "
        "specular) {\n    diffuse = " +
        literal(m.ambient) + " * " + ambient +
        ";\n    specular = vec3(0.0);\n    vec3 l, radiance;\n    float n_dot_l;\n";
    // Gouraud: shadows per pixel (see the fragment shader).
    const bool gouraud = model == facet::ShadingModel::gouraud;
    if (gouraud && lighting.shadow_index >= 0)
        g += "    g_direct_diffuse = vec3(0.0);\n    g_direct_specular = vec3(0.0);\n";
    for (size_t i = 0; i < lighting.lights.size(); ++i) {
        g += arrival_glsl(lighting, i);
        g += "    n_dot_l = dot(n, l);\n    if (n_dot_l > 0.0) {\n";
        const bool shadowed = static_cast<int>(i) == lighting.shadow_index;
        if (shadowed && !gouraud) g += "        radiance *= shadow(p, n);\n";
        g += "        vec3 d = " + literal(m.diffuse) + " * n_dot_l * radiance;\n";
        g += "        diffuse += d;\n";
        std::string highlight = "vec3(0.0)";
        if (m.specular > 0.0f) {
            if (model == facet::ShadingModel::phong)
                g += "        float cosine = dot(2.0 * n_dot_l * n - l, to_eye);\n";
            else
                g += "        vec3 h = l + to_eye;\n        float hl = length(h);\n"
                     "        float cosine = hl > 0.0 ? dot(n, h) / hl : 0.0;\n";
            g += "        vec3 highlight = cosine > 0.0 ? " + literal(m.specular) +
                 " * pow(min(cosine, 1.0), " + literal(m.shininess) +
                 ") * radiance : vec3(0.0);\n        specular += highlight;\n";
            highlight = "highlight";
        }
        if (shadowed && gouraud)
            g += "        g_direct_diffuse = d;\n        g_direct_specular = " + highlight + ";\n";
        g += "    }\n";
    }
    return g + "}\n";
}

}  // namespace

const char* const kPhongVertexShader = R"(
in vec3 a_position;
in vec3 a_normal;
in vec2 a_uv;
uniform mat4 u_model;
uniform mat3 u_normal_matrix;
uniform mat4 u_view_projection;
uniform vec3 u_eye;
out vec3 v_world;
out vec3 v_normal;
out vec2 v_uv;
#ifdef GOURAUD
out vec3 v_diffuse;
out vec3 v_specular;
#ifdef SHADOWS
out vec3 v_direct_diffuse;
out vec3 v_direct_specular;
#endif
#endif
#ifdef FADE
out vec3 v_model;  // facet fades by the model-space position at rest
#endif
void main() {
    vec4 world = u_model * vec4(a_position, 1.0);
    v_world = world.xyz;
    vec3 n = u_normal_matrix * a_normal;
    float len = length(n);
    v_normal = len > 0.0 ? n / len : vec3(0.0, 1.0, 0.0);
    v_uv = a_uv;
#ifdef GOURAUD
    light_point(v_world, v_normal, normalize(u_eye - v_world), v_diffuse, v_specular);
#ifdef SHADOWS
    v_direct_diffuse = g_direct_diffuse;
    v_direct_specular = g_direct_specular;
#endif
#endif
#ifdef FADE
    v_model = a_position;
#endif
    gl_Position = u_view_projection * world;
}
)";

SceneLighting scene_lighting(const facet::SceneDesc& scene, const facet::World& world,
                             int shadow_light) {
    // Said by name, not drawn otherwise: the port has no metal-rough
    // conversion (shade/metal_rough_phong.hpp) in its shaders.
    for (const facet::Material& m : world.materials)
        if (m.metal_rough && !m.unlit && scene.style.shading != facet::ShadingModel::unlit)
            throw std::runtime_error(
                "the llvmpipe phong port does not draw a metallic-roughness "
                "material (" +
                m.name + ") under the Phong family");
    SceneLighting lighting;
    bool first = true;
    for (int frame : scene.output.frames) {
        const facet::FrameState state = facet::evaluate_frame(scene, world.object_bounds, frame);
        std::vector<facet::ShadeLight> lights;
        glm::vec3 ambient(0.0f);
        bool any_ambient = false;
        for (const facet::ShadeLight& l : facet::make_shade_lights(state.lights)) {
            if (l.is_ambient) {
                ambient += l.radiance;
                any_ambient = true;
            } else if (lights.size() < 8) {
                lights.push_back(l);
            }
        }
        if (!any_ambient) ambient = glm::vec3(1.0f);
        if (first) {
            lighting.lights = lights;
            lighting.moving.assign(lights.size(), false);
            lighting.ambient = ambient;
            first = false;
            continue;
        }
        if (lights.size() != lighting.lights.size())
            throw std::runtime_error("the scene's lights come and go between frames");
        for (size_t i = 0; i < lights.size(); ++i)
            if (!same_light(lights[i], lighting.lights[i])) lighting.moving[i] = true;
        if (ambient != lighting.ambient) lighting.ambient_moving = true;
    }
    // make_shade_lights keeps scene order for the lights that shine from
    // somewhere: the shadow light's index among them counts the non-ambient
    // scene lights before it.
    const facet::FrameState first_frame =
        facet::evaluate_frame(scene, world.object_bounds, scene.output.frames.front());
    // As facet's frame inputs: premultiplied by its alpha.
    const glm::vec4 bg = scene.style.background.value_or(scene.output.background);
    lighting.background = glm::vec3(bg) * bg.a;
    if (shadow_light >= 0) {
        // facet's box filter, 2 (softness + 1/2) texels a side. A bilinear
        // comparison halfway between two texels weighs both equally, so
        // taps two texels apart cover the box with a quarter of the taps,
        // as a GL programmer would filter: a 4-texel box is 2 x 2 taps.
        const float width =
            2.0f * first_frame.lights[static_cast<size_t>(shadow_light)].shadow_softness + 1.0f;
        lighting.shadow_taps = std::max(1, static_cast<int>(std::lround(width / 2.0f)));
        lighting.shadow_step = width / static_cast<float>(lighting.shadow_taps);
        lighting.shadow_index = 0;
        for (int i = 0; i < shadow_light; ++i)
            if (scene.lights[static_cast<size_t>(i)].type != facet::LightType::ambient)
                ++lighting.shadow_index;
    }
    return lighting;
}

std::string shadow_filter_defines(const SceneLighting& lighting) {
    return "#define SHADOW_TAPS " + std::to_string(lighting.shadow_taps) +
           "\n#define SHADOW_STEP " + literal(lighting.shadow_step) + "\n";
}

ShaderSources general_phong_program(facet::ShadingModel model, bool textured, bool shadows,
                                    bool fade) {
    // Sidedness is the material's: the general program flips every back face.
    const std::string head = model_defines(model, textured, shadows) + "#define TWO_SIDED\n" +
                             (fade ? "#define FADE\n" : "") + kLightUniformsGlsl +
                             kGeneralLightLoopGlsl + kGeneralMaterialGlsl;
    return {head + kPhongVertexShader, head + kFragmentShader};
}

ShaderSources specialised_phong_program(facet::ShadingModel model, const SceneLighting& lighting,
                                        const facet::Material& m, bool textured, int shadow_size) {
    const bool shadows = lighting.shadow_index >= 0;
    std::string head = model_defines(model, textured, shadows);
    if (m.double_sided) head += "#define TWO_SIDED\n";
    head += "#define ALBEDO " + literal(m.color) + "\n";
    head += "#define UV_SCALE vec2(" + literal(m.base_color_map.transform.linear[0].x) + ", " +
            literal(m.base_color_map.transform.linear[1].y) + ")\n";
    if (m.fade_end > m.fade_start)
        head += "#define FADE\n#define FADE_START " + literal(m.fade_start) +
                "\n#define FADE_END " + literal(m.fade_end) + "\n#define BACKGROUND " +
                literal(lighting.background) + "\n";
    if (model != facet::ShadingModel::unlit) {
        if (shadows) {
            head +=
                "#define SHADOW_TEXEL " + literal(1.0f / static_cast<float>(shadow_size)) + "\n";
            // The sun's direction: compiled in unless it moves.
            const size_t sun = static_cast<size_t>(lighting.shadow_index);
            head += "#define SHADOW_TO_LIGHT " +
                    (lighting.moving[sun] ? "u_light_pos[" + std::to_string(sun) + "].xyz"
                                          : literal(lighting.lights[sun].direction)) +
                    "\n";
        }
        head += kLightUniformsGlsl + specialised_light_point(model, lighting, m);
    }
    return {head + kPhongVertexShader, head + kFragmentShader};
}

}  // namespace facet_bench
