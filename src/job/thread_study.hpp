#pragma once
// The thread study of seed 004 (docs/references.md): the same frames rendered at several thread
// counts, time per frame and speed-up against one thread (`facet bench`).
#include <functional>
#include <string>
#include <vector>

#include "core/image.hpp"
#include "render/world.hpp"
#include "scene/scene_desc.hpp"

namespace facet {

struct ThreadStudyRow {
    unsigned threads;
    double median_ms, min_ms, max_ms;  // render time per frame (no encoding)
    double speedup;                    // median at the first thread count / this median
};

struct ThreadStudy {
    std::string scene;
    int width = 0, height = 0;
    size_t frames = 0, triangles = 0;
    unsigned hardware_threads = 0;
    std::vector<ThreadStudyRow> rows;
};

// Renders `frames` (each once, in order) at every thread count.
ThreadStudy run_thread_study(const SceneDesc& scene, const World& world,
                             const std::vector<unsigned>& threads, const std::vector<int>& frames,
                             const std::function<void(const std::string&)>& progress);

std::string thread_study_markdown(const ThreadStudy& study);

// Two panels: ms per frame, and speed-up with the ideal line.
ColorImage thread_study_plot(const ThreadStudy& study);

}  // namespace facet
