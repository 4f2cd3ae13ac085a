#pragma once
// Which buffers a frame has and which stage resolves them, decided once per
// scene from its style plan and passes (docs/architecture.md, "The frame
// pipeline"). Every stage that writes or reads a frame buffer reads this
// record, so a new screen-space stage changes this file's rule, not each
// stage's own guess of the mode.
#include "output/passes.hpp"
#include "render/frame_inputs.hpp"

namespace facet {

// Where shading writes. `pixels`: finished output pixels, anti-aliased ones
// resolved by shading itself. `samples`: every sample at the rasterizer's
// resolution, for screen-space stages that need them (outlines, hidden
// edges, the lines pass; ambient occlusion runs beside them there, and on
// the pixels otherwise); post/ resolves them after.
enum class ShadeResolution { pixels, samples };

struct FrameTargets {
    ShadeResolution shading = ShadeResolution::pixels;
    // Depth, normal and object at the shading's resolution: what outlines
    // and ambient occlusion read.
    bool gbuffer = false;
    // Each sample's wireframe stroke alone: the lines pass, and hidden
    // edges, which stay under the visible strokes.
    bool line_samples = false;
    // The output passes beyond colour and depth. Shading writes the alpha
    // pass at `pixels`, the resolve at `samples`; the lines pass exists
    // only at `samples`.
    bool alpha = false;
    bool lines = false;
    bool surface_passes = false;  // normal, ids, uv, position, motion
};

FrameTargets plan_frame_targets(const StylePlan& plan, PassSet passes);

}  // namespace facet
