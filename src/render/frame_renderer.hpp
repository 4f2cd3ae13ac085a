#pragma once
// One frame, as a recipe of stages (docs/architecture.md, "The frame
// pipeline"): each stage has a header of its own and hands the next a plain
// record. The renderer owns the stages, which keep their buffers from frame
// to frame.
#include <atomic>
#include <functional>
#include <optional>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

#include "core/half.hpp"
#include "core/image.hpp"
#include "core/memory.hpp"
#include "core/thread_pool.hpp"
#include "raster/rasterizer.hpp"
#include "render/feature_edge_stage.hpp"
#include "render/frame_inputs.hpp"
#include "render/frame_targets.hpp"
#include "render/hidden_edge_stage.hpp"
#include "render/occlusion_stage.hpp"
#include "render/outline_stage.hpp"
#include "render/pose_stage.hpp"
#include "render/previous_frame_stage.hpp"
#include "render/render_plan.hpp"
#include "render/shade_stage.hpp"
#include "render/shadow_stage.hpp"
#include "render/surface_pass_stage.hpp"
#include "render/transmission_stage.hpp"
#include "render/vertex_stage.hpp"
#include "render/world.hpp"

namespace facet {

// A frame's passes (docs/passes.md). Colour and depth are always made;
// the others only when the scene asks for them (else they stay empty).
struct FrameImages {
    HalfColorImage color;        // linear RGBA, premultiplied, half floats (core/half.hpp)
    DepthImage depth;            // linear view depth, +inf where nothing was hit
    HalfColorImage alpha;        // the colour over nothing: coverage in a, premultiplied
    HalfColorImage lines;        // outline and wireframe strokes alone, premultiplied
    SurfacePassImages surface;   // normal, ids, uv, position, motion
    glm::vec2 depth_view_range;  // near..far fitted to the scene, for grey depth views
    glm::mat4 view{1.0f}, projection{1.0f};  // the camera, for the files' metadata
};

// Bytes per pixel of `pass` in FrameImages.
uint64_t frame_image_pixel_bytes(Pass pass);
// The bytes of a FrameImages of `out`: colour and depth always, and every
// other pass `out` asks for, at the output's size.
uint64_t frame_images_bytes(const OutputDesc& out);

class FrameRenderer {
  public:
    // `plan`: plan_render(scene, world), made once per run and read by the
    // memory estimate too.
    FrameRenderer(const SceneDesc& scene, const World& world, RenderPlan plan, ThreadPool& pool,
                  ShadingPaths paths = ShadingPaths::specialised);
    // Plans the run itself: for callers that estimate no memory.
    FrameRenderer(const SceneDesc& scene, const World& world, ThreadPool& pool,
                  ShadingPaths paths = ShadingPaths::specialised);

    // Renders into `out`, reusing its buffers when they have the right size
    // (fresh pages cost more to fault in and clear than the shading itself).
    // `stop`, when given, is asked before each tile is shaded; once it
    // answers true, the tiles not yet shaded and the stages after them are
    // skipped: `out` is then unfinished, for the caller to throw away (an
    // interactive view that has moved on). Answering false changes nothing.
    void render(int frame, size_t camera_index, FrameImages& out,
                const std::function<bool()>& stop = {});

    // What a renderer of `plan` keeps from frame to frame, part by part
    // (its stages' buffers and working records): for the memory estimate
    // (job/render_memory.hpp), which adds the frames in flight.
    static MemoryParts memory(const SceneDesc& scene, const World& world, const RenderPlan& plan);

    // The shading batches of the last frame rendered, and how many took
    // the plain path: for tests and the bench.
    ShadeCounts shading_counts() const { return {batches_.load(), plain_batches_.load()}; }

  private:
    struct FrameLights;
    FrameLights light(const FrameInputs& inputs, const PosedVertices& posed);
    void fit_targets(const FrameInputs& inputs, FrameImages& out);
    ShadeTarget shade_target(FrameImages& out);
    std::span<const glm::vec4> previous_clip(int frame, size_t camera_index);
    void apply_sample_stages(const FrameInputs& inputs, const TransformedVertices& vertices,
                             std::span<const uint8_t> edge_mask);
    void finish_colour(const FrameInputs& inputs, FrameImages& out);
    int peel_glass(const AlphaCoverage& alpha, const SurfacePassInputs& surface_in,
                   FrameImages& out);
    void draw_glass(const AlphaCoverage& alpha, const ShadeInputs& shade_in,
                    const SurfacePassInputs& surface_in, FrameImages& out,
                    const std::function<bool()>& stopped);

    const SceneDesc& scene_;
    const World& world_;
    ThreadPool& pool_;
    ShadingPaths paths_;
    std::atomic<uint64_t> batches_{0}, plain_batches_{0};  // shading_counts()
    int side_;               // samples per pixel side: output.samples = side_ * side_
    const RenderPlan plan_;  // which styles and buffers, glass and cut-outs, decided once
    FrameEvaluator evaluator_;
    PoseStage pose_;
    ShadowStage shadows_;
    VertexStage vertices_;
    Rasterizer rasterizer_;
    FeatureEdgeStage feature_edges_;
    HiddenEdgeStage hidden_edges_;
    // Depth, normal and object per sample (per pixel when occlusion is the
    // only screen-space stage), for 7c and 9.
    OutlineBuffers gbuffer_;
    Image<float> surface_share_;  // with a G-buffer at the pixels (ShadeTarget)
    OcclusionStage occlusion_;
    OutlineStage outlines_;
    TransmissionStage glass_;
    std::optional<PreviousFrameStage> previous_;  // for the motion pass only
    // Every sample in float, when the targets shade at the sample resolution.
    ColorImage sample_color_;
    DepthImage sample_depth_;
    ColorImage sample_lines_;  // the strokes alone (FrameTargets::line_samples)
};

}  // namespace facet
