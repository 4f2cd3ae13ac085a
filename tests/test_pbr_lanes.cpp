// The `pbr` model runs eight points at a time (shade/model_pbr.cpp) through
// the templates of shade/brdf.hpp and shade/light_sample.hpp that also give
// the one-point functions, and the environment has one-point and
// eight-point lookups. These tests pin that each lane gives the one-point
// function's bits, so the documented formulas are what renders.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "pbr_lane_support.hpp"
#include "shade/brdf.hpp"
#include "shade/environment_map.hpp"
#include "shade/shading_models.hpp"
#include "shade/shadow_map.hpp"

using namespace facet;
using simd::splat;

namespace {

bool same_bits(float a, float b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

// Eight unit normals, views and materials spread over what a frame holds:
// grazing and head-on views, smooth and rough, metal and dielectric.
struct LanePoint {
    glm::vec3 n, v;
    glm::vec3 base;
    float metallic, roughness;
};

std::array<LanePoint, simd::kLanes> lane_points() {
    std::array<LanePoint, simd::kLanes> points;
    for (int i = 0; i < simd::kLanes; ++i) {
        const float a = 0.37f * static_cast<float>(i);
        points[i].n = glm::normalize(glm::vec3(std::sin(a) * 0.6f, 1.0f, std::cos(a) * 0.3f));
        points[i].v = glm::normalize(glm::vec3(0.2f, 0.3f + 0.1f * i, 1.0f - 0.12f * i));
        points[i].base = {0.9f - 0.1f * i, 0.2f + 0.05f * i, 0.5f};
        points[i].metallic = (i % 3 == 0) ? 1.0f : 0.1f * i;
        points[i].roughness = 0.05f + 0.13f * i;
    }
    return points;
}

}  // namespace

TEST_CASE("pbr lanes: each lane of the model is brdf.hpp's f(v, l) (n.l) times pi, to the bit",
          "[shade][pbr]") {
    const std::array<LanePoint, simd::kLanes> points = lane_points();
    const glm::vec3 eye(0.0f, 0.0f, 0.0f);
    SurfaceLanes in;
    in.count = simd::kLanes;
    for (int i = 0; i < simd::kLanes; ++i) {
        // The point sits at -v from the eye, so its unit view vector is v.
        const glm::vec3 position = eye - points[i].v * 3.0f;
        in.surface.px[i] = position.x, in.surface.py[i] = position.y, in.surface.pz[i] = position.z;
        in.surface.nx[i] = points[i].n.x, in.surface.ny[i] = points[i].n.y;
        in.surface.nz[i] = points[i].n.z;
        for (int c = 0; c < 3; ++c) {
            in.albedo[c][i] = points[i].base[c];
            in.pbr.f0[c][i] = pbr::f0_from_ior(pbr::kDefaultIor);
            in.pbr.coat_normal[c][i] = points[i].n[c];
        }
        in.pbr.metallic[i] = points[i].metallic;
        in.pbr.roughness[i] = points[i].roughness;
        in.pbr.occlusion[i] = 1.0f;
        in.pbr.f90[i] = 1.0f;
        in.pbr.coat[i] = 0.0f;
        in.pbr.coat_roughness[i] = 0.0f;
        for (int c = 0; c < 3; ++c) in.pbr.sheen_color[c][i] = 0.0f;  // no sheen, no film
        in.pbr.sheen_roughness[i] = 0.0f;
        in.pbr.iridescence[i] = 0.0f;
        in.pbr.iridescence_ior[i] = 1.3f;
        in.pbr.iridescence_thickness[i] = 400.0f;
        in.pbr.anisotropy[i] = 0.0f;  // nor an anisotropy, nor a diffuse transmission
        in.pbr.diffuse_transmission[i] = 0.0f;
        for (int c = 0; c < 3; ++c)
            in.pbr.anisotropy_direction[c][i] = in.pbr.diffuse_transmission_color[c][i] = 0.0f;
    }
    in.surface.receives_shadow = splat(0.0f);
    ShadeLight light;
    light.direction = glm::normalize(glm::vec3(0.3f, 1.0f, 0.4f));
    light.radiance = glm::vec3(1.0f);
    const ShadeLight lights[] = {light};
    ShadingContext context{eye, lights, glm::vec2(0.1f, 10.0f), nullptr};
    ShadedLanes out;
    shade_pbr(in, context, out);

    for (int i = 0; i < simd::kLanes; ++i) {
        // The model's own unit view vector, as it computes it from the
        // position, is what the one-point function must be given.
        const glm::vec3 to_eye(eye.x - in.surface.px[i], eye.y - in.surface.py[i],
                               eye.z - in.surface.pz[i]);
        const glm::vec3 v =
            to_eye *
            (1.0f / std::sqrt(to_eye.x * to_eye.x + to_eye.y * to_eye.y + to_eye.z * to_eye.z));
        const float length =
            std::sqrt(points[i].n.x * points[i].n.x + points[i].n.y * points[i].n.y +
                      points[i].n.z * points[i].n.z);
        const glm::vec3 n = points[i].n * (1.0f / length);
        pbr::Material material;
        material.base_color = points[i].base;
        material.metallic = points[i].metallic;
        material.roughness = points[i].roughness;
        const glm::vec3 expected =
            pbr::kPi *
            pbr::brdf_cosine(n, v, light.direction, material, pbr::MultipleScattering::compensated);
        INFO("lane " << i);
        CHECK(expected.x > 0.0f);
        for (int c = 0; c < 3; ++c) {
            INFO("channel " << c << ": " << out.color[c][i] << " against " << expected[c]);
            CHECK(same_bits(out.color[c][i], expected[c]));
        }
    }
}

namespace {

// An orthographic shadow map from `to_light` whose left half of texels has
// a caster halfway along, so that some lanes are shadowed and some are not.
ShadowMap half_shadowed_map(const glm::vec3& to_light) {
    ShadowMap map;
    const ShadowBasis basis = shadow_basis(-to_light);
    set_orthographic(map, 16, shadow_view(basis, to_light * 10.0f), 4.0f, 0.1f, 20.0f);
    for (int y = 0; y < map.size; ++y)
        for (int x = 0; x < map.size; ++x)
            map.depth[static_cast<size_t>(y * map.size + x)] =
                x < map.size / 2 ? 5.0f : std::numeric_limits<float>::infinity();
    return map;
}

}  // namespace

TEST_CASE("pbr lanes: every term of a lane is the one-point model's, to the bit", "[shade][pbr]") {
    // The one-point instantiation covers what brdf_cosine alone does not:
    // KHR_materials_specular's f0 and f90, the clear coat and its normal,
    // the sheen (on lanes 1, 4 and 7), the thin film (2 and 5), the anisotropy (3 and 7),
    // a diffuse transmission (1 and 5),
    // occlusion, point and spot lights
    // with ranges, shadows, ambient light and the environment's split sum, rotated and scaled.
    const std::array<LanePoint, simd::kLanes> points = lane_points();
    const glm::vec3 eye(0.5f, 2.0f, 4.0f);
    SurfaceLanes in;
    in.count = simd::kLanes;
    for (int i = 0; i < simd::kLanes; ++i) {
        const glm::vec3 position(-2.0f + 0.55f * i, 0.1f * i, 0.3f * (i % 3));
        in.surface.px[i] = position.x, in.surface.py[i] = position.y, in.surface.pz[i] = position.z;
        in.surface.nx[i] = points[i].n.x * 2.0f, in.surface.ny[i] = points[i].n.y * 2.0f;
        in.surface.nz[i] = points[i].n.z * 2.0f;  // any length
        in.surface.receives_shadow[i] = i == 5 ? 0.0f : 1.0f;
        for (int c = 0; c < 3; ++c) {
            in.albedo[c][i] = points[i].base[c];
            in.pbr.f0[c][i] = 0.02f + 0.01f * static_cast<float>(i + c);
            in.pbr.coat_normal[c][i] = points[(i + 3) % simd::kLanes].n[c];
            in.pbr.sheen_color[c][i] = i % 3 == 1 ? 0.3f + 0.2f * static_cast<float>(c) : 0.0f;
        }
        in.pbr.sheen_roughness[i] = 0.1f + 0.12f * static_cast<float>(i);
        in.pbr.iridescence[i] = i % 3 == 2 ? 0.8f : 0.0f;
        in.pbr.iridescence_ior[i] = 1.3f + 0.05f * static_cast<float>(i);
        in.pbr.iridescence_thickness[i] = 200.0f + 50.0f * static_cast<float>(i);
        in.pbr.anisotropy[i] = i % 4 == 3 ? 0.3f + 0.1f * static_cast<float>(i) : 0.0f;
        in.pbr.diffuse_transmission[i] = i % 4 == 1 ? 0.2f + 0.1f * static_cast<float>(i) : 0.0f;
        for (int c = 0; c < 3; ++c)
            in.pbr.diffuse_transmission_color[c][i] = 0.9f - 0.2f * static_cast<float>(c);
        for (int c = 0; c < 3; ++c)
            in.pbr.anisotropy_direction[c][i] = c == 0 ? 1.0f : 0.2f * static_cast<float>(c + i);
        in.pbr.metallic[i] = points[i].metallic;
        in.pbr.roughness[i] = points[i].roughness;
        in.pbr.occlusion[i] = 1.0f - 0.07f * static_cast<float>(i);
        in.pbr.f90[i] = 0.6f + 0.05f * static_cast<float>(i);
        in.pbr.coat[i] = i % 2 == 0 ? 0.0f : 0.2f * static_cast<float>(i);
        in.pbr.coat_roughness[i] = 0.1f * static_cast<float>(i);
    }
    std::vector<ShadeLight> lights(4);
    lights[0].direction = glm::normalize(glm::vec3(0.3f, 1.0f, 0.4f));
    lights[0].radiance = glm::vec3(1.0f, 0.9f, 0.8f);
    const ShadowMap shadow = half_shadowed_map(lights[0].direction);
    lights[0].shadow = &shadow;
    lights[1].is_point = true;
    lights[1].position = glm::vec3(0.0f, 3.0f, 1.0f);
    lights[1].radiance = glm::vec3(4.0f, 2.0f, 1.0f);
    lights[1].inv_range = 1.0f / 4.5f;
    lights[2].is_point = true;
    lights[2].position = glm::vec3(1.0f, 4.0f, 0.0f);
    lights[2].direction = glm::vec3(0.0f, 1.0f, 0.0f);
    lights[2].radiance = glm::vec3(6.0f);
    set_spot_cone(lights[2], 20.0f, 35.0f);
    lights[3].is_ambient = true;
    lights[3].radiance = glm::vec3(0.05f, 0.06f, 0.07f);
    const pbr::SharedEnvironment studio = pbr::shared_studio_environment();
    const EnvironmentLighting environment = environment_at(studio.get(), 0.7f, 33.0f);
    ShadingContext context{eye, lights, glm::vec2(0.1f, 10.0f), &environment};
    ShadedLanes out;
    shade_pbr(in, context, out);

    int shadowed = 0;
    for (int i = 0; i < simd::kLanes; ++i) {
        const glm::vec3 position(in.surface.px[i], in.surface.py[i], in.surface.pz[i]);
        const glm::vec3 normal(in.surface.nx[i], in.surface.ny[i], in.surface.nz[i]);
        pbr::SurfaceTerms<float> terms = test::lane_terms(in.pbr, i);
        for (int c = 0; c < 3; ++c) terms.base[c] = in.albedo[c][i];  // the model's base
        const glm::vec3 expected =
            shade_pbr_point(position, normal, in.surface.receives_shadow[i] > 0.0f, terms, context);
        if (shadow_visibility(shadow, position, normal) < 1.0f) ++shadowed;
        INFO("lane " << i);
        for (int c = 0; c < 3; ++c) {
            INFO("channel " << c << ": " << out.color[c][i] << " against " << expected[c]);
            CHECK(expected[c] > 0.0f);
            CHECK(same_bits(out.color[c][i], expected[c]));
        }
    }
    // The shadow map darkens some lanes and not others.
    CHECK(shadowed > 0);
    CHECK(shadowed < simd::kLanes);
}

TEST_CASE("pbr lanes: the environment's eight-point lookups are its one-point lookups, to the bit",
          "[shade][pbr][environment]") {
    const pbr::SharedEnvironment studio = pbr::shared_studio_environment();
    int compared = 0;
    for (int batch = 0; batch < 64; ++batch) {
        simd::vf d[3], roughness;
        for (int i = 0; i < simd::kLanes; ++i) {
            const float a = 0.173f * static_cast<float>(batch * simd::kLanes + i);
            d[0][i] = std::sin(a) * std::cos(0.31f * a);
            d[1][i] = std::cos(1.7f * a);
            d[2][i] = std::cos(a) * 0.8f;
            // Every level exactly, and values between them.
            roughness[i] =
                (i % 2 == 0) ? static_cast<float>(i / 2) / 7.0f : std::fmod(0.137f * a, 1.1f);
        }
        if (batch == 0) {  // the documented edge cases
            d[0][0] = d[1][0] = d[2][0] = 0.0f;
            roughness[1] = std::numeric_limits<float>::quiet_NaN();
            d[1][2] = std::numeric_limits<float>::infinity();
            roughness[3] = -0.5f;
        }
        simd::vf specular[3], diffuse[3];
        studio->specular(d, roughness, specular);
        studio->diffuse(d, diffuse);
        for (int i = 0; i < simd::kLanes; ++i) {
            const glm::vec3 direction(d[0][i], d[1][i], d[2][i]);
            const glm::vec3 one_specular = studio->specular(direction, roughness[i]);
            INFO("batch " << batch << " lane " << i);
            for (int c = 0; c < 3; ++c) CHECK(same_bits(specular[c][i], one_specular[c]));
            if (batch > 0) {  // diffuse wants a unit normal
                const glm::vec3 one_diffuse = studio->diffuse(glm::normalize(direction));
                simd::vf n[3], lane_diffuse[3];
                const glm::vec3 unit = glm::normalize(direction);
                for (int c = 0; c < 3; ++c) n[c] = splat(unit[c]);
                studio->diffuse(n, lane_diffuse);
                for (int c = 0; c < 3; ++c) CHECK(same_bits(lane_diffuse[c][i], one_diffuse[c]));
            }
            ++compared;
        }
    }
    CHECK(compared == 64 * simd::kLanes);
}

TEST_CASE("pbr lanes: the DFG lookup reads inside its table for any input", "[shade][pbr]") {
    const pbr::DfgTable& table = pbr::dfg_table();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    const simd::vf n_dot_v = {nan, -inf, inf, -1.0f, 0.0f, 0.5f, 1.0f, 2.0f};
    const simd::vf roughness = {0.5f, nan, -inf, inf, -3.0f, 0.0f, 1.0f, 7.0f};
    const pbr::DfgTable::Lanes terms = table.lookup(n_dot_v, roughness);
    for (int i = 0; i < simd::kLanes; ++i) {
        INFO("lane " << i);
        CHECK(std::isfinite(terms.scale[i]));
        CHECK(std::isfinite(terms.bias[i]));
        CHECK(terms.scale[i] >= 0.0f);
        CHECK(terms.scale[i] + terms.bias[i] <= 1.0f);
    }
    // A NaN reads the low end: n.v 0 and the smoothest roughness.
    const pbr::DfgTerms low = table.lookup(0.0f, 0.5f);
    CHECK(same_bits(terms.scale[0], low.scale));
}
