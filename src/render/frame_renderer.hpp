#pragma once
// Renders one frame of a scene: vertex stage, raster core, shading. Owns the
// per-frame buffers, which it reuses from frame to frame.
#include <span>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "cloth/cloth.hpp"
#include "anim/frame_state.hpp"
#include "anim/gltf_pose.hpp"
#include "core/image.hpp"
#include "core/thread_pool.hpp"
#include "post/outlines.hpp"
#include "raster/rasterizer.hpp"
#include "render/camera.hpp"
#include "render/shadow_stage.hpp"
#include "render/style_state.hpp"
#include "render/world.hpp"
#include "shade/lighting.hpp"

namespace facet {

struct FrameImages {
    ColorImage color;            // linear RGBA
    DepthImage depth;            // linear view depth, +inf where nothing was hit
    glm::vec2 depth_view_range;  // near..far fitted to the scene, for grey depth views
};

// Per-vertex results of the vertex stage for one frame.
struct TransformedVertices {
    std::vector<glm::vec4> clip;
    std::vector<glm::vec3> world_position;
    std::vector<glm::vec3> world_normal;
    std::vector<LightingResult> lit;  // Gouraud only: lighting at each vertex
};

class FrameRenderer {
  public:
    FrameRenderer(const SceneDesc& scene, const World& world, ThreadPool& pool);

    // Renders into `out`, reusing its buffers when they have the right size
    // (fresh pages cost more to fault in and clear than the shading itself).
    void render(int frame, size_t camera_index, FrameImages& out);

    // The depth range that fits the visible scene's bounding sphere.
    glm::vec2 depth_view_range(const FrameState& state, const CameraMatrices& camera) const;

  private:
    void update_materials(const FrameState& state);
    const std::vector<Material>& materials() const { return *materials_; }
    void vertex_stage(const FrameState& state, const CameraMatrices& camera,
                      std::span<const ShadeLight> lights);
    void light_vertices(size_t first, size_t last, const glm::vec3& eye,
                        std::span<const ShadeLight> lights);
    void shade_tile(const TileVisibility& tile, const CameraMatrices& camera,
                    std::span<const ShadeLight> lights, glm::vec2 depth_range, FrameImages& out);
    void update_styles(const FrameState& state);
    void make_cloth_simulations();
    void deform_meshes(const FrameState& state);
    void draw_hidden_edges(FrameImages& target);

    const SceneDesc& scene_;
    const World& world_;
    ThreadPool& pool_;
    int side_;  // samples per pixel side: output.samples = side_ * side_
    Rasterizer rasterizer_;
    ShadowStage shadows_;  // shadow maps of the lights that cast shadows
    TransformedVertices vertices_;
    FrameImages supersampled_;                // shading target when side_ > 1
    std::vector<Material> frame_materials_;   // with animated values, when there are any
    const std::vector<Material>* materials_;  // this frame's: world_.materials or frame_materials_

    // Model-space vertices of this frame when glTF animations play (a copy
    // of the world's with the animated parts posed), else empty.
    std::vector<glm::vec3> posed_positions_, posed_normals_;
    std::vector<PosedPart> pose_scratch_;
    std::vector<std::unique_ptr<ClothSimulation>> cloth_sims_;  // per World::cloths

    // Styles: [0] the scene's, then one per object with a `style:` of its own.
    std::vector<const StyleDesc*> style_descs_;
    std::vector<uint32_t> object_style_;  // per scene object, index into styles_
    std::vector<StyleState> styles_;      // this frame's values
    bool any_gouraud_ = false;            // some style lights vertices
    TamCache tams_;
    bool outlines_on_ = false;  // the scene's style draws outlines
    OutlineBuffers outline_buffers_;
    OutlineScratch outline_scratch_;
    ColorImage outline_lines_;
    bool hidden_edges_on_ = false;  // some style draws hidden wireframe edges
    std::vector<float> hidden_coverage_;
    std::vector<glm::vec3> hidden_color_;
};

// The frame's lights for shading: directional, point and spot lights in
// scene order (lights[0] is the key light of the stylised models), then the
// ambient ones. `shadow_maps`, when given, holds each scene light's map or null.
std::vector<ShadeLight> make_shade_lights(const std::vector<LightState>& lights,
                                          std::span<const ShadowMap* const> shadow_maps = {});

}  // namespace facet
