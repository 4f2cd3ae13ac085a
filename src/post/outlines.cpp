#include "post/outlines.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/error.hpp"

namespace facet {

void OutlineBuffers::reset(int w, int h) {
    width = w;
    height = h;
    const size_t n = static_cast<size_t>(w) * static_cast<size_t>(h);
    depth.assign(n, std::numeric_limits<float>::infinity());
    normal.assign(n, glm::vec3(0.0f));
    object_id.assign(n, kNoObject);
}

const LineStyle& OutlineStyle::line(LineKind kind) const {
    switch (kind) {
        case LineKind::crease:
            return crease;
        case LineKind::boundary:
            return boundary;
        case LineKind::intersection:
            return intersection;
        case LineKind::silhouette:
            break;
    }
    return silhouette;
}

namespace {

constexpr LineKind kKinds[kLineKinds] = {LineKind::crease, LineKind::boundary,
                                         LineKind::intersection, LineKind::silhouette};
constexpr size_t kOffImage = std::numeric_limits<size_t>::max();

uint8_t both_directions(LineKind kind) {
    return edge_bit(kind, false) | edge_bit(kind, true);
}

uint8_t enabled_flags(const OutlineStyle& style) {
    uint8_t flags = 0;
    for (LineKind kind : kKinds)
        if (style.line(kind).enabled && style.line(kind).width > 0.0f)
            flags |= both_directions(kind);
    return flags;
}

// What pass 1 compares, per pixel: 1/z (0 on background, so one division
// per pixel rather than per comparison) and the id (kNoObject on background).
struct Surfaces {
    const std::vector<float>& inverse_depth;
    const std::vector<uint32_t>& id;
    const std::vector<glm::vec3>& normal;
    const std::vector<uint64_t>* crossing_pairs;

