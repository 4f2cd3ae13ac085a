#pragma once
// The preview's own camera. It starts as the scene's camera at the frame
// shown and turns with the mouse: orbit about the target, pan across the
// view, dolly towards the target. It reaches the renderer as an override of
// the scene's camera key, so the window, a snapshot and the YAML printed for
// pasting into the scene all describe the same camera.
#include <string>

#include <glm/vec3.hpp>

#include "anim/frame_state.hpp"
#include "scene/scene_desc.hpp"

namespace facet {

struct ViewCamera {
    glm::vec3 position{0, 1, 5}, target{0, 0, 0}, up{0, 1, 0};
    float fov_degrees = 45;
    float near = 0.1f, far = 100;
};

ViewCamera view_camera_from(const CameraState& state);

// Turns the camera about its target: yaw about `up`, then pitch towards or
// away from it, stopping 1 degree short of either pole (where the view
// would flip over).
ViewCamera orbit(const ViewCamera& camera, float yaw_degrees, float pitch_degrees);

// Moves camera and target together across the view, by fractions of the
// view's height at the target's distance: +x right, +y up on screen.
ViewCamera pan(const ViewCamera& camera, float right, float up);

// Moves the camera towards the target (factor < 1) or away. Far moves by
// the distance travelled, so what was in range stays in range; near
// shrinks with the distance coming closer and stays put going away.
ViewCamera dolly(const ViewCamera& camera, float factor);

// The camera as the scene file writes it, one key per line:
//   name: main
//   position: [1.5, 2, 4]
//   ...
// Each number is the shortest text that reads back as the same float.
std::string camera_yaml(const ViewCamera& camera, const std::string& name);

// "camera" or "cameras.N": where the scene file writes this camera.
std::string scene_camera_key(const CameraDesc& scene_camera);

// The override of the scene camera's key (scene_camera_key) that
// replaces it with this still camera (a flow mapping of camera_yaml's keys).
Override camera_override(const ViewCamera& camera, const CameraDesc& scene_camera);

}  // namespace facet
