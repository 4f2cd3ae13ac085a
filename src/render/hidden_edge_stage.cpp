// Hidden edges of wireframe styles (`wireframe.hidden: true`): the feature
// edges behind surfaces, drawn after shading in their own colour. Visible
// edges are drawn by the shading stage itself (shade_stage.cpp).
#include <algorithm>
#include <cmath>

#include "render/frame_renderer.hpp"

namespace facet {
namespace {

// An edge point counts as behind the surface when it is this much farther
// than the depth buffer (relative): edges on the surface itself, whose
// depth matches the buffer only up to the slope across a pixel, stay
// visible-only, while edges behind an object are a whole thickness away.
constexpr float kHiddenDepthTolerance = 1e-2f;

// Clips the segment a-b to the near plane (z <= w in reversed-Z clip space)
// and to w > 0; false when nothing is left.
bool clip_to_near(glm::vec4& a, glm::vec4& b) {
    const float da = a.w - a.z, db = b.w - b.z;  // >= 0 in front of the near plane
    if (da < 0 && db < 0) return false;
    if (da < 0) a = a + (b - a) * (da / (da - db));
    if (db < 0) b = b + (a - b) * (db / (db - da));
    return a.w > 0 && b.w > 0;
}

}  // namespace

void FrameRenderer::draw_hidden_edges(FrameImages& target) {
    const int width = target.color.width, height = target.color.height;
    hidden_coverage_.assign(static_cast<size_t>(width) * height, 0.0f);
    hidden_color_.assign(static_cast<size_t>(width) * height, glm::vec3(0));
    bool any = false;
    for (size_t tri = 0; tri < world_.triangle_count(); ++tri) {
        const Draw& draw = world_.draws[world_.triangle_draw[tri]];
        const StyleState& style = styles_[object_style_[draw.object]];
        if (!style.wireframe || !style.wire_hidden) continue;
        const float half = 0.5f * style.wire.width * static_cast<float>(side_);
        for (int e = 0; e < 3; ++e) {
            if (!(world_.edge_mask[tri] & (1u << e))) continue;
            glm::vec4 a = vertices_.clip[world_.indices[3 * tri + (e + 1) % 3]];
            glm::vec4 b = vertices_.clip[world_.indices[3 * tri + (e + 2) % 3]];
            if (!clip_to_near(a, b)) continue;
            auto screen = [&](const glm::vec4& v) {
                return glm::vec2((v.x / v.w + 1.0f) * 0.5f * width,
                                 (1.0f - v.y / v.w) * 0.5f * height);
            };
            const glm::vec2 sa = screen(a), sb = screen(b);
            const float steps = std::ceil(std::max(std::abs(sb.x - sa.x), std::abs(sb.y - sa.y)));
            if (!(steps < 4.0f * (width + height))) continue;  // off-screen giants and NaN
            // 1/w is affine in screen space, so depth along the line is exact.
            for (int i = 0; i <= static_cast<int>(steps); ++i) {
                const float t = steps > 0 ? static_cast<float>(i) / steps : 0.0f;
                const glm::vec2 p = sa + (sb - sa) * t;
                const float depth = 1.0f / (1.0f / a.w + (1.0f / b.w - 1.0f / a.w) * t);
                // One depth test per point of the line, at the pixel under it.
                const int cx = static_cast<int>(std::floor(p.x)),
                          cy = static_cast<int>(std::floor(p.y));
                if (cx < 0 || cy < 0 || cx >= width || cy >= height) continue;
                if (!(depth > target.depth.at(cx, cy) * (1.0f + kHiddenDepthTolerance))) continue;
                const int x0 = static_cast<int>(std::floor(p.x - half + 0.5f));
                const int y0 = static_cast<int>(std::floor(p.y - half + 0.5f));
                const int size = std::max(1, static_cast<int>(std::lround(2 * half)));
                for (int y = std::max(y0, 0); y < std::min(y0 + size, height); ++y)
                    for (int x = std::max(x0, 0); x < std::min(x0 + size, width); ++x) {
                        const size_t at = static_cast<size_t>(y) * width + x;
                        hidden_coverage_[at] = 1.0f;
                        hidden_color_[at] = style.wire_hidden_color;
                        any = true;
                    }
            }
        }
    }
    if (!any) return;
    for (size_t i = 0; i < hidden_coverage_.size(); ++i)
        if (hidden_coverage_[i] > 0) {
            glm::vec4& c = target.color.pixels[i];
            c = glm::vec4(hidden_color_[i], c.a);
        }
}

}  // namespace facet
