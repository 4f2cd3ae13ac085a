#include "render/frame_renderer.hpp"

#include <utility>

#include "post/resolve.hpp"
#include "render/alpha_coverage.hpp"
#include "render/crossing_stage.hpp"
#include "render/environment_background_stage.hpp"
#include "render/shade_lights.hpp"
#include "render/transmission_stage.hpp"

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

uint64_t frame_image_pixel_bytes(Pass pass) {
    switch (pass) {
        case Pass::color:
            return decltype(FrameImages::color)::kPixelBytes;
        case Pass::alpha:
            return decltype(FrameImages::alpha)::kPixelBytes;
        case Pass::lines:
            return decltype(FrameImages::lines)::kPixelBytes;
        case Pass::depth:
            return decltype(FrameImages::depth)::kPixelBytes;
        default:
            return surface_pass_pixel_bytes(pass);
    }
}

uint64_t frame_images_bytes(const OutputDesc& out) {
    uint64_t pixel_bytes = 0;
    for (const Pass pass : kAllPasses) {
        if (pass == Pass::color || pass == Pass::depth || out.passes.has(pass))
            pixel_bytes += frame_image_pixel_bytes(pass);
    }
    return static_cast<uint64_t>(out.width) * out.height * pixel_bytes;
}

namespace {

// The renderer's own screen-space buffers (fit_targets): every sample's
// colour, depth and strokes when a stage needs the samples, and the
// G-buffer at the shading's resolution (with each pixel's surface share at
// the pixels).
uint64_t screen_space_bytes(const FrameTargets& targets, uint64_t pixels, uint64_t samples) {
    if (targets.shading == ShadeResolution::pixels)
        return targets.gbuffer ? pixels * (kOutlineElementBytes + Image<float>::kPixelBytes) : 0;
    return samples * (ColorImage::kPixelBytes + DepthImage::kPixelBytes +
                      (targets.line_samples ? ColorImage::kPixelBytes : 0) +
                      (targets.gbuffer ? kOutlineElementBytes : 0));
}

}  // namespace

MemoryParts FrameRenderer::memory(const SceneDesc& scene, const World& world,
                                  const RenderPlan& plan) {
    const OutputDesc& out = scene.output;
    const uint64_t pixels = static_cast<uint64_t>(out.width) * out.height;
    const uint64_t side = static_cast<uint64_t>(out.samples_per_side());
    const uint64_t samples = pixels * side * side;
    const uint64_t triangles = world.triangle_count(), vertices = world.positions.size();
    const bool glass = !plan.transmitting.empty();
    MemoryParts parts;
    if (const uint64_t bytes = screen_space_bytes(plan.targets, pixels, samples))
        parts.push_back({"screen-space buffers", bytes});
    if (plan.styles.occlusion) {
        // A value per G-buffer element; cells of a pixel, or of 2 x 2 pixels.
        const uint64_t elements =
            plan.targets.shading == ShadeResolution::pixels ? pixels : samples;
        const uint64_t cells = scene.style.occlusion.half_resolution ? pixels / 4 : pixels;
        parts.push_back({"ambient occlusion", OcclusionStage::bytes(elements, cells)});
    }
    if (glass) parts.push_back({"glass layers", TransmissionStage::bytes(pixels, samples)});
    parts.push_back({"triangles", Rasterizer::bytes(triangles, 0)});
    const uint64_t vertex_bytes =
        VertexStage::bytes(vertices, !world.tangents.empty(), plan.styles.any_gouraud);
    parts.push_back({"vertices", vertex_bytes + Rasterizer::bytes(0, vertices)});
    // The motion pass poses and transforms the frame before each frame
    // afresh, with a vertex stage of its own (PreviousFrameStage).
    if (out.writes(Pass::motion))
        parts.push_back({"previous frame's vertices", VertexStage::bytes(vertices, false, false)});
    parts.push_back({"shadow maps", ShadowStage::bytes(scene, world, glass)});
    return parts;
}

