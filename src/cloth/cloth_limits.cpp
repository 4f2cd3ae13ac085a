// The cloth's limits (cloth.hpp): the checks of its parameters and wind, and
// the stability bound of its explicit step that sets the number of substeps
// (docs/cloth.md, "The stability bound").
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include <glm/geometric.hpp>

#include "cloth/cloth.hpp"
#include "cloth/cloth_grid.hpp"
#include "core/error.hpp"

namespace facet {
namespace {

using namespace cloth_detail;

// Samples per axis of the lattice's wave vectors in the stability bound.
constexpr int kSymbolSamples = 64;
// The most the wind may move a vertex in one substep from rest, as a
// fraction of the smaller cell side: beyond it the strain limit's passes
// cannot pull the cloth back together.
constexpr double kMaxStepMove = 0.1;

// --- Messages ----------------------------------------------------------------

[[noreturn]] void fail_cloth(const std::string& message) {
    throw Error(ExitCode::invalid_input, message);
}

template <typename T>
[[noreturn]] void fail_range(const char* name, T value, const std::string& range,
                             const char* unit = "") {
    std::ostringstream s;
    s << name << " must be " << range << unit << ", got " << value << unit;
    fail_cloth(s.str());
}

bool finite(double v) {
    return std::isfinite(v);
}

// The largest eigenvalue of the springs' stiffness (or damping) matrix of the
// infinite lattice, from its Fourier symbol: a plane wave exp(i theta.j)
// sees K(theta) = sum over spring kinds of 2 k (1 - cos(theta.e)) d d^T.
// The finite grid's matrix is a principal submatrix (pins) of the lattice's
// minus the springs its free edges lack, so its eigenvalues are no larger.
// cos(theta) is sampled directly on [-1, 1] (with sin = sqrt(1 - cos^2)) so
// no trigonometric function is needed: the bound and thus the automatic
// substep count are the same bits everywhere.
double lattice_max_eigenvalue(const SpringConstants& k, const Grid& g) {
    const double d2 = g.dx * g.dx + g.dy * g.dy;
    const double wxx = g.dx * g.dx / d2, wyy = g.dy * g.dy / d2, wxy = g.dx * g.dy / d2;
    const bool bend_x = g.columns >= 3, bend_y = g.rows >= 3;
    double best = 0;
    for (int a = 0; a <= kSymbolSamples; ++a) {
        const double cx = -1.0 + 2.0 * a / kSymbolSamples;
        const double sx = std::sqrt(std::max(0.0, 1.0 - cx * cx));
        for (int b = 0; b <= kSymbolSamples; ++b) {
            const double cy = -1.0 + 2.0 * b / kSymbolSamples;
            const double sy = std::sqrt(std::max(0.0, 1.0 - cy * cy));
            const double down = 1.0 - (cx * cy - sx * sy);  // diagonal (+1, +1): (dx, -dy)
            const double up = 1.0 - (cx * cy + sx * sy);    // diagonal (+1, -1): (dx, +dy)
            double xx = 2 * k.horizontal * (1 - cx) + 2 * k.shear * (down + up) * wxx;
            double yy = 2 * k.vertical * (1 - cy) + 2 * k.shear * (down + up) * wyy;
            const double xy = 2 * k.shear * (up - down) * wxy;
            if (bend_x) xx += 2 * k.bend_horizontal * 2 * sx * sx;  // 1 - cos 2t = 2 sin^2 t
            if (bend_y) yy += 2 * k.bend_vertical * 2 * sy * sy;
            const double mid = 0.5 * (xx + yy), half = 0.5 * (xx - yy);
            best = std::max(best, mid + std::sqrt(half * half + xy * xy));
        }
    }
    return best;
}

// lambda (1/s^2) and gamma (1/s) of the stability number, split so the
// stiffness can be solved for: lambda = stiffness * lambda_per_stiffness,
// gamma = sqrt(stiffness) * spring_gamma_per_root + other_gamma.
struct StabilityTerms {
    double lambda_per_stiffness;
    double spring_gamma_per_root;
    double other_gamma;  // air friction and the wind's drag on moving faces
};

StabilityTerms stability_terms(ClothParams p) {
    const Grid g = grid_of(p);
    const double m = particle_mass(p);
    p.stiffness = 1;
    const SpringConstants k = spring_constants(p, g);
    const SpringConstants c = {critical_damping(p, k.horizontal, m),
                               critical_damping(p, k.vertical, m), critical_damping(p, k.shear, m),
                               critical_damping(p, k.bend_horizontal, m),
                               critical_damping(p, k.bend_vertical, m)};
    // The wind's drag couples the four corners of each cell; by Gershgorin
    // its rate at a vertex is at most drag * (area of its four cells) / 4 / m.
    const double drag = std::max(p.wind_drag, p.wind_tangential_drag);
    const double wind_rate = drag * g.dx * g.dy / m;
    return {lattice_max_eigenvalue(k, g) / m, lattice_max_eigenvalue(c, g) / m,
            p.friction + wind_rate};
}

double stability_number(const StabilityTerms& t, double stiffness, double h) {
    const double lambda = t.lambda_per_stiffness * stiffness;
    const double gamma = t.spring_gamma_per_root * std::sqrt(stiffness) + t.other_gamma;
    // Semi-implicit Euler on x'' = -lambda x - gamma x' is stable while
    // h^2 lambda + 2 h gamma <= 4 (the trace condition of its 2x2 step matrix).
    return (h * h * lambda + 2 * h * gamma) / 4;
}

// The largest stiffness with stability number <= the limit at step h, or 0
// when friction and wind drag alone exceed it: solve the quadratic in
// q = sqrt(stiffness).
double max_stable_stiffness(const StabilityTerms& t, double h) {
    const double a = h * h * t.lambda_per_stiffness;
    const double b = 2 * h * t.spring_gamma_per_root;
    const double c = 2 * h * t.other_gamma - 4 * kClothStabilityLimit;
    if (c >= 0) return 0;
    const double q = (-b + std::sqrt(b * b - 4 * a * c)) / (2 * a);
    return q * q;
}

int substeps_needed(const StabilityTerms& t, double stiffness, double frame_seconds) {
    // h from the quadratic h^2 lambda + 2 h gamma = 4 limit, then round up
    // and step on until the count really satisfies the bound.
    const double lambda = t.lambda_per_stiffness * stiffness;
    const double gamma = t.spring_gamma_per_root * std::sqrt(stiffness) + t.other_gamma;
    const double h =
        (-2 * gamma + std::sqrt(4 * gamma * gamma + 16 * kClothStabilityLimit * lambda)) /
        (2 * lambda);
    const double estimate = std::ceil(frame_seconds / h);
    if (!(estimate <= kMaxClothSubsteps)) return kMaxClothSubsteps + 1;
    int n = std::max(1, static_cast<int>(estimate) - 1);
    while (n <= kMaxClothSubsteps &&
           stability_number(t, stiffness, frame_seconds / n) > kClothStabilityLimit)
        ++n;
    return n;
}

std::string grid_description(const ClothParams& p) {
    std::ostringstream s;
    s << p.columns << "x" << p.rows << " grid of " << p.mass << " kg at " << 1.0 / p.frame_seconds
      << " frames/s";
    return s.str();
}

// The cloth's own weight over the stiffness of a strip as wide as its
// shorter side: roughly the strain it hangs at. Far beyond max_stretch the
// strain limit alone would hold the cloth up, and it cannot within its passes.
double weight_strain(const ClothParams& p) {
    return static_cast<double>(p.mass) * glm::length(glm::dvec3(p.gravity)) /
           (static_cast<double>(p.stiffness) * std::min(p.width, p.height));
}

void check_weight(const ClothParams& p) {
    if (weight_strain(p) <= p.max_stretch) return;
    const double scale = p.max_stretch / weight_strain(p);
    std::ostringstream s;
    s << "mass " << p.mass << " kg is too heavy for stiffness " << p.stiffness
      << " N/m: its weight alone would stretch the cloth by about " << 100 * weight_strain(p)
      << " %, more than max_stretch (" << 100 * p.max_stretch
      << " %); the safe range for mass is (0, " << p.mass * scale
      << "] kg, or raise stiffness to at least " << p.stiffness / scale << " N/m";
    fail_cloth(s.str());
}

void check_stability(const ClothParams& p) {
    const StabilityTerms t = stability_terms(p);
    const int needed = substeps_needed(t, p.stiffness, p.frame_seconds);
    const int used = p.substeps > 0 ? p.substeps : kMaxClothSubsteps;
    if (p.substeps > 0 ? needed <= p.substeps : needed <= kMaxClothSubsteps)
        return check_weight(p);
    const double h = p.frame_seconds / used;
    const double max_k = max_stable_stiffness(t, h);
    std::ostringstream s;
    if (max_k <= 0) {
        s << "friction (" << p.friction << " 1/s) and wind_drag (" << p.wind_drag << ", "
          << p.wind_tangential_drag << " tangential) are too high for " << used
          << " substeps per frame on a " << grid_description(p) << ": lower them or raise substeps";
        fail_cloth(s.str());
    }
    s << "stiffness " << p.stiffness << " N/m is unstable with ";
    if (p.substeps > 0)
        s << p.substeps << " substeps per frame";
    else
        s << "at most " << kMaxClothSubsteps << " substeps per frame";
    s << " on a " << grid_description(p) << ": the safe range is (0, " << max_k << "] N/m";
    if (p.substeps > 0 && needed <= kMaxClothSubsteps)
        s << ", or use at least " << needed << " substeps (0 chooses them)";
    else
        s << " (or raise mass, or use fewer grid vertices)";
    fail_cloth(s.str());
}

}  // namespace

// --- Validation ----------------------------------------------------------------

void check_wind(const WindState& w) {
    const glm::vec3 d = w.direction;
    if (!(finite(d.x) && finite(d.y) && finite(d.z)) || glm::length(d) == 0)
        fail_cloth("wind direction must be a finite, non-zero vector");
    if (!(w.strength >= 0 && w.strength <= kMaxWindStrength))
        fail_range("wind strength", w.strength,
                             "between 0 and " + std::to_string(int(kMaxWindStrength)), " m/s");
    if (!(w.gust >= 0 && w.gust <= 1)) fail_range("wind gust", w.gust, "between 0 and 1");
}

void check_cloth_params(const ClothParams& p, const ClothPins& pins) {
    const std::string side = "between 2 and " + std::to_string(kMaxClothGridSide);
    if (p.columns < 2 || p.columns > kMaxClothGridSide)
        fail_range("grid columns", p.columns, side);
    if (p.rows < 2 || p.rows > kMaxClothGridSide) fail_range("grid rows", p.rows, side);
    if (!(finite(p.width) && p.width > 0))
        fail_range("width", p.width, "finite and greater than 0", " m");
    if (!(finite(p.height) && p.height > 0))
        fail_range("height", p.height, "finite and greater than 0", " m");
    if (!(finite(p.mass) && p.mass > 0))
        fail_range("mass", p.mass, "finite and greater than 0", " kg");
    if (!(finite(p.stiffness) && p.stiffness > 0))
        fail_range("stiffness", p.stiffness, "finite and greater than 0", " N/m");
    if (!(p.shear_stiffness >= 0 && p.shear_stiffness <= 1))
        fail_range("shear_stiffness", p.shear_stiffness, "between 0 and 1");
    if (!(p.bend_stiffness >= 0 && p.bend_stiffness <= 1))
        fail_range("bend_stiffness", p.bend_stiffness, "between 0 and 1");
    if (!(p.max_stretch >= 0.01f && p.max_stretch <= 1))
        fail_range("max_stretch", p.max_stretch, "between 0.01 and 1");
    if (!(p.friction >= 0 && p.friction <= kMaxFriction))
        fail_range("friction", p.friction,
                             "between 0 and " + std::to_string(int(kMaxFriction)), " 1/s");
    if (!(p.damping >= 0 && p.damping <= 1))
        fail_range("damping", p.damping, "between 0 and 1");
    if (!(p.wind_drag >= 0 && p.wind_drag <= kMaxWindDrag))
        fail_range("wind_drag", p.wind_drag,
                             "between 0 and " + std::to_string(int(kMaxWindDrag)));
    if (!(p.wind_tangential_drag >= 0 && p.wind_tangential_drag <= kMaxWindDrag))
        fail_range("wind_tangential_drag", p.wind_tangential_drag,
                             "between 0 and " + std::to_string(int(kMaxWindDrag)));
    const glm::vec3 g = p.gravity;
    if (!(finite(g.x) && finite(g.y) && finite(g.z) && glm::length(g) <= 1000))
        fail_cloth("gravity must be a finite vector no longer than 1000 m/s^2");
    if (!(p.frame_seconds > 0 && p.frame_seconds <= 1))
        fail_range("frame duration", p.frame_seconds, "in (0, 1]", " s");
    if (!(p.preroll_seconds >= 0 && p.preroll_seconds <= 60))
        fail_range("preroll", p.preroll_seconds, "between 0 and 60", " s");
    if (p.substeps < 0 || p.substeps > kMaxClothSubsteps)
        fail_range(
            "substeps", p.substeps,
            "between 1 and " + std::to_string(kMaxClothSubsteps) + " (or 0 to choose them)");
    const long long count = static_cast<long long>(p.columns) * p.rows;
    for (int v : pins.vertices)
        if (v < 0 || v >= count)
            fail_range(
                "pinned vertex", v,
                "an index row * columns + column between 0 and " + std::to_string(count - 1));
    if (!pins.left_edge && !pins.top_edge && pins.vertices.empty())
        fail_cloth(
            "pin: at least one vertex must be pinned (left_edge, top_edge or a vertex list); "
            "a free cloth would fall forever");
    check_stability(p);
}

double cloth_stability_number(const ClothParams& params, int substeps) {
    return stability_number(stability_terms(params), params.stiffness,
                            params.frame_seconds / substeps);
}

int cloth_substeps(const ClothParams& params) {
    if (params.substeps > 0) return params.substeps;
    return substeps_needed(stability_terms(params), params.stiffness, params.frame_seconds);
}

double max_wind_speed(const ClothParams& p) {
    // The wind's drag accelerates a vertex by at most drag * U * (its cells'
    // area / 4) / m (as in stability_terms); over one substep from rest that
    // moves it h^2 times as far.
    const Grid g = grid_of(p);
    const double drag = std::max(p.wind_drag, p.wind_tangential_drag);
    if (drag == 0) return std::numeric_limits<double>::infinity();
    const double h = p.frame_seconds / cloth_substeps(p);
    return kMaxStepMove * std::min(g.dx, g.dy) * particle_mass(p) / (h * h * drag * g.dx * g.dy);
}

void check_wind(const WindState& w, const ClothParams& params) {
    check_wind(w);
    const double peak = static_cast<double>(w.strength) * (1 + static_cast<double>(w.gust));
    const double most = max_wind_speed(params);
    if (peak <= most) return;
    std::ostringstream s;
    s << "wind strength " << w.strength << " m/s with gust " << w.gust
      << " is too strong for this cloth (wind_drag "
      << std::max(params.wind_drag, params.wind_tangential_drag) << ", " << grid_description(params)
      << ", " << cloth_substeps(params) << " substeps): strength x (1 + gust) must be at most "
      << most << " m/s; raise substeps or mass, or lower wind_drag";
    fail_cloth(s.str());
}

}  // namespace facet
