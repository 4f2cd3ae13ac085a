#pragma once
// A style evaluated at one frame: its keyed values resolved and turned into
// the parameter records of the shading models in shade/ (StyleState) and of
// the outlines in post/ (OutlineStyle).
#include <memory>
#include <vector>

#include "anim/track.hpp"
#include "post/outlines.hpp"
#include "scene/style_desc.hpp"
#include "shade/style_state.hpp"
#include "shade/tonal_art_map.hpp"

namespace facet {

// Tonal art maps take a fraction of a second to generate, so each distinct
// set of parameters (every field compared) is generated once per run.
class TamCache {
  public:
    const TonalArtMap& get(const TamParams& params);

  private:
    std::vector<std::unique_ptr<TonalArtMap>> maps_;  // a run uses a handful at most
};

TamParams tam_params(const HatchingDesc& hatching);

StyleState evaluate_style(const StyleDesc& style, const FrameTime& at, TamCache& tams);

// The outline settings of the scene's style at this frame, widths in
// pixels of the image they are drawn on (`pixel_scale` samples per pixel side).
OutlineStyle evaluate_outlines(const OutlinesDesc& outlines, const FrameTime& at,
                               float pixel_scale);

}  // namespace facet
