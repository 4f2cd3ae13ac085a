#include "render/vertex_stage.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "assets/tangent_frames.hpp"
#include "shade/lighting_batch.hpp"
#include "shade/metal_rough_phong.hpp"

namespace facet {
namespace {
constexpr size_t kVerticesPerChunk = 16384;  // fixed: the same cut for any thread count

struct DrawTransform {
    glm::mat4 model;
    glm::mat3 normal;
    float handedness;  // -1 where the model matrix mirrors
};

// See TransformedVertices::world_tangent. A zero tangent (a draw without
// them) stays zero; one that lay along the normal takes a fixed
// perpendicular, as tangent generation does.
glm::vec4 world_tangent(const DrawTransform& t, const glm::vec4& model_tangent,
                        const glm::vec3& world_normal) {
    if (model_tangent.w == 0) return glm::vec4(0);
    glm::vec3 along = glm::mat3(t.model) * glm::vec3(model_tangent);
    along -= world_normal * glm::dot(world_normal, along);
    const float len = glm::length(along);
    return {len > 0 && std::isfinite(len) ? along / len : any_perpendicular(world_normal),
            model_tangent.w * t.handedness};
}
}  // namespace

// A metal-rough material's roughness at vertex `v`: its factor times its
// map's G at the vertex's texture coordinates (the map's full-size level:
// a vertex stands for no footprint of its own).
float VertexStage::vertex_roughness(const Material& m, const Draw& draw, size_t v) const {
    const TextureSlot& map = m.metal_rough_map;
    if (!map || !draw.has_uvs) return m.roughness;
    return m.roughness * map.texture->sample(map.map(world_.uv_set(map)[v])).g;
}

// Gouraud: Blinn-Phong at each vertex, eight at a time, through the same
// batch lighting as per-pixel shading. With `casting` (the shadow-casting
// lights, without their maps), `lights` come without their maps too, and
// the casting lights' direct light is kept apart.
void VertexStage::light(size_t first, size_t last, const FrameInputs& frame, const StylePlan& plan,
                        std::span<const ShadeLight> lights, std::span<const ShadeLight> casting) {
    for (size_t start = first; start < last; start += simd::kLanes) {
        const int count = static_cast<int>(std::min<size_t>(simd::kLanes, last - start));
        SurfaceBatch s;
        for (int i = 0; i < count; ++i) {
            const size_t v = start + i;
            const glm::vec3& p = out_.world_position[v];
            const glm::vec3& n = out_.world_normal[v];
            const uint32_t d = world_.vertex_draw[v];
            const Draw& draw = world_.draws[d];
            const Material& m = frame.materials[draw.material];
            s.px[i] = p.x, s.py[i] = p.y, s.pz[i] = p.z;
            s.nx[i] = n.x, s.ny[i] = n.y, s.nz[i] = n.z;
            s.ambient[i] = m.ambient, s.diffuse[i] = m.diffuse;
            s.specular[i] = m.specular, s.shininess[i] = m.shininess;
            // The highlight's colour and the map's metal are the pixels'
            // (render/shade_batch.cpp); the highlight's width the vertex's.
            // Only a Gouraud object's vertex lighting is drawn: others keep
            // their Phong terms here, and skip the map.
            const uint32_t style = plan.object_style[draw.object];
            if (plan.styles[style]->shading == ShadingModel::gouraud &&
                (frame.draw_features[style * world_.draws.size() + d] & kMetalRough)) {
                s.shininess[i] = roughness_exponent(vertex_roughness(m, draw, v));
                s.specular[i] = normalised_highlight(s.shininess[i]);
                s.ambient_specular[i] = m.ambient;
            }
            s.receives_shadow[i] = world_.receives_shadows[draw.object];
        }
        pad_batch(s, count);
        const LightingBatch l =
            light_surface_batch(s, frame.camera.position, lights, Highlight::blinn);
        for (int i = 0; i < count; ++i)
            out_.lit[start + i] = {{l.dr[i], l.dg[i], l.db[i]}, {l.sr[i], l.sg[i], l.sb[i]}};
        if (casting.empty()) continue;
        s.ambient = s.ambient_specular = simd::splat(0.0f);
        const LightingBatch d =
            light_surface_batch(s, frame.camera.position, casting, Highlight::blinn);
        for (int i = 0; i < count; ++i)
            out_.direct[start + i] = {{d.dr[i], d.dg[i], d.db[i]}, {d.sr[i], d.sg[i], d.sb[i]}};
    }
}

const TransformedVertices& VertexStage::transform(const FrameInputs& frame,
                                                  const PosedVertices& posed,
                                                  std::span<const ShadeLight> lights,
                                                  const StylePlan* light_for, ThreadPool& pool) {
    const bool light_vertices = light_for != nullptr;
    const size_t count = posed.positions.size();
    out_.clip.resize(count);
    out_.world_position.resize(count);
    out_.world_normal.resize(count);
    const bool tangents = !posed.tangents.empty();
    out_.world_tangent.resize(tangents ? count : 0);
    out_.lit.resize(light_vertices ? count : 0);
    // Shadows on Gouraud surfaces are looked up per pixel (render/shade_batch.cpp).
    std::vector<ShadeLight> open(lights.begin(), lights.end()), casting;
    for (ShadeLight& l : open) {
        if (l.shadow) casting.push_back(l), casting.back().shadow = nullptr;
        l.shadow = nullptr;
    }
    out_.direct.resize(light_vertices && !casting.empty() ? count : 0);

    std::vector<DrawTransform> transforms;
    for (const Draw& d : world_.draws) {
        const glm::mat4& m = frame.state.objects[d.object].transform;
        transforms.push_back({m, glm::transpose(glm::inverse(glm::mat3(m))),
                              glm::determinant(glm::mat3(m)) < 0 ? -1.0f : 1.0f});
    }
    const glm::mat4& view_projection = frame.camera.view_projection;
    pool.parallel_for_chunks(count, kVerticesPerChunk, [&](size_t first, size_t last) {
        for (size_t v = first; v < last; ++v) {
            const DrawTransform& t = transforms[world_.vertex_draw[v]];
            const glm::vec4 world = t.model * glm::vec4(posed.positions[v], 1.0f);
            out_.world_position[v] = glm::vec3(world);
            out_.clip[v] = view_projection * world;
            const glm::vec3 n = t.normal * posed.normals[v];
            const float len = glm::length(n);
            out_.world_normal[v] = len > 0 ? n / len : glm::vec3(0, 1, 0);
            if (tangents)
                out_.world_tangent[v] = world_tangent(t, posed.tangents[v], out_.world_normal[v]);
        }
        if (light_vertices) light(first, last, frame, *light_for, open, casting);
    });
    return out_;
}

}  // namespace facet
