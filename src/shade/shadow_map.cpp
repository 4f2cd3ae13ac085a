#include "shade/shadow_map.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <glm/geometric.hpp>

namespace facet {
namespace {

// Offsets in texels at the receiving point (see the header), set with
// tests/test_shadows.cpp: floors lit from straight above to 72 degrees off
// their normal, and by a point light half a unit above them, show no acne
// (with half these offsets neither; with a quarter the grazing point light
// does), and a shadow meets the foot of its caster within a texel or two
// (peter-panning kept small).
constexpr float kNormalOffsetTexels = 1.0f;  // times sin(angle to the light)
constexpr float kConstantBiasTexels = 0.5f;
constexpr float kSlopeBiasTexels = 0.5f;  // per texel of depth change per texel across
// Steeper receiver planes are clamped to this slope (about 84 degrees); there
// n·l is under 0.1, so what the clamp lets through hardly shows.
constexpr float kMaxReceiverSlope = 10.0f;
// The filter covers at most 2 * (8 + 0.5) texels: 18 texels a side, which
// with its start anywhere in a texel spans three chunks of eight.
constexpr int kChunks = 3;
constexpr int kMaxRows = 18;

// The face of a cube map that sees direction d from the light.
int cube_face(const glm::vec3& d) {
    const float ax = std::abs(d.x), ay = std::abs(d.y), az = std::abs(d.z);
    if (ax >= ay && ax >= az) return d.x >= 0 ? 0 : 1;
    if (ay >= az) return d.y >= 0 ? 2 : 3;
    return d.z >= 0 ? 4 : 5;
}

glm::mat4 face_projection(const ShadowMap& m) {
    glm::mat4 p(0.0f);
    p[0][0] = m.scale;
    p[1][1] = m.scale;
    const float n = m.near, f = m.far;
    if (m.projection == ShadowProjection::orthographic) {
        // z_clip = (far + z_view) / (far - near): 1 at the near plane, 0 at the far one.
        p[2][2] = 1.0f / (f - n);
        p[3][2] = f / (f - n);
        p[3][3] = 1.0f;
    } else {
        // As the camera (render/camera.cpp): reversed-Z, w = -z_view.
        p[2][2] = n / (f - n);
        p[3][2] = n * f / (f - n);
        p[2][3] = -1.0f;
    }
    return p;
}

void finish(ShadowMap& m, int size, int faces) {
    m.size = size;
    m.faces = faces;
    m.depth.resize(static_cast<size_t>(faces) * size * size);
    m.blocks = (size + kShadowBlock - 1) / kShadowBlock;
    m.block_nearest.resize(static_cast<size_t>(faces) * m.blocks * m.blocks);
    const glm::mat4 projection = face_projection(m);
    for (int f = 0; f < faces; ++f) m.clip[f] = projection * m.view[f];
}

}  // namespace

ShadowBasis shadow_basis(const glm::vec3& forward) {
    const glm::vec3 hint = std::abs(forward.y) > 0.99f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
    const glm::vec3 right = glm::normalize(glm::cross(forward, hint));
    return {right, glm::cross(right, forward), forward};
}

glm::mat4 shadow_view(const ShadowBasis& b, const glm::vec3& eye) {
    glm::mat4 v(1.0f);
    const glm::vec3 back = -b.forward;
    for (int c = 0; c < 3; ++c) {
        v[c][0] = b.right[c];
        v[c][1] = b.up[c];
        v[c][2] = back[c];
    }
    v[3][0] = -glm::dot(b.right, eye);
    v[3][1] = -glm::dot(b.up, eye);
    v[3][2] = -glm::dot(back, eye);
    return v;
}

void set_orthographic(ShadowMap& m, int size, const glm::mat4& view, float half_width, float near,
                      float far) {
    m.projection = ShadowProjection::orthographic;
    m.view[0] = view;
    m.scale = 1.0f / half_width;
    m.near = near;
    m.far = far;
    finish(m, size, 1);
}

void set_perspective(ShadowMap& m, int size, const glm::vec3& position, const glm::vec3& forward,
                     float tan_half_fov, float near, float far) {
    m.projection = ShadowProjection::perspective;
    m.light_position = position;
    m.view[0] = shadow_view(shadow_basis(forward), position);
    m.scale = 1.0f / tan_half_fov;
    m.near = near;
    m.far = far;
    finish(m, size, 1);
}

void set_cube(ShadowMap& m, int size, const glm::vec3& position, float tan_half_fov, float near,
              float far) {
    static const glm::vec3 kAxes[6] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                       {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
    m.projection = ShadowProjection::cube;
    m.light_position = position;
    for (int f = 0; f < 6; ++f) m.view[f] = shadow_view(shadow_basis(kAxes[f]), position);
    m.scale = 1.0f / tan_half_fov;
    m.near = near;
    m.far = far;
    finish(m, size, 6);
}

float shadow_depth_from_raster(const ShadowMap& m, float z) {
    if (m.projection == ShadowProjection::orthographic) return m.far - z * (m.far - m.near);
    const float a = m.near / (m.far - m.near), b = m.near * m.far / (m.far - m.near);
    return b / (z + a);
}

namespace {

using simd::vf;
using simd::vi;

// The receiving point in its face of the map, after the normal offset.
struct ShadowReceiver {
    bool ortho;
    int face;
    glm::vec3 n;   // unit normal in the light's view space (0 for none)
    float depth;   // distance in front of the light along its axis
    float texel;   // scene units per texel at that depth
    float xs, ys;  // projected position: x and y over depth (as is for parallel light)
    float u, v;    // continuous texel coordinates
};

// Places the point in the map; false where the map casts no shadow on it.
[[gnu::always_inline]] inline bool locate_receiver(const ShadowMap& m, const glm::vec3& position,
                                                   const glm::vec3& normal, ShadowReceiver& r) {
    const bool ortho = m.projection == ShadowProjection::orthographic;
    const int face =
        m.projection == ShadowProjection::cube ? cube_face(position - m.light_position) : 0;
    const glm::mat4& view = m.view[face];
    glm::vec3 p(view * glm::vec4(position, 1.0f));
    const float normal_length = glm::length(normal);
    const glm::vec3 n = normal_length > 0.0f ? glm::mat3(view) * (normal * (1.0f / normal_length))
                                             : glm::vec3(0.0f);
    if (!ortho && !(-p.z > 0.5f * m.near)) return false;  // behind the light or at it

    // Scene units per texel at the point: constant for parallel light,
    // growing with the distance from a point light.
    const float units_per_texel = 2.0f / (static_cast<float>(m.size) * m.scale);
    const float texel_at_point = ortho ? units_per_texel : -p.z * units_per_texel;

    // Normal offset, by sin(angle between normal and light).
    const glm::vec3 to_light = ortho ? glm::vec3(0, 0, 1) : glm::normalize(-p);
    const float cos_light = glm::dot(n, to_light);
    const float sin_light = std::sqrt(std::max(0.0f, 1.0f - cos_light * cos_light));
    p += n * (kNormalOffsetTexels * m.bias * texel_at_point * sin_light);
    const float depth = -p.z;
    if (!ortho && !(depth > 0.5f * m.near)) return false;
    const float texel = ortho ? units_per_texel : depth * units_per_texel;

    // Continuous texel coordinates; texel i spans [i, i + 1], as the raster
    // core samples pixel centres.
    const float inv_depth = ortho ? 1.0f : 1.0f / depth;
    const float xs = p.x * inv_depth, ys = p.y * inv_depth;
    const float size = static_cast<float>(m.size);
    const float u = (xs * m.scale + 1.0f) * 0.5f * size;
    const float v = (1.0f - ys * m.scale) * 0.5f * size;
    // Outside an orthographic or spot map nothing casts (the maps hold every
    // caster, and a spot lights nothing outside its cone).
    if (m.projection != ShadowProjection::cube && !(u >= 0 && v >= 0 && u <= size && v <= size))
        return false;
    r = {ortho, face, n, depth, texel, xs, ys, u, v};
    return true;
}

// The receiver's plane, as depth steps across texels, and its depth bias.
struct ReceiverPlane {
    float gu, gv;  // depth change per texel step in u and in v
    float bias;
};

[[gnu::always_inline]] inline ReceiverPlane receiver_plane(const ShadowMap& m,
                                                           const ShadowReceiver& r) {
    const glm::vec3& n = r.n;
    // Receiver plane: depth change of the surface per texel step in u and
    // v, in texels. Orthographic: the plane's slope n.x / n.z (v runs down).
    // Perspective: along the ray (xs, ys, -1) the plane n·(q - p) = 0 lies
    // at depth * D / (D + n.x dxs + n.y dys), D = n·(xs, ys, -1); its
    // derivative at the point gives the slope.
    const float facing =
        r.ortho ? -std::max(n.z, 1e-6f) : std::min(n.x * r.xs + n.y * r.ys - n.z, -1e-6f);
    const float inv_facing = -1.0f / facing;
    const float slope_u = std::clamp(n.x * inv_facing, -kMaxReceiverSlope, kMaxReceiverSlope);
    const float slope_v = std::clamp(-n.y * inv_facing, -kMaxReceiverSlope, kMaxReceiverSlope);
    const float gu = slope_u * r.texel, gv = slope_v * r.texel;
    const float slope = std::max(std::abs(slope_u), std::abs(slope_v));
    const float bias = m.bias * r.texel * (kConstantBiasTexels + kSlopeBiasTexels * slope);
    return {gu, gv, bias};
}

// The filter's box over the texels and the weights of its columns and rows.
struct FilterBox {
    float half;  // half the box's side, in texels
    int first_u, first_v;
    int last_u;  // the last column with a weight (chunks may run past it)
    int chunks, rows;
    vf weight[kChunks], step[kChunks];
    float row_weight[kChunks * simd::kLanes];
};

[[gnu::always_inline]] inline void filter_box(const ShadowMap& m, const ShadowReceiver& r, float gu,
                                              FilterBox& box) {
    const float u = r.u, v = r.v;
    // Eight texels at a time: lane k of chunk c is texel first + 8c + k,
    // weighed by its overlap with the filter's box (0 outside it). The
    // weights add up to (2 half)^2.
    const float half = m.softness + 0.5f;
    const float lo_u = u - half, hi_u = u + half, lo_v = v - half, hi_v = v + half;
    const int first_u = static_cast<int>(std::floor(lo_u));
    const int first_v = static_cast<int>(std::floor(lo_v));
    const int chunks =
        (static_cast<int>(std::ceil(hi_u)) - first_u + simd::kLanes - 1) / simd::kLanes;
    const int rows = static_cast<int>(std::ceil(hi_v)) - first_v;
    const vf zero = simd::splat(0.0f), one = simd::splat(1.0f), lane = {0, 1, 2, 3, 4, 5, 6, 7};
    for (int c = 0; c < chunks; ++c) {
        const vf texel = lane + static_cast<float>(first_u + c * simd::kLanes);
        box.weight[c] = simd::vmax(
            simd::vmin(simd::splat(hi_u), texel + one) - simd::vmax(simd::splat(lo_u), texel),
            zero);
        box.step[c] = gu * (texel + (0.5f - u));
    }
    for (int c = 0; c * simd::kLanes < rows; ++c) {
        const vf texel = lane + static_cast<float>(first_v + c * simd::kLanes);
        const vf w = simd::vmax(
            simd::vmin(simd::splat(hi_v), texel + one) - simd::vmax(simd::splat(lo_v), texel),
            zero);
        std::memcpy(box.row_weight + c * simd::kLanes, &w, sizeof w);
    }
    box.half = half;
    box.first_u = first_u;
    box.first_v = first_v;
    box.last_u = static_cast<int>(std::ceil(hi_u)) - 1;
    box.chunks = chunks;
    box.rows = rows;
}

// The texels under the box, `stride` floats from row to row: read straight
// from the map where the filter lies inside it, else from a copy in `edge`
// clamped to its edges.
[[gnu::always_inline]] inline const float* box_texels(
    const ShadowMap& m, const std::vector<float>& layer, int face, const FilterBox& box,
    float (&edge)[kMaxRows * kChunks * simd::kLanes], ptrdiff_t& stride) {
    const int first_u = box.first_u, first_v = box.first_v, chunks = box.chunks, rows = box.rows;
    const int size_i = m.size;
    const float* texels = layer.data() + static_cast<size_t>(face) * size_i * size_i;
    if (first_u >= 0 && first_u + chunks * simd::kLanes <= size_i && first_v >= 0 &&
        first_v + rows <= size_i) {
        stride = size_i;
        return texels + static_cast<size_t>(first_v) * size_i + first_u;
    }
    const int last = size_i - 1;
    stride = kChunks * simd::kLanes;
    for (int b = 0; b < rows; ++b) {
        const float* row = texels + static_cast<size_t>(std::clamp(first_v + b, 0, last)) * size_i;
        for (int k = 0; k < chunks * simd::kLanes; ++k)
            edge[b * stride + k] = row[std::clamp(first_u + k, 0, last)];
    }
    return edge;
}

// Whether every texel under the box surely has its caster farther than
// the point, from the blocks' nearest casters alone: then the filter would
// find nothing blocked, and its texels need not be read. The depth the
// filter compares a texel with is the receiver plane's there, which over
// the box differs from the point's by at most (|gu| + |gv|) (half + 1); a
// margin covers the rounding of that sum.
[[gnu::always_inline]] inline bool surely_lit(const ShadowMap& m,
                                              const std::vector<float>& block_nearest, int face,
                                              const FilterBox& box, const ShadowReceiver& r,
                                              const ReceiverPlane& plane) {
    if (block_nearest.empty() || box.first_u < 0 || box.first_v < 0 || box.last_u >= m.size ||
        box.first_v + box.rows > m.size)
        return false;
    const float reach = (std::abs(plane.gu) + std::abs(plane.gv)) * (box.half + 1.0f);
    const float farthest = r.depth - plane.bias + reach;
    const float margin = 1e-4f * (std::abs(r.depth) + std::abs(plane.bias) + reach);
    const float* blocks = block_nearest.data() + static_cast<size_t>(face) * m.blocks * m.blocks;
    const int last_v = box.first_v + box.rows - 1;
    for (int by = box.first_v / kShadowBlock; by <= last_v / kShadowBlock; ++by)
        for (int bx = box.first_u / kShadowBlock; bx <= box.last_u / kShadowBlock; ++bx)
            if (!(blocks[by * m.blocks + bx] > farthest + margin)) return false;
    return true;
}

// Per lane, the weight of the texels whose caster is nearer than the point
// (with `passes`, each times 1 - the share its caster lets through).
[[gnu::always_inline]] inline vf blocked_weight(const float* block, const float* passes,
                                                ptrdiff_t stride, const FilterBox& box,
                                                const ShadowReceiver& r,
                                                const ReceiverPlane& plane) {
    const vf zero = simd::splat(0.0f);
    vf blocked = zero;
    for (int b = 0; b < box.rows; ++b) {
        const float* row = block + b * stride;
        const vf row_depth = simd::splat(
            r.depth - plane.bias + plane.gv * (static_cast<float>(box.first_v + b) + 0.5f - r.v));
        vf row_blocked = zero;
        for (int c = 0; c < box.chunks; ++c) {
            vf stored;
            std::memcpy(&stored, row + c * simd::kLanes, sizeof stored);
            const vi lit = row_depth + box.step[c] <= stored;
            vf weight = box.weight[c];
            if (passes) {
                vf pass;
                std::memcpy(&pass, passes + b * stride + c * simd::kLanes, sizeof pass);
                weight *= 1.0f - pass;
            }
            row_blocked += lit ? zero : weight;
        }
        blocked += box.row_weight[b] * row_blocked;
    }
    return blocked;
}

// The filtered visibility of one layer of casters: the map's, or its glass
// weighed by what it lets through.
[[gnu::always_inline]] inline float layer_visibility(
    const ShadowMap& m, const ShadowReceiver& receiver, const ReceiverPlane& plane,
    const FilterBox& box, const std::vector<float>& depth, const std::vector<float>& block_nearest,
    const std::vector<float>* passes) {
    if (surely_lit(m, block_nearest, receiver.face, box, receiver, plane))
        return 1.0f;  // as the filter would
    float edge[kMaxRows * kChunks * simd::kLanes];
    float pass_edge[kMaxRows * kChunks * simd::kLanes];
    ptrdiff_t stride, pass_stride = 0;
    const float* block = box_texels(m, depth, receiver.face, box, edge, stride);
    const float* pass =
        passes ? box_texels(m, *passes, receiver.face, box, pass_edge, pass_stride) : nullptr;
    const vf blocked = blocked_weight(block, pass, stride, box, receiver, plane);
    float sum = 0.0f;
    for (int k = 0; k < simd::kLanes; ++k) sum += blocked[k];
    // Exactly 1 where nothing blocks the light, so lit surfaces are untouched.
    return std::clamp(1.0f - sum / (4.0f * box.half * box.half), 0.0f, 1.0f);
}

// The filtered visibility at a located receiver: what the opaque casters
// leave, times what the glass leaves.
[[gnu::always_inline]] inline float receiver_visibility(const ShadowMap& m,
                                                        const ShadowReceiver& receiver) {
    const ReceiverPlane plane = receiver_plane(m, receiver);
    FilterBox box;
    filter_box(m, receiver, plane.gu, box);
    const float opaque =
        layer_visibility(m, receiver, plane, box, m.depth, m.block_nearest, nullptr);
    if (m.glass.depth.empty() || opaque == 0.0f) return opaque;
    return opaque * layer_visibility(m, receiver, plane, box, m.glass.depth, m.glass.block_nearest,
                                     &m.glass.passes);
}

// locate_receiver for eight points of one face (an orthographic or
// perspective map), with the same operations in the same order, so each
// lane gets the bits the one-point version gives. Returns the lanes whose
// point the map covers.
struct ReceiverLanes {
    vf nx, ny, nz, depth, texel, xs, ys, u, v;
};

[[gnu::always_inline]] inline vi locate_receivers(const ShadowMap& m, const ShadowPoints& q,
                                                  ReceiverLanes& r) {
    const bool ortho = m.projection == ShadowProjection::orthographic;
    const glm::mat4& view = m.view[0];
    const vf zero = simd::splat(0.0f);
    // glm's order: (c0 x + c1 y) + (c2 z + c3 w), and for mat3 (c0 x + c1 y) + c2 z.
    vf px = (view[0][0] * q.px + view[1][0] * q.py) + (view[2][0] * q.pz + view[3][0] * 1.0f);
    vf py = (view[0][1] * q.px + view[1][1] * q.py) + (view[2][1] * q.pz + view[3][1] * 1.0f);
    vf pz = (view[0][2] * q.px + view[1][2] * q.py) + (view[2][2] * q.pz + view[3][2] * 1.0f);
    const vf normal_length = simd::vsqrt(q.nx * q.nx + q.ny * q.ny + q.nz * q.nz);
    const vi has_normal = normal_length > zero;
    const vf inv_length = 1.0f / (has_normal ? normal_length : simd::splat(1.0f));
    const vf ux = q.nx * inv_length, uy = q.ny * inv_length, uz = q.nz * inv_length;
    vf nx = (view[0][0] * ux + view[1][0] * uy) + view[2][0] * uz;
    vf ny = (view[0][1] * ux + view[1][1] * uy) + view[2][1] * uz;
    vf nz = (view[0][2] * ux + view[1][2] * uy) + view[2][2] * uz;
    nx = has_normal ? nx : zero;
    ny = has_normal ? ny : zero;
    nz = has_normal ? nz : zero;
    const float half_near = 0.5f * m.near;
    vi inside = ortho ? simd::splat_i(-1) : -pz > half_near;

    const float units_per_texel = 2.0f / (static_cast<float>(m.size) * m.scale);
    const vf texel_at_point = ortho ? simd::splat(units_per_texel) : -pz * units_per_texel;
    vf cos_light;
    if (ortho) {
        cos_light = (nx * 0.0f + ny * 0.0f) + nz * 1.0f;
    } else {
        const vf tx = -px, ty = -py, tz = -pz;
        const vf dot = (tx * tx + ty * ty) + tz * tz;
        const vf inv = 1.0f / simd::vsqrt(inside ? dot : simd::splat(1.0f));
        cos_light = (nx * (tx * inv) + ny * (ty * inv)) + nz * (tz * inv);
    }
    // std::max(0, x)'s choice for NaN and -0 too.
    const vf sin_light = simd::vsqrt(simd::vmax(1.0f - cos_light * cos_light, zero));
    const vf offset = kNormalOffsetTexels * m.bias * texel_at_point * sin_light;
    px += nx * offset;
    py += ny * offset;
    pz += nz * offset;
    const vf depth = -pz;
    if (!ortho) inside &= depth > half_near;
    const vf texel = ortho ? simd::splat(units_per_texel) : depth * units_per_texel;
    const vf inv_depth = ortho ? simd::splat(1.0f) : 1.0f / (inside ? depth : simd::splat(1.0f));
    const vf xs = px * inv_depth, ys = py * inv_depth;
    const float size = static_cast<float>(m.size);
    const vf u = (xs * m.scale + 1.0f) * 0.5f * size;
    const vf v = (1.0f - ys * m.scale) * 0.5f * size;
    inside &= (u >= zero) & (v >= zero) & (u <= size) & (v <= size);
    r = {nx, ny, nz, depth, texel, xs, ys, u, v};
    return inside;
}

}  // namespace

// Built for AVX2 and for baseline x86-64, like the lighting batch; both do
// the same IEEE operations in the same order.
float shadow_visibility(const ShadowMap& m, const glm::vec3& position, const glm::vec3& normal) {
    if (m.size == 0) return 1.0f;
    ShadowReceiver receiver;
    if (!locate_receiver(m, position, normal, receiver)) return 1.0f;
    return receiver_visibility(m, receiver);
}

vf shadow_visibility(const ShadowMap& m, const ShadowPoints& q, unsigned lanes) {
    vf visible = simd::splat(1.0f);
    if (m.size == 0 || lanes == 0) return visible;
    if (m.projection == ShadowProjection::cube) {  // a face per lane
        for (int i = 0; i < simd::kLanes; ++i)
            if ((lanes >> i) & 1)
                visible[i] =
                    shadow_visibility(m, {q.px[i], q.py[i], q.pz[i]}, {q.nx[i], q.ny[i], q.nz[i]});
        return visible;
    }
    ReceiverLanes r;
    lanes &= simd::movemask(locate_receivers(m, q, r));
    const bool ortho = m.projection == ShadowProjection::orthographic;
    for (int i = 0; i < simd::kLanes; ++i)
        if ((lanes >> i) & 1)
            visible[i] =
                receiver_visibility(m, {ortho, 0, glm::vec3(r.nx[i], r.ny[i], r.nz[i]), r.depth[i],
                                        r.texel[i], r.xs[i], r.ys[i], r.u[i], r.v[i]});
    return visible;
}

}  // namespace facet
