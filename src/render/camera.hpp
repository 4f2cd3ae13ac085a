#pragma once
// View and projection matrices. Projection is reversed-Z (near -> 1, far -> 0,
// after Reed 2015, "Depth Precision Visualized"): float depth keeps its
// precision where perspective spreads it thinnest.
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "anim/frame_state.hpp"

namespace facet {

struct CameraMatrices {
    glm::mat4 view;
    glm::mat4 projection;
    glm::mat4 view_projection;
    glm::vec3 position;
    glm::vec3 forward;  // unit viewing direction
    float near, far;
};

CameraMatrices make_camera(const CameraState& camera, float aspect);

}  // namespace facet
