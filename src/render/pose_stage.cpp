#include "render/pose_stage.hpp"

#include <algorithm>
#include <cmath>

#include "anim/cloth_scene.hpp"
#include "assets/tangent_frames.hpp"

namespace facet {

PoseStage::PoseStage(const SceneDesc& scene, const World& world) : scene_(scene), world_(world) {
    for (const ClothObject& c : world.cloths)
        cloths_.push_back(scene_cloth_simulation(scene.objects[c.object], scene.output, c.model));
}

void PoseStage::write_part(uint32_t draw, std::span<const glm::vec3> positions,
                           std::span<const glm::vec3> normals,
                           std::span<const glm::vec4> tangents) {
    const Draw& d = world_.draws[draw];
    std::copy(positions.begin(), positions.end(), positions_.begin() + d.first_vertex);
    std::copy(normals.begin(), normals.end(), normals_.begin() + d.first_vertex);
    if (d.has_tangents && tangents.size() == d.vertex_count)
        std::copy(tangents.begin(), tangents.end(), tangents_.begin() + d.first_vertex);
}

void PoseStage::refresh_cloth_tangents(uint32_t draw) {
    const Draw& d = world_.draws[draw];
    if (!d.has_tangents) return;
    const std::span<const glm::vec3> positions(positions_.data() + d.first_vertex, d.vertex_count);
    const std::span<const glm::vec3> normals(normals_.data() + d.first_vertex, d.vertex_count);
    // A cloth has the one coordinate set of its grid.
    const std::span<const glm::vec2> uvs(world_.uvs.data() + d.first_vertex, d.vertex_count);
    const std::span<const uint32_t> indices(world_.indices.data() + 3 * size_t(d.first_triangle),
                                            3 * size_t(d.triangle_count));
    refresh_tangent_directions(
        positions, normals, uvs, indices, d.first_vertex,
        std::span<glm::vec4>(tangents_.data() + d.first_vertex, d.vertex_count));
}

void PoseStage::mark_flipped(uint32_t draw, bool flipped) {
    if (flipped && flipped_.empty()) flipped_.assign(world_.triangle_count(), 0);
    if (flipped_.empty()) return;
    const Draw& d = world_.draws[draw];
    std::fill_n(flipped_.begin() + d.first_triangle, d.triangle_count, flipped ? 1 : 0);
}

PosedVertices PoseStage::pose(const FrameState& state) {
    if (!world_.deforms())
        return {world_.positions, world_.normals, world_.object_bounds, {}, world_.tangents};
    if (positions_.empty()) {
        positions_ = world_.positions;
        normals_ = world_.normals;
        tangents_ = world_.tangents;
    }
    bounds_ = world_.object_bounds;
    for (const AnimatedMesh& a : world_.animated_meshes) {
        pose_mesh(*a.mesh, a.animations,
                  animation_clock(a, state.objects[a.object].animation_seconds), scratch_);
        Bounds posed;
        for (size_t part = 0; part < scratch_.size(); ++part) {
            const uint32_t draw = a.first_draw + static_cast<uint32_t>(part);
            write_part(draw, scratch_[part].positions, scratch_[part].normals,
                       scratch_[part].tangents);
            mark_flipped(draw, scratch_[part].winding_flipped);
            for (const glm::vec3& p : scratch_[part].positions) posed.add(p);
        }
        bounds_[a.object] = posed;
    }
    // Cloth frames count from the scene's first frame; the simulation runs
    // from there in fixed steps whatever frames are rendered.
    const int frame = std::max(0, state.frame - scene_.output.frames.front());
    for (size_t i = 0; i < world_.cloths.size(); ++i) {
        const ClothFrame cloth = cloths_[i]->state_at(frame);
        write_part(world_.cloths[i].draw, cloth.positions, cloth.normals, {});
        refresh_cloth_tangents(world_.cloths[i].draw);
    }
    return {positions_, normals_, bounds_, flipped_, tangents_};
}

}  // namespace facet
