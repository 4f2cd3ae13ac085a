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

glm::vec3 radiance_behind(const RefractedView& point, const TransmissionBackdrop* backdrop,
                          const EnvironmentLighting* environment) {
    if (!backdrop) {
        if (!environment || !environment->map || environment->intensity <= 0.0f)
            return glm::vec3(0.0f);
        const glm::vec3 through = environment->to_map(-point.view);
        return environment->intensity * environment->map->specular(through, point.roughness);
    }
    const Texture& image = backdrop->image;
    const float lod = std::log2(static_cast<float>(image.width)) * point.roughness;
    const float spread = (point.ior - 1.0f) * 0.025f * point.dispersion;
    glm::vec3 result;
    glm::vec4 texel;
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
