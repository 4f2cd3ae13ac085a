#pragma once
// For the motion pass: where every vertex was one frame earlier, in that
// frame's clip space. The scene is a function of the frame number, so the
// previous frame is evaluated and posed afresh (with its own pose and vertex
// stages: glTF animations, cloth, keyed transforms and the camera all move),
// whatever frames the run renders.
#include <span>

#include <glm/vec4.hpp>

#include "core/thread_pool.hpp"
#include "render/frame_inputs.hpp"
#include "render/pose_stage.hpp"
#include "render/vertex_stage.hpp"

namespace facet {

class PreviousFrameStage {
  public:
    PreviousFrameStage(const SceneDesc& scene, const World& world)
        : pose_(scene, world), vertices_(world) {}

    // `previous`: the evaluated frame before the one being rendered.
    // Valid until the next call.
    std::span<const glm::vec4> clip_positions(const FrameInputs& previous, ThreadPool& pool) {
        PosedVertices posed = pose_.pose(previous.state);
        posed.tangents = {};  // only where the vertices were is wanted
        const TransformedVertices& v = vertices_.transform(previous, posed, {}, nullptr, pool);
        return {v.clip.data(), v.clip.size()};
    }

  private:
    PoseStage pose_;
    VertexStage vertices_;
};

}  // namespace facet
