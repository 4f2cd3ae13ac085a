#pragma once
// Stage 1 of a frame: evaluate everything the frame's stages read that the
// scene keys or animates (anim/frame_state.hpp for objects, camera and
// lights; materials, styles and outlines here), into one plain record.
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "anim/frame_state.hpp"
#include "post/ambient_occlusion.hpp"
#include "post/outlines.hpp"
#include "render/camera.hpp"
#include "render/style_eval.hpp"
#include "render/world.hpp"
#include "shade/model_pbr.hpp"
#include "shade/shading_models.hpp"
#include "shade/style_state.hpp"

namespace facet {

// Which style shades which object, fixed for a run: [0] is the scene's
// style, then one per object with a `style:` of its own.
struct StylePlan {
    std::vector<const StyleDesc*> styles;
    std::vector<uint32_t> object_style;  // per scene object, index into styles
    // Per scene object: 1 when its style is `pbr`, which draws normal maps.
    std::vector<uint8_t> object_normal_mapped;
    bool any_gouraud = false;   // some style lights vertices
    bool hidden_edges = false;  // some style draws hidden wireframe edges
    bool outlines = false;      // the scene's style draws outlines
    bool occlusion = false;     // the scene's style darkens corners (ambient occlusion)
};

StylePlan plan_styles(const SceneDesc& scene);

// The camera's heading: the angle about +Y, in degrees, that turns -Z
// (where a camera with no rotation looks) to the camera's forward
// direction seen from above. An environment with follow_camera turns by it.
float camera_heading_degrees(const CameraMatrices& camera);

struct FrameInputs {
    FrameState state;  // objects, camera and lights at this frame
    CameraMatrices camera;
    std::vector<Material> materials;  // the world's, with this frame's animated values
    // Per scene object: how much its transform scales lengths this frame
    // (object_scale, anim/frame_state.hpp), settled once for the shading
    // stage, which scales a volume's thickness by it.
    std::vector<float> object_scales;
    std::vector<StyleState> styles;  // StylePlan::styles at this frame
    // Per style and draw, draw_features[style * draws + draw]: the features
    // (MaterialFeature) the style draws of the draw's material and mesh
    // part at this frame, settled once for the shading stage.
    std::vector<uint32_t> draw_features;
    // Per style: what its model reads, and whether its batches with no
    // drawn feature take the plain path (shade/shading_models.hpp).
    std::vector<ModelNeeds> style_needs;
    std::vector<uint8_t> style_plain;
    OutlineStyle outlines;     // when StylePlan::outlines; widths in sample pixels
    OcclusionStyle occlusion;  // when StylePlan::occlusion
    // Linear RGBA behind everything, premultiplied; transparent black when
    // the environment is the background (composited after shading).
    glm::vec4 background;
    // The `pbr` model's indirect light (map null: none), and whether it
    // shows behind the scene, blurred by environment_blur (0..1).
    EnvironmentLighting environment;
    bool environment_background = false;
    float environment_blur = 0.0f;
    // Near..far of the visible scene's bounding sphere, for grey depth
    // views (the depth PNG, unless output.depth_range is set).
    glm::vec2 depth_view_range;
    // What the `depth` shading model maps to white..black: the style's
    // depth_range, else depth_view_range.
    glm::vec2 style_depth_range;
};

// Evaluates frames of one scene. Keeps what is expensive to make and the
// same across frames (tonal art maps), so evaluate() is not const.
class FrameEvaluator {
  public:
    // `samples_per_side` scales outline widths to the sample grid; `plan`
    // (plan_styles of `scene`) must outlive the evaluator.
    FrameEvaluator(const SceneDesc& scene, const World& world, const StylePlan& plan,
                   int samples_per_side);

    FrameInputs evaluate(int frame, size_t camera_index);

  private:
    const SceneDesc& scene_;
    const World& world_;
    int samples_per_side_;
    const StylePlan& plan_;
    TamCache tams_;
    std::vector<FramingShape> framing_;  // render/framing_shapes.hpp
};

// The depth range that fits the visible scene's bounding sphere.
glm::vec2 fit_depth_view_range(const World& world, const FrameState& state,
                               const CameraMatrices& camera);

}  // namespace facet
