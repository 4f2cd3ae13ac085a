#include "anim/frame_state.hpp"

#include "assets/gltf_pose.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/trigonometric.hpp>

#include "anim/camera_path.hpp"
#include "anim/track.hpp"
#include "scene/color_temperature.hpp"

namespace facet {
namespace {

// Framing fits near/far around the scene; near never goes below this
// fraction of far (reversed-Z float depth keeps precision well past it).
constexpr double kMinNearOverFar = 1e-4;

size_t object_index(const SceneDesc& scene, const std::string& name) {
    for (size_t i = 0; i < scene.objects.size(); ++i)
        if (scene.objects[i].name == name) return i;
    return 0;  // names were checked when the scene was read
}

MaterialState evaluate_material(const MaterialDesc& m, const FrameTime& at) {
    MaterialState s;
    if (m.color && m.color->animated()) s.color = evaluate(*m.color, at);
    auto number = [&](const std::optional<Animated<float>>& v, std::optional<float>& out) {
        if (v && v->animated()) out = evaluate(*v, at);
    };
    number(m.ambient, s.ambient);
    number(m.diffuse, s.diffuse);
    number(m.specular, s.specular);
    number(m.shininess, s.shininess);
    number(m.metallic, s.metallic);
    number(m.roughness, s.roughness);
    return s;
}

glm::mat4 evaluate_transform(const ObjectDesc& obj, const FrameTime& at, double progress) {
    const glm::vec3 translate = evaluate(obj.translate, at);
    const glm::dquat rotation = evaluate_rotation(obj.rotate, at);
    const glm::vec3 scale = evaluate(obj.scale, at);
    if (!obj.spin) return object_matrix(translate, rotation, scale);
    // Spin about the object's own origin, after its own rotation.
    const double degrees = 360.0 * obj.spin->turns * progress;
    const glm::dquat spin =
        glm::angleAxis(glm::radians(degrees), glm::normalize(glm::dvec3(obj.spin->axis)));
    return object_matrix(translate, spin * rotation, scale);
}

LightState evaluate_light(const LightDesc& l, const FrameTime& at) {
    LightState s;
    s.type = l.type;
    s.direction = evaluate(l.direction, at);
    s.position = evaluate(l.position, at);
    if (l.kelvin) {
        const LinearRgb c = kelvin_to_linear_srgb(evaluate(*l.kelvin, at));
        s.color =
            glm::vec3(static_cast<float>(c.r), static_cast<float>(c.g), static_cast<float>(c.b));
    } else {
        s.color = evaluate(l.color, at);
    }
    s.intensity = evaluate(l.intensity, at);
    s.range = l.range ? evaluate(*l.range, at) : 0.0f;
    s.outer_angle = evaluate(l.outer_angle, at);
    // Keyed cone angles may cross; the inner cone never exceeds the outer one.
    s.inner_angle = std::min(evaluate(l.inner_angle, at), s.outer_angle);
    s.shadows = l.shadows;
    s.shadow_resolution = l.shadow_resolution;
    s.shadow_softness = evaluate(l.shadow_softness, at);
    s.shadow_bias = evaluate(l.shadow_bias, at);
    return s;
}

double animation_time(const AnimationChoiceDesc& choice, const FrameTime& at) {
    return choice.offset + choice.speed * at.seconds;
}

// A file light placed by its object's transform at this frame.
LightState object_light_state(const ObjectLight& l, const glm::mat4& model) {
    LightState s;
    s.type = l.light.type == GltfLight::Type::directional ? LightType::directional
             : l.light.type == GltfLight::Type::spot      ? LightType::spot
                                                          : LightType::point;
    s.position = glm::vec3(model * glm::vec4(l.light.position, 1.0f));
    const glm::vec3 direction = glm::mat3(model) * l.light.direction;
    const float length = glm::length(direction);
    s.direction = length > 0 ? direction / length : l.light.direction;
    s.color = l.light.color;
    s.intensity = l.light.intensity * kGltfLightUnit * l.intensity_scale;
    s.range = l.light.range;
    s.inner_angle = l.light.inner_degrees;
    s.outer_angle = l.light.outer_degrees;
    return s;
}

// The objects a framing camera fits, as spheres (steady as objects turn),
// world-space box corners, and world-space vertices (exact).
struct FramedBounds {
    Sphere sphere;
    std::vector<glm::dvec3> corners;
    std::vector<glm::dvec3> points;  // vertices, or corners for objects without them
};

FramedBounds framed_bounds(const SceneDesc& scene, std::span<const Bounds> object_bounds,
                           std::span<const FramingShape> shapes,
                           const std::vector<ObjectState>& objects,
                           const std::vector<std::string>& names, bool want_points = false) {
    std::vector<Sphere> spheres;
    FramedBounds out;
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const bool chosen = names.empty() ? scene.objects[i].visible
                                          : std::find(names.begin(), names.end(),
                                                      scene.objects[i].name) != names.end();
        const Bounds* bounds = i < shapes.size()          ? &shapes[i].bounds
                               : i < object_bounds.size() ? &object_bounds[i]
                                                          : nullptr;
        if (!chosen || !bounds || bounds->empty()) continue;
        spheres.push_back(transformed_box_sphere(*bounds, objects[i].transform));
        const glm::dmat4 m(objects[i].transform);
        for (int c = 0; c < 8; ++c) {
            glm::dvec3 p((c & 1) ? bounds->max.x : bounds->min.x,
                         (c & 2) ? bounds->max.y : bounds->min.y,
                         (c & 4) ? bounds->max.z : bounds->min.z);
            out.corners.emplace_back(m * glm::dvec4(p, 1.0));
        }
        if (!want_points) continue;
        if (i < shapes.size() && !shapes[i].points.empty()) {
            for (const glm::vec3& p : shapes[i].points)
                out.points.emplace_back(m * glm::dvec4(glm::dvec3(p), 1.0));
        } else {
            out.points.insert(out.points.end(), out.corners.end() - 8, out.corners.end());
        }
    }
    out.sphere = enclosing_sphere(spheres);
    return out;
}

// Near and far planes that contain every visible object, for framing cameras.
glm::vec2 fitted_clip_range(const SceneDesc& scene, std::span<const Bounds> bounds,
                            std::span<const FramingShape> shapes,
                            const std::vector<ObjectState>& objects, const glm::dvec3& eye,
                            const glm::dvec3& forward) {
    const Sphere all = framed_bounds(scene, bounds, shapes, objects, {}).sphere;
    const double ahead = glm::dot(all.center - eye, forward);
    // A little slack, so surfaces exactly on the sphere are not clipped.
    const double far = std::max(ahead + all.radius * 1.01, 1e-3);
    const double near = std::max(ahead - all.radius * 1.01, far * kMinNearOverFar);
    return {static_cast<float>(near), static_cast<float>(far)};
}

// The direction from an orbit's centre to the camera at `progress` (0..1
// over the frame range; 1 is the end of the turns).
glm::dvec3 orbit_direction(const OrbitDesc& o, const FrameTime& at, double progress) {
    const double sign = o.clockwise ? -1.0 : 1.0;
    const double angle =
        glm::radians(evaluate(o.start_angle, at) + sign * 360.0 * o.turns * progress);
    const double elevation = glm::radians(static_cast<double>(evaluate(o.elevation, at)));
    return {std::cos(elevation) * std::sin(angle), std::sin(elevation),
            std::cos(elevation) * std::cos(angle)};
}

CameraState evaluate_camera(const SceneDesc& scene, const CameraDesc& cam,
                            std::span<const Bounds> bounds, std::span<const FramingShape> shapes,
                            const std::vector<ObjectState>& objects, const FrameTime& at,
                            double progress, double path_fraction) {
    CameraState state;
    state.position = evaluate(cam.position, at);
    state.target = evaluate(cam.target, at);
    state.up = evaluate(cam.up, at);
    state.fov_degrees = evaluate(cam.fov, at);
    state.near = cam.near ? evaluate(*cam.near, at) : kDefaultCameraNear;
    state.far = cam.far ? evaluate(*cam.far, at) : kDefaultCameraFar;
    if (!cam.target_object.empty()) {
        const size_t i = object_index(scene, cam.target_object);
        const Bounds& b = bounds[i];
        const glm::vec3 centre = b.empty() ? glm::vec3(0) : (b.min + b.max) * 0.5f;
        state.target = glm::vec3(objects[i].transform * glm::vec4(centre, 1.0f));
    }
    if (cam.path) {
        SplinePath path(cam.path->points, cam.path->closed);
        const double fraction = cam.path->at ? evaluate(*cam.path->at, at) : path_fraction;
        state.position = glm::vec3(path.at_fraction(fraction));
    }

    // Where the camera sits as seen from its target: an orbit's direction, or
    // the direction from the target to the given position.
    glm::dvec3 centre(state.target);
    glm::dvec3 toward_camera = glm::dvec3(state.position) - centre;
    double distance = glm::length(toward_camera);
    if (cam.orbit) {
        toward_camera = orbit_direction(*cam.orbit, at, progress);
        centre = glm::dvec3(evaluate(cam.orbit->center, at));
        distance = evaluate(cam.orbit->radius, at);
    }
    if (cam.frame) {
        const FramingFit fit =
            cam.frame->fit.value_or(cam.orbit ? FramingFit::geometry : FramingFit::sphere);
        const FramedBounds framed = framed_bounds(scene, bounds, shapes, objects,
                                                  cam.frame->objects, fit == FramingFit::geometry);
        // The margin is a fraction of the view left free: the view angles
        // shrink by 1 + margin, so the bounds reach 1 / (1 + margin) of the
        // half-view for any fov and aspect.
        const double grow = 1.0 + cam.frame->margin;
        ViewAngles view = view_angles(
            state.fov_degrees, static_cast<double>(scene.output.width) / scene.output.height);
        view.tan_half_vertical /= grow;
        view.tan_half_horizontal /= grow;
        centre = framed.sphere.center;
        if (glm::length(toward_camera) < 1e-12) toward_camera = {0, 0, 1};
        const std::span<const glm::dvec3> points =
            fit == FramingFit::geometry ? framed.points : framed.corners;
        const glm::dvec3 up(state.up);
        if (fit == FramingFit::sphere) {
            distance = sphere_fit_distance(framed.sphere, view);
        } else if (cam.orbit) {
            // The union of the views over the whole orbit: the farthest of
            // the distances at which the points fit, so nothing leaves the
            // frame anywhere on the turn and the widest view fills it.
            constexpr int kOrbitSamples = 72;
            distance = corners_fit_distance(points, centre, toward_camera, up, view);
            for (int k = 0; k <= kOrbitSamples; ++k)
                distance = std::max(
                    distance,
                    corners_fit_distance(points, centre,
                                         orbit_direction(*cam.orbit, at, double(k) / kOrbitSamples),
                                         up, view));
        } else if (fit == FramingFit::box) {
            distance = corners_fit_distance(points, centre, toward_camera, up, view);
        } else {
            const ExactFit exact = exact_fit_distance(points, centre, toward_camera, up, view);
            centre += exact.shift;
            distance = exact.distance;
        }
    }
    if (cam.orbit || cam.frame) {
        const glm::dvec3 eye = centre + glm::normalize(toward_camera) * distance;
        state.position = glm::vec3(eye);
        state.target = glm::vec3(centre);
        if (cam.frame && !(cam.near && cam.far)) {
            const glm::vec2 range = fitted_clip_range(scene, bounds, shapes, objects, eye,
                                                      -glm::normalize(toward_camera));
            if (!cam.near) state.near = range.x;
            if (!cam.far) state.far = range.y;
        }
    }
    state.far = std::max(state.far, state.near * 1.001f);
    return state;
}

// A direction in the camera's frame (x right, y up, z towards the viewer)
// in world space.
glm::vec3 camera_to_world(const CameraState& camera, const glm::vec3& d) {
    const glm::vec3 forward = glm::normalize(camera.target - camera.position);
    const glm::vec3 right = glm::normalize(glm::cross(forward, camera.up));
    const glm::vec3 up = glm::cross(right, forward);
    return glm::normalize(d.x * right + d.y * up - d.z * forward);
}

}  // namespace

