#pragma once
// The llvmpipe reference's frame targets for a scene with glass
// (llvmpipe_pbr.hpp): what a GL programmer sets up to draw refraction in
// real time, as Filament's screen-space refraction does.
//
//   frame()         linear light, half float, with depth (multisampled
//                   when the scene asks for samples): the opaque draws
//                   and then the glass draws go here
//   make_backdrop() the opaque frame resolved into a half-float texture,
//                   its 2x2 box mips made by the GL, bound for the glass
//   present()       the finished frame resolved, its depth copied into the
//                   read-back target, and exposure and tone curve applied
//                   by a full-screen pass into that target's sRGB colour
//
// The backdrop is a copy, so the glass never reads what it draws into.
#include "llvmpipe_gl.hpp"

namespace facet_bench {

class GlassFrame {
  public:
    // Targets of width x height with `samples` per pixel (1: none);
    // `backdrop_unit` the texture unit the glass program reads, and
    // `present_program` the full-screen pass (PbrPeer::present_shaders),
    // linked.
    GlassFrame(const Gl& gl, int width, int height, int samples, int backdrop_unit,
               GLuint present_program);

    // The framebuffer the frame's draws go into.
    GLuint frame() const { return frame_fbo_; }

    // After the opaque draws, before the glass draws.
    void make_backdrop();

    // After the glass draws: the displayed frame and its depth into
    // `target` (single-sampled, sRGB colour and depth).
    void present(GLuint target);

  private:
    // The frame's colour resolved into the backdrop's first level.
    void resolve_colour();

    const Gl& gl_;
    int width_, height_, backdrop_unit_;
    GLuint present_program_;
    GLuint frame_fbo_ = 0, backdrop_fbo_ = 0, backdrop_texture_ = 0;
};

}  // namespace facet_bench
