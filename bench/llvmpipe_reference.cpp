// The llvmpipe reference of facet_bench: a facet scene drawn by OpenGL on
// Mesa's llvmpipe through OSMesa (off-screen), doing the same work as
// facet: the same meshes (posed each frame when they move), the same camera,
// lights, materials and textures, the scene style's shading model as GLSL,
// a two-pass shadow map for a shadow-casting sun, MSAA for output.samples,
// an sRGB framebuffer, and colour plus depth read back; glass under `pbr`
// over the opaque frame it refracts (llvmpipe_glass.hpp). The whole job adds
// a PNG of each frame through libpng at zlib level 1. Built only when
// OSMesa is found.
#include <png.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>
#include <stdexcept>
#include <tuple>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>

#include "anim/camera_path.hpp"
#include "anim/frame_state.hpp"
#include "bench_common.hpp"
#include "core/color.hpp"
#include "core/display_transform.hpp"
#include "core/thread_pool.hpp"
#include "llvmpipe_gl.hpp"
#include "llvmpipe_glass.hpp"
#include "llvmpipe_pbr.hpp"
#include "llvmpipe_phong.hpp"
#include "render/camera.hpp"
#include "render/frame_renderer.hpp"
#include "render/pose_stage.hpp"
#include "render/shade_lights.hpp"
#include "shade/shadow_map.hpp"

