#pragma once
// What every frame of a run is made of, fixed before the first: which style
// shades which object, which buffers a frame has, which triangles are glass
// and which have their coverage tested. Made once per run by plan_render and
// read by the memory estimate (job/render_memory.hpp) and the frame renderer,
// so the two cannot plan a run differently.
#include <cstdint>
#include <vector>

#include "render/frame_inputs.hpp"
#include "render/frame_targets.hpp"
#include "render/world.hpp"
#include "scene/scene_desc.hpp"

namespace facet {

struct RenderPlan {
    StylePlan styles;
    FrameTargets targets;
    // Per triangle of the world: 1 where a transmitting material is drawn
    // by `pbr` (render/transmission_stage.hpp); empty when none is.
    std::vector<uint8_t> transmitting;
    // Per triangle: 1 where the material's alpha mode is mask or blend
    // (render/alpha_coverage.hpp); empty when none is.
    std::vector<uint8_t> alpha_tested;
    // Per triangle: alpha-tested or glass, the triangles whose coverage the
    // rasterizer asks about; empty when none is.
    std::vector<uint8_t> coverage_tested;
};

// The plan of `scene` drawn from `world`. It points into `scene` (its
// styles), which must outlive it.
RenderPlan plan_render(const SceneDesc& scene, const World& world);

}  // namespace facet
