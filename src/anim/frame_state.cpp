#include "anim/frame_state.hpp"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

namespace facet {

glm::mat4 object_matrix(const glm::vec3& translate, const glm::vec3& rotate_degrees,
                        const glm::vec3& scale) {
    glm::mat4 m = glm::translate(glm::mat4(1.0f), translate);
    // "X then Y then Z" applied to the object: the matrix is Rz * Ry * Rx.
    m = glm::rotate(m, glm::radians(rotate_degrees.z), glm::vec3(0, 0, 1));
    m = glm::rotate(m, glm::radians(rotate_degrees.y), glm::vec3(0, 1, 0));
    m = glm::rotate(m, glm::radians(rotate_degrees.x), glm::vec3(1, 0, 0));
    return glm::scale(m, scale);
}

FrameState evaluate_frame(const SceneDesc& scene, int frame) {
    FrameState state;
    state.frame = frame;
    const auto& frames = scene.output.frames;
    const int first = frames.empty() ? 1 : frames.front();
    const int last = frames.empty() ? 1 : frames.back();
    // One full cycle spans last - first + 1 frames, so frame last + 1 would
    // equal frame first again: turntables loop without a repeated frame.
    state.progress = static_cast<double>(frame - first) / static_cast<double>(last - first + 1);
    state.time = static_cast<double>(frame - first) / scene.output.fps;

    const CameraDesc& cam = scene.camera;
    state.camera = {cam.position, cam.target, cam.up, cam.fov, cam.near, cam.far};
    if (cam.orbit) {
        const OrbitDesc& o = *cam.orbit;
        double angle = glm::radians(o.start_angle + 360.0 * o.turns * state.progress);
        double elevation = glm::radians(static_cast<double>(o.elevation));
        glm::dvec3 offset(std::cos(elevation) * std::sin(angle), std::sin(elevation),
                          std::cos(elevation) * std::cos(angle));
        state.camera.position = o.center + glm::vec3(offset * static_cast<double>(o.radius));
        state.camera.target = o.center;
    }

    state.object_transforms.reserve(scene.objects.size());
    for (const ObjectDesc& obj : scene.objects) {
        glm::mat4 m = object_matrix(obj.translate, obj.rotate, obj.scale);
        if (obj.spin) {
            // Spin about the object's own origin, after its static rotation.
            double degrees = 360.0 * obj.spin->turns * state.progress;
            glm::mat4 spin = glm::rotate(glm::mat4(1.0f), static_cast<float>(glm::radians(degrees)),
                                         glm::normalize(obj.spin->axis));
            m = glm::translate(glm::mat4(1.0f), obj.translate) * spin *
                object_matrix(glm::vec3(0), obj.rotate, obj.scale);
        }
        state.object_transforms.push_back(m);
    }
    state.lights = scene.lights;
    return state;
}

}  // namespace facet