    bool may_cross(uint32_t a, uint32_t b) const {
        if (!crossing_pairs) return true;
        const uint64_t key =
            a < b ? (static_cast<uint64_t>(a) << 32) | b : (static_cast<uint64_t>(b) << 32) | a;
        return std::binary_search(crossing_pairs->begin(), crossing_pairs->end(), key);
    }
};

struct EdgeTest {
    float relative_jump;
    float cos_crease;
    uint8_t enabled;
};

// Relative 1/z by which a surface continued over an edge may still be in
// front of the other and count as crossing it.
constexpr float kCrossingTolerance = 1e-4f;

// Flags for the pair (p, q); `p_out` and `q_out` are the pixels beyond p
// and beyond q on the same line, or kOffImage.
uint8_t classify_pair(const Surfaces& s, const EdgeTest& test, size_t p_out, size_t p, size_t q,
                      size_t q_out, bool with_lower) {
    const float iz_p = s.inverse_depth[p], iz_q = s.inverse_depth[q];
    const uint32_t id_p = s.id[p], id_q = s.id[q];
    const bool p_surface = id_p != kNoObject, q_surface = id_q != kNoObject;
    if (!p_surface && !q_surface) return 0;
    // Each side predicts the other's 1/z: linearly from its own two pixels
    // where both show the same object, else as constant. On a plane 1/z is
    // affine in screen space, so the linear prediction is exact there.
    auto predict = [&](size_t far, float iz_near, uint32_t id_near) {
        if (far == kOffImage || id_near == kNoObject || s.id[far] != id_near) return iz_near;
        return 2.0f * iz_near - s.inverse_depth[far];
    };
    const float continued_p = predict(p_out, iz_p, id_p), continued_q = predict(q_out, iz_q, id_q);
    const float miss_p = std::fabs(continued_p - iz_q);
    const float miss_q = std::fabs(continued_q - iz_p);
    const bool jump = std::min(miss_p, miss_q) > test.relative_jump * std::max(iz_p, iz_q);
    // Two surfaces really cross where each, continued over the line, goes
    // behind the other (a smaller 1/z). Along a silhouette close to another
    // surface (an object just above a floor) the front one, continued,
    // stays in front, so no intersection line is drawn there, however
    // small the depth gap. The tolerance absorbs rounding on a flush contact.
    const float behind_tolerance = kCrossingTolerance * std::max(iz_p, iz_q);
    const bool crossing =
        continued_p <= iz_q + behind_tolerance && continued_q <= iz_p + behind_tolerance;

    uint8_t flags = 0;
    if (jump) flags |= edge_bit(LineKind::silhouette, with_lower);
    if (id_p != id_q) flags |= edge_bit(LineKind::boundary, with_lower);
    if (p_surface && q_surface && !jump) {
        if (id_p != id_q && crossing && s.may_cross(id_p, id_q))
            flags |= edge_bit(LineKind::intersection, with_lower);
        if (test.enabled & both_directions(LineKind::crease)) {
            const glm::vec3& np = s.normal[p];
            const glm::vec3& nq = s.normal[q];
            const float dot = np.x * nq.x + np.y * nq.y + np.z * nq.z;
            const float lengths = std::sqrt((np.x * np.x + np.y * np.y + np.z * np.z) *
                                            (nq.x * nq.x + nq.y * nq.y + nq.z * nq.z));
            // cos(angle) < cos(crease angle), for normals of any length.
            if (lengths > 0.0f && dot < test.cos_crease * lengths)
                flags |= edge_bit(LineKind::crease, with_lower);
        }
    }
    return flags & test.enabled;
}

}  // namespace

void find_edges(const OutlineBuffers& b, const OutlineStyle& style, OutlineScratch& scratch,
                ThreadPool& pool, CrossingPairs crossing) {
    const size_t n = static_cast<size_t>(b.width) * static_cast<size_t>(b.height);
    if (b.depth.size() != n || b.normal.size() != n || b.object_id.size() != n)
        throw Error(ExitCode::runtime_failure,
                    "outlines: buffer sizes do not match width * height");
    scratch.edges.assign(n, 0);
    const uint8_t enabled = enabled_flags(style);
    if (enabled == 0) return;
    const int w = b.width, h = b.height;

    // Pass 0: 1/z and id per pixel.
    scratch.inverse_depth.resize(n);
    scratch.id.resize(n);
    pool.parallel_for(static_cast<size_t>(h), [&](size_t row) {
        for (size_t i = row * w; i < (row + 1) * w; ++i) {
            // A surface without an object (a shadow catcher) draws no line.
            const float depth = b.depth[i];
            const bool surface = depth > 0.0f && depth < std::numeric_limits<float>::infinity() &&
                                 b.object_id[i] != kNoObject;
            scratch.inverse_depth[i] = surface ? 1.0f / depth : 0.0f;
            scratch.id[i] = surface ? b.object_id[i] : kNoObject;
        }
    });

    // Pass 1. The crease threshold is computed once per frame, so
    // std::cos cannot make neighbouring pixels disagree.
    const EdgeTest test{style.depth_threshold,
                        static_cast<float>(std::cos(static_cast<double>(style.crease_angle) *
                                                    (std::numbers::pi / 180.0))),
                        enabled};
    const Surfaces s{scratch.inverse_depth, scratch.id, b.normal, crossing};
    const size_t stride = static_cast<size_t>(w);
    pool.parallel_for(static_cast<size_t>(h), [&](size_t row) {
        const int y = static_cast<int>(row);
        for (int x = 0; x < w; ++x) {
            const size_t p = b.index(x, y);
            uint8_t flags = 0;
            if (x + 1 < w)
                flags |= classify_pair(s, test, x > 0 ? p - 1 : kOffImage, p, p + 1,
                                       x + 2 < w ? p + 2 : kOffImage, false);
            if (y + 1 < h)
                flags |= classify_pair(s, test, y > 0 ? p - stride : kOffImage, p, p + stride,
                                       y + 2 < h ? p + 2 * stride : kOffImage, true);
            scratch.edges[p] = flags;
        }
    });
}

void draw_outlines(const OutlineBuffers& b, const OutlineStyle& style, ColorImage& lines,
                   ThreadPool& pool, OutlineScratch& scratch, CrossingPairs crossing) {
    find_edges(b, style, scratch, pool, crossing);
    const int w = b.width, h = b.height;
    if (w == 0 || h == 0 || lines.width != w || lines.height != h) {
        lines = ColorImage(w, h, glm::vec4(0.0f));
    } else {
        pool.parallel_for(static_cast<size_t>(h), [&](size_t row) {
            std::fill_n(&lines.at(0, static_cast<int>(row)), w, glm::vec4(0.0f));
        });
    }

    bool on[kLineKinds];
    float width_of[kLineKinds];
    glm::vec3 color_of[kLineKinds];
    float max_reach = 0.0f;
    for (LineKind kind : kKinds) {
        const int k = static_cast<int>(kind);
        const LineStyle& line = style.line(kind);
        on[k] = line.enabled && line.width > 0.0f;
        width_of[k] = line.width;
        color_of[k] = line.color;
        // A pixel centre further than w/2 + 0.5 from an edge gets nothing.
        if (on[k]) max_reach = std::max(max_reach, 0.5f * line.width + 0.5f);
    }
    if (max_reach <= 0.0f || w == 0 || h == 0) return;
    // Pixel pairs whose midpoint can lie within max_reach of the centre of
    // pixel (x, y) start in columns x − r .. x + r and rows y − r .. y + r.
    const int r = static_cast<int>(std::ceil(max_reach));
    const std::vector<uint8_t>& edges = scratch.edges;
    const size_t stride = static_cast<size_t>(w);

    // Pass 2: near_row[y][x] = 1 if row y has an edge in columns [x − r, x + r].
    scratch.near_row.assign(edges.size(), 0);
    pool.parallel_for(static_cast<size_t>(h), [&](size_t row) {
        const uint8_t* e = &edges[row * stride];
        uint8_t* near = &scratch.near_row[row * stride];
        int count = 0;  // edges in the window
        for (int x = 0; x < r && x < w; ++x) count += e[x] != 0;
        for (int x = 0; x < w; ++x) {
            if (x + r < w) count += e[x + r] != 0;
            if (x - r - 1 >= 0) count -= e[x - r - 1] != 0;
            near[x] = count > 0;
        }
    });

    // Pass 3: the distance to the nearest edge midpoint of each kind, for
    // pixels whose (2r+1)^2 window holds an edge.
    pool.parallel_for(static_cast<size_t>(h), [&](size_t row) {
        const int y = static_cast<int>(row);
        const int j_lo = std::max(0, y - r), j_hi = std::min(h - 1, y + r);
        // Rows of near flags OR-ed together: contiguous bytes, vectorised.
        std::vector<uint8_t> near(stride, 0);
        for (int j = j_lo; j <= j_hi; ++j) {
            const uint8_t* src = &scratch.near_row[static_cast<size_t>(j) * stride];
            for (size_t x = 0; x < stride; ++x) near[x] |= src[x];
        }
        const float inf = std::numeric_limits<float>::infinity();
        for (int x = 0; x < w; ++x) {
            if (!near[x]) continue;
            float nearest2[kLineKinds] = {inf, inf, inf, inf};
            const int i_lo = std::max(0, x - r), i_hi = std::min(w - 1, x + r);
            for (int j = j_lo; j <= j_hi; ++j)
                for (int i = i_lo; i <= i_hi; ++i) {
                    const uint8_t flags = edges[static_cast<size_t>(j) * stride + i];
                    if (!flags) continue;
                    // Midpoints, relative to the centre of pixel (x, y):
                    // with the right neighbour (i − x + 1/2, j − y), with
                    // the lower one (i − x, j − y + 1/2). Exact in float.
                    const float di = static_cast<float>(i - x), dj = static_cast<float>(j - y);
                    const float right2 = (di + 0.5f) * (di + 0.5f) + dj * dj;
                    const float lower2 = di * di + (dj + 0.5f) * (dj + 0.5f);
                    for (int k = 0; k < kLineKinds; ++k) {
                        if (flags & (1u << k)) nearest2[k] = std::min(nearest2[k], right2);
                        if (flags & (1u << (k + 4))) nearest2[k] = std::min(nearest2[k], lower2);
                    }
                }
            // Coverages combine by max, from the top kind down: a lower kind
            // shows only where it reaches beyond the kinds above it. So a
            // silhouette that is also a boundary and a crease is drawn once,
            // in the silhouette's colour, not as a blend of three.
            glm::vec3 weighted(0.0f);
            float alpha = 0.0f;
            for (int k = kLineKinds - 1; k >= 0; --k) {
                if (!on[k] || nearest2[k] == inf) continue;
                const float a =
                    std::clamp(0.5f * width_of[k] + 0.5f - std::sqrt(nearest2[k]), 0.0f, 1.0f);
                if (a > alpha) {
                    weighted += color_of[k] * (a - alpha);
                    alpha = a;
                }
            }
            if (alpha > 0.0f) lines.at(x, y) = glm::vec4(weighted / alpha, alpha);
        }
    });
}

namespace {

// Each line pixel with some coverage through `over(line, pixel)`, row by row.
template <typename Over>
void composite_each(const ColorImage& lines, ColorImage& image, ThreadPool& pool, Over over) {
    if (lines.width != image.width || lines.height != image.height)
        throw Error(ExitCode::runtime_failure, "outlines: line and colour images differ in size");
    pool.parallel_for(static_cast<size_t>(image.height), [&](size_t row) {
        const int y = static_cast<int>(row);
        for (int x = 0; x < image.width; ++x) {
            const glm::vec4& line = lines.at(x, y);
            if (line.a > 0.0f) over(line, image.at(x, y));
        }
    });
}

}  // namespace

void composite_lines(const ColorImage& lines, ColorImage& color, ThreadPool& pool) {
    composite_each(lines, color, pool, [](const glm::vec4& line, glm::vec4& c) {
        const float a = line.a;
        c = glm::vec4(glm::vec3(c) + (glm::vec3(line) - glm::vec3(c)) * a, a + c.a * (1.0f - a));
    });
}

void composite_lines_premultiplied(const ColorImage& lines, ColorImage& image, ThreadPool& pool) {
    composite_each(lines, image, pool, [](const glm::vec4& line, glm::vec4& c) {
        const float a = line.a;
        c = glm::vec4(glm::vec3(line) * a + glm::vec3(c) * (1.0f - a), a + c.a * (1.0f - a));
    });
}

}  // namespace facet
