#pragma once
// A material's keys as the shading models read them, eight points at a
// time: its constants (each model's terms), its maps and its emission and
// fade. The shading stage (render/shade_batch.cpp) gathers the points and
// runs the steps their features ask for (MaterialFeature, assets/mesh.hpp);
// it names no material key itself. The texture lookups and the tangent
// frames are the stage's: each step takes them as callables.
//
// A new material key is read here (or in its model's file), described in
// assets/mesh.hpp with its feature bit when it needs a step of its own, and
// read from scenes and files by scene/material_parser.cpp and
// assets/gltf_materials.cpp (docs/architecture.md, "Adding a material key").
#include <algorithm>
#include <optional>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "assets/mesh.hpp"
#include "core/simd_math.hpp"
#include "shade/brdf.hpp"
#include "shade/metal_rough_phong.hpp"
#include "shade/shading_models.hpp"
#include "shade/style_math.hpp"

namespace facet {

// A value of one group's triangle (the lanes of a batch that show the same
// triangle): splatted for the first group, then selected into each further
// group's lanes. With one group (the usual case) `Single` leaves out the
// selects.
template <bool Single>
[[gnu::always_inline]] inline void put(simd::vf& v, simd::vi mask, float value, bool first) {
    if (Single || first)
        v = simd::splat(value);
    else
        v = mask ? simd::splat(value) : v;
}

// The sheen's, the thin film's, the anisotropy's and the transmissions'
// constants (kExtraLobes); the anisotropy's direction is the shading
// stage's, from the tangent frame (render/shade_batch.cpp), and starts at
// zero. `object_scale` turns the volume's thickness, in the mesh's units,
// into the world's.
template <bool Single>
[[gnu::always_inline]] inline void put_extra_lobes(const Material& m, float object_scale,
                                                   simd::vi mask, bool first,
                                                   pbr::SurfaceTerms<simd::vf>& p) {
    put<Single>(p.transmission, mask, m.transmission, first);
    put<Single>(p.ior, mask, m.ior, first);
    put<Single>(p.thickness, mask, m.thickness * object_scale, first);
    for (int a = 0; a < 3; ++a)
        put<Single>(p.attenuation_color[a], mask, m.attenuation_color[a], first);
    put<Single>(p.attenuation_distance, mask, m.attenuation_distance * object_scale, first);
    put<Single>(p.dispersion, mask, m.dispersion, first);
    put<Single>(p.anisotropy, mask, m.anisotropy, first);
    put<Single>(p.diffuse_transmission, mask, m.diffuse_transmission, first);
    for (int a = 0; a < 3; ++a)
        put<Single>(p.diffuse_transmission_color[a], mask, m.diffuse_transmission_color[a], first);
    for (simd::vf& axis : p.anisotropy_direction) put<Single>(axis, mask, 0.0f, first);
    for (int a = 0; a < 3; ++a) put<Single>(p.sheen_color[a], mask, m.sheen_color[a], first);
    put<Single>(p.sheen_roughness, mask, m.sheen_roughness, first);
    put<Single>(p.iridescence, mask, m.iridescence, first);
    put<Single>(p.iridescence_ior, mask, m.iridescence_ior, first);
    put<Single>(p.iridescence_thickness, mask, m.iridescence_thickness_max, first);
}

// The dielectric's reflectance at normal incidence, from its ior and
// KHR_materials_specular: min(f0(ior) * colour * map colour, 1) * weight *
// map weight (the maps' 1 where a material has none).
inline glm::vec3 dielectric_f0(const Material& m, const glm::vec3& map_color = glm::vec3(1.0f),
                               float map_weight = 1.0f) {
    const float f0 = pbr::f0_from_ior(m.ior);
    glm::vec3 out;
    for (int a = 0; a < 3; ++a)
        out[a] = std::min(f0 * m.specular_color[a] * map_color[a], 1.0f) * m.specular_weight *
                 map_weight;
    return out;
}

// The constants of material `m` that `style`'s model reads, into the lanes
// of `mask`: the albedo (the style's own colour first), the Phong terms,
// and the `pbr` model's terms, the dielectric's reflectances from its ior
// and KHR_materials_specular (f0 = min(f0(ior) * colour, 1) * weight,
// f90 = weight), without occlusion until its map.
template <bool Single>
[[gnu::always_inline]] inline void put_material_terms(const Material& m, float object_scale,
                                                      const StyleState& style,
                                                      const ModelNeeds& needs, simd::vi mask,
                                                      bool first, SurfaceLanes& lanes) {
    SurfaceBatch& s = lanes.surface;
    if (needs.light_terms) {
        put<Single>(s.ambient, mask, m.ambient, first);
        put<Single>(s.diffuse, mask, m.diffuse, first);
        put<Single>(s.specular, mask, m.specular, first);
        put<Single>(s.shininess, mask, m.shininess, first);
        put<Single>(s.ambient_specular, mask, 0.0f, first);
    }
    if (needs.light_terms || needs.vertex_light)
        for (simd::vf& c : lanes.specular_color) put<Single>(c, mask, 1.0f, first);
    if (style.model == ShadingModel::pbr) {
        pbr::SurfaceTerms<simd::vf>& p = lanes.pbr;
        put<Single>(p.metallic, mask, m.metallic, first);
        put<Single>(p.roughness, mask, m.roughness, first);
        put<Single>(p.occlusion, mask, 1.0f, first);
        const glm::vec3 f0 = dielectric_f0(m);
        for (int a = 0; a < 3; ++a) put<Single>(p.f0[a], mask, f0[a], first);
        put<Single>(p.f90, mask, m.specular_weight, first);
        put<Single>(p.coat, mask, m.clearcoat, first);
        put<Single>(p.coat_roughness, mask, m.clearcoat_roughness, first);
        // Without kExtraLobes in the batch every group's are zero: the first puts them.
        if (needs.extra_lobes || first) put_extra_lobes<Single>(m, object_scale, mask, first, p);
    }
    for (int a = 0; a < 3; ++a)
        put<Single>(lanes.albedo[a], mask, style.base_color ? (*style.base_color)[a] : m.color[a],
                    first);
}

// Each lane's material, for the steps below.
using LaneMaterials = const Material* const (&)[simd::kLanes];

// A material texture slot of each lane (null: none), for a `lookup`.
template <typename Slot>
auto slot_of(LaneMaterials material, Slot slot) {
    return [&material, slot](int lane) -> const TextureSlot* {
        const TextureSlot& t = material[lane]->*slot;
        return t ? &t : nullptr;
    };
}

// A shadow catcher's ambient term against its diffuse one, ka / kd (0
// without a diffuse term), lane by lane from the frame's materials: the
// ambient light the Phong family gives it for each unit of direct light
// (render/shade_batch.cpp's catchers; Gouraud's lanes carry no Phong terms).
inline simd::vf ambient_over_diffuse(LaneMaterials material, int count) {
    simd::vf ratio = simd::splat(0.0f);
    for (int i = 0; i < count; ++i) {
        const Material& m = *material[i];
        ratio[i] = m.diffuse > 0.0f ? m.ambient / m.diffuse : 0.0f;
    }
    return ratio;
}

// The steps' texture lookups: `lookup(slot_of, use)` reads each lane's
// slot `slot_of(lane)` (null: none) at the lane's point and footprint and
// calls `use(lane, texel)`.

// kBaseColorMap: the map multiplies the albedo.
template <typename Lookup>
void apply_base_color_maps(LaneMaterials material, Lookup&& lookup, SurfaceLanes& lanes) {
    lookup(slot_of(material, &Material::base_color_map), [&](int i, const glm::vec4& texel) {
        for (int a = 0; a < 3; ++a) lanes.albedo[a][i] *= texel[a];
    });
}

// KHR_materials_pbrSpecularGlossiness's map, texel by texel: specular
// colour s = RGB * specular_factor is the dielectric's f0 (f90 stays 1),
// glossiness g = A * glossiness_factor makes roughness 1 - g, and the
// diffuse colour keeps 1 - max(s) (the archived specification's
// c_diff = diffuse (1 - max(s))).
template <typename Lookup>
void apply_specular_glossiness_map(LaneMaterials material, Lookup&& lookup, SurfaceLanes& lanes) {
    pbr::SurfaceTerms<simd::vf>& p = lanes.pbr;
    lookup(slot_of(material, &Material::specular_glossiness_map), [&](int i, const glm::vec4& t) {
        const Material& m = *material[i];
        float largest = 0.0f;
        for (int a = 0; a < 3; ++a) {
            p.f0[a][i] = m.specular_factor[a] * t[a];
            largest = std::max(largest, p.f0[a][i]);
        }
        for (int a = 0; a < 3; ++a) lanes.albedo[a][i] *= 1.0f - largest;
        p.roughness[i] = 1.0f - m.glossiness_factor * t.a;
    });
}

// kMetalRough: under the Phong family, each such lane's metal and
// roughness (the factors times the metal-rough map's B and G) turn its
// albedo (the base colour, maps applied) into the model's diffuse colour,
// highlight colour, strength and exponent (shade/metal_rough_phong.hpp);
// the ambient light reflects in the highlight's colour too.
template <typename Lookup>
void apply_metal_rough_reading(LaneMaterials material, const uint32_t* features, int count,
                               Lookup&& lookup, SurfaceLanes& lanes) {
    float metallic[simd::kLanes], roughness[simd::kLanes];
    for (int i = 0; i < count; ++i)
        metallic[i] = material[i]->metallic, roughness[i] = material[i]->roughness;
    lookup(slot_of(material, &Material::metal_rough_map), [&](int i, const glm::vec4& t) {
        roughness[i] *= t.g;
        metallic[i] *= t.b;
    });
    SurfaceBatch& s = lanes.surface;
    for (int i = 0; i < count; ++i) {
        if (!(features[i] & kMetalRough)) continue;
        const Material& m = *material[i];
        const PhongReading r =
            read_metal_rough(lanes.albedo_at(i), dielectric_f0(m), metallic[i], roughness[i]);
        for (int a = 0; a < 3; ++a) {
            lanes.albedo[a][i] = r.diffuse[a];
            lanes.specular_color[a][i] = r.specular[a];
        }
        s.specular[i] = r.strength;
        s.shininess[i] = r.shininess;
        s.ambient_specular[i] = m.ambient;
    }
}

// kPhysicalMaps: the `pbr` model's maps (glTF 2.0 §3.9): metallic-roughness
// (B metal, G roughness), occlusion (R, blended by its strength),
// KHR_materials_specular (A weight, RGB colour), clearcoat (R strength,
// G roughness), sheen (RGB colour, A roughness) and iridescence (R
// strength; G thickness from the minimum to the maximum), diffuse
// transmission (A strength, RGB colour), transmission (R) and the volume's
// thickness (G), each multiplying its factor, and the specular-glossiness map.
template <typename Lookup>
void apply_physical_maps(LaneMaterials material, int count, Lookup&& lookup, SurfaceLanes& lanes) {
    pbr::SurfaceTerms<simd::vf>& p = lanes.pbr;
    lookup(slot_of(material, &Material::metal_rough_map), [&](int i, const glm::vec4& t) {
        p.roughness[i] *= t.g;
        p.metallic[i] *= t.b;
    });
    lookup(slot_of(material, &Material::occlusion_map), [&](int i, const glm::vec4& t) {
        p.occlusion[i] = 1.0f + material[i]->occlusion_strength * (t.r - 1.0f);
    });
    float weight[simd::kLanes], tint[3][simd::kLanes];
    std::fill(weight, weight + simd::kLanes, 1.0f);
    std::fill(&tint[0][0], &tint[0][0] + 3 * simd::kLanes, 1.0f);
    lookup(slot_of(material, &Material::specular_weight_map),
           [&](int i, const glm::vec4& t) { weight[i] = t.a; });
    lookup(slot_of(material, &Material::specular_color_map), [&](int i, const glm::vec4& t) {
        for (int a = 0; a < 3; ++a) tint[a][i] = t[a];
    });
    for (int i = 0; i < count; ++i) {
        const Material& m = *material[i];
        if (!m.specular_weight_map && !m.specular_color_map) continue;
        const glm::vec3 f0 = dielectric_f0(m, {tint[0][i], tint[1][i], tint[2][i]}, weight[i]);
        for (int a = 0; a < 3; ++a) p.f0[a][i] = f0[a];
        p.f90[i] = m.specular_weight * weight[i];
    }
    lookup(slot_of(material, &Material::clearcoat_map),
           [&](int i, const glm::vec4& t) { p.coat[i] *= t.r; });
    lookup(slot_of(material, &Material::clearcoat_roughness_map),
           [&](int i, const glm::vec4& t) { p.coat_roughness[i] *= t.g; });
    lookup(slot_of(material, &Material::sheen_color_map), [&](int i, const glm::vec4& t) {
        for (int a = 0; a < 3; ++a) p.sheen_color[a][i] *= t[a];
    });
    lookup(slot_of(material, &Material::sheen_roughness_map),
           [&](int i, const glm::vec4& t) { p.sheen_roughness[i] *= t.a; });
    apply_specular_glossiness_map(material, lookup, lanes);
    lookup(slot_of(material, &Material::iridescence_map),
           [&](int i, const glm::vec4& t) { p.iridescence[i] *= t.r; });
    lookup(slot_of(material, &Material::diffuse_transmission_map),
           [&](int i, const glm::vec4& t) { p.diffuse_transmission[i] *= t.a; });
    lookup(slot_of(material, &Material::diffuse_transmission_color_map),
           [&](int i, const glm::vec4& t) {
               for (int a = 0; a < 3; ++a) p.diffuse_transmission_color[a][i] *= t[a];
           });
    lookup(slot_of(material, &Material::transmission_map),
           [&](int i, const glm::vec4& t) { p.transmission[i] *= t.r; });
    lookup(slot_of(material, &Material::thickness_map),
           [&](int i, const glm::vec4& t) { p.thickness[i] *= t.g; });
    lookup(slot_of(material, &Material::iridescence_thickness_map), [&](int i, const glm::vec4& t) {
        const Material& m = *material[i];
        p.iridescence_thickness[i] =
            m.iridescence_thickness_min +
            (m.iridescence_thickness_max - m.iridescence_thickness_min) * t.g;
    });
}

// kExtraLobes' anisotropy, lane by lane: the direction in the tangent
// frame is the tangent, or the map's RG direction (B scales the strength),
// turned by the material's rotation. `to_mesh_frame(texel, slot)` turns a
// texel's direction from the map's coordinates into the mesh's;
// `to_world(lane, direction)` takes the frame's direction into world space,
// or gives nothing where the lane's part has no tangent frame (loading
// warned of it), which is then drawn isotropic.
template <typename Lookup, typename ToMeshFrame, typename ToWorld>
void apply_anisotropy(LaneMaterials material, int count, Lookup&& lookup,
                      ToMeshFrame&& to_mesh_frame, ToWorld&& to_world, SurfaceLanes& lanes) {
    pbr::SurfaceTerms<simd::vf>& p = lanes.pbr;
    glm::vec3 texel[simd::kLanes];
    lookup(slot_of(material, &Material::anisotropy_map),
           [&](int i, const glm::vec4& t) { texel[i] = glm::vec3(t); });
    for (int i = 0; i < count; ++i) {
        const Material& m = *material[i];
        if (!(m.anisotropy > 0.0f)) continue;
        glm::vec2 d(1.0f, 0.0f);
        if (m.anisotropy_map) {
            const glm::vec3 t = to_mesh_frame(texel[i], m.anisotropy_map);
            d = {2.0f * t.x - 1.0f, 2.0f * t.y - 1.0f};
            p.anisotropy[i] *= t.z;
        }
        const glm::vec2 turned(m.anisotropy_cos * d.x - m.anisotropy_sin * d.y,
                               m.anisotropy_sin * d.x + m.anisotropy_cos * d.y);
        const std::optional<glm::vec3> direction = to_world(i, turned);
        if (!direction) {
            p.anisotropy[i] = 0.0f;
            continue;
        }
        for (int a = 0; a < 3; ++a) p.anisotropy_direction[a][i] = (*direction)[a];
    }
}

// kNormalMaps: the base's and the coat's normal maps, lane by lane.
// `normal_at(lane, slot, scale)` is the map's unit normal at the lane, or
// nothing where the lane's part cannot draw it (no tangents); `set_base`
// and `set_coat` take the results. The coat's map turns the coat's normal
// from the same unmapped normal: its relief is not the base's.
template <typename NormalAt, typename SetBase, typename SetCoat>
void apply_normal_maps(LaneMaterials material, int count, NormalAt&& normal_at, SetBase&& set_base,
                       SetCoat&& set_coat) {
    for (int i = 0; i < count; ++i) {
        const Material& m = *material[i];
        if (m.clearcoat > 0.0f)
            if (const auto n = normal_at(i, m.clearcoat_normal_map, m.clearcoat_normal_scale))
                set_coat(i, *n);
        if (const auto n = normal_at(i, m.normal_map, m.normal_scale)) set_base(i, *n);
    }
}

// kEmission: unlit materials show their albedo; emission (its factor
// times its map) adds to what the model made.
template <typename Lookup>
void add_emission(LaneMaterials material, int count, Lookup&& lookup, const simd::vf (&albedo)[3],
                  simd::vf (&color)[3]) {
    glm::vec3 emitted[simd::kLanes];
    for (int i = 0; i < count; ++i) emitted[i] = material[i]->emissive;
    lookup(
        [&](int i) -> const TextureSlot* {
            const TextureSlot& t = material[i]->emissive_map;
            return t && emitted[i] != glm::vec3(0) ? &t : nullptr;
        },
        [&](int i, const glm::vec4& t) { emitted[i] *= glm::vec3(t); });
    for (int i = 0; i < count; ++i) {
        const Material& m = *material[i];
        for (int a = 0; a < 3; ++a) {
            const float base = m.unlit ? albedo[a][i] : color[a][i];
            color[a][i] = base + emitted[i][a];
        }
    }
}

// kFade: how much of a point of material `m` stays, by its distance from
// its object's origin (model space, at rest): a smoothstep from fade_start
// (all) to fade_end (none).
inline float fade_kept(const Material& m, float distance) {
    return 1.0f - smoothstep(m.fade_start, m.fade_end, distance);
}

}  // namespace facet
