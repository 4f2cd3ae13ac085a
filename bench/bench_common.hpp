#pragma once
// Shared by facet_bench.cpp and llvmpipe_reference.cpp: timing helpers and
// the llvmpipe side's results.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

#include <time.h>

#include "render/world.hpp"
#include "scene/scene_desc.hpp"

namespace facet_bench {

using Clock = std::chrono::steady_clock;

inline double ms_since(Clock::time_point t0, Clock::time_point t1) {
    return std::chrono::duration<double, std::milli>(t1 - t0).count();
}

// CPU time of the whole process (all threads), to show how many cores a
// "1 thread" configuration really keeps busy.
inline double process_cpu_ms() {
    timespec ts{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) * 1e3 + static_cast<double>(ts.tv_nsec) * 1e-6;
}

inline double median(std::vector<double> v) {
    if (v.empty()) return NAN;
    std::sort(v.begin(), v.end());
    size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

struct GlResult {
    bool ok = false;
    std::string error;
    int lp_threads = 0;
    double finish_ms = NAN, readback_ms = NAN;  // medians: draw + glFinish; + glReadPixels
    double readback_min_ms = NAN, readback_max_ms = NAN;
    double readback_cpu_ms = NAN;  // median process CPU time over draw + finish + readback
    std::string renderer;
    int raster_threads_seen = -1;  // llvmpipe-N threads found in /proc/self/task
    size_t min_covered = 0;        // fewest pixels differing from the clear colour, over frames
    double mean_abs_diff = NAN;    // vs facet's first frame, 8-bit linear units
    double coverage_mismatch = NAN;  // fraction of pixels covered in one image only
    size_t differing = 0;            // covered pixels whose colour differs at all
    int max_diff = -1;               // largest channel difference, 8-bit
    size_t coverage_mismatch_px = 0;
};

// Draws `frames` of the scene with OpenGL on llvmpipe through OSMesa, in this
// process (LP_NUM_THREADS must already be set), and compares its first frame
// with facet's. Defined only when OSMesa was found (FACET_BENCH_HAVE_OSMESA).
GlResult bench_llvmpipe(const facet::SceneDesc& scene, const facet::World& world,
                        const std::vector<int>& frames);

}  // namespace facet_bench
