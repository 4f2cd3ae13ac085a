// Deform stage: the vertices that move by themselves this frame, glTF
// animations (skins, morph targets, node channels) and cloth simulations,
// written into a copy of the world's model-space vertex arrays.
#include <algorithm>
#include <cmath>

#include "anim/cloth_scene.hpp"
#include "render/frame_renderer.hpp"

namespace facet {

void FrameRenderer::make_cloth_simulations() {
    const int first = scene_.output.frames.front();
    const double fps = scene_.output.fps;
    for (const ClothObject& c : world_.cloths) {
        const ObjectDesc& obj = scene_.objects[c.object];
        auto wind_at = [&obj, first, fps](int frame) { return cloth_wind(obj, frame, first, fps); };
        cloth_sims_.push_back(std::make_unique<ClothSimulation>(c.model, wind_at));
    }
}

void FrameRenderer::deform_meshes(const FrameState& state) {
    if (posed_positions_.empty()) {
        posed_positions_ = world_.positions;
        posed_normals_ = world_.normals;
    }
    auto write_part = [&](uint32_t draw, const std::vector<glm::vec3>& positions,
                          const std::vector<glm::vec3>& normals) {
        const Draw& d = world_.draws[draw];
        std::copy(positions.begin(), positions.end(), posed_positions_.begin() + d.first_vertex);
        std::copy(normals.begin(), normals.end(), posed_normals_.begin() + d.first_vertex);
    };
    for (const AnimatedMesh& a : world_.animated_meshes) {
        double seconds = state.objects[a.object].animation_seconds;
        if (a.loop && a.duration > 0) {
            seconds = std::fmod(seconds, a.duration);
            if (seconds < 0) seconds += a.duration;
        }
        pose_mesh(*a.mesh, a.animation, seconds, pose_scratch_);
        for (size_t part = 0; part < pose_scratch_.size(); ++part)
            write_part(a.first_draw + static_cast<uint32_t>(part), pose_scratch_[part].positions,
                       pose_scratch_[part].normals);
    }
    // Cloth frames count from the scene's first frame; the simulation runs
    // from there in fixed steps whatever frames are rendered.
    const int frame = std::max(0, state.frame - scene_.output.frames.front());
    for (size_t i = 0; i < world_.cloths.size(); ++i) {
        const ClothFrame cloth = cloth_sims_[i]->state_at(frame);
        write_part(world_.cloths[i].draw, cloth.positions, cloth.normals);
    }
}

}  // namespace facet
