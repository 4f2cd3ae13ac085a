#pragma once
// The physically based model (`shading: pbr`): glTF 2.0's metallic-roughness
// BRDF (shade/brdf.hpp) lit by the scene's lights and by an environment
// (shade/environment_map.hpp). docs/pbr.md gives every formula; in short,
// per point:
//
//   direct   = sum over lights of pi * radiance * visibility * f(v, l) (n.l)
//   indirect = occlusion * intensity * (diffuse weight * c_diff * E(n) / pi
//                                      + prefiltered(r, roughness) * specular albedo)
//
// A light of intensity 1 facing a white Lambertian surface gives it
// radiance 1, as the Phong models do: facet's light intensities are
// irradiance over pi, so switching a scene between `phong` and `pbr` keeps
// its brightness. The environment is radiance, as its file gives it.
#include <glm/vec3.hpp>

#include "core/simd_math.hpp"

namespace facet {

namespace pbr {
class PrefilteredEnvironment;  // shade/environment_map.hpp
template <typename T>
struct SurfaceTerms;  // shade/brdf_terms.hpp
}  // namespace pbr

struct SurfaceLanes;
struct ShadedLanes;
struct ShadingContext;

// The environment at one frame: the prefiltered maps with the scene's keyed
// intensity and rotation about +Y.
struct EnvironmentLighting {
    const pbr::PrefilteredEnvironment* map = nullptr;  // none: no indirect light
    float intensity = 1.0f;
    // cos and sin of the rotation: a feature the map has at direction d is
    // seen at R(rotation) d, so world directions turn by -rotation for lookups.
    float cos_rotation = 1.0f, sin_rotation = 0.0f;

    glm::vec3 to_map(const glm::vec3& d) const {
        return {cos_rotation * d.x - sin_rotation * d.z, d.y,
                sin_rotation * d.x + cos_rotation * d.z};
    }
    // The same for eight directions.
    void to_map(const simd::vf (&d)[3], simd::vf (&out)[3]) const {
        out[0] = cos_rotation * d[0] - sin_rotation * d[2];
        out[1] = d[1];
        out[2] = sin_rotation * d[0] + cos_rotation * d[2];
    }
};

// The rotation's cosine and sine, for EnvironmentLighting, from exact
// series (core/exact_trig.hpp), so they do not depend on the CPU.
EnvironmentLighting environment_at(const pbr::PrefilteredEnvironment* map, float intensity,
                                   float rotation_degrees);

void shade_pbr(const SurfaceLanes& in, const ShadingContext& context, ShadedLanes& out);

// One point through the same template as shade_pbr's eight: a lane's
// colour for the same inputs, to the bit (tests/test_pbr_lanes.cpp).
glm::vec3 shade_pbr_point(const glm::vec3& position, const glm::vec3& normal, bool receives_shadow,
                          const pbr::SurfaceTerms<float>& terms, const ShadingContext& context);

}  // namespace facet
