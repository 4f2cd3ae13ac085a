#pragma once
// The scene evaluated at one frame: a pure function of the scene records, the
// objects' model-space bounds and the frame number, so any subset of frames
// renders the same as a full run.
#include <cmath>
#include <optional>
#include <span>
#include <vector>

#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>
#include <glm/vec3.hpp>

#include "assets/mesh.hpp"
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

// Material values the scene animates; unset ones keep the built material.
struct MaterialState {
    std::optional<glm::vec3> color;
    std::optional<float> ambient, diffuse, specular, shininess, metallic, roughness;
    bool any() const {
        return color || ambient || diffuse || specular || shininess || metallic || roughness;
    }
};

struct ObjectState {
    glm::mat4 transform{1.0f};  // model -> world
    MaterialState material;
    double animation_seconds = 0;  // time in the object's glTF animation, if it plays one
};

// How much `transform` (model -> world) scales lengths: the cube root of
// its linear part's |determinant|, exact for a uniform scale. A volume's
// thickness, given in the mesh's units, is this times longer in the world.
inline float object_scale(const glm::mat4& transform) {
    return static_cast<float>(std::cbrt(std::abs(glm::determinant(glm::mat3(transform)))));
}

struct LightState {
    LightType type = LightType::directional;
    glm::vec3 direction{0, -1, 0};  // the way the light travels (directional, spot)
    glm::vec3 position{0};          // point, spot
    glm::vec3 color{1};             // linear RGB (from a colour temperature when one is given)
    float intensity = 1;
    float range = 0;  // point, spot: distance where the light reaches zero; 0 for no limit
    float inner_angle = 0, outer_angle = 45;  // spot cone half-angles, degrees, inner <= outer
    bool shadows = false;
    int shadow_resolution = 0;
    float shadow_softness = 1;  // filter radius in texels
    float shadow_bias = 1;
};

struct FrameState {
    int frame = 0;
    double time = 0;      // seconds since the first frame of the scene's range
    double progress = 0;  // 0 at the first frame; 1 one frame past the last (loops close)
    CameraState camera;
    std::vector<ObjectState> objects;  // one per scene object
    std::vector<LightState> lights;
};

// What cameras with `frame:` fit of one scene object, in model space.
struct FramingShape {
    Bounds bounds;  // for an animated mesh, over the frames of the scene
    // The vertices `fit: geometry` fits; empty: the bounds' corners.
    std::vector<glm::vec3> points;
};

// A scene camera `from:` a glTF file: the file's camera and what moves it.
struct FileCamera {
    GltfCamera camera;
    std::shared_ptr<const MeshRig> rig;  // null: the scene camera is not from a file
    std::vector<int> animations;         // the file's animations that move the camera
};

// A light of an object's glTF file (`lights: true`), in the object's model
// space: it moves with the object.
struct ObjectLight {
    uint32_t object;
    GltfLight light;
    float intensity_scale = 1;
};

// What the scene's loaded files add to its records.
struct FrameAssets {
    std::span<const FramingShape> framing;  // empty, or one per scene object: what `frame:` fits
    std::span<const FileCamera> cameras;    // empty, or one per scene camera
    std::span<const ObjectLight> lights;    // after the scene's own, in FrameState::lights
};

// `object_bounds` are model-space bounds per scene object (for following
// objects, and for framing when `assets.framing` is empty); `camera`
// indexes scene.cameras.
FrameState evaluate_frame(const SceneDesc& scene, std::span<const Bounds> object_bounds, int frame,
                          size_t camera = 0, const FrameAssets& assets = {});

// A file camera at `seconds` after the scene's first frame: its node's
// world transform (the camera looks down its -Z, +Y up), yfov and planes
// (an infinite far plane becomes 10^4 near planes away).
CameraState file_camera_state(const FileCamera& camera, double seconds);

// Model matrix from translate, a rotation and scale.
glm::mat4 object_matrix(const glm::vec3& translate, const glm::dquat& rotation,
                        const glm::vec3& scale);

}  // namespace facet
