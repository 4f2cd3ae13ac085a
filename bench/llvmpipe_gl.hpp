#pragma once
// The OpenGL entry points the llvmpipe reference uses beyond OpenGL 1.1,
// looked up through OSMesa once its context exists: shared by
// llvmpipe_reference.cpp and the physically based port (llvmpipe_pbr.cpp).
#include <stdexcept>
#include <string>

#include <GL/osmesa.h>  // includes GL/gl.h and GL/glext.h

namespace facet_bench {

template <typename F>
F gl_proc(const char* name) {
    OSMESAproc p = OSMesaGetProcAddress(name);
    if (!p) throw std::runtime_error(std::string("OSMesaGetProcAddress failed for ") + name);
    return reinterpret_cast<F>(p);
}

// clang-format off
#define FACET_GL_FUNCTIONS(X) \
    X(CreateShader, PFNGLCREATESHADERPROC) \
    X(ShaderSource, PFNGLSHADERSOURCEPROC) \
    X(CompileShader, PFNGLCOMPILESHADERPROC) \
    X(GetShaderiv, PFNGLGETSHADERIVPROC) \
    X(GetShaderInfoLog, PFNGLGETSHADERINFOLOGPROC) \
    X(CreateProgram, PFNGLCREATEPROGRAMPROC) \
    X(AttachShader, PFNGLATTACHSHADERPROC) \
    X(BindAttribLocation, PFNGLBINDATTRIBLOCATIONPROC) \
    X(LinkProgram, PFNGLLINKPROGRAMPROC) \
    X(GetProgramiv, PFNGLGETPROGRAMIVPROC) \
    X(GetProgramInfoLog, PFNGLGETPROGRAMINFOLOGPROC) \
    X(UseProgram, PFNGLUSEPROGRAMPROC) \
    X(GetUniformLocation, PFNGLGETUNIFORMLOCATIONPROC) \
    X(UniformMatrix4fv, PFNGLUNIFORMMATRIX4FVPROC) \
    X(UniformMatrix3fv, PFNGLUNIFORMMATRIX3FVPROC) \
    X(Uniform1i, PFNGLUNIFORM1IPROC) \
    X(Uniform1iv, PFNGLUNIFORM1IVPROC) \
    X(Uniform1f, PFNGLUNIFORM1FPROC) \
    X(Uniform2fv, PFNGLUNIFORM2FVPROC) \
    X(Uniform3fv, PFNGLUNIFORM3FVPROC) \
    X(Uniform4fv, PFNGLUNIFORM4FVPROC) \
    X(GenBuffers, PFNGLGENBUFFERSPROC) \
    X(BindBuffer, PFNGLBINDBUFFERPROC) \
    X(BufferData, PFNGLBUFFERDATAPROC) \
    X(BufferSubData, PFNGLBUFFERSUBDATAPROC) \
    X(VertexAttribPointer, PFNGLVERTEXATTRIBPOINTERPROC) \
    X(EnableVertexAttribArray, PFNGLENABLEVERTEXATTRIBARRAYPROC) \
    X(ActiveTexture, PFNGLACTIVETEXTUREPROC) \
    X(GenerateMipmap, PFNGLGENERATEMIPMAPPROC) \
    X(GenFramebuffers, PFNGLGENFRAMEBUFFERSPROC) \
    X(BindFramebuffer, PFNGLBINDFRAMEBUFFERPROC) \
    X(FramebufferTexture2D, PFNGLFRAMEBUFFERTEXTURE2DPROC) \
    X(FramebufferRenderbuffer, PFNGLFRAMEBUFFERRENDERBUFFERPROC) \
    X(CheckFramebufferStatus, PFNGLCHECKFRAMEBUFFERSTATUSPROC) \
    X(GenRenderbuffers, PFNGLGENRENDERBUFFERSPROC) \
    X(BindRenderbuffer, PFNGLBINDRENDERBUFFERPROC) \
    X(RenderbufferStorageMultisample, PFNGLRENDERBUFFERSTORAGEMULTISAMPLEPROC) \
    X(BlitFramebuffer, PFNGLBLITFRAMEBUFFERPROC)
// clang-format on

struct Gl {
#define FACET_GL_MEMBER(name, type) type name = nullptr;
    FACET_GL_FUNCTIONS(FACET_GL_MEMBER)
#undef FACET_GL_MEMBER
    void load() {
#define FACET_GL_LOAD(name, type) name = gl_proc<type>("gl" #name);
        FACET_GL_FUNCTIONS(FACET_GL_LOAD)
#undef FACET_GL_LOAD
    }
};

}  // namespace facet_bench
