#include "render/shade_batch.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>

#include <glm/geometric.hpp>

#include "core/color.hpp"
#include "raster/surface_sample.hpp"
#include "render/hatch_charts.hpp"
#include "render/normal_map_lookup.hpp"
#include "shade/environment_map.hpp"
#include "shade/layers.hpp"
#include "shade/light_sample.hpp"
#include "shade/lighting_batch.hpp"
#include "shade/material_terms.hpp"
#include "shade/shading_models.hpp"
#include "shade/texture_lod.hpp"
#include "shade/wireframe.hpp"

namespace facet {
namespace {

using simd::kLanes;
using simd::vf;
using simd::vi;

// A batch being shaded: the caller's request, the result every path
// writes in full, and what the steps share in between.
struct Batch {
    // The rest is written before it is read: left uninitialised, not cleared per batch.
    Batch(const ShadeRequest& r, ShadeResult& out) : request(r), result(out), count(r.count) {}

    const ShadeRequest& request;
    ShadeResult& result;
    int count;
    const ShadeSetup* setup[kLanes];
    // Per lane: its material, whether its part has texture coordinates and
    // vertex colours, and its draw's features (FrameInputs::draw_features).
    const Material* material[kLanes];
    bool has_uvs[kLanes];
    bool has_colors[kLanes];
    uint32_t features[kLanes];
    SurfaceSamples sample;
    SurfaceLanes lanes;
};

// The lanes that show the same triangle id: most batches hold one or two
// triangles, so their data is loaded once per group, not once per lane.
struct LaneGroup {
    int lane;  // the first lane of the group
    vi mask;
};

[[gnu::always_inline]] inline int group_lanes(const uint32_t (&ids)[kLanes],
                                              LaneGroup (&groups)[kLanes]) {
    if (std::all_of(ids + 1, ids + kLanes, [&](uint32_t id) { return id == ids[0]; })) {
        groups[0] = {0, simd::splat_i(-1)};
        return 1;
    }
    vi all;
    std::memcpy(&all, ids, sizeof all);
    unsigned covered = 0;
    int count = 0;
    for (int lane = 0; lane < kLanes; ++lane) {
        if (covered & (1u << lane)) continue;
        const vi mask = all == simd::splat_i(static_cast<int32_t>(ids[lane]));
        covered |= simd::movemask(mask);
        groups[count++] = {lane, mask};
    }
    return count;
}

// The corners' positions, normals and Gouraud light of each group's
// triangle, as lanes.
struct CornerLanes {
    vf p[3][3], n[3][3], diffuse[3][3], specular[3][3];  // [corner][axis]
    // Gouraud with shadows: the shadow-casting lights' direct light.
    vf direct_diffuse[3][3], direct_specular[3][3];
    vf back{};  // every group sets it; zero for the compiler's sake
};

// Axis `a` of a corner attribute at the lanes' barycentrics.
[[gnu::always_inline]] inline vf interpolate_corners(const vf (&bary)[3], const vf (&corner)[3][3],
                                                     int a) {
    return bary[0] * corner[0][a] + bary[1] * corner[1][a] + bary[2] * corner[2][a];
}

// One group's triangle's corners (positions and normals when `needs` asks,
// Gouraud's light) and which side the viewer sees, into `c`'s lanes.
template <bool Single>
[[gnu::always_inline]] inline void put_corners(const ShadeInputs& in, const ShadeSetup& setup,
                                               vi mask, bool first, const ModelNeeds& needs,
                                               bool face_normal, CornerLanes& c) {
    const TransformedVertices& v = in.vertices;
    const uint32_t* corners = &in.world.indices[3 * static_cast<size_t>(setup.source_triangle)];
    const bool positions = needs.position || face_normal;
    const bool normals = needs.normal && !face_normal;
    for (int k = 0; k < 3; ++k)
        for (int a = 0; a < 3; ++a) {
            if (positions) put<Single>(c.p[k][a], mask, v.world_position[corners[k]][a], first);
            if (normals) put<Single>(c.n[k][a], mask, v.world_normal[corners[k]][a], first);
        }
    put<Single>(c.back, mask, setup.back_facing ? 1.0f : 0.0f, first);
    if (!needs.vertex_light) return;
    for (int k = 0; k < 3; ++k)
        for (int a = 0; a < 3; ++a) {
            put<Single>(c.diffuse[k][a], mask, v.lit[corners[k]].diffuse[a], first);
            put<Single>(c.specular[k][a], mask, v.lit[corners[k]].specular[a], first);
            if (v.direct.empty()) continue;
            const LightingResult& d = v.direct[corners[k]];
            put<Single>(c.direct_diffuse[k][a], mask, d.diffuse[a], first);
            put<Single>(c.direct_specular[k][a], mask, d.specular[a], first);
        }
}

// Each group's corners and material terms into the lanes, and (for the
// general path's steps) each lane's material, part and features.
template <bool Plain, bool Single>
[[gnu::always_inline]] inline void gather_groups(const ShadeInputs& in, const StyleState& style,
                                                 uint32_t style_index, const ModelNeeds& needs,
                                                 const LaneGroup* groups, int group_count, Batch& b,
                                                 CornerLanes& c) {
    const World& world = in.world;
    const bool face_normal = !Plain && style.model == ShadingModel::flat;
    const size_t feature_row = style_index * world.draws.size();
    vi objects = simd::splat_i(0);
    for (int g = 0; g < group_count; ++g) {
        const bool first = g == 0;
        const vi mask = groups[g].mask;
        const ShadeSetup& setup = *b.setup[groups[g].lane];
        put_corners<Single>(in, setup, mask, first, needs, face_normal, c);
        const uint32_t draw_index = world.triangle_draw[setup.source_triangle];
        const Draw& draw = world.draws[draw_index];
        const Material& m = in.frame.materials[draw.material];
        if (needs.position)
            put<Single>(b.lanes.surface.receives_shadow, mask, world.receives_shadows[draw.object],
                        first);
        put_material_terms<Single>(m, in.frame.object_scales[draw.object], style, needs, mask,
                                   first, b.lanes);
        const vi object = simd::splat_i(static_cast<int32_t>(draw.object));
        objects = (Single || first) ? object : (mask ? object : objects);
        if constexpr (Plain) continue;
        const unsigned lanes = Single ? 0xffu : simd::movemask(mask);
        for (int lane = 0; lane < kLanes; ++lane) {
            if (!((lanes >> lane) & 1)) continue;
            b.material[lane] = &m;
            b.has_uvs[lane] = draw.has_uvs;
            b.has_colors[lane] = draw.has_colors;
            b.features[lane] = in.frame.draw_features[feature_row + draw_index];
        }
    }
    std::memcpy(b.result.object, &objects, sizeof objects);
}

// The share of the direct light of `lights` that shadows take from each
// lane, per colour channel: the lights lit twice at the lane, with and
// without their shadow maps, and the diffuse light compared. Ambient,
// material coefficients and highlights are left out: this is the lights'
// share. `unshadowed`, when given, is light no shadow map blocks (the `pbr`
// model's environment), added to both sides.
struct ShadowShare {
    vf channel[3];  // red, green, blue
    vf luminance;   // the same by the light's Rec. 709 luminance
};

ShadowShare shadow_share(const ShadeInputs& in, std::span<const ShadeLight> lights,
                         const SurfaceBatch& surface, const vf* unshadowed = nullptr) {
    SurfaceBatch open = surface;
    open.ambient = simd::splat(0.0f);
    open.diffuse = simd::splat(1.0f);
    open.specular = simd::splat(0.0f);
    open.shininess = simd::splat(1.0f);  // unused without specular, but read
    open.receives_shadow = simd::splat(0.0f);
    SurfaceBatch shadowed = open;
    shadowed.receives_shadow = surface.receives_shadow;
    const glm::vec3 eye = in.frame.camera.position;
    LightingBatch with = light_surface_batch(shadowed, eye, lights, Highlight::blinn);
    LightingBatch without = light_surface_batch(open, eye, lights, Highlight::blinn);
    if (unshadowed)
        for (LightingBatch* l : {&with, &without})
            l->dr += unshadowed[0], l->dg += unshadowed[1], l->db += unshadowed[2];
    const vf zero = simd::splat(0.0f), one = simd::splat(1.0f);
    auto share = [&](vf kept, vf full) {
        const vf s = one - kept / (full > zero ? full : one);
        return full > zero ? simd::vmin(simd::vmax(s, zero), one) : zero;
    };
    ShadowShare out;
    out.channel[0] = share(with.dr, without.dr);
    out.channel[1] = share(with.dg, without.dg);
    out.channel[2] = share(with.db, without.db);
    out.luminance = share(rec709_luminance(with.dr, with.dg, with.db),
                          rec709_luminance(without.dr, without.dg, without.db));
    return out;
}

// Gouraud with shadows: the vertices were lit without shadows, since a
// shadow sampled only at the vertices is as coarse as the mesh (a 6 m pole
// darkening from top to base, a shadow missing from a 4-vertex floor).
// Each pixel takes out, channel by channel, the share of the
// shadow-casting lights' direct light (diffuse and highlight) that its own
// shadow lookups find blocked (the lighting stays per vertex, the shadow
// edge does not). Lights without shadows keep all of theirs.
void shadow_vertex_light(const ShadeInputs& in, const SurfaceSamples& sample, const CornerLanes& c,
                         Batch& b) {
    const ShadowShare share = shadow_share(in, in.shadow_lights, b.lanes.surface);
    for (int a = 0; a < 3; ++a) {
        b.lanes.vertex_diffuse[a] -=
            share.channel[a] * interpolate_corners(sample.bary, c.direct_diffuse, a);
        b.lanes.vertex_specular[a] -=
            share.channel[a] * interpolate_corners(sample.bary, c.direct_specular, a);
    }
}

// The normal the model reads and the G-buffer keeps: the face's for flat
// shading ((p1 - p0) x (p2 - p0)), else the corners' interpolated; turned
// to the viewer. Zero when nothing needs one.
template <bool Plain>
[[gnu::always_inline]] inline void gather_normal(const StyleState& style, const ModelNeeds& needs,
                                                 const SurfaceSamples& sample, const CornerLanes& c,
                                                 Batch& b) {
    vf(&normal)[3] = b.result.normal;
    if (!needs.normal) {
        for (vf& axis : normal) axis = simd::splat(0.0f);
        return;
    }
    if (!Plain && style.model == ShadingModel::flat) {
        vf e1[3], e2[3];
        for (int a = 0; a < 3; ++a) e1[a] = c.p[1][a] - c.p[0][a], e2[a] = c.p[2][a] - c.p[0][a];
        normal[0] = e1[1] * e2[2] - e2[1] * e1[2];
        normal[1] = e1[2] * e2[0] - e2[2] * e1[0];
        normal[2] = e1[0] * e2[1] - e2[0] * e1[1];
    } else {
        for (int a = 0; a < 3; ++a) normal[a] = interpolate_corners(sample.bary, c.n, a);
    }
    const vi facing_away = c.back > simd::splat(0.0f);
    for (int a = 0; a < 3; ++a) normal[a] = facing_away ? -normal[a] : normal[a];
    SurfaceBatch& s = b.lanes.surface;
    s.nx = normal[0], s.ny = normal[1], s.nz = normal[2];
    if (!Plain && style.model == ShadingModel::pbr)
        for (int a = 0; a < 3; ++a) b.lanes.pbr.coat_normal[a] = normal[a];
}

// Positions, normals and Gouraud light interpolated with the lanes'
// barycentrics, and the materials' terms.
template <bool Plain>
[[gnu::always_inline]] inline void gather_vertices(const ShadeInputs& in, const StyleState& style,
                                                   uint32_t style_index, const ModelNeeds& needs,
                                                   const LaneGroup* groups, int group_count,
                                                   const SurfaceSamples& sample, Batch& b) {
    CornerLanes c;
    if (group_count == 1)
        gather_groups<Plain, true>(in, style, style_index, needs, groups, group_count, b, c);
    else
        gather_groups<Plain, false>(in, style, style_index, needs, groups, group_count, b, c);
    gather_normal<Plain>(style, needs, sample, c, b);
    SurfaceBatch& s = b.lanes.surface;
    if (needs.position) {
        s.px = interpolate_corners(sample.bary, c.p, 0);
        s.py = interpolate_corners(sample.bary, c.p, 1);
        s.pz = interpolate_corners(sample.bary, c.p, 2);
    }
    b.lanes.depth = sample.w;
    if (!needs.vertex_light) return;
    for (int a = 0; a < 3; ++a) {
        b.lanes.vertex_diffuse[a] = interpolate_corners(sample.bary, c.diffuse, a);
        b.lanes.vertex_specular[a] = interpolate_corners(sample.bary, c.specular, a);
    }
    if (!in.vertices.direct.empty()) shadow_vertex_light(in, sample, c, b);
}

// The depth of the nearest sample of a pixel of side x side samples centred
// on (x, y): the least of the samples' depths on the lane's triangle, each
// from its 1/w plane as reconstruct_surfaces computes it.
[[gnu::always_inline]] inline vf nearest_depth(const SetupLanes& s, vf x, vf y, int side) {
    vf nearest = simd::splat(INFINITY);
    const float first = 0.5f - 0.5f * static_cast<float>(side);
    for (int sy = 0; sy < side; ++sy)
        for (int sx = 0; sx < side; ++sx) {
            const vf fx = (x + (first + static_cast<float>(sx))) - s.x0;
            const vf fy = (y + (first + static_cast<float>(sy))) - s.y0;
            nearest = simd::vmin(nearest, 1.0f / (s.inv_w[0] + s.inv_w[1] * fx + s.inv_w[2] * fy));
        }
    return nearest;
}

// One lane's surface sample with derivatives per output pixel (k samples):
// shading happens once per pixel, so footprints are a pixel's.
SurfaceSample pixel_sample(const Batch& b, int lane, int side) {
    SurfaceSample s = surface_lane(b.sample, lane, *b.setup[lane]);
    const float k = static_cast<float>(side);
    s.ddx *= k;
    s.ddy *= k;
    return s;
}

// The corners' texture coordinates of each lane's triangle, in `slot`'s
// set and tiling: World::corner_uvs over lanes. Lanes outside `lanes`
// repeat the first of them.
UvLanes corner_uv_lanes(const World& world, const Batch& b, const TextureSlot& slot,
                        unsigned lanes) {
    const std::vector<glm::vec2>& set = world.uv_set(slot);
    const int first = __builtin_ctz(lanes);
    UvLanes c;
    for (int i = 0; i < simd::kLanes; ++i) {
        const int lane = (lanes >> i) & 1 ? i : first;
        const uint32_t* corner =
            &world.indices[3 * static_cast<size_t>(b.setup[lane]->source_triangle)];
        for (int k = 0; k < 3; ++k) {
            c.u[k][i] = set[corner[k]].x;
            c.v[k][i] = set[corner[k]].y;
        }
    }
    if (!slot.transform.identity())
        for (int k = 0; k < 3; ++k) slot.transform.apply(c.u[k], c.v[k]);
    return c;
}

// The texture lookups of shade/material_terms.hpp: each lane's texture
// `slot_of(lane)` (null: none) with the lane's pixel footprint (shading
// happens once per pixel of k x k samples), the lanes that share a slot
// together; `use(lane, texel)` takes each. The coordinates are found over
// the lanes; the filtered lookups, one lane at a time.
struct TextureLookups {
    const ShadeInputs& in;
    const Batch& b;

