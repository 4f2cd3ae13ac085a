#include "render/frame_renderer.hpp"

#include "post/resolve.hpp"
#include "render/alpha_coverage.hpp"
#include "render/crossing_stage.hpp"
#include "render/shade_lights.hpp"
#include "render/shade_stage.hpp"

namespace facet {
namespace {

// Gives `image` the size, keeping its buffer when it has it already.
// Shading writes every pixel (background included), so nothing is cleared.
template <typename Image>
void fit(Image& image, int width, int height) {
    if (image.width != width || image.height != height) image = Image::uninitialized(width, height);
}

RasterInput raster_input(const World& world, const TransformedVertices& vertices,
                         const PosedVertices& posed, const std::vector<uint8_t>& coverage_tested) {
    RasterInput input;
    input.clip = vertices.clip.data();
    input.vertex_count = vertices.clip.size();
    input.indices = world.indices.data();
    input.triangle_count = world.triangle_count();
    input.cull_back = world.cull_back.data();
    input.flip_winding = posed.flipped_triangles.empty() ? nullptr : posed.flipped_triangles.data();
    input.coverage_tested = coverage_tested.empty() ? nullptr : coverage_tested.data();
    return input;
}

}  // namespace

FrameRenderer::FrameRenderer(const SceneDesc& scene, const World& world, ThreadPool& pool)
    : scene_(scene),
      world_(world),
      pool_(pool),
      side_(scene.output.samples_per_side()),
      evaluator_(scene, world, side_),
      pose_(scene, world),
      shadows_(scene, world),
      vertices_(world),
      // Tiles hold whole pixels of the k x k sample grid.
      rasterizer_(scene.output.width * side_, scene.output.height * side_,
                  kTileSize - kTileSize % side_),
      feature_edges_(world),
      hidden_edges_(world),
      coverage_tested_(coverage_tested_triangles(world)) {
    if (scene.output.writes(Pass::motion)) previous_.emplace(scene, world);
}

void FrameRenderer::render(int frame, size_t camera_index, FrameImages& out,
                           const std::function<bool()>& stop) {
    const auto stopped = [&stop] { return stop && stop(); };
    const StylePlan& plan = evaluator_.plan();
    const PassSet passes = scene_.output.passes;
    const FrameInputs inputs = evaluator_.evaluate(frame, camera_index);
    // Animated meshes and cloth take this frame's pose first: the shadow
    // maps and the image are both drawn from it.
    const PosedVertices posed = pose_.pose(inputs.state);
    const auto shadow_maps = shadows_.render(inputs.state, posed, pool_);
    const std::vector<ShadeLight> lights = make_shade_lights(inputs.state.lights, shadow_maps);
    std::vector<ShadeLight> shadow_lights;
    for (const ShadeLight& l : lights)
        if (l.shadow) shadow_lights.push_back(l);
    const TransformedVertices& vertices =
        vertices_.transform(inputs, posed, lights, plan.any_gouraud, pool_);
    rasterizer_.set_geometry(raster_input(world_, vertices, posed, coverage_tested_), pool_);

    // Shading writes finished pixels, resolving anti-aliased ones itself,
    // unless screen-space passes need every sample first (then post/
    // resolves). Either way one sample per pixel without anti-aliasing.
    const int width = scene_.output.width, height = scene_.output.height;
    fit(out.color, width, height);
    fit(out.depth, width, height);
    out.depth_view_range = inputs.depth_view_range;
    out.view = inputs.camera.view;
    out.projection = inputs.camera.projection;
    const bool want_alpha = passes.has(Pass::alpha), want_lines = passes.has(Pass::lines);
    if (want_alpha) fit(out.alpha, width, height);
    if (want_lines) fit(out.lines, width, height);
    const bool want_gbuffer = plan.outlines || plan.occlusion;
    const bool per_sample = want_gbuffer || plan.hidden_edges || want_lines;
    if (per_sample) {
        fit(sample_color_, rasterizer_.width(), rasterizer_.height());
        fit(sample_depth_, rasterizer_.width(), rasterizer_.height());
        // Hidden edges need the visible strokes, to stay under them.
        if (want_lines || plan.hidden_edges)
            fit(sample_lines_, rasterizer_.width(), rasterizer_.height());
    }
    const std::span<const uint8_t> edge_mask = feature_edges_.classify(vertices.clip, inputs, plan);
    const ShadeInputs shade_in{world_, inputs,        plan,  vertices,
                               lights, shadow_lights, side_, edge_mask};
    if (want_gbuffer &&
        (gbuffer_.width != rasterizer_.width() || gbuffer_.height != rasterizer_.height()))
        gbuffer_.reset(rasterizer_.width(), rasterizer_.height());
    ShadeTarget shade_out{per_sample ? nullptr : &out.color, per_sample ? &sample_color_ : nullptr,
                          per_sample ? sample_depth_ : out.depth,
                          want_gbuffer ? &gbuffer_ : nullptr};
    if (want_alpha && !per_sample) shade_out.pixels_over_nothing = &out.alpha;
    if (want_lines || (per_sample && plan.hidden_edges)) shade_out.line_samples = &sample_lines_;

    // The surface passes, when asked for, from the same visibility buffer.
    std::span<const glm::vec4> previous_clip;
    if (previous_)
        previous_clip =
            previous_->clip_positions(evaluator_.evaluate(frame - 1, camera_index), pool_);
    const SurfacePassInputs surface_in{world_,
                                       inputs,
                                       vertices,
                                       previous_clip,
                                       side_,
                                       passes,
                                       scene_.output.normals_in_camera_space,
                                       width,
                                       height};
    const bool surface_passes = wants_surface_passes(passes);
    if (surface_passes) fit_surface_passes(surface_in, out.surface);

    const AlphaCoverage alpha(world_, inputs.materials);
    rasterizer_.draw_tiles(
        pool_,
        [&](const TileVisibility& tile) {
            if (stopped()) return;  // shading is most of a frame's time
            shade_tile(tile, rasterizer_, shade_in, shade_out);
            if (surface_passes) write_surface_passes(tile, rasterizer_, surface_in, out.surface);
        },
        alpha.test());
    if (!per_sample || stopped()) return;
    ColorImage* lines = want_lines ? &sample_lines_ : nullptr;
    if (plan.occlusion)
        occlusion_.apply(gbuffer_, side_, inputs.camera, inputs.occlusion, sample_color_, pool_);
    if (plan.hidden_edges && !edge_mask.empty())
        hidden_edges_.draw(vertices.clip, inputs, plan, edge_mask, side_, sample_depth_,
                           sample_color_, sample_lines_);
    if (plan.outlines) {
        // Stage 8b: intersection lines only where objects really cross.
        std::vector<uint64_t> crossing;
        if (inputs.outlines.intersection.enabled)
            crossing = crossing_object_pairs(world_, vertices);
        gbuffer_.crossing_pairs = inputs.outlines.intersection.enabled ? &crossing : nullptr;
        outlines_.draw(inputs.outlines, gbuffer_, sample_color_, pool_, lines);
        gbuffer_.crossing_pairs = nullptr;
    }
    resolve_supersampled({sample_color_, sample_depth_, lines, side_, inputs.background},
                         {out.color, out.depth, want_alpha ? &out.alpha : nullptr,
                          want_lines ? &out.lines : nullptr},
                         pool_);
}

}  // namespace facet
