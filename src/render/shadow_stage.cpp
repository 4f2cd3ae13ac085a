// Shadow stage: the depth maps of the shadow-casting lights for one frame,
// rendered through the raster core with the frame's object transforms.
#include "render/shadow_stage.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "render/transmission_stage.hpp"

namespace facet {
namespace {

constexpr size_t kVerticesPerChunk = 16384;  // fixed: the same cut for any thread count
// Spots wider than this (half-angle, degrees) get a cube map: one
// perspective map would spread its texels too thin near the edge.
constexpr float kMaxPerspectiveSpotAngle = 60.0f;

// Whether a light's map is a cube of six faces: a point light's, and a
// spot's wider than kMaxPerspectiveSpotAngle.
bool cube_map(LightType type, float outer_angle) {
    return type == LightType::point ||
           (type == LightType::spot && outer_angle > kMaxPerspectiveSpotAngle);
}

// The widest a spot's cone gets: its constant, or its track's widest key.
float widest_outer_angle(const Animated<float>& angle) {
    float widest = angle.value;
    if (angle.track)
        for (const glm::dvec4& key : angle.track->values)
            widest = std::max(widest, static_cast<float>(key.x));
    return widest;
}
// Texels round a spot map's cone, and round each cube face past 90 degrees
// (plus the filter radius), so filters near an edge read real texels.
constexpr int kEdgeTexels = 2;
// The sun's map size in scene units moves in steps of 2^(1/8) (about 9%),
// so a caster moving a little does not change the texel size every frame.
constexpr double kRadiusStepsPerOctave = 8;
// Near plane of perspective maps at least this fraction of the far one.
constexpr float kMinNearOverFar = 1e-4f;

// The nearest depth in each block of a drawn tile (ShadowMap::block_nearest).
void nearest_in_blocks(const float* texels, int size, const TileVisibility& tile, int blocks,
                       float* nearest) {
    for (int by = tile.y0; by < tile.y0 + tile.height; by += kShadowBlock)
        for (int bx = tile.x0; bx < tile.x0 + tile.width; bx += kShadowBlock) {
            float least = std::numeric_limits<float>::infinity();
            const int y_end = std::min(by + kShadowBlock, tile.y0 + tile.height);
            const int x_end = std::min(bx + kShadowBlock, tile.x0 + tile.width);
            for (int y = by; y < y_end; ++y)
                for (int x = bx; x < x_end; ++x)
                    least = std::min(least, texels[static_cast<size_t>(y) * size + x]);
            nearest[(by / kShadowBlock) * blocks + bx / kShadowBlock] = least;
        }
}

}  // namespace

uint64_t ShadowStage::bytes(const SceneDesc& scene, const World& world, bool glass) {
    const uint64_t triangles = world.triangle_count(), vertices = world.positions.size();
    uint64_t bytes = 0;
    for (const LightDesc& light : scene.lights) {
        if (!light.shadows) continue;
        const uint64_t faces = cube_map(light.type, widest_outer_angle(light.outer_angle)) ? 6 : 1;
        const uint64_t side = static_cast<uint64_t>(light.shadow_resolution);
        const uint64_t texel_bytes = sizeof(float) * (glass ? 3 : 1);  // depth; glass depth, share
        bytes += side * side * faces * texel_bytes + Rasterizer::bytes(triangles, vertices);
    }
    return bytes == 0 ? 0 : bytes + vertices * sizeof(glm::vec4);
}

ShadowStage::ShadowStage(const SceneDesc& scene, const World& world, std::span<const uint8_t> glass)
    : world_(world) {
    for (const Draw& d : world.draws) {
        if (!world.casts_shadows[d.object]) continue;
        const uint32_t* first = world.indices.data() + 3 * static_cast<size_t>(d.first_triangle);
        const bool transmits = !glass.empty() && glass[d.first_triangle];
        std::vector<uint32_t>& into = transmits ? glass_indices_ : caster_indices_;
        into.insert(into.end(), first, first + 3 * d.triangle_count);
        if (transmits)
            glass_passes_.insert(glass_passes_.end(), d.triangle_count,
                                 shadow_pass(world.materials[d.material]));
    }
    light_maps_.assign(scene.lights.size(), nullptr);
    size_t shadowed = 0;
    for (const LightDesc& l : scene.lights) shadowed += l.shadows && l.type != LightType::ambient;
    light_data_.reserve(shadowed);  // no reallocation later: light_maps_ points into it
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        const LightDesc& l = scene.lights[i];
        if (!l.shadows || l.type == LightType::ambient) continue;
        light_data_.push_back(
            LightMap{i, ShadowMap{}, Rasterizer(l.shadow_resolution, l.shadow_resolution)});
    }
}

