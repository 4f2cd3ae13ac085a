#include "raster/clip.hpp"

#include <utility>

namespace facet {
namespace {

// Signed distance-like value, >= 0 inside. Reversed-Z clip space: the near
// plane is z = w and the far plane z = 0 (see render/camera.cpp).
inline float plane_distance(int plane, const glm::vec4& p, float gx, float gy) {
    switch (plane) {
        case 0:
            return p.w - p.z;  // near
        case 1:
            return p.z;  // far
        case 2:
            return gx * p.w + p.x;  // left guard band
        case 3:
            return gx * p.w - p.x;  // right
        case 4:
            return gy * p.w + p.y;  // bottom
        default:
            return gy * p.w - p.y;  // top
    }
}

constexpr int kPlaneCount = 6;

}  // namespace

int clip_triangle(const ClipVertex in[3], uint32_t planes, float gx, float gy,
                  ClipVertex out[kMaxClippedVertices]) {
    ClipVertex buffer_a[kMaxClippedVertices], buffer_b[kMaxClippedVertices];
    ClipVertex* src = buffer_a;
    ClipVertex* dst = buffer_b;
    int count = 3;
    for (int i = 0; i < 3; ++i) src[i] = in[i];

    for (int plane = 0; plane < kPlaneCount && count > 0; ++plane) {
        if (!(planes & (1u << plane))) continue;
        int written = 0;
        for (int i = 0; i < count; ++i) {
            const ClipVertex& a = src[i];
            const ClipVertex& b = src[(i + 1) % count];
            float da = plane_distance(plane, a.position, gx, gy);
            float db = plane_distance(plane, b.position, gx, gy);
            if (da >= 0) dst[written++] = a;
            if ((da >= 0) != (db >= 0)) {
                // Interpolate from the inside vertex towards the outside one, so
                // that the two triangles sharing this edge compute the very same
                // point and no crack opens between them.
                const ClipVertex& inside = da >= 0 ? a : b;
                const ClipVertex& outside = da >= 0 ? b : a;
                float di = da >= 0 ? da : db;
                float dout = da >= 0 ? db : da;
                float t = di / (di - dout);
                dst[written].position = inside.position + (outside.position - inside.position) * t;
                dst[written].bary = inside.bary + (outside.bary - inside.bary) * t;
                ++written;
            }
        }
        count = written;
        std::swap(src, dst);
    }
    for (int i = 0; i < count; ++i) out[i] = src[i];
    return count;
}

bool clip_segment_to_near(glm::vec4& a, glm::vec4& b) {
    const float da = plane_distance(0, a, 0, 0), db = plane_distance(0, b, 0, 0);
    if (da < 0 && db < 0) return false;
    if ((da >= 0) != (db >= 0)) {
        const glm::vec4& inside = da >= 0 ? a : b;
        glm::vec4& outside = da >= 0 ? b : a;
        const float di = da >= 0 ? da : db, dout = da >= 0 ? db : da;
        outside = inside + (outside - inside) * (di / (di - dout));
    }
    return a.w > 0 && b.w > 0;
}

}  // namespace facet
