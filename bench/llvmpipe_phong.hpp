#pragma once
// The llvmpipe reference's GLSL for facet's Phong family (phong,
// blinn-phong, gouraud, unlit), in two forms:
//
// - general: one program per texture use, looping over a uniform light
//   count and branching per light on its kind, with the material's terms
//   as uniforms, as a renderer that draws any scene with one shader would;
// - specialised: one program per material, written for the scene as a GL
//   programmer writing a batch renderer would write it (shader variants):
//   the lights unrolled, each light's kind, range, cone and shadow use
//   compiled in, the values the scene fixes (lights that do not move, the
//   material's colour and terms, its sidedness) as constants, so no pixel
//   branches on anything the scene fixes. What changes per frame (camera,
//   object transforms, the shadow map's matrix, lights that move) stays a
//   uniform.
//
// Both read the same uniforms (llvmpipe_reference.cpp sets them all per
// draw; a uniform a specialised program has compiled away has location -1
// and is ignored). The `pbr` port uses kLightUniformsGlsl's light_arriving
// and shadow too.
#include <string>
#include <vector>

#include "render/world.hpp"
#include "scene/scene_desc.hpp"
#include "shade/lighting.hpp"

namespace facet_bench {

// The light uniforms (at most kMaxLights lights, ambient ones summed apart),
// the shadow lookup under SHADOWS, and light_arriving(i, p, point, ranged,
// spot, l).
extern const char* const kLightUniformsGlsl;

// The scene's lights as the reference uploads them, and which of them the
// frames move.
struct SceneLighting {
    std::vector<facet::ShadeLight> lights;  // the first frame's, ambient ones left out, at most 8
    std::vector<bool> moving;               // per light: differs between frames
    glm::vec3 ambient{1.0f};                // summed ambient lights, or white without any
    bool ambient_moving = false;
    int shadow_index = -1;  // among `lights`, the one with the shadow map, or -1
    // The shadow filter's bilinear taps a side and their spacing in texels.
    int shadow_taps = 1;
    float shadow_step = 1.0f;
    glm::vec3 background{0.0f};  // the first frame's, linear: what fading materials fade to
};

// Evaluates every frame of the scene. `shadow_light` is the scene light
// with the reference's shadow map, or -1.
SceneLighting scene_lighting(const facet::SceneDesc& scene, const facet::World& world,
                             int shadow_light);

// One program's sources, each without the "#version" line.
struct ShaderSources {
    std::string vertex, fragment;
};

// SHADOW_TAPS and SHADOW_STEP, which kLightUniformsGlsl's shadow lookup reads.
std::string shadow_filter_defines(const SceneLighting& lighting);

// The general program for a model, with or without a base colour texture,
// and with the fade when some material of the scene fades.
ShaderSources general_phong_program(facet::ShadingModel model, bool textured, bool shadows,
                                    bool fade);

// The program for one material of the scene.
ShaderSources specialised_phong_program(facet::ShadingModel model, const SceneLighting& lighting,
                                        const facet::Material& material, bool textured,
                                        int shadow_size);

// The vertex shader the `pbr` port draws with (no lighting in it), after
// kLightUniformsGlsl and the port's defines.
extern const char* const kPhongVertexShader;

}  // namespace facet_bench
