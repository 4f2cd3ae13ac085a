#include "anim/camera_path.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/trigonometric.hpp>

namespace facet {
namespace {

// Arc-length table resolution. The speed error between samples is second
// order in the sample spacing; 64 per segment keeps it below 0.1% for
// paths whose segments bend less than a right angle.
constexpr int kSamplesPerSegment = 64;

// Centripetal parametrisation: knot spacing is the square root of the chord.
double knot_step(const glm::dvec3& a, const glm::dvec3& b) {
    return std::sqrt(glm::length(b - a));
}

}  // namespace

SplinePath::SplinePath(std::span<const glm::vec3> points, bool closed)
    : closed_(closed), segments_(closed ? points.size() : points.size() - 1) {
    for (const glm::vec3& p : points) points_.emplace_back(p);
    cumulative_.push_back(0);
    glm::dvec3 previous = on_segment(0, 0);
    for (size_t s = 0; s < segments_; ++s) {
        for (int k = 1; k <= kSamplesPerSegment; ++k) {
            glm::dvec3 p = on_segment(s, static_cast<double>(k) / kSamplesPerSegment);
            cumulative_.push_back(cumulative_.back() + glm::length(p - previous));
            previous = p;
        }
    }
}

glm::dvec3 SplinePath::on_segment(size_t segment, double u) const {
    const size_t n = points_.size();
    auto point = [&](long i) -> glm::dvec3 {
        if (closed_) return points_[static_cast<size_t>((i % static_cast<long>(n) + n) % n)];
        // Open ends: mirror the neighbour through the end point.
        if (i < 0) return 2.0 * points_[0] - points_[1];
        if (i >= static_cast<long>(n)) return 2.0 * points_[n - 1] - points_[n - 2];
        return points_[static_cast<size_t>(i)];
    };
    const long i = static_cast<long>(segment);
    const glm::dvec3 p0 = point(i - 1), p1 = point(i), p2 = point(i + 1), p3 = point(i + 2);
    const double t0 = 0, t1 = t0 + knot_step(p0, p1), t2 = t1 + knot_step(p1, p2),
                 t3 = t2 + knot_step(p2, p3);
    const double t = t1 + u * (t2 - t1);
    // Barry-Goldman pyramid (see anim/track.cpp).
    auto mix = [&](const glm::dvec3& a, const glm::dvec3& b, double ka, double kb) {
        return kb == ka ? a : a + (b - a) * ((t - ka) / (kb - ka));
    };
    glm::dvec3 a1 = mix(p0, p1, t0, t1), a2 = mix(p1, p2, t1, t2), a3 = mix(p2, p3, t2, t3);
    glm::dvec3 b1 = mix(a1, a2, t0, t2), b2 = mix(a2, a3, t1, t3);
    return mix(b1, b2, t1, t2);
}

glm::dvec3 SplinePath::at_fraction(double fraction) const {
    // A closed path wraps round (frames past the range keep looping); an
    // open one stops at its ends.
    double f = closed_ ? fraction - std::floor(fraction) : std::clamp(fraction, 0.0, 1.0);
    const double target = f * length();
    auto it = std::upper_bound(cumulative_.begin(), cumulative_.end(), target);
    size_t sample =
        it == cumulative_.begin() ? 0 : static_cast<size_t>(it - cumulative_.begin()) - 1;
    sample = std::min(sample, cumulative_.size() - 2);
    const double span = cumulative_[sample + 1] - cumulative_[sample];
    const double within = span > 0 ? (target - cumulative_[sample]) / span : 0;
    const size_t segment = sample / kSamplesPerSegment;
    const double u =
        (static_cast<double>(sample % kSamplesPerSegment) + within) / kSamplesPerSegment;
    return on_segment(segment, u);
}

Sphere enclosing_sphere(std::span<const Sphere> spheres) {
    if (spheres.empty()) return {};
    // Centre of the box around all spheres, then the radius that reaches the
    // farthest sphere: not minimal, but simple, stable and order independent.
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
    for (const Sphere& s : spheres) {
        lo = glm::min(lo, s.center - s.radius);
        hi = glm::max(hi, s.center + s.radius);
    }
    Sphere out{(lo + hi) * 0.5, 0};
    for (const Sphere& s : spheres)
        out.radius = std::max(out.radius, glm::length(s.center - out.center) + s.radius);
    return out;
}

Sphere transformed_box_sphere(const Bounds& box, const glm::mat4& model) {
    const glm::dmat4 m(model);
    const glm::dvec3 center = (glm::dvec3(box.min) + glm::dvec3(box.max)) * 0.5;
    const double half_diagonal = glm::length(glm::dvec3(box.max) - glm::dvec3(box.min)) * 0.5;
    const double stretch = std::max({glm::length(glm::dvec3(m[0])), glm::length(glm::dvec3(m[1])),
                                     glm::length(glm::dvec3(m[2]))});
    return {glm::dvec3(m * glm::dvec4(center, 1.0)), half_diagonal * stretch};
}

ViewAngles view_angles(double fov_degrees, double aspect) {
    const double v = std::tan(glm::radians(fov_degrees) * 0.5);
    return {v, v * aspect};
}

double sphere_fit_distance(const Sphere& sphere, const ViewAngles& view) {
    // The view cone's narrower half-angle must contain the sphere:
    // d * sin(theta) >= r.
    const double tan_half = std::min(view.tan_half_vertical, view.tan_half_horizontal);
    const double sin_half = tan_half / std::sqrt(1 + tan_half * tan_half);
    return sphere.radius / sin_half;
}

namespace {

struct ViewBasis {
    glm::dvec3 forward, right, up;
};

// The view's axes looking along -toward_camera; another axis stands in for
// an `up` parallel to the view.
ViewBasis view_basis(const glm::dvec3& toward_camera, const glm::dvec3& up) {
    const glm::dvec3 forward = -glm::normalize(toward_camera);
    glm::dvec3 right = glm::cross(forward, up);
    if (glm::length(right) < 1e-9) right = glm::cross(forward, glm::dvec3(0, 0, 1));
    right = glm::normalize(right);
    return {forward, right, glm::cross(right, forward)};
}

}  // namespace

double corners_fit_distance(std::span<const glm::dvec3> corners, const glm::dvec3& center,
                            const glm::dvec3& toward_camera, const glm::dvec3& up,
                            const ViewAngles& view) {
    const ViewBasis basis = view_basis(toward_camera, up);
    const glm::dvec3 forward = basis.forward, right = basis.right, true_up = basis.up;
    double distance = 0;
    for (const glm::dvec3& corner : corners) {
        const glm::dvec3 p = corner - center;
        // At distance d the corner is d + p.forward in front of the camera and
        // must satisfy |p.right| <= depth * tan(horizontal half-angle), the
        // same vertically, and lie in front of the camera.
        const double ahead = glm::dot(p, forward);
        distance =
            std::max(distance, std::abs(glm::dot(p, right)) / view.tan_half_horizontal - ahead);
        distance =
            std::max(distance, std::abs(glm::dot(p, true_up)) / view.tan_half_vertical - ahead);
        distance = std::max(distance, -ahead);
    }
    return distance;
}

ExactFit exact_fit_distance(std::span<const glm::dvec3> points, const glm::dvec3& center,
                            const glm::dvec3& toward_camera, const glm::dvec3& up,
                            const ViewAngles& view) {
    const ViewBasis basis = view_basis(toward_camera, up);
    const glm::dvec3 forward = basis.forward, right = basis.right, true_up = basis.up;
    const double inf = std::numeric_limits<double>::infinity();
    double low_x = -inf, high_x = inf, low_y = -inf, high_y = inf, nearest = inf;
    glm::dvec2 least(inf), most(-inf);  // of the lateral offsets, where the shifts lie
    for (const glm::dvec3& point : points) {
        const glm::dvec3 q = point - center;
        const double z = glm::dot(q, forward), x = glm::dot(q, right), y = glm::dot(q, true_up);
        low_x = std::max(low_x, x - view.tan_half_horizontal * z);
        high_x = std::min(high_x, x + view.tan_half_horizontal * z);
        low_y = std::max(low_y, y - view.tan_half_vertical * z);
        high_y = std::min(high_y, y + view.tan_half_vertical * z);
        nearest = std::min(nearest, z);
        least = glm::min(least, glm::dvec2(x, y));
        most = glm::max(most, glm::dvec2(x, y));
    }
    if (points.empty()) return {0, glm::dvec3(0)};
    double distance = std::max((low_x - high_x) / (2 * view.tan_half_horizontal),
                               (low_y - high_y) / (2 * view.tan_half_vertical));
    // Every point stays in front of the camera.
    distance = std::max(distance, -nearest + 1e-9 * (1 + std::abs(nearest)));
    // At that distance, each axis is centred where the farthest projections
    // either way are equal: the shift s minimising max |x - s| / (d + z).
    // The difference of the two sides falls as s grows, so bisection finds it.
    auto centred = [&](const glm::dvec3& axis, double low, double high) {
        for (int step = 0; step < 80; ++step) {
            const double s = 0.5 * (low + high);
            double ahead = -inf, behind = -inf;
            for (const glm::dvec3& point : points) {
                const glm::dvec3 q = point - center;
                const double depth = distance + glm::dot(q, forward);
                const double x = glm::dot(q, axis);
                ahead = std::max(ahead, (x - s) / depth);
                behind = std::max(behind, (s - x) / depth);
            }
            (ahead > behind ? low : high) = s;
        }
        return 0.5 * (low + high);
    };
    const double shift_x = centred(right, least.x, most.x);
    const double shift_y = centred(true_up, least.y, most.y);
    return {distance, right * shift_x + true_up * shift_y};
}

}  // namespace facet
