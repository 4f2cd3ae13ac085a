#pragma once
// What rendering a scene will hold in memory, estimated before the first
// frame from the scene and its world, so that a scene too big for the
// machine stops with an error naming the parts instead of meeting the
// out-of-memory killer halfway through a sequence.
#include "core/memory.hpp"
#include "render/render_plan.hpp"
#include "render/world.hpp"
#include "scene/scene_desc.hpp"

namespace facet {

// What rendering adds to the loaded world: frame buffers (output images in
// flight, screen-space buffers: samples and G-buffer), per-triangle and per-vertex working
// records, shadow maps.
// `plan`: the run's (plan_render), which the frames are drawn from.
MemoryParts render_memory(const SceneDesc& scene, const World& world, const RenderPlan& plan,
                          unsigned threads);

// Throws facet::Error (runtime_failure) when render_memory adds up to more
// than memory_available().
void check_render_memory(const SceneDesc& scene, const World& world, const RenderPlan& plan,
                         unsigned threads);

}  // namespace facet
