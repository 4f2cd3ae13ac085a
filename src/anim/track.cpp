#include "anim/track.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace facet {
namespace {

// Bisection steps for inverting the Bezier timing curve's x(u): each halves
// the interval, so 60 steps reach double precision from [0, 1] and the
// result does not depend on a starting guess (unlike Newton's method).
constexpr int kBezierSolveSteps = 60;

double cubic_bezier_1d(double p1, double p2, double u) {
    // Endpoints fixed at 0 and 1 (CSS Easing Functions Level 1, §2.2).
    const double v = 1 - u;
    return 3 * v * v * u * p1 + 3 * v * u * u * p2 + u * u * u;
}

// The position of time `t` in the keyed span: the segment index i (keys i and
// i + 1) and the fraction s of the way through it.
struct Segment {
    size_t i;
    double s;
};

Segment find_segment(const std::vector<double>& times, double t) {
    // First key strictly after t; t lies in the segment before it.
    auto next = std::upper_bound(times.begin(), times.end(), t);
    size_t i = next == times.begin() ? 0 : static_cast<size_t>(next - times.begin()) - 1;
    i = std::min(i, times.size() - 2);
    double s = (t - times[i]) / (times[i + 1] - times[i]);
    return {i, std::clamp(s, 0.0, 1.0)};
}

// Time folded into [first, last] for cycling tracks.
double wrap_time(const Track& track, double t) {
    const double first = track.times.front(), last = track.times.back();
    const double period = last - first;
    double offset = std::fmod(t - first, period);
    if (offset < 0) offset += period;
    return first + offset;
}

// Catmull-Rom through p0..p3 at knots t0..t3, evaluated at t in [t1, t2] by
// the Barry-Goldman pyramid (Barry and Goldman 1988, "A recursive
// evaluation algorithm for a class of Catmull-Rom splines"). With the key
// times as knots, unevenly spaced keys still give a curve without kinks.
// `mix(a, b, u)` is lerp for values and slerp for rotations.
template <typename T, typename Mix>
T barry_goldman(const T p[4], const double k[4], double t, Mix mix) {
    auto between = [&](const T& a, const T& b, double ka, double kb) {
        return mix(a, b, (t - ka) / (kb - ka));
    };
    T a1 = between(p[0], p[1], k[0], k[1]);
    T a2 = between(p[1], p[2], k[1], k[2]);
    T a3 = between(p[2], p[3], k[2], k[3]);
    T b1 = between(a1, a2, k[0], k[2]);
    T b2 = between(a2, a3, k[1], k[3]);
    return between(b1, b2, k[1], k[2]);
}

// The four points and knots around segment i; missing neighbours at the ends
// are mirrored through the end key, which makes the end tangent point at
// the neighbouring key.
template <typename T, typename Mix>
void neighbours(const std::vector<T>& values, const std::vector<double>& times, size_t i, T p[4],
                double k[4], Mix mix) {
    const size_t n = values.size();
    p[1] = values[i], p[2] = values[i + 1];
    k[1] = times[i], k[2] = times[i + 1];
    if (i > 0) {
        p[0] = values[i - 1], k[0] = times[i - 1];
    } else {
        p[0] = mix(values[1], values[0], 2.0), k[0] = 2 * times[0] - times[1];
    }
    if (i + 2 < n) {
        p[3] = values[i + 2], k[3] = times[i + 2];
    } else {
        p[3] = mix(values[n - 2], values[n - 1], 2.0), k[3] = 2 * times[n - 1] - times[n - 2];
    }
}

// Interpolates a track's keys (values of type T, mixed by `mix`) at time t,
// with extrapolation outside the keys.
template <typename T, typename Mix>
T interpolate(const Track& track, const std::vector<T>& values, double t, Mix mix) {
    const auto& times = track.times;
    const size_t n = times.size();
    if (n == 1) return values[0];
    if (t < times.front() || t > times.back()) {
        const bool before = t < times.front();
        switch (before ? track.before : track.after) {
            case TrackExtrapolation::hold:
                return before ? values.front() : values.back();
            case TrackExtrapolation::cycle:
                t = wrap_time(track, t);
                break;
            case TrackExtrapolation::linear: {
                if (track.interpolation == TrackInterpolation::step)
                    return before ? values.front() : values.back();
                // Continue the end segment at its average rate.
                size_t i = before ? 0 : n - 2;
                double s = (t - times[i]) / (times[i + 1] - times[i]);
                return mix(values[i], values[i + 1], s);
            }
        }
    }
    const Segment seg = find_segment(times, t);
    switch (track.interpolation) {
        case TrackInterpolation::step:
            return seg.s >= 1 ? values[seg.i + 1] : values[seg.i];
        case TrackInterpolation::linear:
            return mix(values[seg.i], values[seg.i + 1], seg.s);
        case TrackInterpolation::smooth: {
            T p[4];
            double k[4];
            neighbours(values, times, seg.i, p, k, mix);
            return barry_goldman(p, k, times[seg.i] + seg.s * (k[2] - k[1]), mix);
        }
        case TrackInterpolation::ease_in:
        case TrackInterpolation::ease_out:
        case TrackInterpolation::ease_in_out:
        case TrackInterpolation::bezier:
            return mix(values[seg.i], values[seg.i + 1],
                       ease(track.interpolation, track.bezier, seg.s));
    }
    return values[seg.i];
}

glm::dvec4 lerp(const glm::dvec4& a, const glm::dvec4& b, double u) {
    return a + (b - a) * u;
}

// True when two neighbouring keys differ by a full turn or more on an axis:
// the user wrote turns, which the shorter arc would not make.
bool keys_ask_for_turns(const Track& track) {
    for (size_t i = 1; i < track.values.size(); ++i)
        for (int axis = 0; axis < 3; ++axis)
            if (std::abs(track.values[i][axis] - track.values[i - 1][axis]) >= 360) return true;
    return false;
}

}  // namespace

