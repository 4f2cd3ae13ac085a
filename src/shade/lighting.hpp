#pragma once
// Local lighting models: Phong (Phong 1975) and Blinn-Phong (Blinn 1977)
// reflection, evaluated per pixel (Phong shading) or per vertex (Gouraud
// 1971). Colours are linear RGB.
#include <span>

#include <glm/vec3.hpp>

namespace facet {

struct ShadeLight {
    bool is_point = false;
    glm::vec3 direction;  // directional: unit vector towards the light
    glm::vec3 position;   // point
    glm::vec3 radiance;   // colour * intensity
};

struct SurfacePoint {
    glm::vec3 position;
    glm::vec3 normal;  // unit, on the side facing the viewer
    glm::vec3 to_eye;  // unit
};

struct MaterialTerms {
    float ambient, diffuse, specular, shininess;
};

// Light arriving at a point, split so that a texture can scale the diffuse
// part only: colour = albedo * diffuse + specular.
struct LightingResult {
    glm::vec3 diffuse;
    glm::vec3 specular;
};

enum class Highlight { phong, blinn };

LightingResult light_surface(const SurfacePoint& p, const MaterialTerms& m,
                             std::span<const ShadeLight> lights, Highlight highlight);

// Colour-space helpers for the views that show data as grey or colour.
float srgb_to_linear(float c);
float linear_to_srgb(float c);

}  // namespace facet