CameraState file_camera_state(const FileCamera& camera, double seconds) {
    const glm::dmat4 world =
        node_world_matrix(*camera.rig, camera.animations, seconds, camera.camera.node);
    CameraState state;
    const glm::dvec3 position(world * glm::dvec4(0, 0, 0, 1));
    const glm::dvec3 forward = glm::normalize(glm::dvec3(world * glm::dvec4(0, 0, -1, 0)));
    state.position = glm::vec3(position);
    state.target = glm::vec3(position + forward);
    state.up = glm::vec3(glm::normalize(glm::dvec3(world * glm::dvec4(0, 1, 0, 0))));
    state.fov_degrees = static_cast<float>(camera.camera.yfov_degrees);
    state.near = static_cast<float>(camera.camera.znear);
    state.far =
        static_cast<float>(camera.camera.zfar > 0 ? camera.camera.zfar : camera.camera.znear * 1e4);
    return state;
}

glm::mat4 object_matrix(const glm::vec3& translate, const glm::dquat& rotation,
                        const glm::vec3& scale) {
    glm::dmat4 m = glm::translate(glm::dmat4(1.0), glm::dvec3(translate));
    m = m * glm::mat4_cast(rotation);
    return glm::mat4(glm::scale(m, glm::dvec3(scale)));
}

