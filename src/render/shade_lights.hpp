#pragma once
// Stage 4 of a frame: the frame's lights as the shading models take them
// (shade/lighting.hpp), each with its shadow map from the shadow stage.
#include <span>
#include <vector>

#include "anim/frame_state.hpp"
#include "shade/lighting.hpp"
#include "shade/shadow_map.hpp"

namespace facet {

// Directional, point and spot lights in scene order (lights[0] is the key
// light of the stylised models), then the ambient ones. `shadow_maps`, when
// given, holds each scene light's map or null.
std::vector<ShadeLight> make_shade_lights(const std::vector<LightState>& lights,
                                          std::span<const ShadowMap* const> shadow_maps = {});

}  // namespace facet
