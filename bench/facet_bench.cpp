// facet_bench: facet against OpenGL on Mesa's llvmpipe (OSMesa, off-screen),
// scene by scene, in the same run: render only (the image and its depth in
// memory) and the whole job (PNG files written), at each thread count, with
// CPU time per frame. docs/performance.md explains what is measured;
// scripts/bench.sh builds the meshes and runs it.
//
// The llvmpipe side runs in a child process per thread count, because
// llvmpipe reads LP_NUM_THREADS once, when the first context is created:
// the bench re-executes itself with `--gl-child` and LP_NUM_THREADS set.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <sys/resource.h>
#include <unistd.h>

#include "bench_common.hpp"
#include "bench_report.hpp"
#include "blob_mesh.hpp"
#include "codec_study.hpp"
#include "core/error.hpp"
#include "core/thread_pool.hpp"
#include "job/render_job.hpp"
#include "render/frame_renderer.hpp"
#include "render/world.hpp"
#include "scene/scene_desc.hpp"

using namespace facet_bench;
namespace fs = std::filesystem;

namespace {

struct Options {
    std::vector<std::string> scenes;
    int frames = 0;  // 0: all frames of the scene
    std::vector<int> threads = {1, 2};
    std::vector<int> lp_threads = {2};
    bool llvmpipe = true;
    bool general_peer = true;  // llvmpipe with its general shaders too, beside the specialised
    bool jobs = true;          // also time `facet render` writing files
    std::string plot;          // PNG of the ratios, if set
    std::string make_meshes;   // write the blobs into this folder and stop
    uint32_t seed = 1;         // with make_meshes
    bool gl_child = false;     // internal: the llvmpipe side of one scene
    std::string png_dir;       // internal, with gl_child
    bool specialised = true;   // internal, with gl_child: which shaders
    bool codecs = false;       // time each file encoder on each scene's first frame instead
    // facet's render with every batch on the general shading path
    // (render/shade_stage.hpp, ShadingPaths): what the plain path saves.
    facet::ShadingPaths paths = facet::ShadingPaths::specialised;
};

// The suite, in the order of docs/performance.md.
const char* kSuite[] = {
    "blob-5k",           "blob-328k",     "blob-1m",       "blob-5k-unlit",
    "blob-328k-unlit",   "blob-1m-unlit", "blob-textured", "blob-lights4",
    "blob-shadows",      "blob-aa4",      "blob-328k-pbr", "../../scenes/turntable",
    "../../scenes/flag", "small",         "medium",        "large"};

std::vector<int> parse_int_list(const std::string& text, const char* option) {
    std::vector<int> out;
    std::stringstream ss(text);
    std::string item;
    while (std::getline(ss, item, ',')) {
        char* end = nullptr;
        long v = std::strtol(item.c_str(), &end, 10);
        if (item.empty() || *end || v < 0 || v > 256)
            throw std::invalid_argument(std::string(option) + ": not a list of counts: " + text);
        out.push_back(static_cast<int>(v));
    }
    if (out.empty()) throw std::invalid_argument(std::string(option) + ": empty list");
    return out;
}

void usage(std::ostream& os) {
    os << "usage: facet_bench [--frames N] [--threads 1,2] [--llvmpipe-threads 2] [--no-llvmpipe]\n"
          "                   [--no-general-peer] [--general-shading] [--render-only]\n"
          "                   [--plot FILE.png] "
          "[scene.yaml ...]\n"
          "       facet_bench --make-meshes DIR [--seed N]\n"
          "Renders each scene with facet (render only, then the whole job writing PNGs) and with\n"
          "OpenGL on llvmpipe, and prints markdown tables. Default: the suite "
          "in " FACET_BENCH_SCENES_DIR
          ".\n"
          "  --frames N        N frames spread evenly over the scene's range (default: all)\n"
          "  --render-only     skip the whole jobs (files written): a quicker check\n"
          "  --codecs          instead, each file encoder's MB/s and ratio on each scene's first\n"
          "                    frame (one thread, median of 5)\n"
          "  --general-shading facet's render with every batch on the general shading path\n"
          "                    (no plain batches): what the specialised path saves\n"
          "  --no-general-peer llvmpipe with the shaders written for each scene only, not also\n"
          "                    with its general (uniform light loop) shaders\n"
          "  --make-meshes DIR the blobs (5k, 328k, 1.31M triangles) and the texture the suite\n"
          "                    reads; --seed picks the displacement (a new seed: unseen meshes)\n";
}

Options parse_options(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) throw std::invalid_argument(a + " needs a value");
            return argv[++i];
        };
        if (a == "--frames") {
            o.frames = parse_int_list(value(), "--frames").at(0);
        } else if (a == "--threads") {
            o.threads = parse_int_list(value(), "--threads");
        } else if (a == "--llvmpipe-threads") {
            o.lp_threads = parse_int_list(value(), "--llvmpipe-threads");
        } else if (a == "--no-llvmpipe") {
            o.llvmpipe = false;
        } else if (a == "--codecs") {
            o.codecs = true;
        } else if (a == "--no-general-peer") {
            o.general_peer = false;
        } else if (a == "--peer") {
            const std::string peer = value();
            if (peer != "specialised" && peer != "general")
                throw std::invalid_argument("--peer: specialised or general, not " + peer);
            o.specialised = peer == "specialised";
        } else if (a == "--general-shading") {
            o.paths = facet::ShadingPaths::general_only;
        } else if (a == "--render-only") {
            o.jobs = false;
        } else if (a == "--plot") {
            o.plot = value();
        } else if (a == "--make-meshes") {
            o.make_meshes = value();
        } else if (a == "--seed") {
            o.seed = static_cast<uint32_t>(parse_int_list(value(), "--seed").at(0));
        } else if (a == "--gl-child") {
            o.gl_child = true;
        } else if (a == "--png-dir") {
            o.png_dir = value();
        } else if (a == "-h" || a == "--help") {
            usage(std::cout);
            std::exit(0);
        } else if (!a.empty() && a[0] == '-') {
            throw std::invalid_argument("unknown option " + a);
        } else {
            o.scenes.push_back(a);
        }
    }
    if (o.scenes.empty())
        for (const char* name : kSuite)
            o.scenes.push_back(std::string(FACET_BENCH_SCENES_DIR) + "/" + name + ".yaml");
    return o;
}

