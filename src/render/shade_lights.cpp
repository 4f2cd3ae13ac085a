#include "render/shade_lights.hpp"

#include <glm/geometric.hpp>

namespace facet {

std::vector<ShadeLight> make_shade_lights(const std::vector<LightState>& lights,
                                          std::span<const ShadowMap* const> shadow_maps) {
    std::vector<ShadeLight> out, ambient;
    for (size_t i = 0; i < lights.size(); ++i) {
        const LightState& l = lights[i];
        ShadeLight s;
        s.radiance = l.color * l.intensity;
        if (l.type == LightType::ambient) {
            s.is_ambient = true;
            ambient.push_back(s);
            continue;
        }
        s.is_point = l.type == LightType::point || l.type == LightType::spot;
        s.direction = l.type == LightType::point ? glm::vec3(0) : -glm::normalize(l.direction);
        s.position = l.position;
        if (l.type == LightType::spot) set_spot_cone(s, l.inner_angle, l.outer_angle);
        if (s.is_point && l.range > 0) s.inv_range = 1.0f / l.range;
        if (i < shadow_maps.size()) s.shadow = shadow_maps[i];
        out.push_back(s);
    }
    out.insert(out.end(), ambient.begin(), ambient.end());
    return out;
}

}  // namespace facet
