#pragma once
// A style at one frame, as the shading models take it: the parameters of
// each model and layer, keyed values already evaluated (render/style_eval.hpp
// builds it from a scene's StyleDesc).
#include <optional>

#include <glm/vec3.hpp>

#include "scene/style_desc.hpp"
#include "shade/gooch_style.hpp"
#include "shade/palette_style.hpp"
#include "shade/tonal_art_map.hpp"
#include "shade/toon_style.hpp"
#include "shade/wireframe.hpp"

namespace facet {

struct HatchingState {
    const TonalArtMap* tam = nullptr;
    float strength = 1;
    float white = 1;           // the tone at and above which no strokes are drawn
    float exposure_scale = 1;  // 2^exposure: the light's scale before the tone curve
    std::optional<glm::vec3> ink;
    HatchSpace space = HatchSpace::object;
    HatchDirection direction = HatchDirection::curvature;
    glm::vec3 axis{0, 1, 0};
    float angle = 0;          // radians, from the direction
    float scale = 8;          // object and uv space: tiles per unit
    float tile_pixels = 160;  // the tile's size on screen, in output pixels
    float target_lod = 0;     // log2(tam size / tile_pixels): the lod the octaves aim at
    bool pencil = false;
    std::optional<float> wash;  // set: strokes on the paper tinted this much, not the shading
    glm::vec3 paper{1.0f};
    bool additive = false;  // strokes add ink x coverage instead of blending to it
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
    bool wire_hidden = false;         // also draw edges behind surfaces
    bool wire_all_edges = false;      // every edge, not only the features
    float wire_crease_cosine = 0.0f;  // folds whose normals' cosine is below this are creases
    glm::vec3 wire_hidden_color{0.6f};
    glm::vec3 wire_fill{1};
};

}  // namespace facet
