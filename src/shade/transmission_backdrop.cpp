#include "shade/transmission_backdrop.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "shade/environment_map.hpp"
#include "shade/model_pbr.hpp"

namespace facet {
namespace {

// GLSL's refract(i, n, eta) for a unit incident direction i: entering a
// denser medium (eta < 1) it always refracts.
glm::vec3 refracted(const glm::vec3& incident, const glm::vec3& n, float eta) {
    const float cosine = glm::dot(n, incident);
    const float k = 1.0f - eta * eta * (1.0f - cosine * cosine);
    if (k < 0.0f) return incident;  // total internal reflection: never from outside
    return eta * incident - (eta * cosine + std::sqrt(k)) * n;
}

// The backdrop's texture coordinates of a world point: u right, v down,
// as the image's rows. A point behind the eye reads `fallback`'s.
glm::vec2 screen_uv(const TransmissionBackdrop& backdrop, const glm::vec3& point,
                    const glm::vec3& fallback) {
    glm::vec4 clip = backdrop.view_projection * glm::vec4(point, 1.0f);
    if (!(clip.w > 0.0f)) clip = backdrop.view_projection * glm::vec4(fallback, 1.0f);
    if (!(clip.w > 0.0f)) return {0.5f, 0.5f};
    return {0.5f * (clip.x / clip.w + 1.0f), 0.5f * (1.0f - clip.y / clip.w)};
}

}  // namespace

void BackdropPyramid::build(const HalfColorImage& color, ThreadPool& pool) {
    int width = color.width, height = color.height;
    widest_level_ = std::log2(static_cast<float>(width));
    count_ = 0;
    while (true) {
        if (levels_.size() <= count_) levels_.emplace_back();
        Level& level = levels_[count_];
        level.width = width, level.height = height;
        level.texels.resize(static_cast<size_t>(width) * height);
        const size_t w = static_cast<size_t>(width);
        if (count_ == 0) {
            pool.parallel_for_chunks(static_cast<size_t>(height), 32,
                                     [&](size_t first, size_t last) {
                                         for (size_t i = first * w; i < last * w; ++i)
                                             level.texels[i] = glm::vec3(to_float(color.pixels[i]));
                                     });
        } else {
            const Level& above = levels_[count_ - 1];
            const size_t above_w = static_cast<size_t>(above.width);
            pool.parallel_for_chunks(
                static_cast<size_t>(height), 32, [&](size_t first, size_t last) {
                    for (size_t y = first; y < last; ++y) {
                        const glm::vec3* a = &above.texels[2 * y * above_w];
                        const glm::vec3* b =
                            &above.texels[std::min<size_t>(2 * y + 1, above.height - 1) * above_w];
                        for (size_t x = 0; x < w; ++x) {
                            const size_t x0 = 2 * x, x1 = std::min(2 * x + 1, above_w - 1);
                            level.texels[y * w + x] = (a[x0] + a[x1] + b[x0] + b[x1]) * 0.25f;
                        }
                    }
                });
        }
        ++count_;
        if (width == 1 && height == 1) break;
        width = (width + 1) / 2, height = (height + 1) / 2;
    }
}

glm::vec3 BackdropPyramid::bilinear(const Level& level, glm::vec2 uv) const {
    // Texel i spans [i, i + 1]; its centre is at i + 0.5.
    const float tx = std::clamp(uv.x * static_cast<float>(level.width) - 0.5f, 0.0f,
                                static_cast<float>(level.width - 1));
    const float ty = std::clamp(uv.y * static_cast<float>(level.height) - 0.5f, 0.0f,
                                static_cast<float>(level.height - 1));
    const int x0 = static_cast<int>(tx), y0 = static_cast<int>(ty);
    const int x1 = std::min(x0 + 1, level.width - 1), y1 = std::min(y0 + 1, level.height - 1);
    const float fx = tx - static_cast<float>(x0), fy = ty - static_cast<float>(y0);
    const glm::vec3* row0 = &level.texels[static_cast<size_t>(y0) * level.width];
    const glm::vec3* row1 = &level.texels[static_cast<size_t>(y1) * level.width];
    const glm::vec3 top = row0[x0] + (row0[x1] - row0[x0]) * fx;
    const glm::vec3 bottom = row1[x0] + (row1[x1] - row1[x0]) * fx;
    return top + (bottom - top) * fy;
}

glm::vec3 BackdropPyramid::sample(glm::vec2 uv, float lod) const {
    if (count_ == 0) return glm::vec3(0.0f);
    if (!(std::isfinite(uv.x) && std::isfinite(uv.y))) uv = {0.5f, 0.5f};
    const float top = static_cast<float>(count_ - 1);
    if (!(lod > 0.0f)) return bilinear(levels_[0], uv);  // also NaN
    if (lod >= top) return bilinear(levels_[count_ - 1], uv);
    const int fine = static_cast<int>(lod);
    const float t = lod - static_cast<float>(fine);
    const glm::vec3 a = bilinear(levels_[static_cast<size_t>(fine)], uv);
    const glm::vec3 b = bilinear(levels_[static_cast<size_t>(fine) + 1], uv);
    return a + (b - a) * t;
}

glm::vec3 radiance_behind(const RefractedView& point, const TransmissionBackdrop* backdrop,
                          const EnvironmentLighting* environment) {
    if (!backdrop) {
        if (!environment || !environment->map || environment->intensity <= 0.0f)
            return glm::vec3(0.0f);
        const glm::vec3 through = environment->to_map(-point.view);
        return environment->intensity * environment->map->specular(through, point.roughness);
    }
    const BackdropPyramid& image = backdrop->image;
    const float lod = image.widest_level() * point.roughness;
    const float spread = (point.ior - 1.0f) * 0.025f * point.dispersion;
    glm::vec3 result, texel;
    for (int c = 0; c < 3; ++c) {
        // Without dispersion every channel takes the same view: read once.
        if (c == 0 || spread != 0.0f) {
            const float ior = point.ior + static_cast<float>(c - 1) * spread;
            const glm::vec3 direction =
                refracted(-point.view, point.normal, 1.0f / std::max(ior, 1.0f));
            const glm::vec3 exit = point.position + point.thickness * direction;
            texel = image.sample(screen_uv(*backdrop, exit, point.position), lod);
        }
        result[c] = texel[c];
    }
    return result;
}

}  // namespace facet
