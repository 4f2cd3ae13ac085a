#include "render/framing_shapes.hpp"

#include <algorithm>
#include <tuple>

#include "assets/gltf_pose.hpp"

namespace facet {
namespace {

// Poses sampled for an animated mesh's bounds: every frame of a short
// scene, evenly spread frames of a long one.
constexpr size_t kMaxPosedFrames = 256;

std::vector<glm::vec3> distinct(std::vector<glm::vec3> points) {
    auto less = [](const glm::vec3& a, const glm::vec3& b) {
        return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
    };
    std::sort(points.begin(), points.end(), less);
    points.erase(std::unique(points.begin(), points.end()), points.end());
    return points;
}

std::vector<glm::vec3> corners(const Bounds& b) {
    std::vector<glm::vec3> out;
    for (int c = 0; c < 8; ++c)
        out.push_back({(c & 1) ? b.max.x : b.min.x, (c & 2) ? b.max.y : b.min.y,
                       (c & 4) ? b.max.z : b.min.z});
    return out;
}

// The bounds of an animated mesh's poses at the sampled frames of the scene.
Bounds posed_bounds(const SceneDesc& scene, const World& world, const AnimatedMesh& a) {
    const std::vector<int>& frames = scene.output.frames;
    const size_t step =
        std::max<size_t>(1, (frames.size() + kMaxPosedFrames - 1) / kMaxPosedFrames);
    std::vector<size_t> picked;
    for (size_t i = 0; i < frames.size(); i += step) picked.push_back(i);
    if (!frames.empty() && picked.back() != frames.size() - 1) picked.push_back(frames.size() - 1);
    Bounds bounds = world.object_bounds[a.object];
    std::vector<PosedPart> posed;
    for (size_t i : picked) {
        const FrameState state = evaluate_frame(scene, world.object_bounds, frames[i], 0,
                                                FrameAssets{{}, world.file_cameras, {}});
        pose_mesh(*a.mesh, a.animations,
                  animation_clock(a, state.objects[a.object].animation_seconds), posed);
        for (const PosedPart& part : posed)
            for (const glm::vec3& p : part.positions) bounds.add(p);
    }
    return bounds;
}

}  // namespace

std::vector<FramingShape> framing_shapes(const SceneDesc& scene, const World& world) {
    const bool framing = std::any_of(scene.cameras.begin(), scene.cameras.end(),
                                     [](const CameraDesc& c) { return c.frame.has_value(); });
    if (!framing) return {};
    std::vector<FramingShape> shapes(scene.objects.size());
    std::vector<std::vector<glm::vec3>> points(scene.objects.size());
    for (const Draw& d : world.draws)
        points[d.object].insert(points[d.object].end(), world.positions.begin() + d.first_vertex,
                                world.positions.begin() + d.first_vertex + d.vertex_count);
    for (size_t o = 0; o < shapes.size(); ++o) {
        shapes[o].bounds = world.object_bounds[o];
        shapes[o].points = distinct(std::move(points[o]));
    }
    for (const AnimatedMesh& a : world.animated_meshes) {
        shapes[a.object].bounds = posed_bounds(scene, world, a);
        shapes[a.object].points = corners(shapes[a.object].bounds);
    }
    return shapes;
}

}  // namespace facet
