#pragma once
// Shadow stage: each frame, the shadow maps of the lights that cast
// shadows, rendered depth-only through the same raster core as the image
// (docs/scene-format.md, "Shadows"; the maps and their lookup are in
// shade/shadow_map.hpp).
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec4.hpp>

#include "anim/camera_path.hpp"
#include "anim/frame_state.hpp"
#include "core/thread_pool.hpp"
#include "raster/rasterizer.hpp"
#include "render/frame_inputs.hpp"
#include "render/pose_stage.hpp"
#include "render/world.hpp"
#include "shade/shadow_map.hpp"

namespace facet {

class ShadowStage {
  public:
    // `transmitting` (RenderPlan::transmitting): the triangles of glass
    // `pbr` draws, which cast lighter shadows (ShadowMap::glass).
    ShadowStage(const SceneDesc& scene, const World& world, std::span<const uint8_t> transmitting);

    // What the stage keeps for `scene`'s lights over `world`: per light
    // with shadows, its map's depth per texel of every face (with `glass`,
    // the glass's depth and share too) and its rasterizer's records of the
    // casters (counted as every triangle); the casters' clip positions.
    static uint64_t bytes(const SceneDesc& scene, const World& world, bool glass);

    // Renders this frame's maps from the frame's pose and returns, per
    // scene light, its map or null when it casts no shadows (off, an ambient
    // light, or nothing in the scene casts); valid until the next call. The
    // result depends on the frame alone, not on the thread count: the raster
    // core's tiles each write their own texels.
    std::span<const ShadowMap* const> render(const FrameState& state, const PosedVertices& posed,
                                             ThreadPool& pool);

  private:
    struct LightMap {
        size_t light;  // index into SceneDesc::lights
        ShadowMap map;
        Rasterizer raster;  // size x size, reused by every face and frame
    };
    void fit(LightMap& lm, const LightState& light, const Sphere& casters) const;
    void draw_face(LightMap& lm, int face, const FrameState& state,
                   std::span<const glm::vec3> positions, ThreadPool& pool);
    void draw_casters(LightMap& lm, int face, std::span<const uint32_t> indices, bool glass,
                      ThreadPool& pool);

    const World& world_;
    std::vector<uint32_t> caster_indices_;  // triangles of the objects that cast shadows
    // Glass casters' triangles apart, and each one's ShadowMap::Glass::passes.
    std::vector<uint32_t> glass_indices_;
    std::vector<float> glass_passes_;
    std::vector<glm::vec4> clip_;       // per world vertex; only casters' are written
    std::vector<glm::mat4> draw_clip_;  // per draw: model -> the face's clip space
    std::vector<LightMap> light_data_;  // never resized after construction: lights point in
    std::vector<const ShadowMap*> light_maps_;
};

}  // namespace facet
