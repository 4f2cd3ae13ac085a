// Vertex stage: model -> world -> clip space for every vertex of the frame,
// in parallel over fixed chunks (each vertex's result depends only on itself).
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "render/frame_renderer.hpp"
#include "shade/lighting_batch.hpp"

namespace facet {
namespace {
constexpr size_t kVerticesPerChunk = 16384;
}

// Gouraud: Blinn-Phong at each vertex, eight at a time, through the same
// batch lighting as per-pixel shading.
void FrameRenderer::light_vertices(size_t first, size_t last, const glm::vec3& eye,
                                   std::span<const ShadeLight> lights) {
    for (size_t start = first; start < last; start += simd::kLanes) {
        const int count = static_cast<int>(std::min<size_t>(simd::kLanes, last - start));
        SurfaceBatch s;
        for (int i = 0; i < count; ++i) {
            const size_t v = start + i;
            const glm::vec3& p = vertices_.world_position[v];
            const glm::vec3& n = vertices_.world_normal[v];
            const Draw& draw = world_.draws[world_.vertex_draw[v]];
            const Material& m = materials()[draw.material];
            s.px[i] = p.x, s.py[i] = p.y, s.pz[i] = p.z;
            s.nx[i] = n.x, s.ny[i] = n.y, s.nz[i] = n.z;
            s.ambient[i] = m.ambient, s.diffuse[i] = m.diffuse;
            s.specular[i] = m.specular, s.shininess[i] = m.shininess;
            s.receives_shadow[i] = world_.receives_shadows[draw.object];
        }
        pad_batch(s, count);
        const LightingBatch l = light_surface_batch(s, eye, lights, Highlight::blinn);
        for (int i = 0; i < count; ++i)
            vertices_.lit[start + i] = {{l.dr[i], l.dg[i], l.db[i]}, {l.sr[i], l.sg[i], l.sb[i]}};
    }
}

void FrameRenderer::vertex_stage(const FrameState& state, const CameraMatrices& camera,
                                 std::span<const ShadeLight> lights) {
    const size_t count = world_.positions.size();
    vertices_.clip.resize(count);
    vertices_.world_position.resize(count);
    vertices_.world_normal.resize(count);
    const bool gouraud = any_gouraud_;
    vertices_.lit.resize(gouraud ? count : 0);
    const bool posed = world_.deforms();  // posed by render() already
    const std::vector<glm::vec3>& positions = posed ? posed_positions_ : world_.positions;
    const std::vector<glm::vec3>& normals = posed ? posed_normals_ : world_.normals;

    struct DrawTransform {
        glm::mat4 model;
        glm::mat3 normal;
    };
    std::vector<DrawTransform> transforms;
    for (const Draw& d : world_.draws) {
        const glm::mat4& m = state.objects[d.object].transform;
        transforms.push_back({m, glm::transpose(glm::inverse(glm::mat3(m)))});
    }

    const size_t chunks = (count + kVerticesPerChunk - 1) / kVerticesPerChunk;
    pool_.parallel_for(chunks, [&](size_t chunk) {
        const size_t first = chunk * kVerticesPerChunk;
        const size_t last = std::min(first + kVerticesPerChunk, count);
        for (size_t v = first; v < last; ++v) {
            const uint32_t draw = world_.vertex_draw[v];
            const DrawTransform& t = transforms[draw];
            glm::vec4 world = t.model * glm::vec4(positions[v], 1.0f);
            vertices_.world_position[v] = glm::vec3(world);
            vertices_.clip[v] = camera.view_projection * world;
            glm::vec3 n = t.normal * normals[v];
            float len = glm::length(n);
            vertices_.world_normal[v] = len > 0 ? n / len : glm::vec3(0, 1, 0);
        }
        if (gouraud) light_vertices(first, last, camera.position, lights);
    });
}

}  // namespace facet
