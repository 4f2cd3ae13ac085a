#pragma once
// The scene evaluated at one frame: a pure function of the scene records and
// the frame number, so any subset of frames renders the same as a full run.
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "scene/scene_desc.hpp"

namespace facet {

struct CameraState {
    glm::vec3 position;
    glm::vec3 target;
    glm::vec3 up;
    float fov_degrees;
    float near;
    float far;
};

struct FrameState {
    int frame = 0;
    double time = 0;      // seconds since the first frame of the scene's range
    double progress = 0;  // 0 at the first frame; 1 one frame past the last (loops close)
    CameraState camera;
    std::vector<glm::mat4> object_transforms;  // model -> world, one per scene object
    std::vector<LightDesc> lights;
};

FrameState evaluate_frame(const SceneDesc& scene, int frame);

// Model matrix from translate, Euler rotate (X then Y then Z, degrees) and scale.
glm::mat4 object_matrix(const glm::vec3& translate, const glm::vec3& rotate_degrees,
                        const glm::vec3& scale);

}  // namespace facet