// This frame's lights, with their shadow maps (the shadow stage's, until
// its next frame).
struct FrameRenderer::FrameLights {
    std::span<const ShadowMap* const> shadow_maps;
    std::vector<ShadeLight> all;
    std::vector<ShadeLight> casting_shadows;  // with their maps, for Gouraud's per-pixel shadows
};

FrameRenderer::FrameRenderer(const SceneDesc& scene, const World& world, ThreadPool& pool,
                             ShadingPaths paths)
    : FrameRenderer(scene, world, plan_render(scene, world), pool, paths) {}

FrameRenderer::FrameRenderer(const SceneDesc& scene, const World& world, RenderPlan plan,
                             ThreadPool& pool, ShadingPaths paths)
    : scene_(scene),
      world_(world),
      pool_(pool),
      paths_(paths),
      side_(scene.output.samples_per_side()),
      plan_(std::move(plan)),
      evaluator_(scene, world, plan_.styles, side_),
      pose_(scene, world),
      shadows_(scene, world, plan_.transmitting),
      vertices_(world),
      // Tiles hold whole pixels of the k x k sample grid.
      rasterizer_(scene.output.width * side_, scene.output.height * side_,
                  kTileSize - kTileSize % side_),
      feature_edges_(world),
      hidden_edges_(world),
      glass_(plan_.transmitting, plan_.alpha_tested) {
    if (scene.output.writes(Pass::motion)) previous_.emplace(scene, world);
}

void FrameRenderer::render(int frame, size_t camera_index, FrameImages& out,
                           const std::function<bool()>& stop) {
    const auto stopped = [&stop] { return stop && stop(); };
    const StylePlan& plan = plan_.styles;
    const FrameInputs inputs = evaluator_.evaluate(frame, camera_index);
    // Animated meshes and cloth take this frame's pose first: the shadow
    // maps and the image are both drawn from it.
    const PosedVertices posed = pose_.pose(inputs.state);
    const FrameLights lights = light(inputs, posed);
    const TransformedVertices& vertices =
        vertices_.transform(inputs, posed, lights.all, plan.any_gouraud ? &plan : nullptr, pool_);
    rasterizer_.set_geometry(raster_input(world_, vertices, posed, plan_.coverage_tested), pool_);
    fit_targets(inputs, out);
    const std::span<const uint8_t> edge_mask = feature_edges_.classify(vertices.clip, inputs, plan);
    const ShadeInputs shade_in{world_,   inputs,     plan,
                               vertices, lights.all, lights.casting_shadows,
                               side_,    edge_mask,  paths_};
    const ShadeTarget shade_out = shade_target(out);
    const SurfacePassInputs surface_in{
        .world = world_,
        .frame = inputs,
        .vertices = vertices,
        .previous_clip = previous_clip(frame, camera_index),
        .samples_per_side = side_,
        .passes = scene_.output.passes,
        .normals_in_camera_space = scene_.output.normals_in_camera_space,
        .width = scene_.output.width,
        .height = scene_.output.height,
        .normal_mapped = plan.object_normal_mapped};
    if (plan_.targets.surface_passes) fit_surface_passes(surface_in, out.surface);
    const AlphaCoverage alpha(world_, inputs.materials);
    batches_ = 0;
    plain_batches_ = 0;
    glass_.begin_frame(rasterizer_);
    // Stage 7: the opaque surfaces (glass waits for stage 12).
    rasterizer_.draw_tiles(
        pool_,
        [&](const TileVisibility& tile) {
            if (stopped()) return;  // shading is most of a frame's time
            const ShadeCounts counts = shade_tile(tile, rasterizer_, shade_in, shade_out);
            batches_ += counts.batches;
            plain_batches_ += counts.plain;
            if (plan_.targets.surface_passes)
                write_surface_passes(tile, rasterizer_, surface_in, out.surface);
        },
        glass_.test(0, alpha));
    if (stopped()) return;
    if (plan_.targets.shading == ShadeResolution::pixels && plan.occlusion)
        occlusion_.apply_to_pixels(gbuffer_, surface_share_, inputs.camera, inputs.occlusion,
                                   inputs.background, out.color,
                                   plan_.targets.alpha ? &out.alpha : nullptr, pool_);
    if (plan_.targets.shading == ShadeResolution::samples)
        apply_sample_stages(inputs, vertices, edge_mask);
    finish_colour(inputs, out);
    if (glass_.any_in(0)) draw_glass(alpha, shade_in, surface_in, out, stopped);
}

