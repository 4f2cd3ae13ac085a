// The llvmpipe reference of facet_bench: the bench scenes drawn by OpenGL on
// Mesa's llvmpipe through OSMesa (off-screen), with a GLSL program that shades
// exactly as facet's Blinn-Phong does. Built only when OSMesa is found.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <stdexcept>

#include <GL/osmesa.h>  // includes GL/gl.h and GL/glext.h
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>

#include "anim/frame_state.hpp"
#include "bench_common.hpp"
#include "core/thread_pool.hpp"
#include "render/camera.hpp"
#include "render/frame_renderer.hpp"
#include "render/shade_lights.hpp"

namespace facet_bench {
namespace {

template <typename F>
F gl_proc(const char* name) {
    OSMESAproc p = OSMesaGetProcAddress(name);
    if (!p) throw std::runtime_error(std::string("OSMesaGetProcAddress failed for ") + name);
    return reinterpret_cast<F>(p);
}

struct Gl {
    PFNGLCREATESHADERPROC CreateShader;
    PFNGLSHADERSOURCEPROC ShaderSource;
    PFNGLCOMPILESHADERPROC CompileShader;
    PFNGLGETSHADERIVPROC GetShaderiv;
    PFNGLGETSHADERINFOLOGPROC GetShaderInfoLog;
    PFNGLCREATEPROGRAMPROC CreateProgram;
    PFNGLATTACHSHADERPROC AttachShader;
    PFNGLBINDATTRIBLOCATIONPROC BindAttribLocation;
    PFNGLLINKPROGRAMPROC LinkProgram;
    PFNGLGETPROGRAMIVPROC GetProgramiv;
    PFNGLGETPROGRAMINFOLOGPROC GetProgramInfoLog;
    PFNGLUSEPROGRAMPROC UseProgram;
    PFNGLGETUNIFORMLOCATIONPROC GetUniformLocation;
    PFNGLUNIFORMMATRIX4FVPROC UniformMatrix4fv;
    PFNGLUNIFORMMATRIX3FVPROC UniformMatrix3fv;
    PFNGLUNIFORM3FVPROC Uniform3fv;
    PFNGLUNIFORM4FVPROC Uniform4fv;
    PFNGLUNIFORM1IPROC Uniform1i;
    PFNGLGENBUFFERSPROC GenBuffers;
    PFNGLBINDBUFFERPROC BindBuffer;
    PFNGLBUFFERDATAPROC BufferData;
    PFNGLVERTEXATTRIBPOINTERPROC VertexAttribPointer;
    PFNGLENABLEVERTEXATTRIBARRAYPROC EnableVertexAttribArray;