namespace facet_bench {
namespace {

const char* kDepthVertexShader = R"(
in vec3 a_position;
uniform mat4 u_clip;
void main() { gl_Position = u_clip * vec4(a_position, 1.0); }
)";
const char* kDepthFragmentShader = "void main() {}\n";

GLuint compile(const Gl& gl, GLenum type, const std::string& source) {
    GLuint s = gl.CreateShader(type);
    const char* text = source.c_str();
    gl.ShaderSource(s, 1, &text, nullptr);
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

GLuint link(const Gl& gl, const ShaderSources& sources) {
    GLuint program = gl.CreateProgram();
    gl.AttachShader(program, compile(gl, GL_VERTEX_SHADER, "#version 130\n" + sources.vertex));
    gl.AttachShader(program, compile(gl, GL_FRAGMENT_SHADER, "#version 130\n" + sources.fragment));
    gl.BindAttribLocation(program, 0, "a_position");
    gl.BindAttribLocation(program, 1, "a_normal");
    gl.BindAttribLocation(program, 2, "a_uv");
    gl.LinkProgram(program);
    GLint linked = 0;
    gl.GetProgramiv(program, GL_LINK_STATUS, &linked);
    if (!linked) {
        char log[4096];
        gl.GetProgramInfoLog(program, sizeof log, nullptr, log);
        throw std::runtime_error(std::string("program link failed: ") + log);
    }
    return program;
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

// A PNG through libpng's simplified API would pick its own settings; the
// classic one lets the reference say zlib level 1 with default filters.
void write_png_rgb(const std::string& path, const uint8_t* rgb_bottom_up, int width, int height) {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) throw std::runtime_error("cannot write " + path);
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        std::fclose(f);
        throw std::runtime_error("libpng failed on " + path);
    }
    png_init_io(png, f);
    png_set_compression_level(png, 1);
    png_set_IHDR(png, info, width, height, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_set_sRGB(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
    png_write_info(png, info);
    for (int y = height - 1; y >= 0; --y)  // GL rows are bottom-up
        png_write_row(png,
                      const_cast<png_bytep>(rgb_bottom_up + static_cast<size_t>(y) * width * 3));
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
    std::fclose(f);
}

struct Program {
    GLuint id = 0;
    GLint model, normal_matrix, view_projection, eye, albedo, uv_scale, terms, light_count,
        light_pos, light_axis, radiance, spot, ambient_light, shadow_light, shadow_map,
        shadow_matrix, shadow_texel, shadow_view, shadow_offsets, texture, fade, background;
};

Program make_program(const Gl& gl, const ShaderSources& sources) {
    Program p;
    p.id = link(gl, sources);
    auto loc = [&](const char* name) { return gl.GetUniformLocation(p.id, name); };
    p.model = loc("u_model"), p.normal_matrix = loc("u_normal_matrix");
    p.view_projection = loc("u_view_projection"), p.eye = loc("u_eye");
    p.albedo = loc("u_albedo"), p.uv_scale = loc("u_uv_scale"), p.terms = loc("u_terms");
    p.light_count = loc("u_light_count"), p.light_pos = loc("u_light_pos");
    p.light_axis = loc("u_light_axis"), p.radiance = loc("u_radiance"), p.spot = loc("u_spot");
    p.ambient_light = loc("u_ambient_light"), p.shadow_light = loc("u_shadow_light");
    p.shadow_map = loc("u_shadow_map"), p.shadow_matrix = loc("u_shadow_matrix");
    p.shadow_texel = loc("u_shadow_texel"), p.texture = loc("u_texture");
    p.shadow_view = loc("u_shadow_view"), p.shadow_offsets = loc("u_shadow_offsets");
    p.fade = loc("u_fade"), p.background = loc("u_background");
    return p;
}

// Everything the reference draws with, made once.
class Reference {
  public:
    // `specialised`: the Phong family's programs are written for the scene
    // (llvmpipe_phong.hpp); the `pbr` port always is.
    Reference(const facet::SceneDesc& scene, const facet::World& world, bool specialised)
        : scene_(scene), world_(world), width_(scene.output.width), height_(scene.output.height) {
        gl_.load();
        model_ = scene.style.shading;
        samples_ = scene.output.samples;
        for (size_t i = 0; i < scene.lights.size(); ++i)
            if (scene.lights[i].shadows && scene.lights[i].type == facet::LightType::directional &&
                scene.style.shadows.value_or(true) && shadow_light_ < 0)
                shadow_light_ = static_cast<int>(i);
        if (scene.style.shadows == true && shadow_light_ < 0)
            for (size_t i = 0; i < scene.lights.size() && shadow_light_ < 0; ++i)
                if (scene.lights[i].type == facet::LightType::directional)
                    shadow_light_ = static_cast<int>(i);
        make_buffers();
        make_textures();
        make_targets();
        // The shadow map first: a specialised program compiles in its size.
        if (shadow_light_ >= 0) make_shadow_map();
        lighting_ = scene_lighting(scene_, world_, shadow_light_);
        if (model_ == facet::ShadingModel::pbr) pbr_.emplace(gl_, scene, world, shadow_light_);
        if (specialised && !pbr_)
            make_specialised_programs();
        else
            make_general_programs();
        if (pbr_ && pbr_->glass()) {
            const GLuint present = link(gl_, pbr_->present_shaders());
            glass_.emplace(gl_, width_, height_, samples_, PbrPeer::kBackdropUnit, present);
        }
    }

    std::string features() const {
        std::string f = facet::shading_model_name(model_);
        if (pbr_)
            f += " (" + pbr_->features() + ")";
        else if (specialised_)
            f += " (specialised: " + std::to_string(programs_.size()) +
                 " program(s), lights unrolled, material constants)";
        else
            f += " (general: uniform light loop)";
        if (!textures_.empty()) f += ", textured (mipmapped)";
        if (shadow_light_ >= 0) f += ", shadow map " + std::to_string(shadow_size_) + "^2";
        if (samples_ > 1) f += ", " + std::to_string(samples_) + "x MSAA";
        if (world_.deforms()) f += ", vertices posed and uploaded each frame";
        if (scene_.style.occlusion.enabled)
            f += "; not drawn: facet's ambient occlusion (style occlusion), so the check "
                 "compares facet's frame without it";
        return f;
    }

    void draw(int frame, facet::PoseStage& pose) {
        const facet::FrameState state = facet::evaluate_frame(scene_, world_.object_bounds, frame);
        if (world_.deforms()) upload_pose(pose.pose(state));
        if (shadow_light_ >= 0) draw_shadow_map(state, pose);
        const GLuint target = glass_ ? glass_->frame() : samples_ > 1 ? msaa_fbo_ : resolve_fbo_;
        gl_.BindFramebuffer(GL_FRAMEBUFFER, target);
        glViewport(0, 0, width_, height_);
        glEnable(GL_FRAMEBUFFER_SRGB);
        const glm::vec4 bg = scene_.style.background.value_or(scene_.output.background);
        glClearColor(bg.r, bg.g, bg.b, bg.a);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        const View view = view_of(state);
        if (glass_) {
            draw_with_glass(state, view);
            return;
        }
        for (const facet::Draw& d : world_.draws) draw_surface(d, state, view, false);
        if (samples_ > 1) {  // resolve, as facet's output is one sample per pixel
            gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, msaa_fbo_);
            gl_.BindFramebuffer(GL_DRAW_FRAMEBUFFER, resolve_fbo_);
            gl_.BlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_,
                                GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT, GL_NEAREST);
        }
        gl_.BindFramebuffer(GL_FRAMEBUFFER, resolve_fbo_);
    }

    void read_back(std::vector<uint8_t>& rgb, std::vector<float>& depth) {
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, width_, height_, GL_RGB, GL_UNSIGNED_BYTE, rgb.data());
        glReadPixels(0, 0, width_, height_, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
    }

  private:
    // The frame's camera and lights, as every draw takes them.
    struct View {
        facet::CameraMatrices camera;
        glm::mat4 view_projection;
        std::vector<facet::ShadeLight> lights;
    };

    View view_of(const facet::FrameState& state) const {
        const float aspect = static_cast<float>(width_) / static_cast<float>(height_);
        View view;
        view.camera = facet::make_camera(state.camera, aspect);
        view.view_projection = glm::perspective(glm::radians(state.camera.fov_degrees), aspect,
                                                state.camera.near, state.camera.far) *
                               view.camera.view;
        view.lights = facet::make_shade_lights(state.lights);
        return view;
    }

    // The opaque draws into the linear frame, its backdrop, the glass
    // draws over it from the farthest to the nearest (by their bounds'
    // centres, as real-time renderers sort), then the displayed frame
    // into the read-back target.
    void draw_with_glass(const facet::FrameState& state, const View& view) {
        std::vector<std::pair<float, const facet::Draw*>> glass;
        for (const facet::Draw& d : world_.draws) {
            if (!PbrPeer::transmits(world_.materials[d.material])) {
                draw_surface(d, state, view, false);
                continue;
            }
            const glm::vec3 centre(facet::transformed_box_sphere(world_.object_bounds[d.object],
                                                                 state.objects[d.object].transform)
                                       .center);
            glass.push_back({glm::distance(centre, view.camera.position), &d});
        }
        glass_->make_backdrop();
        std::stable_sort(glass.begin(), glass.end(),
                         [](const auto& a, const auto& b) { return a.first > b.first; });
        for (const auto& [distance, d] : glass) draw_surface(*d, state, view, true);
        glass_->present(resolve_fbo_);
    }

    // One draw, with its program's uniforms; `glass`: with the glass program.
    void draw_surface(const facet::Draw& d, const facet::FrameState& state, const View& view,
                      bool glass) {
        const facet::Material& m = world_.materials[d.material];
        const bool textured = m.base_color_map && d.has_uvs;
        const Program& p =
            programs_.at({specialised_ ? static_cast<int>(d.material) : -1, textured, glass});
        gl_.UseProgram(p.id);
        set_lights(p, view.lights, view.camera.position, view.view_projection);
        const glm::mat4& model_matrix = state.objects[d.object].transform;
        if (pbr_) pbr_->set_draw(p.id, state, m);
        if (glass) pbr_->set_glass(p.id, m, facet::object_scale(model_matrix));
        const glm::mat3 normal_matrix = glm::transpose(glm::inverse(glm::mat3(model_matrix)));
        gl_.UniformMatrix4fv(p.model, 1, GL_FALSE, glm::value_ptr(model_matrix));
        gl_.UniformMatrix3fv(p.normal_matrix, 1, GL_FALSE, glm::value_ptr(normal_matrix));
        gl_.Uniform3fv(p.albedo, 1, glm::value_ptr(m.color));
        gl_.Uniform2fv(p.uv_scale, 1,
                       glm::value_ptr(glm::vec2(m.base_color_map.transform.linear[0].x,
                                                m.base_color_map.transform.linear[1].y)));
        const glm::vec4 terms(m.ambient, m.diffuse, m.specular, m.shininess);
        gl_.Uniform4fv(p.terms, 1, glm::value_ptr(terms));
        // The general program's fade: beyond every point where none is asked for.
        const bool fades = m.fade_end > m.fade_start;
        const glm::vec2 fade =
            fades ? glm::vec2(m.fade_start, m.fade_end) : glm::vec2(1e30f, 2e30f);
        gl_.Uniform2fv(p.fade, 1, glm::value_ptr(fade));
        gl_.Uniform3fv(p.background, 1, glm::value_ptr(lighting_.background));
        if (textured) {
            gl_.ActiveTexture(GL_TEXTURE0);
            glBindTexture(GL_TEXTURE_2D, textures_.at(m.base_color_map.texture.get()));
            gl_.Uniform1i(p.texture, 0);
        }
        if (m.double_sided)
            glDisable(GL_CULL_FACE);
        else
            glEnable(GL_CULL_FACE);
        draw_elements(d);
    }

    void make_general_programs() {
        bool fade = false;
        for (const facet::Material& m : world_.materials) fade = fade || m.fade_end > m.fade_start;
        const std::string filter = shadow_filter_defines(lighting_);
        const bool glass = pbr_ && pbr_->glass();
        for (bool textured : {false, true})
            for (bool glass_program : {false, true}) {
                if (glass_program && !glass) continue;
                const bool shadows = shadow_light_ >= 0;
                // The pbr port's fragment shader follows the light uniforms.
                const std::string pbr_head = std::string(textured ? "#define TEXTURED\n" : "") +
                                             (shadows ? "#define SHADOWS\n" : "") +
                                             kLightUniformsGlsl;
                const PbrOutput output = glass_program ? PbrOutput::glass
                                         : glass       ? PbrOutput::linear
                                                       : PbrOutput::displayed;
                const ShaderSources sources =
                    pbr_ ? ShaderSources{pbr_head + kPhongVertexShader,
                                         pbr_head + pbr_->fragment_shader(output)}
                         : general_phong_program(model_, textured, shadows, fade);
                const Program p =
                    make_program(gl_, {filter + sources.vertex, filter + sources.fragment});
                if (pbr_) pbr_->prepare(p.id);
                programs_[{-1, textured, glass_program}] = p;
            }
    }

    // One program per material and texture use the draws need.
    void make_specialised_programs() {
        specialised_ = true;
        const std::string filter = shadow_filter_defines(lighting_);
        for (const facet::Draw& d : world_.draws) {
            const facet::Material& m = world_.materials[d.material];
            const std::tuple<int, bool, bool> key{static_cast<int>(d.material),
                                                  m.base_color_map && d.has_uvs, false};
            if (programs_.count(key)) continue;
            const ShaderSources sources =
                specialised_phong_program(model_, lighting_, m, std::get<1>(key), shadow_size_);
            programs_[key] =
                make_program(gl_, {filter + sources.vertex, filter + sources.fragment});
        }
    }

    void make_buffers() {
        gl_.GenBuffers(4, buffers_);
        auto array = [&](GLuint buffer, GLuint attribute, int size, const void* data,
                         size_t bytes) {
            gl_.BindBuffer(GL_ARRAY_BUFFER, buffer);
            gl_.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(bytes), data,
                           world_.deforms() ? GL_DYNAMIC_DRAW : GL_STATIC_DRAW);
            gl_.VertexAttribPointer(attribute, size, GL_FLOAT, GL_FALSE, 0, nullptr);
            gl_.EnableVertexAttribArray(attribute);
        };
        array(buffers_[0], 0, 3, world_.positions.data(), world_.positions.size() * 12);
        array(buffers_[1], 1, 3, world_.normals.data(), world_.normals.size() * 12);
        array(buffers_[2], 2, 2, world_.uvs.data(), world_.uvs.size() * 8);
        gl_.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers_[3]);
        gl_.BufferData(GL_ELEMENT_ARRAY_BUFFER,
                       static_cast<GLsizeiptr>(world_.indices.size() * sizeof(uint32_t)),
                       world_.indices.data(), GL_STATIC_DRAW);
    }

    void upload_pose(const facet::PosedVertices& posed) {
        gl_.BindBuffer(GL_ARRAY_BUFFER, buffers_[0]);
        gl_.BufferSubData(GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(posed.positions.size() * 12),
                          posed.positions.data());
        gl_.BindBuffer(GL_ARRAY_BUFFER, buffers_[1]);
        gl_.BufferSubData(GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(posed.normals.size() * 12),
                          posed.normals.data());
    }

    // Textures as facet decodes them (linear RGBA float), stored as sRGB
    // bytes so the sampler decodes them as facet's do; mipmaps by the GL.
    void make_textures() {
        for (const facet::Material& m : world_.materials) {
            if (!m.base_color_map || textures_.count(m.base_color_map.texture.get())) continue;
            const facet::Texture& t = *m.base_color_map.texture;
            std::vector<uint8_t> bytes(static_cast<size_t>(t.width) * t.height * 4);
            for (int y = 0; y < t.height; ++y)
                for (int x = 0; x < t.width; ++x) {
                    const glm::vec4 c = t.texel(0, x, y);
                    uint8_t* b = &bytes[(static_cast<size_t>(y) * t.width + x) * 4];
                    for (int k = 0; k < 3; ++k)
                        b[k] = static_cast<uint8_t>(
                            std::lround(facet::linear_to_srgb(std::clamp(c[k], 0.0f, 1.0f)) * 255));
                    b[3] = static_cast<uint8_t>(std::lround(std::clamp(c[3], 0.0f, 1.0f) * 255));
                }
            GLuint id = 0;
            glGenTextures(1, &id);
            glBindTexture(GL_TEXTURE_2D, id);
            glTexImage2D(GL_TEXTURE_2D, 0, GL_SRGB8_ALPHA8, t.width, t.height, 0, GL_RGBA,
                         GL_UNSIGNED_BYTE, bytes.data());
            gl_.GenerateMipmap(GL_TEXTURE_2D);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
            auto gl_wrap = [](facet::Wrap w) -> GLint {
                return w == facet::Wrap::clamp    ? GL_CLAMP_TO_EDGE
                       : w == facet::Wrap::mirror ? GL_MIRRORED_REPEAT
                                                  : GL_REPEAT;
            };
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, gl_wrap(t.sampler.wrap_s));
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, gl_wrap(t.sampler.wrap_t));
            textures_[m.base_color_map.texture.get()] = id;
        }
    }

    // The image targets: sRGB colour and 24-bit depth, multisampled when
    // the scene asks for samples (then resolved into the single-sample pair).
    void make_targets() {
        GLuint rb[4];
        gl_.GenRenderbuffers(4, rb);
        gl_.GenFramebuffers(1, &resolve_fbo_);
        gl_.BindFramebuffer(GL_FRAMEBUFFER, resolve_fbo_);
        attach(rb[0], rb[1], 0);
        if (samples_ > 1) {
            gl_.GenFramebuffers(1, &msaa_fbo_);
            gl_.BindFramebuffer(GL_FRAMEBUFFER, msaa_fbo_);
            attach(rb[2], rb[3], samples_);
        }
    }

    void attach(GLuint color, GLuint depth, int samples) {
        gl_.BindRenderbuffer(GL_RENDERBUFFER, color);
        gl_.RenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_SRGB8_ALPHA8, width_,
                                           height_);
        gl_.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color);
        gl_.BindRenderbuffer(GL_RENDERBUFFER, depth);
        gl_.RenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH_COMPONENT24, width_,
                                           height_);
        gl_.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
        if (gl_.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
            throw std::runtime_error("framebuffer incomplete (samples " + std::to_string(samples) +
                                     ")");
    }

    void make_shadow_map() {
        const facet::LightDesc& l = scene_.lights[static_cast<size_t>(shadow_light_)];
        shadow_size_ = l.shadow_resolution > 0 ? l.shadow_resolution : 2048;
        glGenTextures(1, &shadow_texture_);
        glBindTexture(GL_TEXTURE_2D, shadow_texture_);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, shadow_size_, shadow_size_, 0,
                     GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
        gl_.GenFramebuffers(1, &shadow_fbo_);
        gl_.BindFramebuffer(GL_FRAMEBUFFER, shadow_fbo_);
        gl_.FramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D,
                                 shadow_texture_, 0);
        glDrawBuffer(GL_NONE);
        glReadBuffer(GL_NONE);
        if (gl_.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
            throw std::runtime_error("shadow framebuffer incomplete");
        depth_program_ = link(gl_, {kDepthVertexShader, kDepthFragmentShader});
        depth_clip_ = gl_.GetUniformLocation(depth_program_, "u_clip");
    }

    // Pass one: the casters' depth from the sun, in the box facet's shadow
    // stage fits (render/shadow_stage.cpp): round the casters' bounding
    // sphere, its half width in steps of 2^(1/8) with a two-texel margin,
    // its centre on whole texels, depth from 0 to twice the half width.
    void draw_shadow_map(const facet::FrameState& state, facet::PoseStage& pose) {
        const facet::PosedVertices posed = pose.pose(state);
        std::vector<facet::Sphere> spheres;
        for (const facet::Draw& d : world_.draws)
            if (world_.casts_shadows[d.object] && !posed.object_bounds[d.object].empty())
                spheres.push_back(facet::transformed_box_sphere(posed.object_bounds[d.object],
                                                                state.objects[d.object].transform));
        const facet::Sphere s = facet::enclosing_sphere(spheres);
        const facet::LightState& light = state.lights[static_cast<size_t>(shadow_light_)];
        const double steps = std::ceil(std::log2(std::max(s.radius, 1e-6)) * 8.0);
        const float half = static_cast<float>(std::exp2(steps / 8.0)) *
                           (1.0f + 2.0f / static_cast<float>(shadow_size_));
        const float texel = 2.0f * half / static_cast<float>(shadow_size_);
        const facet::ShadowBasis basis = facet::shadow_basis(glm::normalize(light.direction));
        const glm::vec3 centre(s.center);
        const float x = std::round(glm::dot(centre, basis.right) / texel) * texel;
        const float y = std::round(glm::dot(centre, basis.up) / texel) * texel;
        const float z = glm::dot(centre, basis.forward) - half;
        const glm::mat4 view =
            facet::shadow_view(basis, basis.right * x + basis.up * y + basis.forward * z);
        const glm::mat4 light_clip = glm::ortho(-half, half, -half, half, 0.0f, 2.0f * half) * view;
        const glm::mat4 to_texture = glm::translate(glm::mat4(1), glm::vec3(0.5f)) *
                                     glm::scale(glm::mat4(1), glm::vec3(0.5f));
        shadow_matrix_ = to_texture * light_clip;
        shadow_view_ = glm::mat3(view);
        // The lookup's offsets (shade/shadow_map.cpp), scaled by the light's
        // bias: the normal offset in scene units per unit of sin(angle to
        // the light), the depth bias in map depth units per unit of slope.
        shadow_offsets_ = glm::vec2(light.shadow_bias * texel, light.shadow_bias / shadow_size_);

        gl_.BindFramebuffer(GL_FRAMEBUFFER, shadow_fbo_);
        glViewport(0, 0, shadow_size_, shadow_size_);
        glClear(GL_DEPTH_BUFFER_BIT);
        glDisable(GL_CULL_FACE);  // both sides cast, as in facet
        gl_.UseProgram(depth_program_);
        for (const facet::Draw& d : world_.draws) {
            if (!world_.casts_shadows[d.object]) continue;
            const glm::mat4 clip = light_clip * state.objects[d.object].transform;
            gl_.UniformMatrix4fv(depth_clip_, 1, GL_FALSE, glm::value_ptr(clip));
            draw_elements(d);
        }
    }

    void set_lights(const Program& p, const std::vector<facet::ShadeLight>& lights,
                    const glm::vec3& eye, const glm::mat4& view_projection) {
        std::vector<glm::vec4> pos, axis;
        std::vector<glm::vec3> radiance;
        std::vector<glm::vec2> spot;
        glm::vec3 ambient(0);
        bool any_ambient = false;
        int shadow_index = -1;
        // make_shade_lights keeps scene order for the lights that shine
        // from somewhere, so the shadow light's index among them is found by
        // counting the non-ambient scene lights before it.
        int scene_index = -1, lit_index = 0;
        for (const facet::LightDesc& l : scene_.lights) {
            ++scene_index;
            if (l.type == facet::LightType::ambient) continue;
            if (scene_index == shadow_light_) shadow_index = lit_index;
            ++lit_index;
        }
        for (const facet::ShadeLight& l : lights) {
            if (l.is_ambient) {
                ambient += l.radiance;
                any_ambient = true;
                continue;
            }
            if (pos.size() == 8) continue;
            pos.push_back(l.is_point ? glm::vec4(l.position, 1) : glm::vec4(l.direction, 0));
            axis.push_back(glm::vec4(l.direction, l.inv_range));
            radiance.push_back(l.radiance);
            spot.push_back(l.is_spot ? glm::vec2(l.spot_scale, l.spot_offset) : glm::vec2(0, 1));
        }
        if (!any_ambient) ambient = glm::vec3(1);
        const int count = static_cast<int>(pos.size());
        gl_.UniformMatrix4fv(p.view_projection, 1, GL_FALSE, glm::value_ptr(view_projection));
        gl_.Uniform3fv(p.eye, 1, glm::value_ptr(eye));
        gl_.Uniform1i(p.light_count, count);
        if (count) {
            gl_.Uniform4fv(p.light_pos, count, glm::value_ptr(pos[0]));
            gl_.Uniform4fv(p.light_axis, count, glm::value_ptr(axis[0]));
            gl_.Uniform3fv(p.radiance, count, glm::value_ptr(radiance[0]));
            gl_.Uniform2fv(p.spot, count, glm::value_ptr(spot[0]));
        }
        gl_.Uniform3fv(p.ambient_light, 1, glm::value_ptr(ambient));
        gl_.Uniform1i(p.shadow_light, shadow_index);
        if (shadow_light_ >= 0) {
            gl_.ActiveTexture(GL_TEXTURE1);
            glBindTexture(GL_TEXTURE_2D, shadow_texture_);
            gl_.Uniform1i(p.shadow_map, 1);
            gl_.UniformMatrix4fv(p.shadow_matrix, 1, GL_FALSE, glm::value_ptr(shadow_matrix_));
            gl_.Uniform1f(p.shadow_texel, 1.0f / static_cast<float>(shadow_size_));
            gl_.UniformMatrix3fv(p.shadow_view, 1, GL_FALSE, glm::value_ptr(shadow_view_));
            gl_.Uniform2fv(p.shadow_offsets, 1, glm::value_ptr(shadow_offsets_));
        }
    }

    void draw_elements(const facet::Draw& d) {
        glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(d.triangle_count * 3), GL_UNSIGNED_INT,
                       reinterpret_cast<const void*>(static_cast<uintptr_t>(d.first_triangle) * 3 *
                                                     sizeof(uint32_t)));
    }

    const facet::SceneDesc& scene_;
    const facet::World& world_;
    int width_, height_;
    Gl gl_;
    facet::ShadingModel model_;
    int samples_ = 1;
    int shadow_light_ = -1;  // scene light index of the sun with the shadow map
    int shadow_size_ = 0;
    GLuint buffers_[4] = {};
    std::map<const facet::Texture*, GLuint> textures_;
    GLuint resolve_fbo_ = 0, msaa_fbo_ = 0, shadow_fbo_ = 0, shadow_texture_ = 0;
    GLuint depth_program_ = 0;
    GLint depth_clip_ = -1;
    glm::mat4 shadow_matrix_{1};
    glm::mat3 shadow_view_{1};     // world -> the sun's view: right, up, towards the sun
    glm::vec2 shadow_offsets_{0};  // see draw_shadow_map
    // By (material, textured, glass); the general programs' material is -1.
    std::map<std::tuple<int, bool, bool>, Program> programs_;
    bool specialised_ = false;
    SceneLighting lighting_;           // the scene's lights over its frames, its background
    std::optional<PbrPeer> pbr_;       // the `pbr` model's GLSL port and its textures
    std::optional<GlassFrame> glass_;  // with glass, the targets it is drawn with
};

