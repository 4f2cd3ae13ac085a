#pragma once
// Stage 5 of a frame: every vertex from model space to world and clip space,
// in parallel over fixed chunks (each vertex's result depends only on
// itself); Gouraud styles also light each vertex here.
#include <span>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "core/bulk_buffer.hpp"
#include "core/thread_pool.hpp"
#include "render/frame_inputs.hpp"
#include "render/pose_stage.hpp"
#include "render/world.hpp"
#include "shade/lighting.hpp"

namespace facet {

// Per-vertex results, in World's vertex order.
struct TransformedVertices {
    BulkVector<glm::vec4> clip;
    BulkVector<glm::vec3> world_position;
    BulkVector<glm::vec3> world_normal;  // unit, +Y for a zero normal
    // Tangent frames in world space, when the world has any (World::tangents;
    // else empty, and nothing is spent on them): xyz turned by the model
    // matrix's linear part, made perpendicular to world_normal here (one
    // Gram-Schmidt step, so morphs and face-derived normals cannot leave it
    // askew) and unit; w flipped where the model matrix mirrors, so that
    // w (n x t) still points up the texture. Zero for the draws without
    // tangents. Interpolating across a triangle bends the two apart again:
    // a shader that wants them exactly perpendicular orthogonalises per pixel.
    BulkVector<glm::vec4> world_tangent;
    BulkVector<LightingResult> lit;  // Gouraud only (else empty): lighting at each vertex
    // Gouraud with shadow-casting lights (else empty): `lit` is then without
    // shadows, and this is the direct light (diffuse and highlight, without
    // the ambient term) of the lights that cast them, which each pixel's own
    // shadow lookups scale down.
    BulkVector<LightingResult> direct;
};

class VertexStage {
  public:
    explicit VertexStage(const World& world) : world_(world) {}

    // What transform() keeps for `vertices`: each one's clip and world
    // position and normal; its tangent when `tangents` (normal maps); its
    // lighting, and its direct share for per-pixel shadows, when `lit`
    // (Gouraud).
    static uint64_t bytes(uint64_t vertices, bool tangents, bool lit) {
        return vertices *
               (sizeof(glm::vec4) + 2 * sizeof(glm::vec3) + (tangents ? sizeof(glm::vec4) : 0) +
                (lit ? 2 * sizeof(LightingResult) : 0));
    }

    // Valid until the next call. `light_for`, when some style lights
    // vertices: fill `lit` (Blinn-Phong with the frame's materials and
    // lights, a metal-rough material read as its object's style reads it).
    const TransformedVertices& transform(const FrameInputs& frame, const PosedVertices& posed,
                                         std::span<const ShadeLight> lights,
                                         const StylePlan* light_for, ThreadPool& pool);

  private:
    float vertex_roughness(const Material& m, const Draw& draw, size_t v) const;
    void light(size_t first, size_t last, const FrameInputs& frame, const StylePlan& plan,
               std::span<const ShadeLight> lights, std::span<const ShadeLight> casting);

    const World& world_;
    TransformedVertices out_;
};

}  // namespace facet
