#pragma once
// The lane checks of the `pbr` model's layers (tests/test_pbr_sheen.cpp,
// tests/test_pbr_iridescence.cpp, tests/test_pbr_anisotropy.cpp): eight one-point surfaces put into
// the lanes of one batch, and the check that each lane of brdf_cosine and environment_response is
// its one-point result to the bit, and that a lane without the layer keeps the bits it has without
// the layer's code.
#include <array>
#include <cstring>
#include <functional>

#include <catch2/catch.hpp>

#include "shade/brdf.hpp"

namespace facet::test {

using PointTerms = std::array<pbr::SurfaceTerms<float>, simd::kLanes>;
using PointViews = std::array<lanes::Vec3<float>, simd::kLanes>;

inline pbr::SurfaceTerms<simd::vf> lanes_of(const PointTerms& points) {
    pbr::SurfaceTerms<simd::vf> out;
    for (int i = 0; i < simd::kLanes; ++i) {
        const pbr::SurfaceTerms<float>& t = points[i];
        for (int a = 0; a < 3; ++a) {
            out.base[a][i] = t.base[a];
            out.f0[a][i] = t.f0[a];
            out.coat_normal[a][i] = t.coat_normal[a];
            out.sheen_color[a][i] = t.sheen_color[a];
            out.anisotropy_direction[a][i] = t.anisotropy_direction[a];
            out.diffuse_transmission_color[a][i] = t.diffuse_transmission_color[a];
            out.attenuation_color[a][i] = t.attenuation_color[a];
        }
        out.metallic[i] = t.metallic, out.roughness[i] = t.roughness;
        out.occlusion[i] = t.occlusion, out.f90[i] = t.f90;
        out.coat[i] = t.coat, out.coat_roughness[i] = t.coat_roughness;
        out.sheen_roughness[i] = t.sheen_roughness;
        out.iridescence[i] = t.iridescence, out.iridescence_ior[i] = t.iridescence_ior;
        out.iridescence_thickness[i] = t.iridescence_thickness;
        out.anisotropy[i] = t.anisotropy;
        out.diffuse_transmission[i] = t.diffuse_transmission;
        out.transmission[i] = t.transmission, out.ior[i] = t.ior;
        out.thickness[i] = t.thickness, out.attenuation_distance[i] = t.attenuation_distance;
        out.dispersion[i] = t.dispersion;
    }
    return out;
}

// Lane i of `lanes`, as one point's terms: lanes_of's inverse.
inline pbr::SurfaceTerms<float> lane_terms(const pbr::SurfaceTerms<simd::vf>& lanes, int i) {
    pbr::SurfaceTerms<float> t;
    for (int a = 0; a < 3; ++a) {
        t.base[a] = lanes.base[a][i];
        t.f0[a] = lanes.f0[a][i];
        t.coat_normal[a] = lanes.coat_normal[a][i];
        t.sheen_color[a] = lanes.sheen_color[a][i];
        t.anisotropy_direction[a] = lanes.anisotropy_direction[a][i];
        t.diffuse_transmission_color[a] = lanes.diffuse_transmission_color[a][i];
        t.attenuation_color[a] = lanes.attenuation_color[a][i];
    }
    t.metallic = lanes.metallic[i], t.roughness = lanes.roughness[i];
    t.occlusion = lanes.occlusion[i], t.f90 = lanes.f90[i];
    t.coat = lanes.coat[i], t.coat_roughness = lanes.coat_roughness[i];
    t.sheen_roughness = lanes.sheen_roughness[i];
    t.iridescence = lanes.iridescence[i], t.iridescence_ior = lanes.iridescence_ior[i];
    t.iridescence_thickness = lanes.iridescence_thickness[i];
    t.anisotropy = lanes.anisotropy[i];
    t.diffuse_transmission = lanes.diffuse_transmission[i];
    t.transmission = lanes.transmission[i], t.ior = lanes.ior[i];
    t.thickness = lanes.thickness[i], t.attenuation_distance = lanes.attenuation_distance[i];
    t.dispersion = lanes.dispersion[i];
    return t;
}

// Eight varied surfaces (metals every third lane, dielectrics between,
// roughness rising) seen from head-on to grazing, and `add_layer(i, t)`
// gives lane i its layer.
inline void varied_lanes(PointTerms& points, PointViews& views,
                         const std::function<void(int, pbr::SurfaceTerms<float>&)>& add_layer) {
    for (int i = 0; i < simd::kLanes; ++i) {
        const float f = static_cast<float>(i);
        points[i] =
            pbr::surface_terms({glm::vec3(0.4f + 0.05f * f, 0.3f, 0.2f), i % 3 == 0 ? 1.0f : 0.0f,
                                0.2f + 0.08f * f, pbr::kDefaultIor});
        add_layer(i, points[i]);
        const float mu = 1.0f - 0.11f * f;
        views[i] = {std::sqrt(1.0f - mu * mu), 0.0f, mu};
    }
}

// Lanes with normal +Z; `without` removes the layer from a point's terms,
// and `has_layer(i)` says which lanes have it (there the layer must show).
inline void check_layer_lanes(
    const PointTerms& points, const PointViews& views,
    const std::function<pbr::SurfaceTerms<float>(pbr::SurfaceTerms<float>)>& without,
    const std::function<bool(int)>& has_layer) {
    const auto same_bits = [](float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; };
    const auto compensated = pbr::MultipleScattering::compensated;
    const lanes::Vec3<float> n = {0.0f, 0.0f, 1.0f};
    lanes::Vec3<simd::vf> n8, v8;
    for (int i = 0; i < simd::kLanes; ++i)
        for (int a = 0; a < 3; ++a) n8[a][i] = n[a], v8[a][i] = views[i][a];
    const pbr::PbrPoint<simd::vf> p =
        pbr::prepare_point(n8, v8, lanes_of(points), compensated, pbr::dfg_table());
    const lanes::Vec3<float> l = {0.6f, 0.3f, std::sqrt(1.0f - 0.45f)};
    const lanes::Vec3<simd::vf> lit =
        pbr::brdf_cosine(p, {simd::splat(l[0]), simd::splat(l[1]), simd::splat(l[2])});
    const lanes::Vec3<float> grey = {0.4f, 0.5f, 0.6f};
    const lanes::Vec3<simd::vf> grey8 = {simd::splat(0.4f), simd::splat(0.5f), simd::splat(0.6f)};
    const lanes::Vec3<simd::vf> env = pbr::environment_response(p, grey8, grey8, grey8);
    for (int i = 0; i < simd::kLanes; ++i) {
        INFO("lane " << i);
        const pbr::PbrPoint<float> one =
            pbr::prepare_point(n, views[i], points[i], compensated, pbr::dfg_table());
        const pbr::PbrPoint<float> bare =
            pbr::prepare_point(n, views[i], without(points[i]), compensated, pbr::dfg_table());
        const lanes::Vec3<float> lit_one = pbr::brdf_cosine(one, l);
        const lanes::Vec3<float> lit_bare = pbr::brdf_cosine(bare, l);
        const lanes::Vec3<float> env_one = pbr::environment_response(one, grey, grey, grey);
        const lanes::Vec3<float> env_bare = pbr::environment_response(bare, grey, grey, grey);
        for (int c = 0; c < 3; ++c) {
            CHECK(same_bits(lit[c][i], lit_one[c]));
            CHECK(same_bits(env[c][i], env_one[c]));
            if (!has_layer(i)) {
                CHECK(same_bits(lit_one[c], lit_bare[c]));
                CHECK(same_bits(env_one[c], env_bare[c]));
            }
        }
        if (has_layer(i)) CHECK(lit_one != lit_bare);  // the layer shows
    }
}

}  // namespace facet::test