// facet's first frame against llvmpipe's, both as 8-bit sRGB, covered
// where each drew a surface (its depth). The peer draws no ambient
// occlusion, so facet's frame is drawn without it (features() says so).
void compare_first_frame(const facet::SceneDesc& scene, const facet::World& world, int frame,
                         const std::vector<uint8_t>& gl_rgb, const std::vector<float>& gl_depth,
                         GlResult& r) {
    const int width = scene.output.width, height = scene.output.height;
    facet::ThreadPool pool(2);
    facet::SceneDesc as_drawn = scene;
    as_drawn.style.occlusion.enabled = false;
    facet::FrameRenderer renderer(as_drawn, world, pool);
    facet::FrameImages ours;
    renderer.render(frame, 0, ours);
    double diff_sum = 0;
    size_t both = 0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const size_t at =
                static_cast<size_t>(height - 1 - y) * width + x;  // GL rows are bottom-up
            const uint8_t* g = &gl_rgb[at * 3];
            // By depth, not colour: a surface faded into the background is still drawn.
            const bool gl_hit = gl_depth[at] < 1.0f;
            const bool our_hit = std::isfinite(ours.depth.at(x, y));
            if (gl_hit != our_hit) {
                ++r.coverage_mismatch_px;
                continue;
            }
            if (!our_hit) continue;
            ++both;
            // As facet's PNG: exposure and tone curve, then sRGB.
            const glm::vec4 c =
                facet::display_color(facet::to_float(ours.color.at(x, y)), scene.output.display);
            int worst = 0;
            for (int k = 0; k < 3; ++k) {
                const int mine = static_cast<int>(
                    std::lround(facet::linear_to_srgb(std::clamp(c[k], 0.0f, 1.0f)) * 255));
                worst = std::max(worst, std::abs(mine - g[k]));
            }
            diff_sum += worst;
            r.max_abs_diff = std::max(r.max_abs_diff, worst);
            if (worst > 8) ++r.differing;
        }
    r.mean_abs_diff = both ? diff_sum / static_cast<double>(both) : NAN;
}

}  // namespace