// The samples resolved into the output's pixels, and the environment
// composited behind: the finished colour, over which glass is drawn.
void FrameRenderer::finish_colour(const FrameInputs& inputs, FrameImages& out) {
    if (plan_.targets.shading == ShadeResolution::samples) {
        ColorImage* lines = plan_.targets.lines ? &sample_lines_ : nullptr;
        resolve_supersampled({sample_color_, sample_depth_, lines, side_, inputs.background},
                             {out.color, out.depth, plan_.targets.alpha ? &out.alpha : nullptr,
                              plan_.targets.lines ? &out.lines : nullptr},
                             pool_);
    }
    if (inputs.environment_background)
        composite_environment_background(out.color, inputs.camera, inputs.environment,
                                         inputs.environment_blur, pool_);
}

// Stage 12, first half: the glass layers, nearest first
// (render/transmission_stage.hpp). The first shows the nearest surface of
// every sample, glass or not: the surface passes are its. Returns how
// many layers have glass.
int FrameRenderer::peel_glass(const AlphaCoverage& alpha, const SurfacePassInputs& surface_in,
                              FrameImages& out) {
    int layers = 0;
    while (layers < kMaxGlassLayers && glass_.any_in(layers)) {
        const int layer = layers + 1;
        const std::span<const uint8_t> tiles = glass_.tiles_of(layer);
        if (std::find(tiles.begin(), tiles.end(), 1) == tiles.end()) break;
        rasterizer_.draw_tiles(
            pool_,
            [&](const TileVisibility& tile) {
                glass_.keep_layer(layer, tile, rasterizer_);
                if (layer == 1 && plan_.targets.surface_passes)
                    write_surface_passes(tile, rasterizer_, surface_in, out.surface);
            },
            glass_.test(layer, alpha), tiles);
        if (!glass_.any_in(layer)) break;  // found none: not a layer
        layers = layer;
    }
    return layers;
}

// Stage 12, second half: each layer shaded back to front over a backdrop
// of the frame so far.
void FrameRenderer::draw_glass(const AlphaCoverage& alpha, const ShadeInputs& shade_in,
                               const SurfacePassInputs& surface_in, FrameImages& out,
                               const std::function<bool()>& stopped) {
    const int layers = peel_glass(alpha, surface_in, out);
    // Over the finished colour: no G-buffer, strokes or surface share.
    ShadeTarget target = shade_target(out);
    target.gbuffer = nullptr;
    target.line_samples = nullptr;
    target.surface_share = nullptr;
    target.over_existing = true;
    const FrameInputs& inputs = shade_in.frame;
    for (int layer = layers; layer >= 1 && !stopped(); --layer) {
        ShadeInputs glass_in = shade_in;
        glass_in.backdrop = &glass_.backdrop(out.color, inputs.camera, pool_);
        const std::span<const uint8_t> tiles = glass_.glass_tiles(layer);
        pool_.parallel_for(tiles.size(), [&](size_t tile) {
            if (!tiles[tile] || stopped()) return;
            const TileVisibility visible =
                glass_.layer_tile(layer, static_cast<int>(tile), rasterizer_);
            const ShadeCounts counts = shade_tile(visible, rasterizer_, glass_in, target);
            batches_ += counts.batches;
        });
        // At the samples the layer is resolved again; at the pixels it
        // was drawn over the finished colour.
        if (plan_.targets.shading == ShadeResolution::samples) finish_colour(inputs, out);
    }
}

FrameRenderer::FrameLights FrameRenderer::light(const FrameInputs& inputs,
                                                const PosedVertices& posed) {
    FrameLights lights;
    lights.shadow_maps = shadows_.render(inputs.state, posed, pool_);
    lights.all = make_shade_lights(inputs.state.lights, lights.shadow_maps);
    for (const ShadeLight& l : lights.all)
        if (l.shadow) lights.casting_shadows.push_back(l);
    return lights;
}

