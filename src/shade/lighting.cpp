#include "shade/lighting.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace facet {

LightingResult light_surface(const SurfacePoint& p, const MaterialTerms& m,
                             std::span<const ShadeLight> lights, Highlight highlight) {
    LightingResult out{glm::vec3(m.ambient), glm::vec3(0)};
    for (const ShadeLight& light : lights) {
        glm::vec3 to_light;
        glm::vec3 radiance = light.radiance;
        if (light.is_point) {
            glm::vec3 d = light.position - p.position;
            float dist2 = glm::dot(d, d);
            if (dist2 <= 0) continue;
            to_light = d / std::sqrt(dist2);
            radiance /= dist2;  // inverse-square falloff
        } else {
            to_light = light.direction;
        }
        float n_dot_l = glm::dot(p.normal, to_light);
        if (n_dot_l <= 0) continue;
        out.diffuse += m.diffuse * n_dot_l * radiance;
        if (m.specular <= 0) continue;
        float cosine;
        if (highlight == Highlight::blinn) {
            glm::vec3 half = to_light + p.to_eye;
            float len = glm::length(half);
            cosine = len > 0 ? glm::dot(p.normal, half / len) : 0.0f;
        } else {
            glm::vec3 reflected = 2.0f * n_dot_l * p.normal - to_light;
            cosine = glm::dot(reflected, p.to_eye);
        }
        if (cosine > 0) out.specular += m.specular * std::pow(cosine, m.shininess) * radiance;
    }
    return out;
}

float srgb_to_linear(float c) {
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

float linear_to_srgb(float c) {
    c = std::clamp(c, 0.0f, 1.0f);
    return c <= 0.0031308f ? c * 12.92f : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

}  // namespace facet