    template <typename SlotOf, typename Use>
    void operator()(SlotOf&& slot_of, Use&& use) const {
        unsigned todo = 0;
        for (int i = 0; i < b.count; ++i)
            if (slot_of(i)) todo |= 1u << i;
        if (todo == 0) return;
        const float k = static_cast<float>(in.samples_per_side);
        const SurfaceSamples& s = b.sample;
        const FootprintLanes footprint{s.bary[1],    s.bary[2],    s.ddx[1] * k,
                                       s.ddx[2] * k, s.ddy[1] * k, s.ddy[2] * k};
        while (todo) {
            const TextureSlot* slot = slot_of(__builtin_ctz(todo));
            unsigned mine = 0;
            for (int i = 0; i < b.count; ++i)
                if ((todo >> i) & 1 && slot_of(i) == slot) mine |= 1u << i;
            const Texture& texture = *slot->texture;
            const TextureLookupLanes t =
                texture_lookups(corner_uv_lanes(in.world, b, *slot, mine), footprint,
                                glm::vec2(texture.width, texture.height));
            for (int i = 0; i < b.count; ++i)
                if ((mine >> i) & 1) use(i, texture.sample(t.at(i)));
            todo &= ~mine;
        }
    }
};

// The lane's interpolated vertex normal on its triangle's front side, unit:
// the normal the tangent frames are built about.
glm::vec3 front_normal(const Batch& b, int i, const SurfaceSample& pixel) {
    const vf(&normal)[3] = b.result.normal;
    const glm::vec3 shown(normal[0][i], normal[1][i], normal[2][i]);
    return normalise_or(pixel.back_facing ? -shown : shown, glm::vec3(0, 1, 0));
}

// kNormalMaps: the maps' normals in the tangent frame the vertices carry
// (shade/normal_map.hpp). The G-buffer's normal (outlines, occlusion, the
// normal pass) turns with the base's.
void apply_normal_maps(const ShadeInputs& in, Batch& b) {
    vf(&normal)[3] = b.result.normal;
    auto normal_at = [&](int i, const TextureSlot& map, float scale) -> std::optional<glm::vec3> {
        if (!draws_normal_map(in.world, in.vertices, map, b.setup[i]->source_triangle))
            return std::nullopt;
        const SurfaceSample pixel = pixel_sample(b, i, in.samples_per_side);
        return normal_from_map(in.world, in.vertices, map, scale, pixel, front_normal(b, i, pixel));
    };
    SurfaceBatch& s = b.lanes.surface;
    facet::apply_normal_maps(
        b.material, b.count, normal_at,
        [&](int i, const glm::vec3& n) {
            for (int a = 0; a < 3; ++a) normal[a][i] = n[a];
            s.nx[i] = n.x, s.ny[i] = n.y, s.nz[i] = n.z;
        },
        [&](int i, const glm::vec3& n) {
            for (int a = 0; a < 3; ++a) b.lanes.pbr.coat_normal[a][i] = n[a];
        });
}

// kExtraLobes' anisotropy (shade/material_terms.hpp): its direction in
// the tangent frame the vertices carry, as the normal map's, so it is
// worked out before the normal maps turn the normal.
void apply_anisotropy(const ShadeInputs& in, const TextureLookups& lookup, Batch& b) {
    const auto to_mesh_frame = [](const glm::vec3& texel, const TextureSlot& slot) {
        return texel_in_mesh_frame(texel, slot.transform);
    };
    const auto to_world = [&](int i, const glm::vec2& in_frame) -> std::optional<glm::vec3> {
        if (!has_tangent_frames(in.world, in.vertices, b.setup[i]->source_triangle))
            return std::nullopt;
        const SurfaceSample pixel = pixel_sample(b, i, in.samples_per_side);
        return anisotropy_direction(in.world, in.vertices, in_frame, pixel,
                                    front_normal(b, i, pixel));
    };
    facet::apply_anisotropy(b.material, b.count, lookup, to_mesh_frame, to_world, b.lanes);
}

// kVertexColors: they multiply the albedo, lane by lane.
void apply_vertex_colors(const ShadeInputs& in, Batch& b) {
    for (int i = 0; i < b.count; ++i) {
        if (!b.has_colors[i]) continue;
        const uint32_t* c = &in.world.indices[3 * static_cast<size_t>(b.setup[i]->source_triangle)];
        const glm::vec3 color = b.sample.bary[0][i] * in.world.colors[c[0]] +
                                b.sample.bary[1][i] * in.world.colors[c[1]] +
                                b.sample.bary[2][i] * in.world.colors[c[2]];
        for (int a = 0; a < 3; ++a) b.lanes.albedo[a][i] *= color[a];
    }
}

// Under `pbr`, the light the environment gives a white matte surface at
// each lane (its diffuse radiance times the intensity): what lights a
// shadow catcher's shadow, which the lights' shadow maps do not block.
// False, and nothing written, without an environment.
bool environment_diffuse(const ShadeInputs& in, const StyleState& style, const SurfaceBatch& s,
                         vf (&out)[3]) {
    const EnvironmentLighting& e = in.frame.environment;
    if (style.model != ShadingModel::pbr || !e.map || !(e.intensity > 0.0f)) return false;
    const lanes::Vec3<vf> n = lanes::normalise_or<vf>(
        {s.nx, s.ny, s.nz}, {simd::splat(0.0f), simd::splat(1.0f), simd::splat(0.0f)});
    vf turned[3];
    e.to_map({n[0], n[1], n[2]}, turned);
    e.map->diffuse(turned, out);
    for (vf& channel : out) channel *= e.intensity;
    return true;
}

// The light no shadow map blocks at a shadow catcher, in the units of
// shadow_share's direct light (a white surface's n.l times the lights'
// radiance): the same rule for every model that draws shadows. Under
// `pbr`, the environment's diffuse light and the ambient lights (a uniform
// environment there). Under the Phong family, the ambient term the model
// gives the catcher, ka times the ambient light (white 1 without ambient
// lights), over its kd, since shadow_share weighs the lights by 1 where
// the model weighs them by kd.
void unshadowed_light(const ShadeInputs& in, const StyleState& style, const Batch& b,
                      vf (&out)[3]) {
    for (vf& channel : out) channel = simd::splat(0.0f);
    if (style.model == ShadingModel::pbr) {
        environment_diffuse(in, style, b.lanes.surface, out);
        glm::vec3 ambient(0.0f);
        for (const ShadeLight& light : in.lights)
            if (light.is_ambient) ambient += light.radiance;
        for (int a = 0; a < 3; ++a) out[a] += ambient[a];
        return;
    }
    const glm::vec3 ambient = ambient_light(in.lights);
    const vf ratio = ambient_over_diffuse(b.material, b.count);
    for (int a = 0; a < 3; ++a) out[a] = ratio * ambient[a];
}

// kShadowCatcher: the share of the light the shadows take at each point,
// from the same lights lit twice, with and without their shadow maps, and
// compared by the diffuse light's luminance. The lane then shows the
// background darkened by that share, which covers it by as much. Only the
// lit models and Gouraud know positions and normals; with the others
// nothing shows.
void apply_shadow_catchers(const ShadeInputs& in, uint32_t style_index, Batch& b) {
    const StyleState& style = in.frame.styles[style_index];
    const glm::vec4 background = in.frame.background;
    vf unshadowed[3];
    unshadowed_light(in, style, b, unshadowed);
    const vf share = in.frame.style_needs[style_index].position
                         ? shadow_share(in, in.lights, b.lanes.surface, unshadowed).luminance
                         : simd::splat(0.0f);
    ShadeResult& r = b.result;
    for (int i = 0; i < b.count; ++i) {
        if (!(b.features[i] & kShadowCatcher)) continue;
        for (int a = 0; a < 3; ++a) r.color[a][i] = background[a] * (1.0f - share[i]);
        r.coverage[i] = share[i];
        // No lines of its own: no wireframe, and no object in the G-buffer
        // (outlines read it as background; post/outlines.hpp).
        r.wire[i] = 0.0f;
        r.object[i] = kNoObject;
    }
}

// kFade: the colour goes to the background, and the coverage with it, by
// the distance of the point from its object's origin (model space, at rest).
void apply_fades(const ShadeInputs& in, Batch& b) {
    const glm::vec4 background = in.frame.background;
    ShadeResult& r = b.result;
    for (int i = 0; i < b.count; ++i) {
        if (!(b.features[i] & kFade)) continue;
        const uint32_t* c = &in.world.indices[3 * static_cast<size_t>(b.setup[i]->source_triangle)];
        const glm::vec3 p = b.sample.bary[0][i] * in.world.positions[c[0]] +
                            b.sample.bary[1][i] * in.world.positions[c[1]] +
                            b.sample.bary[2][i] * in.world.positions[c[2]];
        const float kept = fade_kept(*b.material[i], glm::length(p));
        for (int a = 0; a < 3; ++a)
            r.color[a][i] = background[a] + (r.color[a][i] - background[a]) * kept;
        r.coverage[i] *= kept;
    }
}

// What the layers need, lane by lane: wire coverage, and (after shading,
// from `shaded`) where to read the strokes and the paper. Lanes whose tone
// draws no strokes skip the strokes' footprint; only pencil reads paper.
void layer_inputs(const ShadeInputs& in, const StyleState& style, const Batch& b,
                  const ShadedLanes* shaded, LayerInputs (&out)[kLanes]) {
    const int side = in.samples_per_side;
    for (int i = 0; i < b.count; ++i) {
        LayerInputs& l = out[i];
        l.albedo = b.lanes.albedo_at(i);
        l.wire = 0.0f;
        l.hatch.count = 0;
        l.paper.count = 0;
        l.hatch_tone = 1.0f;
        const SurfaceSample s = pixel_sample(b, i, side);
        if (style.wireframe && !in.edge_mask.empty())
            l.wire = wire_coverage(edge_distances(s.bary, s.ddx, s.ddy), style.wire.width,
                                   in.edge_mask[s.triangle]);
        if (!style.hatching || !shaded) continue;
        const HatchingState& h = *style.hatching;
        l.hatch_tone = hatch_tone(style, shaded->color_at(i), shaded->palette_tone[i]);
        const bool strokes = h.strength > 0.0f && l.hatch_tone < 1.0f;
        if (!strokes && !h.pencil) continue;
        // pixel_sample's derivatives are per output pixel already.
        const glm::vec2 at = glm::vec2(b.request.x[i], b.request.y[i]) / static_cast<float>(side);
        const HatchPoint point{s.triangle, s.bary, s.ddx, s.ddy, at, b.has_uvs[i]};
        hatch_footprints(in.world, h, point, strokes ? &l.hatch : nullptr,
                         h.pencil ? &l.paper : nullptr);
    }
}

// The colours of a style with layers (or lines alone), lane by lane.
void finish_layers(const ShadeInputs& in, const StyleState& style, const ShadingContext& context,
                   Batch& b) {
    LayerInputs layers[kLanes];
    ShadeResult& r = b.result;
    const bool lines_alone = style.wireframe && !style.wire_fill_shading;  // on a flat fill
    ShadedLanes shaded;
    if (!lines_alone) shade_lanes(style, context, b.lanes, shaded);
    layer_inputs(in, style, b, lines_alone ? nullptr : &shaded, layers);
    if (b.request.want_wire && style.wireframe) {
        for (int i = 0; i < b.count; ++i) r.wire[i] = layers[i].wire;
        r.wire_color = style.wire.color;
    }
    for (int i = 0; i < b.count; ++i) {
        const glm::vec3 c =
            lines_alone ? style.wire_fill + (style.wire.color - style.wire_fill) * layers[i].wire
                        : apply_layers(style, shaded.color_at(i), layers[i]);
        for (int a = 0; a < 3; ++a) r.color[a][i] = c[a];
    }
}

// The features of the batch's draws: the OR of each group's draw's set.
uint32_t batch_features(const ShadeInputs& in, uint32_t style, const Batch& b,
                        const LaneGroup* groups, int group_count) {
    const World& world = in.world;
    const uint32_t* row = &in.frame.draw_features[style * world.draws.size()];
    uint32_t features = 0;
    for (int g = 0; g < group_count; ++g)
        features |= row[world.triangle_draw[b.setup[groups[g].lane]->source_triangle]];
    return features;
}

// The surface path. `Plain` compiles out every feature's step, the layers
// and the lines pass (the caller checks the batch needs none of them), so
// that the common batch does no work for them and asks no lane about them:
// a GL programmer compiles them out of the shader the same way
// (docs/performance.md). Both instantiations run the same operations in
// the same order, so a batch gets the same bits from either
// (tests/test_shade_plain.cpp).
template <bool Plain>
[[gnu::always_inline]] inline void shade_surface(const ShadeInputs& in, uint32_t style_index,
                                                 const LaneGroup* groups, int group_count,
                                                 const SetupLanes& setup, uint32_t features,
                                                 Batch& b) {
    const StyleState& style = in.frame.styles[style_index];
    const ShadeRequest& request = b.request;
    ShadeResult& r = b.result;
    // A local, so that the plain path computes only what it reads (the
    // derivatives are the textures' and the layers').
    const SurfaceSamples sample = reconstruct_surfaces(setup, request.x, request.y);
    if constexpr (!Plain) b.sample = sample;
    r.depth = sample.w;
    r.pixel_depth = request.pixel_side > 0
                        ? nearest_depth(setup, request.x, request.y, request.pixel_side)
                        : sample.w;
    std::fill(r.wire, r.wire + kLanes, 0.0f);
    r.wire_color = glm::vec3(0.0f);
    b.lanes.count = b.count;
    ModelNeeds needs = in.frame.style_needs[style_index];
    needs.normal = needs.normal || request.want_normal;
    if constexpr (Plain) needs.vertex_light = false;  // the plain models light no vertices
    needs.extra_lobes = !Plain && (features & kExtraLobes);
    gather_vertices<Plain>(in, style, style_index, needs, groups, group_count, sample, b);
    const TextureLookups lookup{in, b};
    if (!Plain && (features & kBaseColorMap)) apply_base_color_maps(b.material, lookup, b.lanes);
    if (!Plain && (features & kVertexColors)) apply_vertex_colors(in, b);
    if (!Plain && (features & kMetalRough))
        apply_metal_rough_reading(b.material, b.features, b.count, lookup, b.lanes);
    if (!Plain && (features & kPhysicalMaps))
        apply_physical_maps(b.material, b.count, lookup, b.lanes);
    if (!Plain && (features & kExtraLobes)) apply_anisotropy(in, lookup, b);
    if (!Plain && (features & kNormalMaps)) apply_normal_maps(in, b);
    const ShadingContext context{in.frame.camera.position, in.lights, in.frame.style_depth_range,
                                 &in.frame.environment, in.backdrop};
    if (!Plain && has_layers(style)) {
        finish_layers(in, style, context, b);
    } else {
        ShadedLanes shaded;
        if (Plain)
            shade_plain_model(style, context, b.lanes, shaded);
        else
            shade_lanes(style, context, b.lanes, shaded);
        for (int a = 0; a < 3; ++a) r.color[a] = shaded.color[a];
    }
    if (!Plain && (features & kEmission))
        add_emission(b.material, b.count, lookup, b.lanes.albedo, r.color);
    r.coverage = simd::splat(1.0f);
    if (!Plain && (features & kShadowCatcher)) apply_shadow_catchers(in, style_index, b);
    if (!Plain && (features & kFade)) apply_fades(in, b);
}

// The general instantiation as a function of its own, so that the compiler
// shares no work between it and the plain one inlined in shade_batch: the
// plain one then computes only what it reads (not the derivatives that
// textures and layers need).
[[gnu::noinline]] void shade_general(const ShadeInputs& in, uint32_t style_index,
                                     const LaneGroup* groups, int group_count,
                                     const SetupLanes& setup, uint32_t features, Batch& b) {
    shade_surface<false>(in, style_index, groups, group_count, setup, features, b);
}

}  // namespace

bool shade_batch(const ShadeInputs& in, const Rasterizer& raster, uint32_t style,
                 const ShadeRequest& request, ShadeResult& result) {
    Batch b(request, result);
    LaneGroup groups[kLanes];
    const int group_count = group_lanes(request.id, groups);
    if (group_count == 1)
        std::fill(b.setup, b.setup + kLanes, &raster.shade_setup(request.id[0]));
    else
        for (int i = 0; i < kLanes; ++i) b.setup[i] = &raster.shade_setup(request.id[i]);
    SetupLanes setup = splat_setup(*b.setup[0]);
    for (int g = 1; g < group_count; ++g)
        select_setup(setup, groups[g].mask, *b.setup[groups[g].lane]);
    const uint32_t features = batch_features(in, style, b, groups, group_count);
    const bool plain = in.paths == ShadingPaths::specialised && features == 0 &&
                       !request.want_wire && in.frame.style_plain[style];
    if (plain)
        shade_surface<true>(in, style, groups, group_count, setup, features, b);
    else
        shade_general(in, style, groups, group_count, setup, features, b);
    return plain;
}

}  // namespace facet