facet::SceneDesc load(const std::string& path, std::vector<facet::Override> overrides = {}) {
    facet::SceneOptions options;
    options.style_dirs = {FACET_STYLES_DIR};
    options.overrides = std::move(overrides);
    return facet::load_scene(path, options);
}

// The frames to render: all of the scene's, or `count` spread evenly over
// them (the turntable still goes round the whole circle).
std::vector<int> pick_frames(const facet::SceneDesc& scene, int count) {
    const auto& all = scene.output.frames;
    if (count <= 0 || count >= static_cast<int>(all.size())) return all;
    std::vector<int> out;
    for (int i = 0; i < count; ++i) out.push_back(all[static_cast<size_t>(i) * all.size() / count]);
    return out;
}

// Render only: FrameRenderer::render into reused buffers, as `facet render`
// does, after one untimed frame.
FacetRun bench_render(const facet::SceneDesc& scene, const facet::World& world,
                      const std::vector<int>& frames, int threads, facet::ShadingPaths paths) {
    facet::ThreadPool pool(static_cast<unsigned>(threads));
    facet::FrameRenderer renderer(scene, world, pool, paths);
    facet::FrameImages images;
    renderer.render(frames.front(), 0, images);
    std::vector<double> wall, cpu;
    for (int frame : frames) {
        const double c0 = process_cpu_ms();
        const auto t0 = Clock::now();
        renderer.render(frame, 0, images);
        wall.push_back(ms_since(t0, Clock::now()));
        cpu.push_back(process_cpu_ms() - c0);
    }
    return {threads, stat_of(wall), median(cpu)};
}

