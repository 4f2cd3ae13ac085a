#include "job/thread_study.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <thread>

#include "core/elapsed.hpp"
#include "core/thread_pool.hpp"
#include "job/labels.hpp"
#include "job/plot.hpp"
#include "render/frame_renderer.hpp"

namespace facet {

ThreadStudy run_thread_study(const SceneDesc& scene, const World& world,
                             const std::vector<unsigned>& threads, const std::vector<int>& frames,
                             const std::function<void(const std::string&)>& progress) {
    ThreadStudy study;
    study.scene = scene.path;
    study.width = scene.output.width;
    study.height = scene.output.height;
    study.frames = frames.size();
    study.triangles = world.triangle_count();
    study.hardware_threads = available_cores();
    for (unsigned count : threads) {
        ThreadPool pool(count);
        FrameRenderer renderer(scene, world, pool);
        FrameImages images;
        // One untimed frame first: buffers and page faults are a one-off
        // cost of the first frame, not of the thread count.
        if (!frames.empty()) renderer.render(frames.front(), 0, images);
        std::vector<double> times;
        for (int frame : frames) {
            const auto start = std::chrono::steady_clock::now();
            renderer.render(frame, 0, images);
            times.push_back(ms_since(start));
        }
        std::vector<double> sorted = times;
        std::sort(sorted.begin(), sorted.end());
        const double median =
            sorted.size() % 2 ? sorted[sorted.size() / 2]
                              : 0.5 * (sorted[sorted.size() / 2 - 1] + sorted[sorted.size() / 2]);
        study.rows.push_back({count, median, sorted.front(), sorted.back(), 0});
        if (progress) {
            char line[128];
            std::snprintf(line, sizeof line, "%u thread%s: %.1f ms per frame (median of %zu)",
                          count, count == 1 ? "" : "s", median, times.size());
            progress(line);
        }
    }
    for (ThreadStudyRow& row : study.rows)
        row.speedup = study.rows.front().median_ms / row.median_ms;
    return study;
}

std::string thread_study_markdown(const ThreadStudy& study) {
    std::string out;
    char line[256];
    std::snprintf(line, sizeof line,
                  "Thread study of `%s`: %dx%d, %zu frames, %zu triangles, %u hardware threads; "
                  "render time per frame, encoding excluded.\n\n",
                  study.scene.c_str(), study.width, study.height, study.frames, study.triangles,
                  study.hardware_threads);
    out += line;
    out += "| threads | ms per frame (median) | min | max | speed-up | efficiency |\n";
    out += "|---:|---:|---:|---:|---:|---:|\n";
    for (const ThreadStudyRow& r : study.rows) {
        std::snprintf(line, sizeof line, "| %u | %.1f | %.1f | %.1f | %.2fx | %.0f%% |\n",
                      r.threads, r.median_ms, r.min_ms, r.max_ms, r.speedup,
                      100.0 * r.speedup * study.rows.front().threads / r.threads);
        out += line;
    }
    return out;
}

ColorImage thread_study_plot(const ThreadStudy& study) {
    constexpr int kPanelWidth = 420, kPanelHeight = 320;
    ColorImage image(2 * kPanelWidth, kPanelHeight, glm::vec4(1.0f));
    PlotPanel time{"Render time per frame", "threads", "ms", {}};
    PlotPanel speed{"Speed-up", "threads", "x", {}};
    PlotSeries ms{"median", {}, glm::vec3(0.1f, 0.35f, 0.75f), false};
    PlotSeries measured{"measured", {}, glm::vec3(0.8f, 0.25f, 0.1f), false};
    PlotSeries ideal{"ideal", {}, glm::vec3(0.5f), true};
    const double base = study.rows.empty() ? 1 : study.rows.front().threads;
    for (const ThreadStudyRow& r : study.rows) {
        ms.points.push_back({r.threads, r.median_ms});
        measured.points.push_back({r.threads, r.speedup});
        ideal.points.push_back({r.threads, r.threads / base});
    }
    time.integer_x = speed.integer_x = true;
    time.series = {ms};
    speed.series = {ideal, measured};
    draw_plot(image, 0, 0, kPanelWidth, kPanelHeight, time);
    draw_plot(image, kPanelWidth, 0, kPanelWidth, kPanelHeight, speed);
    return image;
}

}  // namespace facet
