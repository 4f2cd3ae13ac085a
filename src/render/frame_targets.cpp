#include "render/frame_targets.hpp"

#include "render/surface_pass_stage.hpp"

namespace facet {

FrameTargets plan_frame_targets(const StylePlan& plan, PassSet passes) {
    FrameTargets targets;
    targets.gbuffer = plan.outlines || plan.occlusion;
    targets.lines = passes.has(Pass::lines);
    targets.line_samples = targets.lines || plan.hidden_edges;
    // Occlusion varies slowly: alone, it reads a G-buffer of pixels and
    // darkens the resolved pixels, so shading stays at the pixels. Lines
    // need every sample.
    const bool sample_stages = plan.outlines || targets.line_samples;
    targets.shading = sample_stages ? ShadeResolution::samples : ShadeResolution::pixels;
    targets.alpha = passes.has(Pass::alpha);
    targets.surface_passes = wants_surface_passes(passes);
    return targets;
}

}  // namespace facet
