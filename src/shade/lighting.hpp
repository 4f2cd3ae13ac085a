#pragma once
// Types shared by the lighting models (shade/lighting_batch.hpp): Phong
// (Phong 1975) and Blinn-Phong (Blinn 1977) reflection, evaluated per pixel
// (Phong shading) or per vertex (Gouraud 1971). Colours are linear RGB.
#include <glm/vec3.hpp>

namespace facet {

struct ShadeLight {
    bool is_point = false;
    glm::vec3 direction;  // directional: unit vector towards the light
    glm::vec3 position;   // point
    glm::vec3 radiance;   // colour * intensity
};

// Light arriving at a point, split so that a texture can scale the diffuse
// part only: colour = albedo * diffuse + specular.
struct LightingResult {
    glm::vec3 diffuse;
    glm::vec3 specular;
};

enum class Highlight { phong, blinn };

}  // namespace facet
