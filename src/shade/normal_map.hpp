#pragma once
// Tangent-space normal maps (glTF 2.0 §3.9.3, normalTexture): a texel's RGB
// is a unit vector in the surface's tangent frame, each component stored as
// (c + 1) / 2, with +X along the texture's +u, +Y along +v in the OpenGL
// convention (green up), and +Z along the surface normal. docs/pbr.md,
// "Normal maps".
#include <cmath>
#include <optional>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "shade/light_sample.hpp"

namespace facet {

// The tangent frame at one point, t' = normalise(t - n (n.t)) (the
// interpolated tangent made perpendicular again, Gram-Schmidt) and
// b = w (n x t') (glTF's bitangent, w = +1 or -1), for the interpolated
// vertex normal of the triangle's front `n` (unit) and tangent with its
// sign in w. None where the tangent is zero or parallel to the normal.
struct TangentFrame {
    glm::vec3 t, b;
};
inline std::optional<TangentFrame> tangent_frame(const glm::vec3& n, const glm::vec4& tangent) {
    glm::vec3 t(tangent.x, tangent.y, tangent.z);
    t -= n * dot3(n, t);
    const float t_length = std::sqrt(dot3(t, t));
    if (!(t_length > 1e-8f)) return std::nullopt;
    t *= 1.0f / t_length;
    const float sign = tangent.w < 0.0f ? -1.0f : 1.0f;
    return TangentFrame{
        t, sign * glm::vec3(n.y * t.z - n.z * t.y, n.z * t.x - n.x * t.z, n.x * t.y - n.y * t.x)};
}

// The normal a map gives at one point, in tangent_frame's t' and b:
//   m  = (2 texel - 1) * (scale, scale, 1)
//   n' = normalise(m.x t' + m.y b + m.z n)
// Seen from the back, the whole frame turns over, so the result is the
// mapped normal negated, on the viewer's side like the shading normal. A
// point without a frame keeps its normal.
inline glm::vec3 mapped_normal(const glm::vec3& front_normal, const glm::vec4& tangent,
                               bool back_facing, const glm::vec3& texel, float scale) {
    const glm::vec3& n = front_normal;
    glm::vec3 result = n;
    if (const std::optional<TangentFrame> frame = tangent_frame(n, tangent)) {
        const glm::vec3 m((2.0f * texel.x - 1.0f) * scale, (2.0f * texel.y - 1.0f) * scale,
                          2.0f * texel.z - 1.0f);
        result = normalise_or(m.x * frame->t + m.y * frame->b + m.z * n, n);
    }
    return back_facing ? -result : result;
}

}  // namespace facet
