#pragma once
// Keyframe track evaluation: pure functions of the track and the time.
#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "scene/animated.hpp"

namespace facet {

// Where a frame sits on both time axes a track can be keyed on.
struct FrameTime {
    double frame = 1;
    double seconds = 0;  // since the first frame of the scene's range
};

// The timing curve of an eased segment: s in [0, 1] -> eased s. For
// `bezier` it is the CSS cubic-bezier(x1, y1, x2, y2) timing function.
double ease(TrackInterpolation mode, const glm::dvec4& bezier, double s);

// The track's value at `time` (frames or seconds, as the track is keyed),
// clamped to the track's range.
glm::dvec4 evaluate_track(const Track& track, double time);

float evaluate(const Animated<float>& value, const FrameTime& at);
glm::vec3 evaluate(const Animated<glm::vec3>& value, const FrameTime& at);

// Euler degrees (X then Y then Z, applied to the object) as a quaternion.
glm::dquat euler_to_quat(const glm::dvec3& degrees);

// A rotation track of Euler keys, interpolated as its RotationPath says.
glm::dquat evaluate_rotation(const Animated<glm::vec3>& euler_degrees, const FrameTime& at);

// Spherical linear interpolation along the great circle through a and b;
// u outside [0, 1] continues along it (used for extrapolation).
glm::dquat slerp_unclamped(const glm::dquat& a, const glm::dquat& b, double u);

}  // namespace facet
