#include "render/feature_edge_stage.hpp"

namespace facet {
namespace {

// Faces whose normals differ by less than this are one flat polygon: even
// `edges: all` skips the diagonals that split it.
constexpr float kCoplanarCosine = 0.9998f;  // about 1 degree

// Whether the triangle winds counter-clockwise on screen. The sign of the
// 3x3 determinant of the vertices' homogeneous (x, y, w) is the screen
// winding times the sign of w0 w1 w2 (Olano and Greer 1997, "Triangle Scan
// Conversion using 2D Homogeneous Coordinates"), so it needs no division
// and stays meaningful for vertices behind the camera. Only the comparison
// between two neighbours matters, so mirrored draws need no correction.
bool winds_forward(const glm::vec4& a, const glm::vec4& b, const glm::vec4& c) {
    const double det = static_cast<double>(a.x) *
                           (static_cast<double>(b.y) * c.w - static_cast<double>(c.y) * b.w) -
                       static_cast<double>(a.y) *
                           (static_cast<double>(b.x) * c.w - static_cast<double>(c.x) * b.w) +
                       static_cast<double>(a.w) *
                           (static_cast<double>(b.x) * c.y - static_cast<double>(c.x) * b.y);
    return det > 0;
}

}  // namespace

std::span<const uint8_t> FeatureEdgeStage::classify(std::span<const glm::vec4> clip,
                                                    const FrameInputs& frame,
                                                    const StylePlan& plan) {
    if (world_.edge_neighbor.empty()) return {};
    const size_t triangles = world_.triangle_count();
    front_facing_.resize(triangles);
    for (size_t t = 0; t < triangles; ++t) {
        const uint32_t* v = &world_.indices[3 * t];
        front_facing_[t] = winds_forward(clip[v[0]], clip[v[1]], clip[v[2]]) ? 1 : 0;
    }
    masks_.assign(triangles, 0);
    for (size_t t = 0; t < triangles; ++t) {
        const Draw& draw = world_.draws[world_.triangle_draw[t]];
        const StyleState& style = frame.styles[plan.object_style[draw.object]];
        // A shadow catcher shows only the shadows on it: no edges of its own.
        if (!style.wireframe || world_.materials[draw.material].shadow_catcher) continue;
        uint8_t mask = 0;
        for (int e = 0; e < 3; ++e) {
            const uint32_t neighbor = world_.edge_neighbor[3 * t + e];
            const float cosine = world_.edge_cosine[3 * t + e];
            bool draw_edge;
            if (neighbor == World::kNoNeighbor)
                draw_edge = true;  // a boundary
            else if (style.wire_all_edges)
                draw_edge = cosine < kCoplanarCosine;
            else
                draw_edge = cosine < style.wire_crease_cosine ||
                            front_facing_[t] != front_facing_[neighbor];
            if (draw_edge) mask |= static_cast<uint8_t>(1u << e);
        }
        masks_[t] = mask;
    }
    return masks_;
}

}  // namespace facet