void ShadowStage::fit(LightMap& lm, const LightState& light, const Sphere& casters) const {
    ShadowMap& map = lm.map;
    const int size = lm.raster.width();
    map.softness = light.shadow_softness;
    map.bias = light.shadow_bias;
    const glm::vec3 centre(casters.center);
    const float radius = static_cast<float>(casters.radius);

    if (light.type == LightType::directional) {
        // An orthographic map round the casters' bounding sphere: the sphere
        // keeps its size as objects turn, its radius moves in steps, and the
        // map moves by whole texels, so static shadows stay still from frame
        // to frame (Valient 2008, "Stable rendering of cascaded shadow maps").
        // Receivers outside the map have no caster between them and the sun.
        const double steps =
            std::ceil(std::log2(std::max(casters.radius, 1e-6)) * kRadiusStepsPerOctave);
        const float half = static_cast<float>(std::exp2(steps / kRadiusStepsPerOctave)) *
                           (1.0f + 2.0f / static_cast<float>(size));
        const float texel = 2.0f * half / static_cast<float>(size);
        const ShadowBasis basis = shadow_basis(glm::normalize(light.direction));
        const float x = std::round(glm::dot(centre, basis.right) / texel) * texel;
        const float y = std::round(glm::dot(centre, basis.up) / texel) * texel;
        const float z = glm::dot(centre, basis.forward) - half;
        const glm::vec3 eye = basis.right * x + basis.up * y + basis.forward * z;
        set_orthographic(map, size, shadow_view(basis, eye), half, 0.0f, 2.0f * half);
        return;
    }

    // Perspective and cube maps reach from just before the nearest caster to
    // just past the farthest one.
    const float distance = glm::length(centre - light.position);
    const float far = std::max((distance + radius) * 1.01f, 1e-3f);
    const float near = std::max((distance - radius) * 0.99f, far * kMinNearOverFar);
    const int reach = std::min(size / 4, kEdgeTexels + static_cast<int>(std::ceil(map.softness)));
    const float widen = static_cast<float>(size) / static_cast<float>(size - 2 * reach);
    if (!cube_map(light.type, light.outer_angle)) {  // a spot's perspective map
        const float tan_half = std::tan(glm::radians(light.outer_angle)) * widen;
        set_perspective(map, size, light.position, glm::normalize(light.direction), tan_half, near,
                        far);
    } else {
        set_cube(map, size, light.position, widen, near, far);
    }
}

void ShadowStage::draw_face(LightMap& lm, int face, const FrameState& state,
                            std::span<const glm::vec3> positions, ThreadPool& pool) {
    ShadowMap& map = lm.map;
    draw_clip_.resize(world_.draws.size());
    for (size_t d = 0; d < world_.draws.size(); ++d)
        draw_clip_[d] = map.clip[face] * state.objects[world_.draws[d].object].transform;

    const size_t count = positions.size();
    clip_.resize(count);
    pool.parallel_for_chunks(count, kVerticesPerChunk, [&](size_t first, size_t last) {
        for (size_t v = first; v < last; ++v) {
            const uint32_t draw = world_.vertex_draw[v];
            if (!world_.casts_shadows[world_.draws[draw].object]) continue;
            clip_[v] = draw_clip_[draw] * glm::vec4(positions[v], 1.0f);
        }
    });

    draw_casters(lm, face, caster_indices_, false, pool);
    if (!glass_indices_.empty()) draw_casters(lm, face, glass_indices_, true, pool);
}

