#pragma once
// Stage 2 of a frame: the vertices that move by themselves, glTF animations
// (skins, morph targets, node channels) and cloth simulations, posed for
// this frame in model space. Scenes without them pass the world's own
// arrays through.
#include <memory>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "anim/frame_state.hpp"
#include "anim/gltf_pose.hpp"
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
};

class PoseStage {
  public:
    PoseStage(const SceneDesc& scene, const World& world);

    // Valid until the next call.
    PosedVertices pose(const FrameState& state);

  private:
    void write_part(uint32_t draw, std::span<const glm::vec3> positions,
                    std::span<const glm::vec3> normals);

    const SceneDesc& scene_;
    const World& world_;
    std::vector<std::unique_ptr<ClothSimulation>> cloths_;  // per World::cloths
    // A copy of the world's arrays with the moving parts posed, when any move.
    std::vector<glm::vec3> positions_, normals_;
    std::vector<Bounds> bounds_;
    std::vector<PosedPart> scratch_;
};

}  // namespace facet
