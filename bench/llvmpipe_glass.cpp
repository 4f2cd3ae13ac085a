#include "llvmpipe_glass.hpp"

#include <string>

namespace facet_bench {

GlassFrame::GlassFrame(const Gl& gl, int width, int height, int samples, int backdrop_unit,
                       GLuint present_program)
    : gl_(gl),
      width_(width),
      height_(height),
      backdrop_unit_(backdrop_unit),
      present_program_(present_program) {
    // Half float, as facet's frame: light above 1 stays for the glass to
    // pass on, and the tone curve comes after it.
    GLuint buffers[2];
    gl_.GenRenderbuffers(2, buffers);
    gl_.GenFramebuffers(1, &frame_fbo_);
    gl_.BindFramebuffer(GL_FRAMEBUFFER, frame_fbo_);
    gl_.BindRenderbuffer(GL_RENDERBUFFER, buffers[0]);
    gl_.RenderbufferStorageMultisample(GL_RENDERBUFFER, samples > 1 ? samples : 0, GL_RGBA16F,
                                       width, height);
    gl_.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, buffers[0]);
    gl_.BindRenderbuffer(GL_RENDERBUFFER, buffers[1]);
    gl_.RenderbufferStorageMultisample(GL_RENDERBUFFER, samples > 1 ? samples : 0,
                                       GL_DEPTH_COMPONENT24, width, height);
    gl_.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, buffers[1]);
    if (gl_.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error("glass frame incomplete (samples " + std::to_string(samples) +
                                 ")");

    // The backdrop: clamped at the frame's edges, read trilinearly.
    gl_.ActiveTexture(GL_TEXTURE0 + backdrop_unit);
    glGenTextures(1, &backdrop_texture_);
    glBindTexture(GL_TEXTURE_2D, backdrop_texture_);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16F, width, height, 0, GL_RGBA, GL_HALF_FLOAT, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    gl_.GenerateMipmap(GL_TEXTURE_2D);  // the levels exist from here on
    gl_.ActiveTexture(GL_TEXTURE0);
    gl_.GenFramebuffers(1, &backdrop_fbo_);
    gl_.BindFramebuffer(GL_FRAMEBUFFER, backdrop_fbo_);
    gl_.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, backdrop_texture_,
                             0);
    if (gl_.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error("glass backdrop incomplete");

    gl_.UseProgram(present_program_);
    gl_.Uniform1i(gl_.GetUniformLocation(present_program_, "u_frame"), backdrop_unit);
}

void GlassFrame::resolve_colour() {
    gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, frame_fbo_);
    gl_.BindFramebuffer(GL_DRAW_FRAMEBUFFER, backdrop_fbo_);
    gl_.BlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT,
                        GL_NEAREST);
}

void GlassFrame::make_backdrop() {
    resolve_colour();
    gl_.ActiveTexture(GL_TEXTURE0 + backdrop_unit_);
    glBindTexture(GL_TEXTURE_2D, backdrop_texture_);
    gl_.GenerateMipmap(GL_TEXTURE_2D);
    gl_.ActiveTexture(GL_TEXTURE0);
    gl_.BindFramebuffer(GL_FRAMEBUFFER, frame_fbo_);
}

void GlassFrame::present(GLuint target) {
    // The backdrop's first level takes the finished frame: its mips go
    // stale, and the pass reads that level alone.
    resolve_colour();
    gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, frame_fbo_);
    gl_.BindFramebuffer(GL_DRAW_FRAMEBUFFER, target);
    gl_.BlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_DEPTH_BUFFER_BIT,
                        GL_NEAREST);
    gl_.BindFramebuffer(GL_FRAMEBUFFER, target);
    glDisable(GL_DEPTH_TEST);  // also leaves the copied depth as it is
    glDisable(GL_CULL_FACE);
    gl_.UseProgram(present_program_);
    gl_.ActiveTexture(GL_TEXTURE0 + backdrop_unit_);
    glBindTexture(GL_TEXTURE_2D, backdrop_texture_);
    gl_.ActiveTexture(GL_TEXTURE0);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glEnable(GL_DEPTH_TEST);
}

}  // namespace facet_bench
