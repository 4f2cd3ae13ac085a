#include "job/render_memory.hpp"

#include "job/frame_encoder.hpp"
#include "job/pass_files.hpp"
#include "render/frame_renderer.hpp"

namespace facet {

MemoryParts render_memory(const SceneDesc& scene, const World& world, const RenderPlan& plan,
                          unsigned threads) {
    MemoryParts parts;
    parts.push_back(
        {"output images", frame_images_bytes(scene.output) * frames_in_flight(threads)});
    parts.push_back({"encoding", encoding_bytes(scene.output) * encoder_workers(threads)});
    for (const auto& [part, bytes] : FrameRenderer::memory(scene, world, plan))
        if (bytes > 0) parts.push_back({part, bytes});
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