    void load() {
#define FACET_GL(name) name = gl_proc<decltype(name)>("gl" #name)
        FACET_GL(CreateShader);
        FACET_GL(ShaderSource);
        FACET_GL(CompileShader);
        FACET_GL(GetShaderiv);
        FACET_GL(GetShaderInfoLog);
        FACET_GL(CreateProgram);
        FACET_GL(AttachShader);
        FACET_GL(BindAttribLocation);
        FACET_GL(LinkProgram);
        FACET_GL(GetProgramiv);
        FACET_GL(GetProgramInfoLog);
        FACET_GL(UseProgram);
        FACET_GL(GetUniformLocation);
        FACET_GL(UniformMatrix4fv);
        FACET_GL(UniformMatrix3fv);
        FACET_GL(Uniform3fv);
        FACET_GL(Uniform4fv);
        FACET_GL(Uniform1i);
        FACET_GL(GenBuffers);
        FACET_GL(BindBuffer);
        FACET_GL(BufferData);
        FACET_GL(VertexAttribPointer);
        FACET_GL(EnableVertexAttribArray);
#undef FACET_GL
    }
};

// Per-pixel Blinn-Phong, term for term what src/shade/lighting_batch.cpp and
// src/render/shade_stage.cpp compute: colour = albedo * (ambient + sum of
// diffuse) + sum of specular; directional radiance = colour * intensity,
// point radiance divided by distance squared; normals interpolated in world
// space and flipped on back faces.
const char* kVertexShader = R"(#version 130
in vec3 a_position;
in vec3 a_normal;
uniform mat4 u_model;
uniform mat3 u_normal_matrix;
uniform mat4 u_view_projection;
out vec3 v_world;
out vec3 v_normal;
void main() {
    vec4 world = u_model * vec4(a_position, 1.0);
    v_world = world.xyz;
    vec3 n = u_normal_matrix * a_normal;
    float len = length(n);
    v_normal = len > 0.0 ? n / len : vec3(0.0, 1.0, 0.0);
    gl_Position = u_view_projection * world;
}
)";

const char* kFragmentShader = R"(#version 130
const int kMaxLights = 8;
in vec3 v_world;
in vec3 v_normal;
uniform vec3 u_eye;
uniform vec3 u_albedo;
uniform vec4 u_terms;  // ambient, diffuse, specular, shininess
uniform int u_light_count;
uniform vec4 u_light[kMaxLights];  // w = 1: point at xyz; w = 0: unit direction towards the light
uniform vec3 u_radiance[kMaxLights];
void main() {
    float len = length(v_normal);
    vec3 n = len > 0.0 ? v_normal / len : vec3(0.0, 1.0, 0.0);
    if (!gl_FrontFacing) n = -n;
    vec3 to_eye = normalize(u_eye - v_world);
    vec3 diffuse = vec3(u_terms.x);
    vec3 specular = vec3(0.0);
    for (int i = 0; i < u_light_count; ++i) {
        vec3 to_light;
        vec3 radiance = u_radiance[i];
        if (u_light[i].w > 0.5) {
            vec3 d = u_light[i].xyz - v_world;
            float dist2 = dot(d, d);
            if (dist2 <= 0.0) continue;
            to_light = d / sqrt(dist2);
            radiance /= dist2;
        } else {
            to_light = u_light[i].xyz;
        }
        float n_dot_l = dot(n, to_light);
        if (n_dot_l <= 0.0) continue;
        diffuse += u_terms.y * n_dot_l * radiance;
        if (u_terms.z <= 0.0) continue;
        vec3 half_vector = to_light + to_eye;
        float hl = length(half_vector);
        float cosine = hl > 0.0 ? dot(n, half_vector / hl) : 0.0;
        if (cosine > 0.0) specular += u_terms.z * pow(cosine, u_terms.w) * radiance;
    }
    gl_FragColor = vec4(u_albedo * diffuse + specular, 1.0);
}
)";

GLuint compile(const Gl& gl, GLenum type, const char* source) {
    GLuint s = gl.CreateShader(type);
    gl.ShaderSource(s, 1, &source, nullptr);
    gl.CompileShader(s);
    GLint ok = 0;
    gl.GetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[4096];
        gl.GetShaderInfoLog(s, sizeof log, nullptr, log);
        throw std::runtime_error(std::string("shader compile failed: ") + log);
    }
    return s;
}

int count_llvmpipe_threads() {
    int n = 0;
    std::error_code ec;
    for (const auto& e : std::filesystem::directory_iterator("/proc/self/task", ec)) {
        std::FILE* f = std::fopen((e.path() / "comm").c_str(), "r");
        if (!f) continue;
        char name[64] = {};
        if (std::fgets(name, sizeof name, f) && std::strncmp(name, "llvmpipe-", 9) == 0) ++n;
        std::fclose(f);
    }
    return n;
}

}  // namespace

