#pragma once
// Values that may change over time: a constant, or a keyframe track. These
// are plain records read from the scene file; anim/track.hpp evaluates them.
#include <memory>
#include <vector>

#include <glm/vec4.hpp>

#include "core/error.hpp"

namespace facet {

// How a track moves from one key to the next (docs/scene-format.md, "Animation").
enum class TrackInterpolation {
    step,         // holds each key's value until the next key
    linear,       // straight line (slerp for rotations)
    smooth,       // Catmull-Rom through the keys
    ease_in,      // CSS cubic-bezier(0.42, 0, 1, 1) on each segment
    ease_out,     // cubic-bezier(0, 0, 0.58, 1)
    ease_in_out,  // cubic-bezier(0.42, 0, 0.58, 1)
    bezier,       // cubic-bezier(Track::bezier) given by the user
};

// What a track does before its first key and after its last.
enum class TrackExtrapolation {
    hold,    // keeps the end key's value
    cycle,   // repeats the keyed span
    linear,  // continues along the end segment
};

// Rotations given as Euler keys: quaternion interpolation along the shorter
// arc (no flips, no gimbal wobble), or the Euler angles themselves, so that
// 0 -> 720 makes two full turns. `automatic` takes the angles when two
// neighbouring keys differ by a full turn or more on some axis (the user
// asked for turns) and the shorter arc otherwise.
enum class RotationPath { automatic, shortest, angles };

struct Track {
    std::vector<double> times;       // strictly increasing; frames, or seconds when `seconds`
    std::vector<glm::dvec4> values;  // one per key, `components` of them used
    std::vector<SourceLocation> at;  // where each key was written
    int components = 1;
    bool seconds = false;
    TrackInterpolation interpolation = TrackInterpolation::linear;
    glm::dvec4 bezier = {0.42, 0, 0.58, 1};  // x1, y1, x2, y2 of the timing curve
    TrackExtrapolation before = TrackExtrapolation::hold;
    TrackExtrapolation after = TrackExtrapolation::hold;
    RotationPath rotation = RotationPath::automatic;  // used by rotation tracks only
    // Evaluated values are clamped to this range (smooth keys overshoot, and
    // linear extrapolation runs on), so a field never leaves its valid range.
    double min = -1e30, max = 1e30;
    SourceLocation where;
};

// A value of type T (float, glm::vec3) that is either constant or keyed.
template <typename T>
struct Animated {
    T value{};  // the constant; for a track, its first key's value
    std::shared_ptr<const Track> track;

    Animated() = default;
    Animated(T constant) : value(constant) {}  // NOLINT: constants convert implicitly
    bool animated() const { return track != nullptr; }
};

}  // namespace facet
