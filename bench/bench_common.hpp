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
// configuration really keeps busy.
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

// Median, minimum and maximum of per-frame figures.
struct Stat {
    double median = NAN, min = NAN, max = NAN;
};

inline Stat stat_of(const std::vector<double>& v) {
    if (v.empty()) return {};
    return {median(v), *std::min_element(v.begin(), v.end()),
            *std::max_element(v.begin(), v.end())};
}

struct GlResult {
    bool ok = false;
    std::string error;
    int lp_threads = 0;
    bool specialised = true;  // the peer's shaders written for the scene, or the general ones
    // Render only: draw, glFinish, and read back colour (RGB8) and depth (float).
    Stat render_ms;
    double render_cpu_ms = NAN;  // median process CPU time per frame
    // Whole job: the same plus libpng (zlib level 1) and writing the file.
    Stat job_ms;
    double job_cpu_ms = NAN;
    std::string renderer;
    std::string features;          // what the reference draws, e.g. "phong, 4x MSAA, shadow map"
    int raster_threads_seen = -1;  // llvmpipe-N threads found in /proc/self/task
    size_t min_covered = 0;        // fewest pixels differing from the clear colour, over frames
    // The first frame against facet's, both as 8-bit sRGB.
    size_t coverage_mismatch_px = 0;  // pixels covered in one image only
    size_t differing = 0;             // pixels covered in both whose colour differs by > 8/255
    double mean_abs_diff = NAN;       // over pixels covered in both, largest channel, /255
    int max_abs_diff = 0;             // the largest of those, /255
};

// Draws `frames` of the scene with OpenGL on llvmpipe through OSMesa, in this
// process (LP_NUM_THREADS must already be set), and compares its first frame
// with facet's. Defined only when OSMesa was found (FACET_BENCH_HAVE_OSMESA).
// `png_dir` receives the whole job's PNG files. `specialised`: the shaders
// written for the scene (llvmpipe_phong.hpp), else the general ones.
GlResult bench_llvmpipe(const facet::SceneDesc& scene, const facet::World& world,
                        const std::vector<int>& frames, const std::string& png_dir,
                        bool specialised);

}  // namespace facet_bench
