#include "shade/shading_models.hpp"

#include "shade/gooch_style.hpp"
#include "shade/layers.hpp"
#include "shade/light_sample.hpp"
#include "shade/model_depth_view.hpp"
#include "shade/model_gouraud.hpp"
#include "shade/model_normal_view.hpp"
#include "shade/model_phong.hpp"
#include "shade/model_unlit.hpp"
#include "shade/palette_style.hpp"
#include "shade/toon_style.hpp"

namespace facet {
namespace {

// The stylised models light one point at a time: unit normal and view vector.
template <typename Model>
void shade_stylised(const SurfaceLanes& in, const ShadingContext& context, Model model,
                    ShadedLanes& out) {
    const SurfaceBatch& s = in.surface;
    for (int i = 0; i < in.count; ++i) {
        const glm::vec3 position(s.px[i], s.py[i], s.pz[i]);
        const glm::vec3 n = normalise_or({s.nx[i], s.ny[i], s.nz[i]}, glm::vec3(0, 1, 0));
        const glm::vec3 v = normalise_or(context.eye - position, n);
        const float highlight_strength = s.specular[i] / kDefaultSpecular;
        out.set(i, model(i, position, n, v, s.receives_shadow[i] > 0, highlight_strength,
                         out.palette_tone[i]));
    }
}

}  // namespace

void shade_lanes(const StyleState& style, const ShadingContext& context, SurfaceLanes& in,
                 ShadedLanes& out) {
    for (int i = 0; i < in.count; ++i) out.palette_tone[i] = -1;
    const std::span<const ShadeLight> lights = context.lights;
    switch (style.model) {
        case ShadingModel::unlit:
        case ShadingModel::blinn_phong:
        case ShadingModel::phong:
            return shade_plain_model(style, context, in, out);
        case ShadingModel::depth:
            return shade_depth_view(in, context.depth_range, out);
        case ShadingModel::normal:
            return shade_normal_view(in, out);
        case ShadingModel::gouraud:
            return shade_gouraud(in, out);
        case ShadingModel::flat:  // Blinn-Phong with the face's normal
            if (in.count < simd::kLanes) pad_batch(in.surface, in.count);
            shade_phong(in, context, Highlight::blinn, out);
            return;
        case ShadingModel::palette:
            shade_stylised(
                in, context,
                [&](int i, auto& p, auto& n, auto& v, bool r, float h, float& tone) {
                    return shade_palette(style.palette, in.albedo_at(i), p, n, v, lights, r, h,
                                         tone);
                },
                out);
            return;
        case ShadingModel::gooch:
            shade_stylised(
                in, context,
                [&](int i, auto& p, auto& n, auto& v, bool r, float h, float&) {
                    return shade_gooch(style.gooch, style.palette, in.albedo_at(i), p, n, v, lights,
                                       r, h);
                },
                out);
            return;
        case ShadingModel::pbr:
            return shade_pbr(in, context, out);
        case ShadingModel::toon:
            shade_stylised(
                in, context,
                [&](int i, auto& p, auto& n, auto& v, bool r, float h, float&) {
                    return shade_toon(style.toon, in.albedo_at(i), p, n, v, lights, r, h);
                },
                out);
            return;
    }
}

void shade_plain_model(const StyleState& style, const ShadingContext& context, SurfaceLanes& in,
                       ShadedLanes& out) {
    if (style.model == ShadingModel::unlit) return shade_unlit(in, out);
    if (in.count < simd::kLanes) pad_batch(in.surface, in.count);
    shade_phong(in, context,
                style.model == ShadingModel::phong ? Highlight::phong : Highlight::blinn, out);
}

ModelNeeds needs_of(ShadingModel m) {
    const bool lit = m == ShadingModel::flat || m == ShadingModel::phong ||
                     m == ShadingModel::blinn_phong || m == ShadingModel::palette ||
                     m == ShadingModel::gooch || m == ShadingModel::toon || m == ShadingModel::pbr;
    // Gouraud lights the vertices, but looks up shadows per pixel, which
    // needs the pixel's position and normal.
    const bool gouraud = m == ShadingModel::gouraud;
    return {lit || gouraud, lit || gouraud || m == ShadingModel::normal, lit, gouraud};
}

bool phong_family(ShadingModel m) {
    return m == ShadingModel::phong || m == ShadingModel::blinn_phong || m == ShadingModel::flat ||
           m == ShadingModel::gouraud;
}

uint32_t drawn_features(ShadingModel model, bool style_base_color, uint32_t features) {
    if (style_base_color) features &= ~(kBaseColorMap | kVertexColors | kMetalRough);
    if (model != ShadingModel::pbr) features &= ~kPbrOnlyFeatures;
    if (!phong_family(model)) features &= ~kMetalRough;
    // The unlit, normal and depth models show no emission: views stay measurements.
    if (!needs_of(model).position) features &= ~kEmission;
    return features;
}

uint32_t drawn_features(const StyleState& style, uint32_t features) {
    return drawn_features(style.model, style.base_color.has_value(), features);
}

bool plain_style(const StyleState& style) {
    const ShadingModel m = style.model;
    return (m == ShadingModel::phong || m == ShadingModel::blinn_phong ||
            m == ShadingModel::unlit) &&
           !has_layers(style);
}

}  // namespace facet
