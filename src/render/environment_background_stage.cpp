#include "render/environment_background_stage.hpp"

#include <glm/mat3x3.hpp>

#include "shade/environment_map.hpp"
#include "shade/light_sample.hpp"

namespace facet {

void composite_environment_background(HalfColorImage& color, const CameraMatrices& camera,
                                      const EnvironmentLighting& environment, float blur,
                                      ThreadPool& pool) {
    if (!environment.map) return;
    const pbr::PrefilteredEnvironment& map = *environment.map;
    // A pixel's ray in view space is (x_ndc + P20) / P00, (y_ndc + P21) / P11,
    // -1 for a perspective projection; the view's rotation turns it to the
    // world (its transpose is its inverse).
    const glm::mat4& p = camera.projection;
    const glm::mat3 to_world = glm::transpose(glm::mat3(camera.view));
    const float width = static_cast<float>(color.width), height = static_cast<float>(color.height);
    pool.parallel_for(static_cast<size_t>(color.height), [&](size_t row) {
        const int y = static_cast<int>(row);
        const float ndc_y = 1.0f - 2.0f * (static_cast<float>(y) + 0.5f) / height;
        for (int x = 0; x < color.width; ++x) {
            Rgba16F& pixel = color.at(x, y);
            const glm::vec4 c = to_float(pixel);
            if (c.a >= 1.0f) continue;
            const float ndc_x = 2.0f * (static_cast<float>(x) + 0.5f) / width - 1.0f;
            const glm::vec3 view_ray((ndc_x + p[2][0]) / p[0][0], (ndc_y + p[2][1]) / p[1][1],
                                     -1.0f);
            const glm::vec3 ray = normalise_or(to_world * view_ray, camera.forward);
            const glm::vec3 radiance =
                environment.intensity * map.radiance(environment.to_map(ray), blur);
            pixel = to_half(glm::vec4(glm::vec3(c) + radiance * (1.0f - c.a), 1.0f));
        }
    });
}

}  // namespace facet
