#pragma once
// A style evaluated at one frame: its keyed values resolved and turned into
// the parameter records of the shading models in shade/ and post/.
#include <map>
#include <memory>
#include <optional>
#include <tuple>
#include <vector>

#include "anim/track.hpp"
#include "post/outlines.hpp"
#include "scene/style_desc.hpp"
#include "shade/gooch_style.hpp"
#include "shade/lighting.hpp"
#include "shade/palette_style.hpp"
#include "shade/tonal_art_map.hpp"
#include "shade/toon_style.hpp"
#include "shade/wireframe.hpp"

namespace facet {

struct HatchingState {
    const TonalArtMap* tam = nullptr;
    float strength = 1;
    std::optional<glm::vec3> ink;
    bool screen_space = false;
    float scale = 8;          // tiles per UV unit
    float tile_pixels = 128;  // screen space: output pixels per tile
    bool pencil = false;
};

struct StyleState {
    ShadingModel model = ShadingModel::blinn_phong;
    std::optional<glm::vec3> base_color;
    PaletteStyle palette;
    GoochStyle gooch;
    ToonStyle toon;
    std::optional<HatchingState> hatching;
    bool wireframe = false;
    WireframeStyle wire;
    bool wire_fill_shading = true;
    bool wire_hidden = false;  // also draw edges behind surfaces
    glm::vec3 wire_hidden_color{0.6f};
    glm::vec3 wire_fill{1};
};

// Tonal art maps take a fraction of a second to generate, so each distinct
// set of parameters is generated once per run.
class TamCache {
  public:
    const TonalArtMap& get(const TamParams& params);

  private:
    std::map<std::vector<float>, std::unique_ptr<TonalArtMap>> maps_;
};

TamParams tam_params(const HatchingDesc& hatching);

StyleState evaluate_style(const StyleDesc& style, const FrameTime& at, TamCache& tams);

// The outline settings of the scene's style at this frame, widths in
// pixels of the image they are drawn on (`pixel_scale` samples per pixel side).
OutlineStyle evaluate_outlines(const OutlinesDesc& outlines, const FrameTime& at,
                               float pixel_scale);

}  // namespace facet
