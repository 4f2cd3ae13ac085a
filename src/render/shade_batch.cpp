#include "render/shade_batch.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <glm/geometric.hpp>

#include "core/color.hpp"
#include "render/hatch_charts.hpp"
#include "render/normal_map_lookup.hpp"
#include "shade/brdf.hpp"
#include "shade/environment_map.hpp"
#include "shade/layers.hpp"
#include "shade/lighting_batch.hpp"
#include "shade/model_phong.hpp"
#include "shade/model_unlit.hpp"
#include "shade/style_math.hpp"
#include "shade/texture_lod.hpp"
#include "shade/wireframe.hpp"

namespace facet {
namespace {

using simd::kLanes;
using simd::vf;
using simd::vi;

// What a style's model reads besides the barycentrics and the albedo.
struct Needs {
    bool position, normal, light_terms, vertex_light;
};

Needs needs_of(const StyleState& style, bool gbuffer_normal) {
    const ShadingModel m = style.model;
    const bool lit = m == ShadingModel::flat || m == ShadingModel::phong ||
                     m == ShadingModel::blinn_phong || m == ShadingModel::palette ||
                     m == ShadingModel::gooch || m == ShadingModel::toon || m == ShadingModel::pbr;
    // Gouraud lights the vertices, but looks up shadows per pixel, which
    // needs the pixel's position and normal.
    const bool gouraud = m == ShadingModel::gouraud;
    return {lit || gouraud, lit || gouraud || m == ShadingModel::normal || gbuffer_normal, lit,
            gouraud};
}

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

// A value from one group's triangle: splatted for the first group, then
// selected into each further group's lanes. With one group (the usual case)
// `Single` leaves out the selects.
template <bool Single>
[[gnu::always_inline]] inline void put(vf& v, vi mask, float value, bool first) {
    if (Single || first)
        v = simd::splat(value);
    else
        v = mask ? simd::splat(value) : v;
}

// The `pbr` model's terms of a material (shade/model_pbr.hpp): the
// dielectric's reflectances from its ior and KHR_materials_specular
// (f0 = min(f0(ior) * colour, 1) * weight, f90 = weight), no occlusion yet.
template <bool Single>
[[gnu::always_inline]] inline void put_physical_terms(const Material& m, vi mask, bool first,
                                                      PbrLanes& p) {
    put<Single>(p.metallic, mask, m.metallic, first);
    put<Single>(p.roughness, mask, m.roughness, first);
    put<Single>(p.occlusion, mask, 1.0f, first);
    const float f0 = pbr::f0_from_ior(m.ior);
    for (int a = 0; a < 3; ++a)
        put<Single>(p.f0[a], mask, std::min(f0 * m.specular_color[a], 1.0f) * m.specular_weight,
                    first);
    put<Single>(p.f90, mask, m.specular_weight, first);
    put<Single>(p.clearcoat, mask, m.clearcoat, first);
    put<Single>(p.clearcoat_roughness, mask, m.clearcoat_roughness, first);
}

// The corners' positions, normals and Gouraud light, and the material's
// terms, of each group's triangle, as lanes.
struct CornerLanes {
    vf p[3][3], n[3][3], diffuse[3][3], specular[3][3];  // [corner][axis]
    // Gouraud with shadows: the shadow-casting lights' direct light.
    vf direct_diffuse[3][3], direct_specular[3][3];
    vf back{};  // every group sets it; zero for the compiler's sake
};

// One group's triangle's corner positions and normals (each when asked)
// and which side the viewer sees, into `c`'s lanes.
template <bool Single>
[[gnu::always_inline]] inline void put_corners(const ShadeInputs& in, const ShadeSetup& setup,
                                               vi mask, bool first, bool positions, bool normals,
                                               CornerLanes& c) {
    const TransformedVertices& v = in.vertices;
    const uint32_t* corners = &in.world.indices[3 * static_cast<size_t>(setup.source_triangle)];
    for (int k = 0; k < 3; ++k)
        for (int a = 0; a < 3; ++a) {
            if (positions) put<Single>(c.p[k][a], mask, v.world_position[corners[k]][a], first);
            if (normals) put<Single>(c.n[k][a], mask, v.world_normal[corners[k]][a], first);
        }
    put<Single>(c.back, mask, setup.back_facing ? 1.0f : 0.0f, first);
}

// Axis `a` of a corner attribute at the lanes' barycentrics.
[[gnu::always_inline]] inline vf interpolate_corners(const vf (&bary)[3], const vf (&corner)[3][3],
                                                     int a) {
    return bary[0] * corner[0][a] + bary[1] * corner[1][a] + bary[2] * corner[2][a];
}

// A normal of the triangle's front turned to the side the viewer sees.
[[gnu::always_inline]] inline void turn_to_viewer(const CornerLanes& c, vf (&normal)[3]) {
    const vi facing_away = c.back > simd::splat(0.0f);
    for (int a = 0; a < 3; ++a) normal[a] = facing_away ? -normal[a] : normal[a];
}

template <bool Single>
[[gnu::always_inline]] inline void gather_groups(const ShadeInputs& in, const StyleState& style,
                                                 const Needs& needs, const LaneGroup* groups,
                                                 int group_count, ShadeBatch& b, CornerLanes& c) {
    const World& world = in.world;
    const TransformedVertices& v = in.vertices;
    const bool flat = style.model == ShadingModel::flat;
    SurfaceBatch& s = b.lanes.surface;
    for (int g = 0; g < group_count; ++g) {
        const bool first = g == 0;
        const vi mask = groups[g].mask;
        const ShadeSetup& setup = *b.setup[groups[g].lane];
        put_corners<Single>(in, setup, mask, first, needs.position || flat, needs.normal && !flat,
                            c);
        const uint32_t* corners = &world.indices[3 * static_cast<size_t>(setup.source_triangle)];
        if (needs.vertex_light)
            for (int k = 0; k < 3; ++k)
                for (int a = 0; a < 3; ++a) {
                    put<Single>(c.diffuse[k][a], mask, v.lit[corners[k]].diffuse[a], first);
                    put<Single>(c.specular[k][a], mask, v.lit[corners[k]].specular[a], first);
                    if (!v.direct.empty()) {
                        const LightingResult& d = v.direct[corners[k]];
                        put<Single>(c.direct_diffuse[k][a], mask, d.diffuse[a], first);
                        put<Single>(c.direct_specular[k][a], mask, d.specular[a], first);
                    }
                }
        const Draw& draw = world.draws[world.triangle_draw[setup.source_triangle]];
        const Material& m = in.frame.materials[draw.material];
        if (needs.light_terms) {
            put<Single>(s.ambient, mask, m.ambient, first);
            put<Single>(s.diffuse, mask, m.diffuse, first);
            put<Single>(s.specular, mask, m.specular, first);
            put<Single>(s.shininess, mask, m.shininess, first);
        }
        if (needs.position)
            put<Single>(s.receives_shadow, mask, world.receives_shadows[draw.object], first);
        if (style.model == ShadingModel::pbr)
            put_physical_terms<Single>(m, mask, first, b.lanes.pbr);
        for (int a = 0; a < 3; ++a)
            put<Single>(b.lanes.albedo[a], mask,
                        style.base_color ? (*style.base_color)[a] : m.color[a], first);
        const unsigned lanes = Single ? 0xffu : simd::movemask(mask);
        for (int lane = 0; lane < kLanes; ++lane)
            if ((lanes >> lane) & 1) {
                b.object[lane] = draw.object;
                b.material[lane] = &m;
                b.has_uvs[lane] = draw.has_uvs;
                b.has_colors[lane] = draw.has_colors;
            }
        b.any_texture = b.any_texture || m.base_color_map;
        b.any_physical_map = b.any_physical_map || m.metal_rough_map || m.occlusion_map ||
                             m.normal_map || m.clearcoat_normal_map || m.specular_weight_map ||
                             m.specular_color_map || m.clearcoat_map || m.clearcoat_roughness_map;
        b.any_vertex_colors = b.any_vertex_colors || draw.has_colors;
        b.any_emission = b.any_emission || m.unlit || m.emissive != glm::vec3(0);
        b.any_shadow_catcher = b.any_shadow_catcher || m.shadow_catcher;
        b.any_fade = b.any_fade || m.fade_end > m.fade_start;
    }
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
template <typename Interpolate>
void shadow_vertex_light(const ShadeInputs& in, const CornerLanes& c, Interpolate&& interpolate,
                         ShadeBatch& b) {
    const ShadowShare share = shadow_share(in, in.shadow_lights, b.lanes.surface);
    for (int a = 0; a < 3; ++a) {
        b.lanes.vertex_diffuse[a] -= share.channel[a] * interpolate(c.direct_diffuse, a);
        b.lanes.vertex_specular[a] -= share.channel[a] * interpolate(c.direct_specular, a);
    }
}

// Positions, normals and Gouraud light interpolated with the lanes'
// barycentrics; normals turned to the viewer.
[[gnu::always_inline]] inline void gather_vertices(const ShadeInputs& in, const StyleState& style,
                                                   const Needs& needs, const LaneGroup* groups,
                                                   int group_count, ShadeBatch& b) {
    CornerLanes c;
    b.any_texture = b.any_vertex_colors = b.any_emission = b.any_shadow_catcher = false;
    b.any_physical_map = false;
    b.any_fade = false;
    if (group_count == 1)
        gather_groups<true>(in, style, needs, groups, group_count, b, c);
    else
        gather_groups<false>(in, style, needs, groups, group_count, b, c);
    auto interpolate = [&](const vf(&corner)[3][3], int a) {
        return interpolate_corners(b.sample.bary, corner, a);
    };
    SurfaceBatch& s = b.lanes.surface;
    if (style.model == ShadingModel::flat) {  // the face normal: (p1 - p0) x (p2 - p0)
        vf e1[3], e2[3];
        for (int a = 0; a < 3; ++a) e1[a] = c.p[1][a] - c.p[0][a], e2[a] = c.p[2][a] - c.p[0][a];
        b.normal[0] = e1[1] * e2[2] - e2[1] * e1[2];
        b.normal[1] = e1[2] * e2[0] - e2[2] * e1[0];
        b.normal[2] = e1[0] * e2[1] - e2[0] * e1[1];
    } else if (needs.normal) {
        for (int a = 0; a < 3; ++a) b.normal[a] = interpolate(c.n, a);
    }
    if (needs.normal) {
        turn_to_viewer(c, b.normal);
        s.nx = b.normal[0], s.ny = b.normal[1], s.nz = b.normal[2];
        if (style.model == ShadingModel::pbr)
            for (int a = 0; a < 3; ++a) b.lanes.pbr.coat_normal[a] = b.normal[a];
    }
    if (needs.position)
        s.px = interpolate(c.p, 0), s.py = interpolate(c.p, 1), s.pz = interpolate(c.p, 2);
    b.lanes.depth = b.sample.w;
    if (needs.vertex_light) {
        for (int a = 0; a < 3; ++a) {
            b.lanes.vertex_diffuse[a] = interpolate(c.diffuse, a);
            b.lanes.vertex_specular[a] = interpolate(c.specular, a);
        }
        if (!in.vertices.direct.empty()) shadow_vertex_light(in, c, interpolate, b);
    }
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
SurfaceSample pixel_sample(const ShadeBatch& b, int lane, int side) {
    SurfaceSample s = surface_lane(b.sample, lane, *b.setup[lane]);
    const float k = static_cast<float>(side);
    s.ddx *= k;
    s.ddy *= k;
    return s;
}

// The corners' texture coordinates of each lane's triangle, in `slot`'s
// set and tiling: World::corner_uvs over lanes. Lanes outside `lanes`
// repeat the first of them.
UvLanes corner_uv_lanes(const World& world, const ShadeBatch& b, const TextureSlot& slot,
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

// Looks up each lane's texture `slot_of(lane)` (null: none) with the
// lane's pixel footprint (shading happens once per pixel of k x k samples),
// the lanes that share a slot together; `use(lane, texel)` takes each.
// The coordinates are found over the lanes; the filtered lookups, one lane
// at a time.
template <typename SlotOf, typename Use>
void sample_slots(const ShadeInputs& in, const ShadeBatch& b, SlotOf slot_of, Use use) {
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
            if ((mine >> i) & 1) use(i, texture.sample(glm::vec2(t.u[i], t.v[i]), t.lod[i]));
        todo &= ~mine;
    }
}

// A material texture slot of each lane, for sample_slots.
template <typename Slot>
auto slot_of(const ShadeBatch& b, Slot slot) {
    return [&b, slot](int lane) -> const TextureSlot* {
        const TextureSlot& t = b.material[lane]->*slot;
        return t ? &t : nullptr;
    };
}

void apply_textures(const ShadeInputs& in, ShadeBatch& b) {
    sample_slots(in, b, slot_of(b, &Material::base_color_map), [&](int i, const glm::vec4& texel) {
        for (int a = 0; a < 3; ++a) b.lanes.albedo[a][i] *= texel[a];
    });
}

// The `pbr` model's maps (glTF 2.0 §3.9): metallic-roughness (B metal, G
// roughness), occlusion (R, blended by its strength), KHR_materials_specular
// (A weight, RGB colour) and clearcoat (R strength, G roughness), each
// multiplying its factor.
void apply_physical_maps(const ShadeInputs& in, ShadeBatch& b) {
    PbrLanes& p = b.lanes.pbr;
    sample_slots(in, b, slot_of(b, &Material::metal_rough_map), [&](int i, const glm::vec4& t) {
        p.roughness[i] *= t.g;
        p.metallic[i] *= t.b;
    });
    sample_slots(in, b, slot_of(b, &Material::occlusion_map), [&](int i, const glm::vec4& t) {
        p.occlusion[i] = 1.0f + b.material[i]->occlusion_strength * (t.r - 1.0f);
    });
    float weight[simd::kLanes], tint[3][simd::kLanes];
    std::fill(weight, weight + simd::kLanes, 1.0f);
    std::fill(&tint[0][0], &tint[0][0] + 3 * simd::kLanes, 1.0f);
    sample_slots(in, b, slot_of(b, &Material::specular_weight_map),
                 [&](int i, const glm::vec4& t) { weight[i] = t.a; });
    sample_slots(in, b, slot_of(b, &Material::specular_color_map), [&](int i, const glm::vec4& t) {
        for (int a = 0; a < 3; ++a) tint[a][i] = t[a];
    });
    for (int i = 0; i < b.count; ++i) {
        const Material& m = *b.material[i];
        if (!m.specular_weight_map && !m.specular_color_map) continue;
        const float f0 = pbr::f0_from_ior(m.ior);
        for (int a = 0; a < 3; ++a)
            p.f0[a][i] = std::min(f0 * m.specular_color[a] * tint[a][i], 1.0f) * m.specular_weight *
                         weight[i];
        p.f90[i] = m.specular_weight * weight[i];
    }
    sample_slots(in, b, slot_of(b, &Material::clearcoat_map),
                 [&](int i, const glm::vec4& t) { p.clearcoat[i] *= t.r; });
    sample_slots(in, b, slot_of(b, &Material::clearcoat_roughness_map),
                 [&](int i, const glm::vec4& t) { p.clearcoat_roughness[i] *= t.g; });
}

// Normal maps turn the shading normal, lane by lane, in the tangent frame
// the vertices carry (shade/normal_map.hpp). The G-buffer's normal (outlines,
// occlusion, the normal pass) turns with it. A clear coat's own map turns
// the coat's normal from the same unmapped normal: its relief is not the base's.
void apply_normal_maps(const ShadeInputs& in, ShadeBatch& b) {
    SurfaceBatch& s = b.lanes.surface;
    for (int i = 0; i < b.count; ++i) {
        const Material& m = *b.material[i];
        const uint32_t triangle = b.setup[i]->source_triangle;
        const bool base = draws_normal_map(in.world, in.vertices, m.normal_map, triangle);
        const bool coat = m.clearcoat > 0.0f &&
                          draws_normal_map(in.world, in.vertices, m.clearcoat_normal_map, triangle);
        if (!base && !coat) continue;
        const SurfaceSample pixel = pixel_sample(b, i, in.samples_per_side);
        const glm::vec3 shown(b.normal[0][i], b.normal[1][i], b.normal[2][i]);
        const glm::vec3 front =
            normalise_or(pixel.back_facing ? -shown : shown, glm::vec3(0, 1, 0));
        if (coat) {
            const glm::vec3 n = normal_from_map(in.world, in.vertices, m.clearcoat_normal_map,
                                                m.clearcoat_normal_scale, pixel, front);
            for (int a = 0; a < 3; ++a) b.lanes.pbr.coat_normal[a][i] = n[a];
        }
        if (!base) continue;
        const glm::vec3 n =
            normal_from_map(in.world, in.vertices, m.normal_map, m.normal_scale, pixel, front);
        for (int a = 0; a < 3; ++a) b.normal[a][i] = n[a];
        s.nx[i] = n.x, s.ny[i] = n.y, s.nz[i] = n.z;
    }
}

// Vertex colours multiply the albedo, lane by lane: few meshes have them.
void apply_vertex_colors(const ShadeInputs& in, ShadeBatch& b) {
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
    const vf length = simd::vsqrt(s.nx * s.nx + s.ny * s.ny + s.nz * s.nz);
    const vi ok = length > simd::splat(0.0f);
    const vf inverse = 1.0f / (ok ? length : simd::splat(1.0f));
    const vf n[3] = {ok ? s.nx * inverse : simd::splat(0.0f),
                     ok ? s.ny * inverse : simd::splat(1.0f),
                     ok ? s.nz * inverse : simd::splat(0.0f)};
    vf turned[3];
    e.to_map(n, turned);
    e.map->diffuse(turned, out);
    for (vf& channel : out) channel *= e.intensity;
    return true;
}

// Shadow catchers: the share of the light the shadows take at each point,
// from the same lights lit twice, with and without their shadow maps, and
// compared by the diffuse light's luminance. The lane then shows the
// background darkened by that share, which covers it by as much. Only the
// lit models and Gouraud know positions and normals; with the others
// nothing shows.
void apply_shadow_catchers(const ShadeInputs& in, const StyleState& style, ShadeBatch& b) {
    const glm::vec4 background = in.frame.background;
    vf environment[3];
    const bool lit_by_environment = environment_diffuse(in, style, b.lanes.surface, environment);
    const vf share = needs_of(style, false).position
                         ? shadow_share(in, in.lights, b.lanes.surface,
                                        lit_by_environment ? environment : nullptr)
                               .luminance
                         : simd::splat(0.0f);
    for (int i = 0; i < b.count; ++i) {
        if (!b.material[i]->shadow_catcher) continue;
        for (int a = 0; a < 3; ++a) b.color[a][i] = background[a] * (1.0f - share[i]);
        b.coverage[i] = share[i];
    }
}

// Fading materials: by the distance of the point from the object's origin
// (model space, at rest), the colour goes to the background and the
// coverage with it (smoothstep from fade_start to fade_end), as a shadow
// catcher's does.
void apply_fades(const ShadeInputs& in, ShadeBatch& b) {
    const glm::vec4 background = in.frame.background;
    for (int i = 0; i < b.count; ++i) {
        const Material& m = *b.material[i];
        if (!(m.fade_end > m.fade_start)) continue;
        const uint32_t* c = &in.world.indices[3 * static_cast<size_t>(b.setup[i]->source_triangle)];
        const glm::vec3 p = b.sample.bary[0][i] * in.world.positions[c[0]] +
                            b.sample.bary[1][i] * in.world.positions[c[1]] +
                            b.sample.bary[2][i] * in.world.positions[c[2]];
        const float kept = 1.0f - smoothstep(m.fade_start, m.fade_end, glm::length(p));
        for (int a = 0; a < 3; ++a)
            b.color[a][i] = background[a] + (b.color[a][i] - background[a]) * kept;
        b.coverage[i] *= kept;
    }
}

// Unlit materials show their albedo; emission (its factor times its map)
// adds to what the model made. Only the models that light a surface:
// normal and depth views stay measurements.
void apply_emission(const ShadeInputs& in, const StyleState& style, ShadeBatch& b) {
    if (!needs_of(style, false).light_terms && style.model != ShadingModel::gouraud) return;
    glm::vec3 emitted[simd::kLanes];
    for (int i = 0; i < b.count; ++i) emitted[i] = b.material[i]->emissive;
    sample_slots(
        in, b,
        [&](int i) -> const TextureSlot* {
            const TextureSlot& t = b.material[i]->emissive_map;
            return t && emitted[i] != glm::vec3(0) ? &t : nullptr;
        },
        [&](int i, const glm::vec4& t) { emitted[i] *= glm::vec3(t); });
    for (int i = 0; i < b.count; ++i) {
        const Material& m = *b.material[i];
        for (int a = 0; a < 3; ++a) {
            const float base = m.unlit ? b.lanes.albedo[a][i] : b.color[a][i];
            b.color[a][i] = base + emitted[i][a];
        }
    }
}

// What the layers need, lane by lane: wire coverage, and (after shading,
// from `shaded`) where to read the strokes and the paper. Lanes whose tone
// draws no strokes skip the strokes' footprint; only pencil reads paper.
void layer_inputs(const ShadeInputs& in, const StyleState& style, const ShadeBatch& b,
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
        l.hatch_tone = hatch_tone(style, shaded->color_at(i), l.albedo, shaded->palette_tone[i]);
        const bool strokes = h.strength > 0.0f && l.hatch_tone < 1.0f;
        if (!strokes && !h.pencil) continue;
        // pixel_sample's derivatives are per output pixel already.
        const HatchPoint point{
            s.triangle,  s.bary, s.ddx, s.ddy, glm::vec2(b.x[i], b.y[i]) / static_cast<float>(side),
            b.has_uvs[i]};
        hatch_footprints(in.world, h, point, strokes ? &l.hatch : nullptr,
                         h.pencil ? &l.paper : nullptr);
    }
}

// The colours of a style with layers (or lines alone), lane by lane.
void finish_layers(const ShadeInputs& in, const StyleState& style, const ShadingContext& context,
                   ShadeBatch& b) {
    LayerInputs layers[kLanes];
    if (style.wireframe && !style.wire_fill_shading) {  // lines alone, on a flat fill
        layer_inputs(in, style, b, nullptr, layers);
        if (b.want_wire) {
            for (int i = 0; i < b.count; ++i) b.wire[i] = layers[i].wire;
            b.wire_color = style.wire.color;
        }
        for (int i = 0; i < b.count; ++i) {
            const glm::vec3 c =
                style.wire_fill + (style.wire.color - style.wire_fill) * layers[i].wire;
            for (int a = 0; a < 3; ++a) b.color[a][i] = c[a];
        }
        return;
    }
    ShadedLanes shaded;
    shade_lanes(style, context, b.lanes, shaded);
    layer_inputs(in, style, b, &shaded, layers);
    if (b.want_wire && style.wireframe) {
        for (int i = 0; i < b.count; ++i) b.wire[i] = layers[i].wire;
        b.wire_color = style.wire.color;
    }
    for (int i = 0; i < b.count; ++i) {
        const glm::vec3 c = apply_layers(style, shaded.color_at(i), layers[i]);
        for (int a = 0; a < 3; ++a) b.color[a][i] = c[a];
    }
}

// --- Plain batches: the common case compiled apart ---
//
// Most batches of most scenes show triangles of one mesh whose material
// only its constants colour, under a Phong, Blinn-Phong or unlit style
// without layers. Asking each lane which of the general path's features
// apply (textures, vertex colours, emission, shadow catchers, fades,
// several materials) costs 10-20% of such a frame; a GL programmer
// compiles them out of the shader (docs/performance.md). shade_plain does
// the same operations as the general path in the same order and calls the
// same model (shade_phong, shade_unlit), so it writes the same bits
// (tests/test_shade_plain.cpp).

// takes_plain_path, inlined where each batch asks.
[[gnu::always_inline]] inline bool plain_draw(const StyleState& style, const Draw& draw,
                                              const Material& m) {
    const ShadingModel model = style.model;
    const bool lit = model == ShadingModel::phong || model == ShadingModel::blinn_phong;
    if ((!lit && model != ShadingModel::unlit) || has_layers(style)) return false;
    if (!style.base_color && (m.base_color_map || draw.has_colors)) return false;
    if (m.shadow_catcher || m.fade_end > m.fade_start) return false;
    // The unlit model adds no emission (apply_emission).
    return model == ShadingModel::unlit || !(m.unlit || m.emissive != glm::vec3(0));
}

// The batch shaded if it is plain (all its triangles of one draw, which
// takes_plain_path); false, and nothing written, otherwise.
bool shade_plain(const ShadeInputs& in, const StyleState& style, const LaneGroup* groups,
                 int group_count, const SetupLanes& planes, ShadeBatch& b) {
    if (b.want_wire) return false;
    const World& world = in.world;
    const uint32_t draw_index = world.triangle_draw[b.setup[0]->source_triangle];
    for (int g = 1; g < group_count; ++g)
        if (world.triangle_draw[b.setup[groups[g].lane]->source_triangle] != draw_index)
            return false;
    const Draw& draw = world.draws[draw_index];
    const Material& m = in.frame.materials[draw.material];
    if (!plain_draw(style, draw, m)) return false;

    const bool lit = style.model != ShadingModel::unlit;
    const SurfaceSamples sample = reconstruct_surfaces(planes, b.x, b.y);
    b.sample.w = sample.w;
    if (b.pixel_side > 0) b.pixel_depth = nearest_depth(planes, b.x, b.y, b.pixel_side);
    CornerLanes c;
    const bool normals = lit || b.want_normal;
    if (group_count == 1)
        put_corners<true>(in, *b.setup[0], groups[0].mask, true, lit, normals, c);
    else
        for (int g = 0; g < group_count; ++g)
            put_corners<false>(in, *b.setup[groups[g].lane], groups[g].mask, g == 0, lit, normals,
                               c);
    if (normals) {
        for (int a = 0; a < 3; ++a) b.normal[a] = interpolate_corners(sample.bary, c.n, a);
        turn_to_viewer(c, b.normal);
    }
    std::fill(b.object, b.object + kLanes, draw.object);
    const glm::vec3 albedo = style.base_color ? *style.base_color : m.color;
    SurfaceLanes& lanes = b.lanes;
    lanes.count = b.count;
    for (int a = 0; a < 3; ++a) lanes.albedo[a] = simd::splat(albedo[a]);
    b.coverage = simd::splat(1.0f);
    ShadedLanes shaded;
    if (!lit) {
        shade_unlit(lanes, shaded);
        for (int a = 0; a < 3; ++a) b.color[a] = shaded.color[a];
        return true;
    }
    SurfaceBatch& s = lanes.surface;
    s.px = interpolate_corners(sample.bary, c.p, 0);
    s.py = interpolate_corners(sample.bary, c.p, 1);
    s.pz = interpolate_corners(sample.bary, c.p, 2);
    s.nx = b.normal[0], s.ny = b.normal[1], s.nz = b.normal[2];
    s.ambient = simd::splat(m.ambient);
    s.diffuse = simd::splat(m.diffuse);
    s.specular = simd::splat(m.specular);
    s.shininess = simd::splat(m.shininess);
    s.receives_shadow = simd::splat(world.receives_shadows[draw.object]);
    if (b.count < kLanes) pad_batch(s, b.count);
    const ShadingContext context{in.frame.camera.position, in.lights, in.frame.style_depth_range,
                                 &in.frame.environment};
    shade_phong(lanes, context,
                style.model == ShadingModel::phong ? Highlight::phong : Highlight::blinn, shaded);
    for (int a = 0; a < 3; ++a) b.color[a] = shaded.color[a];
    return true;
}

}  // namespace

bool takes_plain_path(const StyleState& style, const Draw& draw, const Material& m) {
    return plain_draw(style, draw, m);
}

bool shade_batch(const ShadeInputs& in, const Rasterizer& raster, uint32_t style_index,
                 ShadeBatch& b) {
    const StyleState& style = in.frame.styles[style_index];
    LaneGroup groups[kLanes];
    const int group_count = group_lanes(b.id, groups);
    if (group_count == 1)
        std::fill(b.setup, b.setup + kLanes, &raster.shade_setup(b.id[0]));
    else
        for (int i = 0; i < kLanes; ++i) b.setup[i] = &raster.shade_setup(b.id[i]);
    SetupLanes setup = splat_setup(*b.setup[0]);
    for (int g = 1; g < group_count; ++g)
        select_setup(setup, groups[g].mask, *b.setup[groups[g].lane]);
    if (in.paths == ShadingPaths::specialised &&
        shade_plain(in, style, groups, group_count, setup, b))
        return true;
    b.sample = reconstruct_surfaces(setup, b.x, b.y);
    if (b.pixel_side > 0) b.pixel_depth = nearest_depth(setup, b.x, b.y, b.pixel_side);
    b.lanes.count = b.count;
    if (b.want_wire) std::fill(b.wire, b.wire + kLanes, 0.0f);
    gather_vertices(in, style, needs_of(style, b.want_normal), groups, group_count, b);
    if (b.any_texture && !style.base_color) apply_textures(in, b);
    if (b.any_vertex_colors && !style.base_color) apply_vertex_colors(in, b);
    if (b.any_physical_map && style.model == ShadingModel::pbr) {
        apply_physical_maps(in, b);
        apply_normal_maps(in, b);
    }
    const ShadingContext context{in.frame.camera.position, in.lights, in.frame.style_depth_range,
                                 &in.frame.environment};
    if (has_layers(style)) {
        finish_layers(in, style, context, b);
    } else {
        ShadedLanes shaded;
        shade_lanes(style, context, b.lanes, shaded);
        for (int a = 0; a < 3; ++a) b.color[a] = shaded.color[a];
    }
    if (b.any_emission) apply_emission(in, style, b);
    b.coverage = simd::splat(1.0f);
    if (b.any_shadow_catcher) apply_shadow_catchers(in, style, b);
    if (b.any_fade) apply_fades(in, b);
    return false;
}

}  // namespace facet