GlResult bench_llvmpipe(const facet::SceneDesc& scene, const facet::World& world,
                        const std::vector<int>& frames, const std::string& png_dir,
                        bool specialised) {
    GlResult r;
    const char* lp = std::getenv("LP_NUM_THREADS");
    r.lp_threads = lp ? std::atoi(lp) : -1;
    const int width = scene.output.width, height = scene.output.height;

    // OSMesa wants a buffer of its own; everything is drawn into FBOs.
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
    if (!ctx) throw std::runtime_error("OSMesaCreateContextExt failed");
    std::vector<uint8_t> window(4 * 16 * 16);
    if (!OSMesaMakeCurrent(ctx, window.data(), GL_UNSIGNED_BYTE, 16, 16))
        throw std::runtime_error("OSMesaMakeCurrent failed");
    r.renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    r.renderer += " / GL ";
    r.renderer += reinterpret_cast<const char*>(glGetString(GL_VERSION));

    Reference reference(scene, world, specialised);
    r.features = reference.features();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glFrontFace(GL_CCW);
    glCullFace(GL_BACK);
    facet::PoseStage pose(scene, world);
    std::vector<uint8_t> rgb(static_cast<size_t>(width) * height * 3), first;
    std::vector<float> depth(static_cast<size_t>(width) * height), first_depth;

    // One untimed frame first: llvmpipe compiles shader variants on first use.
    reference.draw(frames.front(), pose);
    reference.read_back(rgb, depth);
    r.raster_threads_seen = count_llvmpipe_threads();

    std::vector<double> render, render_cpu, job, job_cpu;
    const glm::vec4 bg = scene.style.background.value_or(scene.output.background);
    uint8_t clear[3];
    for (int c = 0; c < 3; ++c)
        clear[c] = static_cast<uint8_t>(
            std::lround(facet::linear_to_srgb(std::clamp(bg[c], 0.0f, 1.0f)) * 255));
    r.min_covered = SIZE_MAX;
    for (int pass = 0; pass < 2; ++pass) {  // render only, then the whole job
        for (int frame : frames) {
            const double c0 = process_cpu_ms();
            const auto t0 = Clock::now();
            reference.draw(frame, pose);
            glFinish();
            reference.read_back(rgb, depth);
            if (pass == 1) {
                char name[64];
                std::snprintf(name, sizeof name, "/gl.%04d.png", frame);
                write_png_rgb(png_dir + name, rgb.data(), width, height);
            }
            const double ms = ms_since(t0, Clock::now());
            const double cpu = process_cpu_ms() - c0;
            (pass == 0 ? render : job).push_back(ms);
            (pass == 0 ? render_cpu : job_cpu).push_back(cpu);
            if (pass == 0) {
                size_t covered = 0;
                for (size_t p = 0; p < rgb.size(); p += 3)
                    covered += std::memcmp(&rgb[p], clear, 3) != 0;
                r.min_covered = std::min(r.min_covered, covered);
                if (first.empty()) first = rgb, first_depth = depth;
            }
        }
    }
    if (GLenum err = glGetError(); err != GL_NO_ERROR)
        throw std::runtime_error("GL error " + std::to_string(err));
    OSMesaDestroyContext(ctx);
    r.render_ms = stat_of(render);
    r.render_cpu_ms = median(render_cpu);
    r.job_ms = stat_of(job);
    r.job_cpu_ms = median(job_cpu);
    compare_first_frame(scene, world, frames.front(), first, first_depth, r);
    r.ok = true;
    return r;
}

}  // namespace facet_bench
