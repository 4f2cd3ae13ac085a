#include "render/camera.hpp"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

namespace facet {

CameraMatrices make_camera(const CameraState& camera, float aspect) {
    CameraMatrices m;
    m.position = camera.position;
    m.near = camera.near;
    m.far = camera.far;
    glm::vec3 forward = glm::normalize(camera.target - camera.position);
    glm::vec3 up = glm::normalize(camera.up);
    // Looking along `up` leaves the roll undefined; pick another up vector.
    if (glm::length(glm::cross(forward, up)) < 1e-6f)
        up = std::abs(forward.z) < 0.9f ? glm::vec3(0, 0, 1) : glm::vec3(1, 0, 0);
    m.forward = forward;
    m.view = glm::lookAt(camera.position, camera.target, up);

    const float f = 1.0f / std::tan(glm::radians(camera.fov_degrees) * 0.5f);
    const float n = camera.near, fa = camera.far;
    m.projection = glm::mat4(0.0f);
    m.projection[0][0] = f / aspect;
    m.projection[1][1] = f;
    // z_clip = A z_view + B with w_clip = -z_view, so z/w is 1 at -near and 0 at -far.
    m.projection[2][2] = n / (fa - n);
    m.projection[3][2] = n * fa / (fa - n);
    m.projection[2][3] = -1.0f;
    m.view_projection = m.projection * m.view;
    return m;
}

}  // namespace facet