GlResult bench_llvmpipe(const facet::SceneDesc& scene, const facet::World& world,
                        const std::vector<int>& frames) {
    GlResult r;
    const char* lp = std::getenv("LP_NUM_THREADS");
    r.lp_threads = lp ? std::atoi(lp) : -1;
    const int width = scene.output.width, height = scene.output.height;

    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
    if (!ctx) throw std::runtime_error("OSMesaCreateContextExt failed");
    std::vector<uint8_t> target(static_cast<size_t>(width) * height * 4);
    if (!OSMesaMakeCurrent(ctx, target.data(), GL_UNSIGNED_BYTE, width, height))
        throw std::runtime_error("OSMesaMakeCurrent failed");
    r.renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    r.renderer += " / GL ";
    r.renderer += reinterpret_cast<const char*>(glGetString(GL_VERSION));

    Gl gl;
    gl.load();
    GLuint program = gl.CreateProgram();
    gl.AttachShader(program, compile(gl, GL_VERTEX_SHADER, kVertexShader));
    gl.AttachShader(program, compile(gl, GL_FRAGMENT_SHADER, kFragmentShader));
    gl.BindAttribLocation(program, 0, "a_position");
    gl.BindAttribLocation(program, 1, "a_normal");
    gl.LinkProgram(program);
    GLint linked = 0;
    gl.GetProgramiv(program, GL_LINK_STATUS, &linked);
    if (!linked) {
        char log[4096];
        gl.GetProgramInfoLog(program, sizeof log, nullptr, log);
        throw std::runtime_error(std::string("program link failed: ") + log);
    }
    gl.UseProgram(program);
    auto loc = [&](const char* name) { return gl.GetUniformLocation(program, name); };
    const GLint u_model = loc("u_model"), u_normal_matrix = loc("u_normal_matrix"),
                u_view_projection = loc("u_view_projection"), u_eye = loc("u_eye"),
                u_albedo = loc("u_albedo"), u_terms = loc("u_terms"),
                u_light_count = loc("u_light_count"), u_light = loc("u_light"),
                u_radiance = loc("u_radiance");

    // The same model-space arrays facet's vertex stage reads.
    GLuint buffers[3];
    gl.GenBuffers(3, buffers);
    gl.BindBuffer(GL_ARRAY_BUFFER, buffers[0]);
    gl.BufferData(GL_ARRAY_BUFFER, world.positions.size() * sizeof(glm::vec3),
                  world.positions.data(), GL_STATIC_DRAW);
    gl.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
    gl.EnableVertexAttribArray(0);
    gl.BindBuffer(GL_ARRAY_BUFFER, buffers[1]);
    gl.BufferData(GL_ARRAY_BUFFER, world.normals.size() * sizeof(glm::vec3), world.normals.data(),
                  GL_STATIC_DRAW);
    gl.VertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
    gl.EnableVertexAttribArray(1);
    gl.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers[2]);
    gl.BufferData(GL_ELEMENT_ARRAY_BUFFER, world.indices.size() * sizeof(uint32_t),
                  world.indices.data(), GL_STATIC_DRAW);

    glViewport(0, 0, width, height);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glFrontFace(GL_CCW);
    glCullFace(GL_BACK);
    const glm::vec4 bg = scene.output.background;
    glClearColor(bg.r, bg.g, bg.b, bg.a);
    glClearDepth(1.0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);

    bool textured = false;
    for (const auto& m : world.materials) textured |= static_cast<bool>(m.texture);
    if (textured) std::cerr << "warning: the llvmpipe side ignores textures\n";

    // The clear colour as the bytes glReadPixels returns for it.
    uint8_t clear[4];
    for (int c = 0; c < 4; ++c)
        clear[c] = static_cast<uint8_t>(std::lround(std::clamp(bg[c], 0.0f, 1.0f) * 255.0f));

    std::vector<uint8_t> pixels(target.size()), first_image;
    std::vector<double> finish, readback, cpu;
    r.min_covered = SIZE_MAX;
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    auto draw_frame = [&](int frame) {
        const facet::FrameState state = facet::evaluate_frame(scene, world.object_bounds, frame);
        // Same view as facet (make_camera), standard GL projection (depth -1..1).
        const facet::CameraMatrices cam = facet::make_camera(state.camera, aspect);
        const glm::mat4 projection = glm::perspective(glm::radians(state.camera.fov_degrees),
                                                      aspect, state.camera.near, state.camera.far);
        const glm::mat4 view_projection = projection * cam.view;
        const std::vector<facet::ShadeLight> lights = facet::make_shade_lights(state.lights);
        const int light_count = static_cast<int>(std::min<size_t>(lights.size(), 8));
        std::vector<glm::vec4> light_vec;
        std::vector<glm::vec3> radiance;
        for (int i = 0; i < light_count; ++i) {
            const auto& l = lights[static_cast<size_t>(i)];
            light_vec.push_back(l.is_point ? glm::vec4(l.position, 1) : glm::vec4(l.direction, 0));
            radiance.push_back(l.radiance);
        }
        gl.UniformMatrix4fv(u_view_projection, 1, GL_FALSE, glm::value_ptr(view_projection));
        gl.Uniform3fv(u_eye, 1, glm::value_ptr(cam.position));
        gl.Uniform1i(u_light_count, light_count);
        if (light_count) {
            gl.Uniform4fv(u_light, light_count, glm::value_ptr(light_vec[0]));
            gl.Uniform3fv(u_radiance, light_count, glm::value_ptr(radiance[0]));
        }
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        for (const facet::Draw& d : world.draws) {
            const glm::mat4& model = state.objects[d.object].transform;
            const glm::mat3 normal_matrix = glm::transpose(glm::inverse(glm::mat3(model)));
            const facet::Material& m = world.materials[d.material];
            gl.UniformMatrix4fv(u_model, 1, GL_FALSE, glm::value_ptr(model));
            gl.UniformMatrix3fv(u_normal_matrix, 1, GL_FALSE, glm::value_ptr(normal_matrix));
            gl.Uniform3fv(u_albedo, 1, glm::value_ptr(m.color));
            const glm::vec4 terms(m.ambient, m.diffuse, m.specular, m.shininess);
            gl.Uniform4fv(u_terms, 1, glm::value_ptr(terms));
            if (m.double_sided)
                glDisable(GL_CULL_FACE);
            else
                glEnable(GL_CULL_FACE);
            glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(d.triangle_count * 3),
                           GL_UNSIGNED_INT,
                           reinterpret_cast<const void*>(static_cast<uintptr_t>(d.first_triangle) *
                                                         3 * sizeof(uint32_t)));
        }
    };

    // One untimed frame first: llvmpipe compiles shader variants on first use.
    draw_frame(frames.front());
    glFinish();
    r.raster_threads_seen = count_llvmpipe_threads();

    for (int frame : frames) {
        const double c0 = process_cpu_ms();
        auto t0 = Clock::now();
        draw_frame(frame);
        glFinish();
        auto t1 = Clock::now();
        glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
        auto t2 = Clock::now();
        cpu.push_back(process_cpu_ms() - c0);
        finish.push_back(ms_since(t0, t1));
        readback.push_back(ms_since(t0, t2));
        size_t covered = 0;
        for (size_t p = 0; p < pixels.size(); p += 4)
            covered += std::memcmp(&pixels[p], clear, 3) != 0;
        r.min_covered = std::min(r.min_covered, covered);
        if (first_image.empty()) first_image = pixels;
    }
    if (GLenum err = glGetError(); err != GL_NO_ERROR)
        throw std::runtime_error("GL error " + std::to_string(err));
    OSMesaDestroyContext(ctx);

    r.finish_ms = median(finish);
    r.readback_ms = median(readback);
    r.readback_cpu_ms = median(cpu);
    r.readback_min_ms = *std::min_element(readback.begin(), readback.end());
    r.readback_max_ms = *std::max_element(readback.begin(), readback.end());

    // Sanity check of equivalence: facet's first frame against llvmpipe's,
    // both as 8-bit linear colour (GL rows are bottom-up).
    facet::ThreadPool pool(2);
    facet::FrameRenderer renderer(scene, world, pool);
    facet::FrameImages ours;
    renderer.render(frames.front(), 0, ours);
    double diff_sum = 0;
    size_t mismatched = 0, both = 0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const uint8_t* g = &first_image[(static_cast<size_t>(height - 1 - y) * width + x) * 4];
            const bool gl_hit = std::memcmp(g, clear, 3) != 0;
            const bool our_hit = std::isfinite(ours.depth.at(x, y));
            if (gl_hit != our_hit) {
                ++mismatched;
                continue;
            }
            if (!our_hit) continue;
            ++both;
            bool pixel_differs = false;
            const glm::vec4 c = ours.color.at(x, y);
            for (int k = 0; k < 3; ++k) {
                const int v = static_cast<int>(std::lround(std::clamp(c[k], 0.0f, 1.0f) * 255.0f));
                const int d = std::abs(v - static_cast<int>(g[k]));
                diff_sum += d;
                r.max_diff = std::max(r.max_diff, d);
                pixel_differs |= d != 0;
            }
            r.differing += pixel_differs;
        }
    r.mean_abs_diff = both ? diff_sum / (3.0 * static_cast<double>(both)) : NAN;
    r.coverage_mismatch = static_cast<double>(mismatched) / (static_cast<double>(width) * height);
    r.coverage_mismatch_px = mismatched;
    r.ok = true;
    return r;
}

}  // namespace facet_bench