// The whole job: render_scene, what `facet render` runs, writing the files
// into a fresh folder; per frame, total wall and CPU time over the frames.
FacetRun bench_job(const std::string& path, const std::vector<int>& frames, int threads,
                   const std::vector<facet::Override>& outputs) {
    const facet::SceneDesc scene = load(path, outputs);
    const facet::World world = facet::build_world(scene);
    const fs::path dir = fs::temp_directory_path() / ("facet-bench-" + std::to_string(getpid()));
    fs::remove_all(dir);
    facet::RenderOptions options;
    options.frames = frames;
    options.threads = static_cast<unsigned>(threads);
    options.out_dir = dir.string();
    const double c0 = process_cpu_ms();
    const auto t0 = Clock::now();
    facet::render_scene(scene, world, options, nullptr);
    const double n = static_cast<double>(frames.size());
    const double wall = ms_since(t0, Clock::now()) / n;
    const double cpu = (process_cpu_ms() - c0) / n;
    fs::remove_all(dir);
    return {threads, {wall, wall, wall}, cpu};
}

std::string shell_quote(const std::string& s) {
    std::string out = "'";
    for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

std::string self_path() {
    char buf[4096];
    ssize_t n = readlink("/proc/self/exe", buf, sizeof buf - 1);
    if (n <= 0) throw std::runtime_error("cannot find /proc/self/exe");
    buf[n] = 0;
    return buf;
}

// Runs `facet_bench --gl-child` for one scene with LP_NUM_THREADS set and
// reads back its one result line.
GlResult run_gl_child(const std::string& scene_path, int frames, int lp_threads, bool specialised) {
    GlResult r;
    r.lp_threads = lp_threads;
    r.specialised = specialised;
    const fs::path dir = fs::temp_directory_path() / ("facet-bench-gl-" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::string cmd = "LP_NUM_THREADS=" + std::to_string(lp_threads) + " GALLIUM_DRIVER=llvmpipe " +
                      shell_quote(self_path()) + " --gl-child --peer " +
                      (specialised ? "specialised" : "general") + " --frames " +
                      std::to_string(frames) + " --png-dir " + shell_quote(dir.string()) + " " +
                      shell_quote(scene_path);
    std::FILE* pipe = popen(cmd.c_str(), "r");
    if (!pipe) {
        r.error = "popen failed";
        return r;
    }
    std::string line, result;
    char buf[4096];
    while (std::fgets(buf, sizeof buf, pipe)) {
        line = buf;
        if (line.rfind("GLRESULT ", 0) == 0) result = line.substr(9);
    }
    const int status = pclose(pipe);
    fs::remove_all(dir);
    if (result.empty()) {
        r.error = "llvmpipe child failed (status " + std::to_string(status) + ")";
        return r;
    }
    return parse_gl_result(result, lp_threads, specialised);
}

int gl_child_main(const Options& o) {
    try {
#ifdef FACET_BENCH_HAVE_OSMESA
        if (o.scenes.size() != 1) throw std::invalid_argument("--gl-child takes one scene");
        facet::SceneDesc scene = load(o.scenes[0]);
        facet::World world = facet::build_world(scene);
        const GlResult r =
            bench_llvmpipe(scene, world, pick_frames(scene, o.frames), o.png_dir, o.specialised);
        std::printf("GLRESULT %s\n", format_gl_result(r).c_str());
#else
        (void)o;
        std::printf("GLRESULT error=built_without_OSMesa\n");
#endif
        return 0;
    } catch (const std::exception& e) {
        std::string msg = e.what();
        for (char& c : msg)
            if (c == ' ' || c == '\n') c = '_';
        std::printf("GLRESULT error=%s\n", msg.c_str());
        return 1;
    }
}

int make_meshes(const Options& o) {
    fs::create_directories(o.make_meshes);
    for (const auto& [name, levels] :
         {std::pair<const char*, int>{"blob-5k", 4}, {"blob-328k", 7}, {"blob-1m", 8}}) {
        const std::string path = (fs::path(o.make_meshes) / (std::string(name) + ".obj")).string();
        write_blob_obj(path, levels, o.seed);
        std::cerr << "wrote " << path << " (seed " << o.seed << ")\n";
    }
    write_blob_texture((fs::path(o.make_meshes) / "blob-texture.png").string(), 1024);
    return 0;
}

SceneResult bench_scene(const std::string& path, const Options& o) {
    const CpuSnapshot before = cpu_snapshot();
    const facet::SceneDesc scene = load(path);
    const auto t0 = Clock::now();
    const facet::World world = facet::build_world(scene);
    const std::vector<int> frames = pick_frames(scene, o.frames);
    SceneResult sr;
    sr.name = scene.name;
    sr.triangles = world.triangle_count();
    sr.frames = static_cast<int>(frames.size());
    sr.size = std::to_string(scene.output.width) + "x" + std::to_string(scene.output.height);
    std::cerr << "== " << scene.name << ": " << sr.triangles << " triangles, " << sr.size << ", "
              << frames.size() << " frames (world built in " << ms_since(t0, Clock::now())
              << " ms)\n";
    for (int threads : o.threads) {
        sr.render.push_back(bench_render(scene, world, frames, threads, o.paths));
        std::cerr << "  facet render  " << threads << "T: " << describe(sr.render.back()) << "\n";
    }
    const int job_threads = *std::max_element(o.threads.begin(), o.threads.end());
    if (o.jobs) {
        sr.job_png = bench_job(
            path, frames, job_threads,
            {{"output.passes", "[color]", "bench"}, {"output.formats", "[png]", "bench"}});
        std::cerr << "  facet job PNG " << job_threads << "T: " << describe(sr.job_png) << "\n";
        sr.job_all = bench_job(path, frames, job_threads,
                               {{"output.passes", "[color, depth]", "bench"},
                                {"output.formats", "[png, exr]", "bench"}});
        std::cerr << "  facet job PNG+EXR colour+depth " << job_threads
                  << "T: " << describe(sr.job_all) << "\n";
    }
    if (o.llvmpipe)
        for (int lp : o.lp_threads)
            for (bool specialised : {true, false}) {
                if (!specialised && !o.general_peer) continue;
                const GlResult g = run_gl_child(path, o.frames, lp, specialised);
                std::cerr << "  llvmpipe " << (specialised ? "specialised" : "general")
                          << " LP_NUM_THREADS=" << lp << ": " << describe(g) << "\n";
                sr.gl.push_back(g);
            }
    sr.load = load_between(before, cpu_snapshot());
    return sr;
}

// --codecs: the encoders timed on each scene's first frame, rendered on 2 threads.
int codec_study(const Options& o) {
    std::cout << codec_table_header();
    for (const std::string& path : o.scenes) {
        const facet::SceneDesc scene = load(path);
        const facet::World world = facet::build_world(scene);
        facet::ThreadPool pool(2);
        facet::FrameRenderer renderer(scene, world, pool);
        facet::FrameImages images;
        renderer.render(scene.output.frames.front(), 0, images);
        std::cout << codec_rows(scene.name, images, 5) << std::flush;
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    Options o;
    try {
        o = parse_options(argc, argv);
    } catch (const std::exception& e) {
        std::cerr << "facet_bench: " << e.what() << "\n";
        usage(std::cerr);
        return 2;
    }
    if (o.gl_child) return gl_child_main(o);
    try {
        if (!o.make_meshes.empty()) return make_meshes(o);
#ifndef FACET_BENCH_HAVE_OSMESA
        if (o.llvmpipe) {
            std::cerr << "facet_bench: built without OSMesa (libosmesa6-dev not found at "
                         "configure time): no llvmpipe reference in this run\n";
            o.llvmpipe = false;
        }
#endif
        if (o.codecs) return codec_study(o);
        std::vector<SceneResult> results;
        for (const std::string& path : o.scenes) results.push_back(bench_scene(path, o));
        std::cout << report_markdown(results, o.threads, o.lp_threads);
        if (!o.plot.empty()) {
            write_report_plot(o.plot, results);
            std::cerr << "wrote " << o.plot << "\n";
        }
    } catch (const facet::Error& e) {
        std::cerr << "facet_bench: " << e.what() << "\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "facet_bench: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
