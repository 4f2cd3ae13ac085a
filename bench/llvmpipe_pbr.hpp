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
//   program = link(..., pbr.fragment_shader(output)); pbr.prepare(program);
// per draw, after the shared uniforms (lights, matrices, u_albedo):
//   pbr.set_draw(program, state, material);
// and for a glass draw (transmits(material)), with the glass program:
//   pbr.set_glass(program, material, object_scale(transform));
//
// Glass (KHR_materials_transmission, _volume, _dispersion) is drawn as
// real-time renderers draw it (Filament, three.js) and as facet does with
// one glass layer: the opaque draws into a linear half-float frame
// (PbrOutput::linear), that frame resolved into a texture with its mip
// chain (llvmpipe_glass.hpp), the glass draws back to front reading it
// (PbrOutput::glass), then exposure and tone curve in a full-screen pass
// (present_shaders). Glass seen through glass shows the opaque frame only,
// as in those renderers; facet peels the layers.
#include <map>
#include <string>
#include <vector>

#include "anim/frame_state.hpp"
#include "llvmpipe_gl.hpp"
#include "llvmpipe_phong.hpp"
#include "render/world.hpp"
#include "scene/scene_desc.hpp"

namespace facet_bench {

// What a program's fragments leave: the displayed colour (exposure and
// tone curve applied, for the sRGB framebuffer: scenes without glass), or
// linear light for a frame glass is drawn over, by the opaque draws or by
// the glass draws (which read the backdrop).
enum class PbrOutput { displayed, linear, glass };

class PbrPeer {
  public:
    // The texture unit of the glass's backdrop (llvmpipe_glass.hpp).
    static constexpr int kBackdropUnit = 5;

    // Drawn as glass: a transmission (under `pbr`, the port's one model).
    static bool transmits(const facet::Material& m) { return m.transmission > 0.0f; }

    // Uploads the environment's levels and the DFG table. `shadow_light` is
    // the scene light with the reference's shadow map, or -1. Throws
    // std::runtime_error for what the port does not draw (clear coats, the
    // physically based maps, emission, tone curves other than none and
    // neutral, double-sided glass, glass casting a shadow), so that no
    // comparison is made against a different picture.
    PbrPeer(const Gl& gl, const facet::SceneDesc& scene, const facet::World& world,
            int shadow_light);

    // A fragment shader's source, to follow the reference's shared
    // lighting code (its uniforms, light_arriving and shadow).
    std::string fragment_shader(PbrOutput output) const;

    // A draw of the scene transmits: its frame is drawn with glass.
    bool glass() const { return glass_; }

    // The full-screen pass ending a frame with glass: its shaders, the
    // frame's resolved linear light bound to unit u_frame.
    ShaderSources present_shaders() const;

    // Once per linked program: the uniforms that never change.
    void prepare(GLuint program);

    // Per draw, with the program in use: the frame's environment rotation
    // and intensity, the material's terms, and the textures bound.
    void set_draw(GLuint program, const facet::FrameState& state, const facet::Material& material);

    // Per glass draw, with the glass program in use: the transmission's
    // terms, lengths scaled by the object's (facet's object_scale).
    void set_glass(GLuint program, const facet::Material& material, float object_scale);

    // What the port draws, for the report's "what it draws" column.
    std::string features() const;

  private:
    struct GlassLocations {
        GLint transmission, ior, thickness, transmittance, dispersion;
    };
    struct Locations {
        GLint metallic_roughness, f0, f90, rotation, intensity, sheen_color, sheen_roughness;
        GlassLocations glass;
    };

    void upload_dfg_table();
    void upload_sheen_table();
    void upload_environment();

    const Gl& gl_;
    const facet::SceneDesc& scene_;
    const facet::World& world_;
    // The fragment shaders' parts: the scene's defines, the exposure and
    // tone curve, and direct_light without and with light from behind.
    std::string defines_, tone_, direct_light_, glass_direct_light_;
    GLuint dfg_texture_ = 0, environment_texture_ = 0, sheen_texture_ = 0;
    bool sheen_ = false;       // a material has a sheen: the shader is compiled with it
    bool glass_ = false;       // a draw transmits: the frame is drawn with glass
    bool dispersion_ = false;  // a glass disperses: its program reads three ways
    // Of each level of the environment in the atlas texture: its first
    // row and its size without the border.
    std::vector<GLint> level_rows_, level_sizes_;
    std::map<GLuint, Locations> locations_;
};

}  // namespace facet_bench
