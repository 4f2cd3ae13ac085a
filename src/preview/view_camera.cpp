#include "preview/view_camera.hpp"

#include "preview/tweaks.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtx/rotate_vector.hpp>

namespace facet {
namespace {

constexpr float kPoleMarginDegrees = 1.0f;
constexpr float kMinDistance = 1e-4f;

// The camera's keys in order, each as "key: value".
std::vector<std::string> camera_lines(const ViewCamera& camera, const std::string& name) {
    return {"name: " + yaml_value(TweakValue(name)),   "position: " + yaml_vector(camera.position),
            "target: " + yaml_vector(camera.target),   "up: " + yaml_vector(camera.up),
            "fov: " + yaml_number(camera.fov_degrees), "near: " + yaml_number(camera.near),
            "far: " + yaml_number(camera.far)};
}

// A unit vector at right angles to `v`: the axis to turn or slide about
// when the view runs along `up` (a camera looking straight down).
glm::vec3 any_perpendicular(const glm::vec3& v) {
    const glm::vec3 axis =
        std::abs(v.x) < 0.9f * glm::length(v) ? glm::vec3(1, 0, 0) : glm::vec3(0, 0, 1);
    return glm::normalize(glm::cross(v, axis));
}

// cross(a, b) normalised, or a perpendicular of `a` when they are parallel.
glm::vec3 normal_to(const glm::vec3& a, const glm::vec3& b) {
    const glm::vec3 c = glm::cross(a, b);
    return glm::length(c) > 1e-6f * glm::length(a) * glm::length(b) ? glm::normalize(c)
                                                                    : any_perpendicular(a);
}

float degrees_between(const glm::vec3& a, const glm::vec3& b) {
    const float c = glm::dot(glm::normalize(a), glm::normalize(b));
    return glm::degrees(std::acos(std::clamp(c, -1.0f, 1.0f)));
}

}  // namespace

ViewCamera view_camera_from(const CameraState& state) {
    return {state.position, state.target, state.up, state.fov_degrees, state.near, state.far};
}

ViewCamera orbit(const ViewCamera& camera, float yaw_degrees, float pitch_degrees) {
    const glm::vec3 up = glm::normalize(camera.up);
    glm::vec3 offset = camera.position - camera.target;
    offset = glm::rotate(offset, glm::radians(yaw_degrees), up);
    // Pitch about the screen's right axis; a positive pitch raises the
    // camera towards `up`. Clamped so the view never crosses a pole.
    const float from_pole = degrees_between(offset, up);
    const float wanted =
        std::clamp(from_pole - pitch_degrees, kPoleMarginDegrees, 180.0f - kPoleMarginDegrees);
    offset = glm::rotate(offset, glm::radians(from_pole - wanted), normal_to(offset, up));
    ViewCamera out = camera;
    out.position = camera.target + offset;
    return out;
}

ViewCamera pan(const ViewCamera& camera, float right, float up) {
    const glm::vec3 forward = camera.target - camera.position;
    const float distance = glm::length(forward);
    const glm::vec3 screen_right = normal_to(forward, camera.up);
    const glm::vec3 screen_up = glm::normalize(glm::cross(screen_right, forward));
    const float view_height = 2.0f * distance * std::tan(glm::radians(camera.fov_degrees) * 0.5f);
    const glm::vec3 move = (screen_right * right + screen_up * up) * view_height;
    ViewCamera out = camera;
    out.position += move;
    out.target += move;
    return out;
}

ViewCamera dolly(const ViewCamera& camera, float factor) {
    const glm::vec3 offset = camera.position - camera.target;
    const float distance = glm::length(offset);
    const float scaled = std::max(distance * factor, kMinDistance);
    ViewCamera out = camera;
    if (distance > 0.0f) out.position = camera.target + offset * (scaled / distance);
    // Far moves with the camera, so everything that was in range still is;
    // near shrinks coming closer (what is in front of the target comes
    // nearer too), and never grows.
    const float ratio = distance > 0.0f ? scaled / distance : 1.0f;
    out.near = camera.near * std::min(ratio, 1.0f);
    out.far = std::max(camera.far + (scaled - distance), out.near * 2.0f);
    return out;
}

std::string camera_yaml(const ViewCamera& camera, const std::string& name) {
    std::string text;
    for (const std::string& line : camera_lines(camera, name)) text += line + "\n";
    return text;
}

std::string scene_camera_key(const CameraDesc& scene_camera) {
    // A scene without `camera:` has one default camera, with no key of its own.
    return scene_camera.key.empty() ? "camera" : scene_camera.key;
}

Override camera_override(const ViewCamera& camera, const CameraDesc& scene_camera) {
    std::string value;
    for (const std::string& line : camera_lines(camera, scene_camera.name))
        value += (value.empty() ? "{" : ", ") + line;
    value += "}";
    return {scene_camera_key(scene_camera), value, "preview camera"};
}

}  // namespace facet
