#pragma once
// facet_bench's records and its report: the markdown tables and the plot
// of docs/performance.md, and the line the llvmpipe child prints.
#include <string>
#include <vector>

#include "bench_common.hpp"

namespace facet_bench {

// Machine-wide CPU use from /proc/stat next to this process's own (and its
// finished children's, the llvmpipe runs): what is left is other people's
// work competing for the same cores, the main source of noise here.
struct CpuSnapshot {
    Clock::time_point when = Clock::now();
    double busy_s = 0, steal_s = 0, ours_s = 0;
};
CpuSnapshot cpu_snapshot();

struct Load {
    double wall_s = 0, others_cores = NAN, steal_cores = NAN;
};
Load load_between(const CpuSnapshot& a, const CpuSnapshot& b);

struct FacetRun {
    int threads = 0;
    Stat ms;  // wall time per frame
    double cpu_ms = NAN;
};

struct SceneResult {
    std::string name, size;
    size_t triangles = 0;
    int frames = 0;
    std::vector<FacetRun> render;  // per thread count
    FacetRun job_png;              // `facet render`, PNG colour only
    FacetRun job_all;              // PNG + EXR, colour + depth
    std::vector<GlResult> gl;      // per LP_NUM_THREADS and peer (specialised, general)
    Load load;
};

std::string describe(const FacetRun& run);
std::string describe(const GlResult& gl);

// The child's result as one line of key=value words, and back.
std::string format_gl_result(const GlResult& r);
GlResult parse_gl_result(const std::string& line, int lp_threads, bool specialised);

std::string report_markdown(const std::vector<SceneResult>& results,
                            const std::vector<int>& threads, const std::vector<int>& lp_threads);

// Speed ratios (llvmpipe time / facet time) per scene, render only and whole
// job, with the goal line at 2.
void write_report_plot(const std::string& path, const std::vector<SceneResult>& results);

}  // namespace facet_bench