double ease(TrackInterpolation mode, const glm::dvec4& bezier, double s) {
    glm::dvec4 c;
    switch (mode) {
        case TrackInterpolation::ease_in:
            c = {0.42, 0, 1, 1};
            break;
        case TrackInterpolation::ease_out:
            c = {0, 0, 0.58, 1};
            break;
        case TrackInterpolation::ease_in_out:
            c = {0.42, 0, 0.58, 1};
            break;
        case TrackInterpolation::bezier:
            c = bezier;
            break;
        default:
            return s;
    }
    if (s <= 0) return 0;
    if (s >= 1) return 1;
    // x(u) is monotonic for x1, x2 in [0, 1]: find u with x(u) = s, return y(u).
    double lo = 0, hi = 1;
    for (int step = 0; step < kBezierSolveSteps; ++step) {
        double mid = 0.5 * (lo + hi);
        (cubic_bezier_1d(c.x, c.z, mid) < s ? lo : hi) = mid;
    }
    return cubic_bezier_1d(c.y, c.w, 0.5 * (lo + hi));
}

glm::dvec4 evaluate_track(const Track& track, double time) {
    glm::dvec4 v = interpolate(track, track.values, time, lerp);
    for (int c = 0; c < track.components; ++c) v[c] = std::clamp(v[c], track.min, track.max);
    return v;
}

float evaluate(const Animated<float>& value, const FrameTime& at) {
    if (!value.track) return value.value;
    const Track& t = *value.track;
    return static_cast<float>(evaluate_track(t, t.seconds ? at.seconds : at.frame).x);
}

glm::vec3 evaluate(const Animated<glm::vec3>& value, const FrameTime& at) {
    if (!value.track) return value.value;
    const Track& t = *value.track;
    return glm::vec3(evaluate_track(t, t.seconds ? at.seconds : at.frame));
}

glm::dquat euler_to_quat(const glm::dvec3& degrees) {
    const glm::dvec3 r = glm::radians(degrees);
    // X first, then Y, then Z: q = qz * qy * qx.
    return glm::angleAxis(r.z, glm::dvec3(0, 0, 1)) * glm::angleAxis(r.y, glm::dvec3(0, 1, 0)) *
           glm::angleAxis(r.x, glm::dvec3(1, 0, 0));
}

glm::dquat slerp_unclamped(const glm::dquat& a, const glm::dquat& b, double u) {
    double cos_angle = std::clamp(glm::dot(a, b), -1.0, 1.0);
    double angle = std::acos(cos_angle);
    double sin_angle = std::sin(angle);
    // Nearly equal rotations: the sine ratios lose precision, and the chord
    // is the arc to within rounding anyway.
    if (sin_angle < 1e-9) return glm::normalize(a + (b - a) * u);
    double wa = std::sin((1 - u) * angle) / sin_angle;
    double wb = std::sin(u * angle) / sin_angle;
    return glm::normalize(a * wa + b * wb);
}

glm::dquat evaluate_rotation(const Animated<glm::vec3>& euler_degrees, const FrameTime& at) {
    if (!euler_degrees.track) return euler_to_quat(glm::dvec3(euler_degrees.value));
    const Track& track = *euler_degrees.track;
    const double time = track.seconds ? at.seconds : at.frame;
    const bool angles = track.rotation == RotationPath::angles ||
                        (track.rotation == RotationPath::automatic && keys_ask_for_turns(track));
    if (angles) return euler_to_quat(glm::dvec3(evaluate_track(track, time)));

    // q and -q are the same rotation; flipping each key into the hemisphere
    // of the one before makes every segment take the shorter arc.
    std::vector<glm::dquat> keys;
    keys.reserve(track.values.size());
    for (const glm::dvec4& v : track.values) {
        glm::dquat q = euler_to_quat(glm::dvec3(v));
        if (!keys.empty() && glm::dot(keys.back(), q) < 0) q = -q;
        keys.push_back(q);
    }
    return interpolate(track, keys, time, slerp_unclamped);
}

}  // namespace facet
