#pragma once
// Camera placement helpers: spline paths travelled at constant speed, and
// framing (the distance at which bounds fill the view).
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "assets/mesh.hpp"

namespace facet {

// A centripetal Catmull-Rom spline through the points (Yuksel, Schaefer and
// Keyser 2011, "Parameterization and applications of Catmull-Rom curves":
// the centripetal form never forms cusps or loops between control points),
// re-parametrised by arc length.
class SplinePath {
  public:
    SplinePath(std::span<const glm::vec3> points, bool closed);
    double length() const { return cumulative_.back(); }
    // The point at `fraction` (0..1) of the path's length.
    glm::dvec3 at_fraction(double fraction) const;

  private:
    glm::dvec3 on_segment(size_t segment, double u) const;  // u in [0, 1]

    std::vector<glm::dvec3> points_;
    bool closed_;
    size_t segments_;
    // Arc length at each sample (kSamplesPerSegment per segment, plus the end).
    std::vector<double> cumulative_;
};

// A sphere that contains all of the given world-space spheres.
struct Sphere {
    glm::dvec3 center{0};
    double radius = 0;
};
Sphere enclosing_sphere(std::span<const Sphere> spheres);

// The sphere around a model-space box after transforming by `model`; its
// radius does not change as the object turns, so framing stays steady.
Sphere transformed_box_sphere(const Bounds& box, const glm::mat4& model);

struct ViewAngles {
    double tan_half_vertical;
    double tan_half_horizontal;
};
ViewAngles view_angles(double fov_degrees, double aspect);

// Camera distance from the sphere's centre at which the sphere fits the view.
double sphere_fit_distance(const Sphere& sphere, const ViewAngles& view);

// Distance from `center` along `toward_camera` at which every corner fits the
// view of a camera looking at `center` with the given `up`.
double corners_fit_distance(std::span<const glm::dvec3> corners, const glm::dvec3& center,
                            const glm::dvec3& toward_camera, const glm::dvec3& up,
                            const ViewAngles& view);

// The exact fit of points in a perspective view looking along
// -toward_camera: the least distance at which every point's projection fits
// the view, and the sideways shift (along the view's right and up) that
// centres their projections. Per axis, a point at lateral offset x and
// depth z past the centre plane fits when |x - s| <= t (d + z), which
// holds for all points iff d >= (max(x - t z) - min(x + t z)) / (2 t), with
// s = (max(x - t z) + min(x + t z)) / 2.
struct ExactFit {
    double distance;
    glm::dvec3 shift;
};
ExactFit exact_fit_distance(std::span<const glm::dvec3> points, const glm::dvec3& center,
                            const glm::dvec3& toward_camera, const glm::dvec3& up,
                            const ViewAngles& view);

}  // namespace facet
