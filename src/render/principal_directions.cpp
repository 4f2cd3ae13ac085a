#include "render/principal_directions.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

namespace facet {
namespace {

constexpr int kSmoothingPasses = 2;

// The anisotropy |κ1 − κ2| / (|κ1| + |κ2| + 1/size) below which no
// direction is trusted, and above which it is fully.
constexpr float kAnisotropyNone = 0.3f;
constexpr float kAnisotropyFull = 0.6f;

std::vector<std::vector<uint32_t>> vertex_neighbours(const MeshPart& part) {
    std::vector<std::vector<uint32_t>> out(part.positions.size());
    for (size_t t = 0; t + 2 < part.indices.size(); t += 3)
        for (int e = 0; e < 3; ++e) {
            const uint32_t a = part.indices[t + e], b = part.indices[t + (e + 1) % 3];
            if (a == b) continue;
            out[a].push_back(b);
            out[b].push_back(a);
        }
    for (auto& n : out) {
        std::sort(n.begin(), n.end());
        n.erase(std::unique(n.begin(), n.end()), n.end());
    }
    return out;
}

// Any unit vector perpendicular to n.
glm::vec3 perpendicular(glm::vec3 n) {
    const glm::vec3 helper = std::fabs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    return glm::normalize(glm::cross(n, helper));
}

// The second fundamental form at vertex i, as a 3x3 tensor in model space
// (zero along the normal): the symmetric II that best gives, for each edge
// to a neighbour, its normal curvature κ = tᵀ·II·t, t the edge's unit
// direction in the tangent plane — least squares over the three entries.
// A sphere's edges all bend alike, so its II is round, however unevenly
// the edges are spread; zero when fewer than three directions fix it.
glm::mat3 curvature_tensor(const MeshPart& part, const std::vector<uint32_t>& neighbours,
                           size_t i) {
    const glm::vec3 p = part.positions[i], n = part.normals[i];
    if (!(glm::dot(n, n) > 0.5f)) return glm::mat3(0.0f);
    const glm::vec3 t1 = perpendicular(n), t2 = glm::cross(n, t1);
    // Normal equations of rows (x², 2xy, y²) · (a, b, c) = κ.
    glm::mat3 normal_matrix(0.0f);
    glm::vec3 rhs(0.0f);
    for (uint32_t j : neighbours) {
        const glm::vec3 e = part.positions[j] - p;
        const float len2 = glm::dot(e, e);
        const float x = glm::dot(e, t1), y = glm::dot(e, t2);
        const float along2 = x * x + y * y;
        if (!(len2 > 0.0f) || !(along2 > 0.0f)) continue;
        const glm::vec3 row(x * x / along2, 2.0f * x * y / along2, y * y / along2);
        const float kappa = 2.0f * glm::dot(n, e) / len2;
        normal_matrix += glm::outerProduct(row, row);
        rhs += row * kappa;
    }
    // Edges along fewer than three directions leave the fit undetermined: the
    // determinant is then rounding noise, so it is judged against the
    // matrix's own scale, not an absolute threshold.
    const float scale = (normal_matrix[0][0] + normal_matrix[1][1] + normal_matrix[2][2]) / 3.0f;
    if (!(glm::determinant(normal_matrix) > 1e-3f * scale * scale * scale)) return glm::mat3(0.0f);
    const glm::vec3 abc = glm::inverse(normal_matrix) * rhs;
    return abc.x * glm::outerProduct(t1, t1) +
           abc.y * (glm::outerProduct(t1, t2) + glm::outerProduct(t2, t1)) +
           abc.z * glm::outerProduct(t2, t2);
}

float part_size(const MeshPart& part) {
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const glm::vec3& p : part.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
    const float size = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
    return std::isfinite(size) && size > 0.0f ? size : 1.0f;
}

}  // namespace

std::vector<glm::vec3> principal_directions(const MeshPart& part) {
    const size_t count = part.positions.size();
    std::vector<glm::vec3> out(count, glm::vec3(0.0f));
    if (part.normals.size() != count) return out;
    const auto neighbours = vertex_neighbours(part);

    std::vector<glm::mat3> tensor(count, glm::mat3(0.0f));
    for (size_t i = 0; i < count; ++i) tensor[i] = curvature_tensor(part, neighbours[i], i);
    for (int pass = 0; pass < kSmoothingPasses; ++pass) {
        std::vector<glm::mat3> smoothed(count);
        for (size_t i = 0; i < count; ++i) {
            glm::mat3 sum = tensor[i];
            for (uint32_t j : neighbours[i]) sum += tensor[j];
            smoothed[i] = sum / static_cast<float>(neighbours[i].size() + 1);
        }
        tensor.swap(smoothed);
    }

    const float inverse_size = 1.0f / part_size(part);
    for (size_t i = 0; i < count; ++i) {
        const glm::vec3 n = part.normals[i];
        if (!(glm::dot(n, n) > 0.5f)) continue;
        // The 2x2 tensor in a tangent frame (t1, t2).
        const glm::vec3 t1 = perpendicular(n), t2 = glm::cross(n, t1);
        const glm::mat3& m = tensor[i];
        const float m11 = glm::dot(t1, m * t1), m22 = glm::dot(t2, m * t2);
        const float m12 = glm::dot(t1, m * t2);
        const float mean = 0.5f * (m11 + m22);
        const float radius = std::sqrt(0.25f * (m11 - m22) * (m11 - m22) + m12 * m12);
        const float high = mean + radius, low = mean - radius;
        const float anisotropy =
            std::fabs(high - low) / (std::fabs(high) + std::fabs(low) + inverse_size);
        const float confidence = std::clamp(
            (anisotropy - kAnisotropyNone) / (kAnisotropyFull - kAnisotropyNone), 0.0f, 1.0f);
        if (!(confidence > 0.0f)) continue;
        // The eigenvector of `high` is at half the angle of (m11 − m22, 2·m12);
        // the curvature of smaller magnitude may be the other one.
        float angle = 0.5f * std::atan2(2.0f * m12, m11 - m22);
        if (std::fabs(low) < std::fabs(high)) angle += 0.5f * 3.14159265f;
        out[i] = confidence * (std::cos(angle) * t1 + std::sin(angle) * t2);
    }
    return out;
}

}  // namespace facet
