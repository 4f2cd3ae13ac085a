#pragma once
// Stage 2 of a frame: the vertices that move by themselves, glTF animations
// (skins, morph targets, node channels) and cloth simulations, posed for
// this frame in model space. Scenes without them pass the world's own
// arrays through.
#include <memory>
#include <span>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "anim/frame_state.hpp"
#include "assets/gltf_pose.hpp"
#include "cloth/cloth.hpp"
#include "render/world.hpp"

namespace facet {

// Model-space vertex arrays of this frame, in World's vertex order, and the
// bounds of each scene object in this pose (animated meshes can leave their
// rest bounds).
struct PosedVertices {
    std::span<const glm::vec3> positions;
    std::span<const glm::vec3> normals;
    std::span<const Bounds> object_bounds;
    // Per triangle, 1 where the pose mirrors its part (a negative scale):
    // its winding on screen is reversed. Empty when nothing is mirrored.
    std::span<const uint8_t> flipped_triangles;
    // World::tangents posed: turned with the skin or node transform (its
    // linear part, w flipped where it mirrors), a cloth's recomputed from
    // its moved triangles. Empty when the world has none.
    std::span<const glm::vec4> tangents;
};

class PoseStage {
  public:
    PoseStage(const SceneDesc& scene, const World& world);

    // Valid until the next call.
    PosedVertices pose(const FrameState& state);

  private:
    void write_part(uint32_t draw, std::span<const glm::vec3> positions,
                    std::span<const glm::vec3> normals, std::span<const glm::vec4> tangents);
    // A cloth's tangents from its posed triangles (the solver moves no tangents).
    void refresh_cloth_tangents(uint32_t draw);
    // Records whether the pose mirrors the draw's triangles.
    void mark_flipped(uint32_t draw, bool flipped);

    const SceneDesc& scene_;
    const World& world_;
    std::vector<std::unique_ptr<ClothSimulation>> cloths_;  // per World::cloths
    // A copy of the world's arrays with the moving parts posed, when any move.
    std::vector<glm::vec3> positions_, normals_;
    std::vector<glm::vec4> tangents_;
    std::vector<Bounds> bounds_;
    std::vector<uint8_t> flipped_;  // per triangle; empty until a part is mirrored
    std::vector<PosedPart> scratch_;
};

}  // namespace facet
