#include "assets/polygon_triangulation.hpp"

#include <cmath>
#include <numbers>
#include <optional>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

namespace facet {
namespace {

using Triangles = std::vector<std::array<size_t, 3>>;

// The corners in the polygon's own plane, with axes u x v = its normal, so
// the outline runs counter-clockwise; nothing when it has no area at all.
std::optional<std::vector<glm::dvec2>> plane_coordinates(const std::vector<glm::dvec3>& pts) {
    const size_t n = pts.size();
    glm::dvec3 normal(0);  // Newell's method
    for (size_t i = 0; i < n; ++i) normal += glm::cross(pts[i], pts[(i + 1) % n]);
    const double len = glm::length(normal);
    if (!(len > 0)) return std::nullopt;
    normal /= len;
    const glm::dvec3 helper = std::abs(normal.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 u = glm::normalize(glm::cross(helper, normal));
    const glm::dvec3 v = glm::cross(normal, u);
    std::vector<glm::dvec2> p(n);
    for (size_t i = 0; i < n; ++i) p[i] = {glm::dot(pts[i], u), glm::dot(pts[i], v)};
    return p;
}

// Twice the signed area of a, b, c: positive for a left turn.
double turn(const std::vector<glm::dvec2>& p, size_t a, size_t b, size_t c) {
    return (p[b].x - p[a].x) * (p[c].y - p[a].y) - (p[b].y - p[a].y) * (p[c].x - p[a].x);
}

// A quad split along the shorter diagonal, as tinyobjloader did (in float,
// ties to 1-3), so existing renders keep their triangles; the other diagonal
// only when that one would leave the quad (concave). Nothing when neither
// diagonal stays inside.
std::optional<Triangles> split_quad(const std::vector<glm::dvec3>& pts,
                                    const std::vector<glm::dvec2>& p) {
    auto squared = [&](size_t a, size_t b) {
        const glm::vec3 d = glm::vec3(pts[b]) - glm::vec3(pts[a]);
        return d.x * d.x + d.y * d.y + d.z * d.z;
    };
    auto ccw = [&](size_t a, size_t b, size_t c) { return turn(p, a, b, c) > 0; };
    const bool via02 = ccw(0, 1, 2) && ccw(0, 2, 3), via13 = ccw(0, 1, 3) && ccw(1, 2, 3);
    if (via02 && (squared(0, 2) < squared(1, 3) || !via13)) return Triangles{{0, 1, 2}, {0, 2, 3}};
    if (via13) return Triangles{{0, 1, 3}, {1, 2, 3}};
    return std::nullopt;
}

// Whether every corner turns left, once round: most n-gons exporters write
// are caps of this kind.
bool is_convex(const std::vector<glm::dvec2>& p) {
    const size_t n = p.size();
    double angle = 0;
    for (size_t i = 0; i < n; ++i) {
        const size_t a = (i + n - 1) % n, c = (i + 1) % n;
        if (!(turn(p, a, i, c) > 0)) return false;
        const glm::dvec2 d0 = p[i] - p[a], d1 = p[c] - p[i];
        angle += std::atan2(d0.x * d1.y - d0.y * d1.x, glm::dot(d0, d1));
    }
    return std::abs(angle - 2 * std::numbers::pi) < 1e-6;
}

// Ear clipping over a doubly linked ring of corners.
class EarClipper {
  public:
    EarClipper(const std::vector<glm::dvec2>& p, uint64_t& work)
        : p_(p), prev_(p.size()), next_(p.size()), work_(work) {
        const size_t n = p.size();
        for (size_t i = 0; i < n; ++i) {
            prev_[i] = (i + n - 1) % n;
            next_[i] = (i + 1) % n;
        }
    }

    Triangles run() {
        const size_t n = p_.size();
        const uint64_t budget = 8 * uint64_t(n) * n;
        size_t remaining = n, at = 0, misses = 0;
        while (remaining > 3) {
            if (tests_ < budget && is_ear(at)) {
                at = clip(at);
            } else if (at = next_[at]; ++misses >= remaining || tests_ >= budget) {
                // No clean ear: the outline crosses itself or is degenerate.
                // The most convex corner, so the face still gives n - 2 triangles.
                at = clip(most_convex_from(at));
            } else {
                continue;
            }
            --remaining;
            misses = 0;
        }
        triangles_.push_back({prev_[at], at, next_[at]});
        return std::move(triangles_);
    }

  private:
    bool is_ear(size_t b) {
        const size_t a = prev_[b], c = next_[b];
        if (!(turn(p_, a, b, c) > 0)) return false;  // reflex or straight corner
        for (size_t j = next_[c]; j != a; j = next_[j]) {
            ++tests_;
            ++work_;
            // Corners repeated by a bridge to a hole coincide with the ear's own.
            if (p_[j] == p_[a] || p_[j] == p_[b] || p_[j] == p_[c]) continue;
            if (turn(p_, a, b, j) >= 0 && turn(p_, b, c, j) >= 0 && turn(p_, c, a, j) >= 0)
                return false;
        }
        return true;
    }

    size_t most_convex_from(size_t at) {
        size_t best = at;
        double best_turn = turn(p_, prev_[at], at, next_[at]);
        for (size_t j = next_[at]; j != at; j = next_[j]) {
            ++work_;
            if (const double t = turn(p_, prev_[j], j, next_[j]); t > best_turn) {
                best = j;
                best_turn = t;
            }
        }
        return best;
    }

    // Cuts the triangle at corner b; returns the corner after it.
    size_t clip(size_t b) {
        triangles_.push_back({prev_[b], b, next_[b]});
        next_[prev_[b]] = next_[b];
        prev_[next_[b]] = prev_[b];
        return next_[b];
    }

    const std::vector<glm::dvec2>& p_;
    std::vector<size_t> prev_, next_;
    Triangles triangles_;
    uint64_t tests_ = 0;  // corner tests of ears, against the budget
    uint64_t& work_;      // those and the scans for the most convex corner
};

}  // namespace

Triangles triangulate_polygon(const std::vector<glm::dvec3>& corners, uint64_t* work) {
    const size_t n = corners.size();
    Triangles fan;
    const auto p = plane_coordinates(corners);
    if (!p) {  // no area at all: any split is as good as another
        for (size_t i = 1; i + 1 < n; ++i) fan.push_back({0, i, i + 1});
        return fan;
    }
    if (n == 4)
        if (auto quad = split_quad(corners, *p)) return *quad;
    if (is_convex(*p)) {
        // The fan round the last corner: what ear clipping gives a convex
        // outline, so files render as they did before this shortcut.
        for (size_t i = 0; i + 2 < n; ++i) fan.push_back({n - 1, i, i + 1});
        return fan;
    }
    uint64_t own_work = 0;
    return EarClipper(*p, work ? *work : own_work).run();
}

}  // namespace facet