FrameState evaluate_frame(const SceneDesc& scene, std::span<const Bounds> object_bounds, int frame,
                          size_t camera, const FrameAssets& assets) {
    FrameState state;
    state.frame = frame;
    const auto& frames = scene.output.frames;
    const int first = frames.empty() ? 1 : frames.front();
    const int last = frames.empty() ? 1 : frames.back();
    // One full cycle spans last - first + step frames (step: the gap before
    // the last frame, 1 for a plain range), so frame last + step would equal
    // frame first again: turntables loop without a repeated frame, and
    // `1-72:2` turns exactly as the same frames of `1-72`.
    const int step = frames.size() > 1 ? frames.back() - frames[frames.size() - 2] : 1;
    state.progress = static_cast<double>(frame - first) / static_cast<double>(last - first + step);
    state.time = static_cast<double>(frame - first) / scene.output.fps;
    const FrameTime at{static_cast<double>(frame), state.time};

    state.objects.reserve(scene.objects.size());
    for (const ObjectDesc& obj : scene.objects) {
        ObjectState o;
        o.transform = evaluate_transform(obj, at, state.progress);
        o.material = evaluate_material(obj.material, at);
        if (obj.animation) o.animation_seconds = animation_time(*obj.animation, at);
        state.objects.push_back(o);
    }
    for (const LightDesc& l : scene.lights) state.lights.push_back(evaluate_light(l, at));
    for (const ObjectLight& l : assets.lights)
        state.lights.push_back(object_light_state(l, state.objects[l.object].transform));

    // An open path runs from its first point at the first frame to its last
    // point at the last frame; a closed one loops like an orbit.
    const CameraDesc& cam = scene.cameras.at(camera);
    const double open_fraction =
        last > first ? static_cast<double>(frame - first) / (last - first) : 0.0;
    const double path_fraction = cam.path && cam.path->closed ? state.progress : open_fraction;
    if (camera < assets.cameras.size() && assets.cameras[camera].rig)
        state.camera = file_camera_state(assets.cameras[camera], state.time);
    else
        state.camera = evaluate_camera(scene, cam, object_bounds, assets.framing, state.objects, at,
                                       state.progress, path_fraction);
    for (size_t i = 0; i < scene.lights.size(); ++i)
        if (scene.lights[i].camera_relative)
            state.lights[i].direction = camera_to_world(state.camera, state.lights[i].direction);
    return state;
}

}  // namespace facet
