#include "job/render_memory.hpp"

#include <algorithm>
#include <utility>

#include "job/frame_encoder.hpp"
#include "output/exr_compression.hpp"
#include "render/frame_inputs.hpp"
#include "render/frame_targets.hpp"
#include "render/transmission_stage.hpp"

namespace facet {
namespace {

// Bytes per item of the working records, rounded up from the structures
// they stand for (raster/setup_bins.hpp, render/vertex_stage.hpp).
constexpr uint64_t kPerTriangle = 160;   // set-up, shading planes, bin entries, source indices
constexpr uint64_t kPerVertex = 96;      // model, clip, world position and normal, screen, lighting
constexpr uint64_t kPerSample = 16 + 4;  // float colour and depth per sample
constexpr uint64_t kPerLineSample = 16;  // a sample's stroke, float RGBA
constexpr uint64_t kPerGbufferSample = 4 + 12 + 4;  // depth, normal, object id
constexpr uint64_t kPerSurfaceShare = 4;            // a pixel's share of surface samples
// Glass (render/transmission_stage.hpp): per pixel the frame as the
// backdrop's pyramid of float RGB;
// per sample the count of glass asked about, and its triangle id and
// depth in each layer, at most every sample's.
constexpr uint64_t kPerGlassPixel = 12 + 4;  // float RGB, its pyramid's levels (4/3)
constexpr uint64_t kPerGlassSample = 1 + 8 * kMaxGlassLayers;
constexpr uint64_t kPerOcclusionFactor = 4;         // occlusion's value per G-buffer element
constexpr uint64_t kPerOcclusionCell = 20 + 4 + 4;  // a cell's depth, normal, object; raw, blurred

// Bytes per pixel of each pass as a frame's images keep it
// (render/frame_renderer.hpp's FrameImages): half RGBA colour, alpha and
// lines, float depth, normal, uv, position and motion, 32-bit ids.
constexpr std::pair<Pass, uint64_t> kPassPixelBytes[] = {
    {Pass::color, 8},     {Pass::depth, 4},     {Pass::alpha, 8},       {Pass::lines, 8},
    {Pass::normal, 12},   {Pass::object_id, 4}, {Pass::material_id, 4}, {Pass::uv, 8},
    {Pass::position, 12}, {Pass::motion, 8}};

// An output pixel of each frame in flight (job/render_job.cpp's
// FrameImages): colour and depth always, and every other pass asked for.
uint64_t output_pixel_bytes(PassSet passes) {
    uint64_t bytes = 0;
    for (const auto& [pass, pass_bytes] : kPassPixelBytes)
        if (pass == Pass::color || pass == Pass::depth || passes.has(pass)) bytes += pass_bytes;
    return bytes;
}

// An EXR file in memory per byte of its samples: facet's writer (zip,
// zips, none) sizes it once, at most as large as the samples; OpenEXR's
// methods (rle, piz, dwaa) can grow it past them.
uint64_t exr_file_factor(ExrCompression method) {
    return written_by_facet(method) ? 1 : 2;
}

// What one encoder holds while it writes a frame's largest file
// (job/pass_files.cpp); the samples themselves are read where the frame
// keeps them. An EXR: the file (a multi-layer one holds every pass
// written). A PNG: its view's samples (8-bit RGB or RGBA, 16-bit grey for
// depth), the filtered rows, the compressed bytes and the file, four times
// the view.
uint64_t encoder_pixel_bytes(const OutputDesc& out) {
    uint64_t largest = 0, all = 0;
    for (const auto& [pass, pass_bytes] : kPassPixelBytes) {
        if (!out.writes(pass)) continue;
        all += pass_bytes;
        if (out.write_exr && !out.exr_multilayer)
            largest = std::max(largest, pass_bytes * exr_file_factor(out.exr_compression.of(pass)));
        if (out.write_png && pass != Pass::position && pass != Pass::motion)
            largest = std::max<uint64_t>(largest, 4 * (pass == Pass::depth ? 2 : 4));
    }
    if (out.write_exr && out.exr_multilayer)
        largest = std::max(largest, all * exr_file_factor(out.exr_compression.all));
    return largest;
}

// The frame's screen-space buffers, as the frame's targets have them
// (render/frame_targets.hpp): every sample's colour, depth and strokes
// when a stage needs the samples, and the G-buffer at the shading's
// resolution (with each pixel's surface share at the pixels).
uint64_t screen_space_bytes(const FrameTargets& targets, uint64_t pixels, uint64_t samples) {
    if (targets.shading == ShadeResolution::pixels)
        return targets.gbuffer ? pixels * (kPerGbufferSample + kPerSurfaceShare) : 0;
    return samples * (kPerSample + (targets.line_samples ? kPerLineSample : 0) +
                      (targets.gbuffer ? kPerGbufferSample : 0));
}

}  // namespace

MemoryParts render_memory(const SceneDesc& scene, const World& world, const RenderPlan& plan,
                          unsigned threads) {
    const OutputDesc& out = scene.output;
    const uint64_t pixels = static_cast<uint64_t>(out.width) * out.height;
    const uint64_t side = static_cast<uint64_t>(out.samples_per_side());
    const uint64_t samples = pixels * side * side;
    const FrameTargets& targets = plan.targets;
    const bool glass = !plan.transmitting.empty();
    MemoryParts parts;
    parts.push_back(
        {"output images", pixels * output_pixel_bytes(out.passes) * frames_in_flight(threads)});
    parts.push_back({"encoding", pixels * encoder_pixel_bytes(out) * encoder_workers(threads)});
    if (const uint64_t screen_space = screen_space_bytes(targets, pixels, samples))
        parts.push_back({"screen-space buffers", screen_space});
    if (scene.style.occlusion.enabled) {
        // Its value for each G-buffer element, and its cells: one per pixel,
        // or per 2 x 2 pixels (post/ambient_occlusion.hpp).
        const uint64_t elements = targets.shading == ShadeResolution::pixels ? pixels : samples;
        const uint64_t cells = scene.style.occlusion.half_resolution ? pixels / 4 : pixels;
        parts.push_back(
            {"ambient occlusion", elements * kPerOcclusionFactor + cells * kPerOcclusionCell});
    }
    if (glass)  // render/transmission_stage.hpp
        parts.push_back({"glass layers", pixels * kPerGlassPixel + samples * kPerGlassSample});
    parts.push_back({"triangles", static_cast<uint64_t>(world.triangle_count()) * kPerTriangle});
    const uint64_t vertex_bytes = static_cast<uint64_t>(world.positions.size()) * kPerVertex;
    parts.push_back({"vertices", vertex_bytes});
    // The motion pass poses and transforms the frame before each frame
    // afresh, with vertex records of its own (render/previous_frame_stage.hpp).
    if (out.passes.has(Pass::motion)) parts.push_back({"previous frame's vertices", vertex_bytes});
    uint64_t shadows = 0;
    for (const LightDesc& light : scene.lights) {
        if (!light.shadows) continue;
        const uint64_t faces = light.type == LightType::point ? 6 : 1;
        const uint64_t side_texels = static_cast<uint64_t>(light.shadow_resolution);
        // The depth map and its raster buffer; with glass, its depth and share too.
        shadows += side_texels * side_texels * faces * (glass ? 4 + 4 + 4 + 4 : 4 + 4);
    }
    parts.push_back({"shadow maps", shadows});
    return parts;
}

void check_render_memory(const SceneDesc& scene, const World& world, const RenderPlan& plan,
                         unsigned threads) {
    check_memory("rendering " + scene.path, render_memory(scene, world, plan, threads),
                 memory_available(),
                 "a smaller output.size or output.samples, or --threads 1 (fewer frames in "
                 "flight), needs less");
}

}  // namespace facet