// The output images, and the sample buffers when the targets shade at the
// sample resolution. One sample per pixel without anti-aliasing.
void FrameRenderer::fit_targets(const FrameInputs& inputs, FrameImages& out) {
    const int width = scene_.output.width, height = scene_.output.height;
    fit(out.color, width, height);
    fit(out.depth, width, height);
    out.depth_view_range = inputs.depth_view_range;
    out.view = inputs.camera.view;
    out.projection = inputs.camera.projection;
    if (plan_.targets.alpha) fit(out.alpha, width, height);
    if (plan_.targets.lines) fit(out.lines, width, height);
    if (plan_.targets.shading == ShadeResolution::pixels) {
        if (!plan_.targets.gbuffer) return;
        if (gbuffer_.width != width || gbuffer_.height != height) gbuffer_.reset(width, height);
        fit(surface_share_, width, height);
        return;
    }
    const int sample_width = rasterizer_.width(), sample_height = rasterizer_.height();
    fit(sample_color_, sample_width, sample_height);
    fit(sample_depth_, sample_width, sample_height);
    if (plan_.targets.line_samples) fit(sample_lines_, sample_width, sample_height);
    if (plan_.targets.gbuffer &&
        (gbuffer_.width != sample_width || gbuffer_.height != sample_height))
        gbuffer_.reset(sample_width, sample_height);
}

ShadeTarget FrameRenderer::shade_target(FrameImages& out) {
    OutlineBuffers* gbuffer = plan_.targets.gbuffer ? &gbuffer_ : nullptr;
    if (plan_.targets.shading == ShadeResolution::pixels)
        return {.resolution = ShadeResolution::pixels,
                .pixels = &out.color,
                .samples = nullptr,
                .depth = out.depth,
                .gbuffer = gbuffer,
                .pixels_over_nothing = plan_.targets.alpha ? &out.alpha : nullptr,
                .line_samples = nullptr,
                .surface_share = gbuffer ? &surface_share_ : nullptr};
    return {.resolution = ShadeResolution::samples,
            .pixels = nullptr,
            .samples = &sample_color_,
            .depth = sample_depth_,
            .gbuffer = gbuffer,
            .pixels_over_nothing = nullptr,
            .line_samples = plan_.targets.line_samples ? &sample_lines_ : nullptr,
            .surface_share = nullptr};
}

// The previous frame's clip positions, for the motion pass; else empty.
std::span<const glm::vec4> FrameRenderer::previous_clip(int frame, size_t camera_index) {
    if (!previous_) return {};
    return previous_->clip_positions(evaluator_.evaluate(frame - 1, camera_index), pool_);
}

// Stages 7c to 9, on the samples: ambient occlusion, hidden edges, outlines.
void FrameRenderer::apply_sample_stages(const FrameInputs& inputs,
                                        const TransformedVertices& vertices,
                                        std::span<const uint8_t> edge_mask) {
    const StylePlan& plan = plan_.styles;
    if (plan.occlusion)
        occlusion_.apply_to_samples(gbuffer_, side_, inputs.camera, inputs.occlusion, sample_color_,
                                    pool_);
    if (plan.hidden_edges && !edge_mask.empty())
        hidden_edges_.draw(vertices.clip, inputs, plan, edge_mask, side_, sample_depth_,
                           sample_color_, sample_lines_);
    if (!plan.outlines) return;
    // Stage 8b: intersection lines only where objects really cross.
    const bool intersections = inputs.outlines.intersection.enabled;
    const std::vector<uint64_t> crossing =
        intersections ? crossing_object_pairs(world_, vertices) : std::vector<uint64_t>{};
    outlines_.draw(inputs.outlines, gbuffer_, intersections ? &crossing : nullptr, sample_color_,
                   pool_, plan_.targets.lines ? &sample_lines_ : nullptr);
}

}  // namespace facet
