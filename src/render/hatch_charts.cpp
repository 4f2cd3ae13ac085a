#include "render/hatch_charts.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace facet {
namespace {

// Triplanar weights go as |n|^4: sharp enough that most points use one or
// two planes, soft enough that the change between them is not a seam.
// Shares below kMinPlaneShare are dropped.
constexpr float kMinPlaneShare = 0.03f;

struct Triangle {
    glm::vec3 p[3];  // model space, at rest
    glm::vec2 uv[3];
    glm::vec3 normal;  // interpolated at the point, unit
    glm::vec3 position, dpdx, dpdy;
};

Triangle gather(const World& world, const HatchPoint& pt) {
    Triangle t;
    const uint32_t* c = &world.indices[3 * static_cast<size_t>(pt.triangle)];
    glm::vec3 n(0.0f);
    t.position = t.dpdx = t.dpdy = glm::vec3(0.0f);
    for (int k = 0; k < 3; ++k) {
        t.p[k] = world.positions[c[k]];
        t.uv[k] = world.uvs[c[k]];
        n += pt.bary[k] * world.normals[c[k]];
        t.position += pt.bary[k] * t.p[k];
        t.dpdx += pt.ddx[k] * t.p[k];
        t.dpdy += pt.ddy[k] * t.p[k];
    }
    if (!(glm::dot(n, n) > 1e-12f)) n = glm::cross(t.p[1] - t.p[0], t.p[2] - t.p[0]);
    const float len = glm::length(n);
    t.normal = len > 0.0f ? n / len : glm::vec3(0, 1, 0);
    return t;
}

glm::vec3 onto_plane(glm::vec3 v, glm::vec3 n) {
    return v - n * glm::dot(n, v);
}

// The object's axis along the surface; where the surface faces along the
// axis (a floor, for the up axis), a second axis square to it takes over
// smoothly. The sum still vanishes at a few points of a closed surface
// (tilted about 14° from facing the axis), where the strokes turn round
// the point: any direction field on a sphere has such points, and these
// keep them off the flat floors the fallback is for.
glm::vec3 axis_direction(glm::vec3 axis, glm::vec3 n) {
    const glm::vec3 helper = std::fabs(axis.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 0, 1);
    const glm::vec3 second = glm::normalize(glm::cross(glm::cross(axis, helper), axis));
    const glm::vec3 along = onto_plane(axis, n);
    const float share = std::max(0.0f, 0.5f - glm::length(along));
    return along + share * onto_plane(second, n);
}

// The texture's u direction on the triangle, dP/du, if its UVs span it.
bool uv_direction(const Triangle& t, glm::vec3& out) {
    const glm::vec3 e1 = t.p[1] - t.p[0], e2 = t.p[2] - t.p[0];
    const glm::vec2 u1 = t.uv[1] - t.uv[0], u2 = t.uv[2] - t.uv[0];
    const float det = u1.x * u2.y - u2.x * u1.y;
    if (!(std::fabs(det) > 1e-12f)) return false;
    out = onto_plane((e1 * u2.y - e2 * u1.y) / det, t.normal);
    return glm::dot(out, out) > 1e-12f;
}

// The direction field at the point (unit, tangent): the principal
// curvature direction blended, by its confidence, with the fallback (u,
// then the axis). Directions have no sign, so they blend as doubled
// angles in a frame round the fallback.
glm::vec3 stroke_direction(const World& world, const HatchingState& h, const HatchPoint& pt,
                           const Triangle& t) {
    glm::vec3 fallback;
    const bool use_uv = h.direction != HatchDirection::axis && pt.has_uvs;
    if (!use_uv || !uv_direction(t, fallback)) fallback = axis_direction(h.axis, t.normal);
    const glm::vec3 f = glm::normalize(fallback);
    if (h.direction != HatchDirection::curvature || world.hatch_directions.empty()) return f;

    const uint32_t* c = &world.indices[3 * static_cast<size_t>(pt.triangle)];
    glm::vec3 d[3];
    int strongest = 0;
    for (int k = 0; k < 3; ++k) {
        d[k] = world.hatch_directions[c[k]];
        if (glm::dot(d[k], d[k]) > glm::dot(d[strongest], d[strongest])) strongest = k;
    }
    glm::vec3 field(0.0f);
    for (int k = 0; k < 3; ++k) {
        const float sign = glm::dot(d[k], d[strongest]) < 0.0f ? -1.0f : 1.0f;
        field += pt.bary[k] * sign * d[k];
    }
    field = onto_plane(field, t.normal);
    const float confidence = std::min(glm::length(field), 1.0f);
    if (!(confidence > 0.0f)) return f;
    const glm::vec3 g = glm::cross(t.normal, f);
    const float x = glm::dot(field, f), y = glm::dot(field, g);
    const float len2 = x * x + y * y;
    const glm::vec2 doubled = confidence * glm::vec2(x * x - y * y, 2.0f * x * y) / len2 +
                              (1.0f - confidence) * glm::vec2(1.0f, 0.0f);
    const float angle = 0.5f * std::atan2(doubled.y, doubled.x);
    return std::cos(angle) * f + std::sin(angle) * g;
}

// Writes `dir`, a tangent vector, in the triangle's edge coordinates:
// dir ≈ a·(p1 − p0) + b·(p2 − p0), least squares in the plane.
glm::vec2 edge_coordinates(const Triangle& t, glm::vec3 dir) {
    const glm::vec3 e1 = t.p[1] - t.p[0], e2 = t.p[2] - t.p[0];
    const float g11 = glm::dot(e1, e1), g12 = glm::dot(e1, e2), g22 = glm::dot(e2, e2);
    const float r1 = glm::dot(e1, dir), r2 = glm::dot(e2, dir);
    const float det = g11 * g22 - g12 * g12;
    if (!(std::fabs(det) > 0.0f)) return glm::vec2(0.0f);
    return glm::vec2(g22 * r1 - g12 * r2, g11 * r2 - g12 * r1) / det;
}

float angle_of(glm::vec2 v) {
    return glm::dot(v, v) > 0.0f ? std::atan2(v.y, v.x) : 0.0f;
}

void object_charts(const HatchingState& h, const Triangle& t, glm::vec3 dir, float turn,
                   float target_lod, HatchFootprint& out) {
    float share[3], total = 0.0f;
    for (int a = 0; a < 3; ++a) {
        const float n2 = t.normal[a] * t.normal[a];
        share[a] = n2 * n2;
        total += share[a];
    }
    float kept = 0.0f;
    for (int a = 0; a < 3; ++a) {
        share[a] = share[a] / total >= kMinPlaneShare ? share[a] : 0.0f;
        kept += share[a];
    }
    const int size = h.tam->params.size;
    for (int a = 0; a < 3; ++a) {
        if (!(share[a] > 0.0f)) continue;
        const int i = (a + 1) % 3, j = (a + 2) % 3;  // the plane's two axes, right-handed
        HatchChart chart;
        chart.coords = glm::vec2(t.position[i], t.position[j]) * h.scale;
        chart.ddx = glm::vec2(t.dpdx[i], t.dpdx[j]) * h.scale;
        chart.ddy = glm::vec2(t.dpdy[i], t.dpdy[j]) * h.scale;
        chart.angle = angle_of(glm::vec2(dir[i], dir[j])) + turn;
        chart.weight = share[a] / kept;
        add_hatch_chart(chart, size, target_lod, true, out);
    }
}

void uv_chart(const HatchingState& h, const HatchPoint& pt, const Triangle& t, glm::vec3 dir,
              float turn, float target_lod, HatchFootprint& out) {
    const glm::vec2 e1 = (t.uv[1] - t.uv[0]) * h.scale, e2 = (t.uv[2] - t.uv[0]) * h.scale;
    HatchChart chart;
    chart.coords =
        (t.uv[0] + (t.uv[1] - t.uv[0]) * pt.bary.y + (t.uv[2] - t.uv[0]) * pt.bary.z) * h.scale;
    chart.ddx = e1 * pt.ddx.y + e2 * pt.ddx.z;
    chart.ddy = e1 * pt.ddy.y + e2 * pt.ddy.z;
    const glm::vec2 ab = edge_coordinates(t, dir);
    chart.angle = angle_of(ab.x * e1 + ab.y * e2) + turn;
    chart.weight = 1.0f;
    add_hatch_chart(chart, h.tam->params.size, target_lod, true, out);
}

void screen_chart(const HatchingState& h, const HatchPoint& pt, const Triangle& t, glm::vec3 dir,
                  float turn, float target_lod, HatchFootprint& out) {
    HatchChart chart;
    chart.coords = pt.pixel / h.tile_pixels;
    chart.ddx = glm::vec2(1.0f / h.tile_pixels, 0.0f);
    chart.ddy = glm::vec2(0.0f, 1.0f / h.tile_pixels);
    // The direction's image on screen: a step (a, b) in edge coordinates is
    // a step J⁻¹(a, b) in pixels, J the barycentrics' screen Jacobian.
    const glm::vec2 ab = edge_coordinates(t, dir);
    const float j11 = pt.ddx.y, j12 = pt.ddy.y, j21 = pt.ddx.z, j22 = pt.ddy.z;
    const float det = j11 * j22 - j12 * j21;
    glm::vec2 step(0.0f);
    if (std::fabs(det) > 0.0f)
        step = glm::vec2(j22 * ab.x - j12 * ab.y, j11 * ab.y - j21 * ab.x) / det;
    chart.angle = angle_of(step) + turn;
    chart.weight = 1.0f;
    add_hatch_chart(chart, h.tam->params.size, target_lod, false, out);
}

// What a footprint is for (see hatch_footprints).
enum class HatchLayer { strokes, paper };

// One layer's charts at the gathered point.
void layer_charts(const World& world, const HatchingState& h, const HatchPoint& pt,
                  const Triangle& t, HatchLayer layer, HatchFootprint& out) {
    out.count = 0;
    // `fixed`, and the paper: the layout space's own first axis (turned by
    // `angle` for strokes). Paper grain does not turn with the strokes.
    const bool field = layer == HatchLayer::strokes && h.direction != HatchDirection::fixed;
    const glm::vec3 dir = field ? stroke_direction(world, h, pt, t) : glm::vec3(0.0f);
    const float turn = layer == HatchLayer::strokes ? h.angle : 0.0f;
    switch (h.space) {
        case HatchSpace::screen:
            screen_chart(h, pt, t, dir, turn, h.target_lod, out);
            break;
        case HatchSpace::uv:
            if (pt.has_uvs) {
                uv_chart(h, pt, t, dir, turn, h.target_lod, out);
                break;
            }
            [[fallthrough]];
        case HatchSpace::object:
            object_charts(h, t, dir, turn, h.target_lod, out);
            break;
    }
}

}  // namespace

void hatch_footprints(const World& world, const HatchingState& h, const HatchPoint& pt,
                      HatchFootprint* strokes, HatchFootprint* paper) {
    const Triangle t = gather(world, pt);
    if (strokes) layer_charts(world, h, pt, t, HatchLayer::strokes, *strokes);
    if (paper) layer_charts(world, h, pt, t, HatchLayer::paper, *paper);
}

}  // namespace facet
