#pragma once
// The llvmpipe reference's port of facet's `pbr` shading model
// (src/shade/model_pbr.cpp, docs/pbr.md) to GLSL 1.30: the glTF BRDF under
// the scene's lights, the split-sum environment light from facet's own
// prefiltered octahedral levels, spherical harmonics and DFG table
// (uploaded once as float textures and uniforms, filtered in GLSL as facet
// filters them), and the scene's tone curve, before the sRGB framebuffer
// encodes. The program is compiled for the scene: its light count and
// kinds, the shadow light, the environment and the tone curve are
// constants, so no pixel branches on what the scene fixes.
//
// Set up once, untimed, beside the reference's other textures:
//   PbrPeer pbr(gl, scene, world, shadow_light);
//   program = link(..., pbr.fragment_shader()); pbr.prepare(program);
// per draw, after the shared uniforms (lights, matrices, u_albedo):
//   pbr.set_draw(program, state, material);
#include <map>
#include <string>
#include <vector>

#include "anim/frame_state.hpp"
#include "llvmpipe_gl.hpp"
#include "render/world.hpp"
#include "scene/scene_desc.hpp"

namespace facet_bench {

class PbrPeer {
  public:
    // Uploads the environment's levels and the DFG table. `shadow_light` is
    // the scene light with the reference's shadow map, or -1. Throws
    // std::runtime_error for what the port does not draw (clear coats, the
    // physically based maps, emission, tone curves other than none and
    // neutral), so that no comparison is made against a different picture.
    PbrPeer(const Gl& gl, const facet::SceneDesc& scene, const facet::World& world,
            int shadow_light);

    // The fragment shader's source, to follow the reference's shared
    // lighting code (its uniforms, light_arriving and shadow).
    const std::string& fragment_shader() const { return fragment_; }

    // Once per linked program: the uniforms that never change.
    void prepare(GLuint program);

    // Per draw, with the program in use: the frame's environment rotation
    // and intensity, the material's terms, and the textures bound.
    void set_draw(GLuint program, const facet::FrameState& state, const facet::Material& material);

    // What the port draws, for the report's "what it draws" column.
    std::string features() const;

  private:
    struct Locations {
        GLint metallic_roughness, f0, f90, rotation, intensity, sheen_color, sheen_roughness;
    };

    void upload_dfg_table();
    void upload_sheen_table();
    void upload_environment();

    const Gl& gl_;
    const facet::SceneDesc& scene_;
    const facet::World& world_;
    std::string fragment_;
    GLuint dfg_texture_ = 0, environment_texture_ = 0, sheen_texture_ = 0;
    bool sheen_ = false;  // a material has a sheen: the shader is compiled with it
    // Of each level of the environment in the atlas texture: its first
    // row and its size without the border.
    std::vector<GLint> level_rows_, level_sizes_;
    std::map<GLuint, Locations> locations_;
};

}  // namespace facet_bench
