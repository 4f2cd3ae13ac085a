#include "render/hidden_edge_stage.hpp"

#include <algorithm>
#include <cmath>

#include "raster/clip.hpp"

namespace facet {
namespace {

// An edge point counts as behind the surface when it is this much farther
// than the depth buffer (relative): edges on the surface itself, whose
// depth matches the buffer only up to the slope across a pixel, stay
// visible-only, while edges behind an object are a whole thickness away.
constexpr float kHiddenDepthTolerance = 1e-2f;

}  // namespace

void HiddenEdgeStage::draw(std::span<const glm::vec4> clip, const FrameInputs& frame,
                           const StylePlan& plan, std::span<const uint8_t> edge_mask,
                           int samples_per_side, const DepthImage& depth, ColorImage& color,
                           ColorImage& lines) {
    const int width = color.width, height = color.height;
    coverage_.assign(static_cast<size_t>(width) * height, 0.0f);
    line_color_.assign(static_cast<size_t>(width) * height, glm::vec3(0));
    const float half_w = 0.5f * static_cast<float>(width);
    const float half_h = 0.5f * static_cast<float>(height);
    bool any = false;
    // One square dab of the line's width per point of the line.
    auto dab = [&](glm::vec2 p, float half, const glm::vec3& line) {
        const int x0 = static_cast<int>(std::floor(p.x - half + 0.5f));
        const int y0 = static_cast<int>(std::floor(p.y - half + 0.5f));
        const int size = std::max(1, static_cast<int>(std::lround(2 * half)));
        for (int y = std::max(y0, 0); y < std::min(y0 + size, height); ++y)
            for (int x = std::max(x0, 0); x < std::min(x0 + size, width); ++x) {
                const size_t at = static_cast<size_t>(y) * width + x;
                coverage_[at] = 1.0f;
                line_color_[at] = line;
                any = true;
            }
    };
    for (size_t tri = 0; tri < world_.triangle_count(); ++tri) {
        const Draw& draw = world_.draws[world_.triangle_draw[tri]];
        const StyleState& style = frame.styles[plan.object_style[draw.object]];
        if (!style.wireframe || !style.wire_hidden) continue;
        const float half = 0.5f * style.wire.width * static_cast<float>(samples_per_side);
        for (int e = 0; e < 3; ++e) {
            if (!(edge_mask[tri] & (1u << e))) continue;
            glm::vec4 a = clip[world_.indices[3 * tri + (e + 1) % 3]];
            glm::vec4 b = clip[world_.indices[3 * tri + (e + 2) % 3]];
            if (!clip_segment_to_near(a, b)) continue;
            const glm::vec2 sa = clip_to_screen(a, half_w, half_h);
            const glm::vec2 sb = clip_to_screen(b, half_w, half_h);
            const float steps = std::ceil(std::max(std::abs(sb.x - sa.x), std::abs(sb.y - sa.y)));
            if (!(steps < 4.0f * (width + height))) continue;  // off-screen giants and NaN
            // 1/w is affine in screen space, so depth along the line is exact.
            for (int i = 0; i <= static_cast<int>(steps); ++i) {
                const float t = steps > 0 ? static_cast<float>(i) / steps : 0.0f;
                const glm::vec2 p = sa + (sb - sa) * t;
                const float point_depth = 1.0f / (1.0f / a.w + (1.0f / b.w - 1.0f / a.w) * t);
                // One depth test per point of the line, at the pixel under it.
                const int cx = static_cast<int>(std::floor(p.x)),
                          cy = static_cast<int>(std::floor(p.y));
                if (cx < 0 || cy < 0 || cx >= width || cy >= height) continue;
                if (!(point_depth > depth.at(cx, cy) * (1.0f + kHiddenDepthTolerance))) continue;
                dab(p, half, style.wire_hidden_color);
            }
        }
    }
    if (!any) return;
    // Opaque lines under the visible ones: where a visible stroke covers
    // the sample by w, it keeps w and the hidden line shows through the
    // rest. The sample counts as covered (alpha 1) even where the line
    // crosses the background.
    for (size_t i = 0; i < coverage_.size(); ++i) {
        if (!(coverage_[i] > 0)) continue;
        const glm::vec4 visible = lines.pixels[i];  // premultiplied
        const glm::vec4 merged =
            visible + glm::vec4(line_color_[i], 1.0f) * (1.0f - std::min(visible.a, 1.0f));
        color.pixels[i] = merged;
        lines.pixels[i] = merged;
    }
}

}  // namespace facet
