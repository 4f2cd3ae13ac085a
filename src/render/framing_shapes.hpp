#pragma once
// What cameras with `frame:` fit (anim/frame_state.hpp, FramingShape), made
// once per run from the world: each object's distinct model-space vertices,
// and for a mesh playing glTF animations, the bounds of its poses over the
// frames of the scene, so that it stays in view however it moves.
#include <vector>

#include "anim/frame_state.hpp"
#include "render/world.hpp"

namespace facet {

// One per scene object; empty when no camera has `frame:`. Depends on the
// scene's whole frame range, never on which frames a run renders, so any
// subset of frames is framed as in a full run.
std::vector<FramingShape> framing_shapes(const SceneDesc& scene, const World& world);

}  // namespace facet
