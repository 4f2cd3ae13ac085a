#include "render/style_eval.hpp"

#include <cmath>

namespace facet {

const TonalArtMap& TamCache::get(const TamParams& params) {
    for (const auto& map : maps_)
        if (map->params == params) return *map;
    maps_.push_back(std::make_unique<TonalArtMap>(generate_tonal_art_map(params)));
    return *maps_.back();
}

TamParams tam_params(const HatchingDesc& h) {
    TamParams p = h.pencil ? TamParams::pencil() : TamParams{};
    p.levels = h.levels;
    p.seed = static_cast<uint32_t>(h.seed);
    p.hatch_angle = 0;  // along the tile's u: the lookup turns them (shade/hatch_mapping.hpp)
    p.stroke_width = h.stroke_width;
    p.cross_from_level = h.levels / 2;  // cross strokes in the darker half
    return p;
}

StyleState evaluate_style(const StyleDesc& d, const FrameTime& at, TamCache& tams) {
    StyleState s;
    s.model = d.shading;
    if (d.base_color) s.base_color = evaluate(*d.base_color, at);

    PaletteStyle& p = s.palette;
    p.shadow_color = evaluate(d.cool, at);
    p.lit_color = evaluate(d.warm, at);
    p.alpha = evaluate(d.alpha, at);
    p.beta = evaluate(d.beta, at);
    p.ambient = evaluate(d.ambient, at);
    // Keyed cel counts move through whole numbers (a fade from 2 to 6 cels
    // steps 2, 3, 4, 5, 6).
    p.cels = static_cast<int>(std::lround(evaluate(d.cels, at)));
    p.cels_keep_hue = d.cels_keep_hue;
    p.hatch_below = evaluate(d.hatch_below, at);
    p.specular = evaluate(d.specular, at);
    p.shininess = evaluate(d.shininess, at);

    s.gooch.shininess = p.shininess;
    s.gooch.highlight_color = glm::vec3(p.specular);

    ToonStyle& t = s.toon;
    t.bands.clear();
    for (const ToonBandDesc& b : d.toon.bands) t.bands.push_back({b.threshold, b.value});
    t.mode = d.toon.ramp ? ToonMode::ramp : ToonMode::bands;
    t.band_softness = evaluate(d.toon.softness, at);
    t.specular_color = evaluate(d.toon.specular_color, at);
    t.specular_threshold = evaluate(d.toon.specular_threshold, at);
    t.shininess = d.toon.shininess;
    t.rim_color = evaluate(d.toon.rim_color, at);
    t.rim_power = d.toon.rim_power;
    t.rim_threshold = evaluate(d.toon.rim_threshold, at);

    if (d.hatching) {
        HatchingState h;
        h.tam = &tams.get(tam_params(*d.hatching));
        h.strength = evaluate(d.hatching->strength, at);
        h.white = evaluate(d.hatching->white, at);
        h.exposure_scale = std::exp2(evaluate(d.hatching->exposure, at));
        if (d.hatching->ink) h.ink = evaluate(*d.hatching->ink, at);
        h.space = d.hatching->space;
        h.direction = d.hatching->direction;
        h.axis = d.hatching->axis;
        h.angle = glm::radians(d.hatching->angle);
        h.scale = d.hatching->scale;
        h.tile_pixels = d.hatching->tile_pixels;
        h.target_lod = std::log2(static_cast<float>(h.tam->params.size) / h.tile_pixels);
        h.pencil = d.hatching->pencil;
        if (d.hatching->wash) h.wash = evaluate(*d.hatching->wash, at);
        h.paper = evaluate(d.hatching->paper, at);
        h.additive = d.hatching->additive;
        s.hatching = h;
    }
    if (d.wireframe.enabled) {
        s.wireframe = true;
        s.wire.width = evaluate(d.wireframe.width, at);
        s.wire.color = evaluate(d.wireframe.color, at);
        s.wire_fill_shading = d.wireframe.fill_shading;
        s.wire_hidden = d.wireframe.hidden;
        s.wire_all_edges = d.wireframe.all_edges;
        s.wire_crease_cosine = std::cos(glm::radians(d.wireframe.crease_angle));
        s.wire_hidden_color = evaluate(d.wireframe.hidden_color, at);
        s.wire_fill = evaluate(d.wireframe.fill_color, at);
    }
    return s;
}

OutlineStyle evaluate_outlines(const OutlinesDesc& o, const FrameTime& at, float pixel_scale) {
    auto line = [&](const LineDesc& d) {
        return LineStyle{d.enabled, evaluate(d.width, at) * pixel_scale, evaluate(d.color, at)};
    };
    OutlineStyle s;
    s.silhouette = line(o.silhouette);
    s.crease = line(o.crease);
    s.boundary = line(o.boundary);
    s.intersection = line(o.intersection);
    s.crease_angle = o.crease_angle;
    s.depth_threshold = o.depth_threshold;
    return s;
}

}  // namespace facet