// One face of the map's opaque casters, or of its glass
// (ShadowMap::Glass), from the clip positions draw_face left.
void ShadowStage::draw_casters(LightMap& lm, int face, std::span<const uint32_t> indices,
                               bool glass, ThreadPool& pool) {
    ShadowMap& map = lm.map;
    RasterInput input;
    input.clip = clip_.data();
    input.vertex_count = clip_.size();
    input.indices = indices.data();
    input.triangle_count = indices.size() / 3;
    input.cull_back = nullptr;  // both sides cast: open meshes and planes too
    lm.raster.set_geometry(input, pool);

    const int size = map.size;
    const size_t face_texels = static_cast<size_t>(face) * size * size;
    float* texels = (glass ? map.glass.depth : map.depth).data() + face_texels;
    float* passes = glass ? map.glass.passes.data() + face_texels : nullptr;
    const float infinity = std::numeric_limits<float>::infinity();
    float* blocks = (glass ? map.glass.block_nearest : map.block_nearest).data() +
                    static_cast<size_t>(face) * map.blocks * map.blocks;
    // Tiles start on whole blocks, so each block is one tile's own.
    static_assert(kTileSize % kShadowBlock == 0);
    lm.raster.draw_tiles(pool, [&](const TileVisibility& tile) {
        for (int ty = 0; ty < tile.height; ++ty) {
            const size_t row = static_cast<size_t>(tile.y0 + ty) * size + tile.x0;
            for (int tx = 0; tx < tile.width; ++tx) {
                const int at = ty * kTileSize + tx;
                const uint32_t id = tile.id[at];
                texels[row + tx] =
                    id == kNoTriangle ? infinity : shadow_depth_from_raster(map, tile.depth[at]);
                // Where no glass casts, the filter never reads the share.
                if (passes && id != kNoTriangle)
                    passes[row + tx] = glass_passes_[lm.raster.shade_setup(id).source_triangle];
            }
        }
        nearest_in_blocks(texels, size, tile, map.blocks, blocks);
    });
}

std::span<const ShadowMap* const> ShadowStage::render(const FrameState& state,
                                                      const PosedVertices& posed,
                                                      ThreadPool& pool) {
    if (light_data_.empty()) return light_maps_;
    // The casters' bounding sphere: what the maps must hold, in this pose.
    const std::span<const Bounds> object_bounds = posed.object_bounds;
    std::vector<Sphere> spheres;
    std::vector<uint8_t> seen(object_bounds.size(), 0);
    for (const Draw& d : world_.draws) {
        if (!world_.casts_shadows[d.object] || seen[d.object] || object_bounds[d.object].empty())
            continue;
        seen[d.object] = 1;
        spheres.push_back(
            transformed_box_sphere(object_bounds[d.object], state.objects[d.object].transform));
    }
    const bool casters = !spheres.empty() && !(caster_indices_.empty() && glass_indices_.empty());
    const Sphere casters_sphere = enclosing_sphere(spheres);
    for (LightMap& lm : light_data_) {
        light_maps_[lm.light] = nullptr;
        if (!casters) continue;
        fit(lm, state.lights[lm.light], casters_sphere);
        if (!glass_indices_.empty()) {
            ShadowMap::Glass& glass = lm.map.glass;
            glass.depth.resize(lm.map.depth.size());
            glass.passes.resize(lm.map.depth.size());
            glass.block_nearest.resize(lm.map.block_nearest.size());
        }
        for (int face = 0; face < lm.map.faces; ++face)
            draw_face(lm, face, state, posed.positions, pool);
        light_maps_[lm.light] = &lm.map;
    }
    return light_maps_;
}

}  // namespace facet
