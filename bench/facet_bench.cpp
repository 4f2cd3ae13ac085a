// facet_bench: median frame time of facet's renderer on the bench/scenes
// turntables at 1 and 2 threads, side by side with the same scenes drawn by
// OpenGL on Mesa's llvmpipe (OSMesa, off-screen) in the same run.
// docs/performance.md explains what is measured; scripts/bench.sh runs it.
//
// The llvmpipe side runs in a child process per thread count, because
// llvmpipe reads LP_NUM_THREADS once, when the first context is created:
// the bench re-executes itself with `--gl-child` and LP_NUM_THREADS set.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <sys/resource.h>
#include <unistd.h>

#include "core/error.hpp"
#include "core/thread_pool.hpp"
#include "output/encoders.hpp"
#include "render/frame_renderer.hpp"
#include "render/world.hpp"
#include "scene/scene_desc.hpp"

#include "bench_common.hpp"

using namespace facet_bench;

namespace {

// Machine-wide CPU use from /proc/stat next to this process's own (and its
// finished children's, the llvmpipe runs): what is left is other people's
// work competing for the same cores, the main source of noise here.
struct CpuSnapshot {
    Clock::time_point when = Clock::now();
    double busy_s = 0, steal_s = 0, ours_s = 0;
};

CpuSnapshot cpu_snapshot() {
    CpuSnapshot s;
    if (std::FILE* f = std::fopen("/proc/stat", "r")) {
        unsigned long long v[8] = {};
        if (std::fscanf(f, "cpu %llu %llu %llu %llu %llu %llu %llu %llu", &v[0], &v[1], &v[2], &v[3],
                        &v[4], &v[5], &v[6], &v[7]) == 8) {
            const double tick = static_cast<double>(sysconf(_SC_CLK_TCK));
            s.busy_s = static_cast<double>(v[0] + v[1] + v[2] + v[5] + v[6]) / tick;
            s.steal_s = static_cast<double>(v[7]) / tick;
        }
        std::fclose(f);
    }
    for (int who : {RUSAGE_SELF, RUSAGE_CHILDREN}) {
        rusage u{};
        getrusage(who, &u);
        s.ours_s += static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
                    static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec) * 1e-6;
    }
    return s;
}

struct Load {
    double wall_s = 0, others_cores = NAN, steal_cores = NAN;
};

Load load_between(const CpuSnapshot& a, const CpuSnapshot& b) {
    Load l;
    l.wall_s = std::chrono::duration<double>(b.when - a.when).count();
    if (l.wall_s > 0 && b.busy_s > 0) {
        l.others_cores = std::max(0.0, (b.busy_s - a.busy_s) - (b.ours_s - a.ours_s)) / l.wall_s;
        l.steal_cores = (b.steal_s - a.steal_s) / l.wall_s;
    }
    return l;
}

struct Options {
    std::vector<std::string> scenes;
    int frames = 0;  // 0: all frames of the scene
    std::vector<int> threads = {1, 2};
    std::vector<int> lp_threads = {0, 1, 2};  // 0: rasterize in the calling thread
    bool llvmpipe = true;
    // Internal: run the llvmpipe side of one scene in this process.
    bool gl_child = false;
};

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
    os << "usage: facet_bench [--frames N] [--threads 1,2] [--llvmpipe-threads 0,1,2]\n"
          "                   [--no-llvmpipe] [scene.yaml ...]\n"
          "Renders each scene's frames with facet at each thread count, then with OpenGL on\n"
          "llvmpipe (OSMesa) at each LP_NUM_THREADS value, and prints a markdown table of\n"
          "median ms per frame. Default scenes: " FACET_BENCH_SCENES_DIR "/{small,medium,large}.yaml\n"
          "  --frames N   render N frames spread evenly over the scene's range (default: all)\n";
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
        } else if (a == "--gl-child") {
            o.gl_child = true;
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
        for (const char* name : {"small", "medium", "large"})
            o.scenes.push_back(std::string(FACET_BENCH_SCENES_DIR) + "/" + name + ".yaml");
    return o;
}

facet::SceneDesc load(const std::string& path) {
    facet::SceneOptions options;
    options.style_dirs = {FACET_STYLES_DIR};
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

struct FacetResult {
    int threads;
    double render_ms, total_ms, encode_ms;  // medians
    double render_min_ms, render_max_ms;
    size_t png_bytes;
    double render_cpu_ms;  // median process CPU time during render
};

FacetResult bench_facet(const facet::SceneDesc& scene, const facet::World& world,
                        const std::vector<int>& frames, int threads) {
    facet::ThreadPool pool(static_cast<unsigned>(threads));
    facet::FrameRenderer renderer(scene, world, pool);
    std::vector<double> render, total, encode, cpu;
    size_t png_bytes = 0;
    facet::FrameImages images;  // reused from frame to frame, as `facet render` does
    for (int frame : frames) {
        const double c0 = process_cpu_ms();
        auto t0 = Clock::now();
        renderer.render(frame, 0, images);
        auto t1 = Clock::now();
        cpu.push_back(process_cpu_ms() - c0);
        std::vector<uint8_t> png = facet::encode_png_color(images.color, scene.output.png_compression);
        auto t2 = Clock::now();
        render.push_back(ms_since(t0, t1));
        total.push_back(ms_since(t0, t2));
        encode.push_back(ms_since(t1, t2));
        png_bytes = png.size();
    }
    return {threads,
            median(render),
            median(total),
            median(encode),
            *std::min_element(render.begin(), render.end()),
            *std::max_element(render.begin(), render.end()),
            png_bytes,
            median(cpu)};
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
GlResult run_gl_child(const std::string& scene_path, int frames, int lp_threads) {
    GlResult r;
    r.lp_threads = lp_threads;
    std::string cmd = "LP_NUM_THREADS=" + std::to_string(lp_threads) + " GALLIUM_DRIVER=llvmpipe " +
                      shell_quote(self_path()) + " --gl-child --frames " + std::to_string(frames) +
                      " " + shell_quote(scene_path);
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
    int status = pclose(pipe);
    if (result.empty()) {
        r.error = "llvmpipe child failed (status " + std::to_string(status) + ")";
        return r;
    }
    std::map<std::string, std::string> kv;
    std::stringstream ss(result);
    std::string tok;
    while (ss >> tok) {
        auto eq = tok.find('=');
        if (eq != std::string::npos) kv[tok.substr(0, eq)] = tok.substr(eq + 1);
    }
    if (kv.count("error")) {
        r.error = kv["error"];
        return r;
    }
    r.ok = true;
    r.finish_ms = std::stod(kv["finish_ms"]);
    r.readback_ms = std::stod(kv["readback_ms"]);
    r.readback_cpu_ms = std::stod(kv["readback_cpu_ms"]);
    r.readback_min_ms = std::stod(kv["readback_min_ms"]);
    r.readback_max_ms = std::stod(kv["readback_max_ms"]);
    r.raster_threads_seen = std::stoi(kv["raster_threads"]);
    r.min_covered = std::stoull(kv["min_covered"]);
    r.mean_abs_diff = std::stod(kv["mean_abs_diff"]);
    r.coverage_mismatch = std::stod(kv["coverage_mismatch"]);
    r.coverage_mismatch_px = std::stoull(kv["coverage_mismatch_px"]);
    r.differing = std::stoull(kv["differing"]);
    r.max_diff = std::stoi(kv["max_diff"]);
    r.renderer = kv["renderer"];
    for (char& c : r.renderer)
        if (c == '_') c = ' ';
    return r;
}

int gl_child_main(const Options& o) {
    try {
#ifdef FACET_BENCH_HAVE_OSMESA
        if (o.scenes.size() != 1) throw std::invalid_argument("--gl-child takes one scene");
        facet::SceneDesc scene = load(o.scenes[0]);
        facet::World world = facet::build_world(scene);
        GlResult r = bench_llvmpipe(scene, world, pick_frames(scene, o.frames));
        std::string renderer = r.renderer;
        for (char& c : renderer)
            if (c == ' ' || c == '=') c = '_';
        std::printf("GLRESULT finish_ms=%.4f readback_ms=%.4f readback_cpu_ms=%.4f readback_min_ms=%.4f readback_max_ms=%.4f "
                    "raster_threads=%d min_covered=%zu mean_abs_diff=%.4f coverage_mismatch=%.6f "
                    "coverage_mismatch_px=%zu differing=%zu max_diff=%d renderer=%s\n",
                    r.finish_ms, r.readback_ms, r.readback_cpu_ms, r.readback_min_ms, r.readback_max_ms,
                    r.raster_threads_seen, r.min_covered, r.mean_abs_diff, r.coverage_mismatch,
                    r.coverage_mismatch_px, r.differing, r.max_diff, renderer.c_str());
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

std::string fmt(double v, int decimals = 1) {
    if (std::isnan(v)) return "n/a";
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

std::string with_thousands(size_t n) {
    std::string s = std::to_string(n), out;
    for (size_t i = 0; i < s.size(); ++i) {
        if (i && (s.size() - i) % 3 == 0) out += ',';
        out += s[i];
    }
    return out;
}

struct SceneResult {
    std::string name;
    size_t triangles = 0;
    int frames = 0;
    std::vector<FacetResult> facet;
    std::vector<GlResult> gl;
    Load load;
};

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

#ifndef FACET_BENCH_HAVE_OSMESA
    if (o.llvmpipe) {
        std::cerr << "facet_bench: built without OSMesa (libosmesa6-dev not found at configure time): "
                     "no llvmpipe reference in this run\n";
        o.llvmpipe = false;
    }
#endif

    std::vector<SceneResult> results;
    try {
        for (const std::string& path : o.scenes) {
            const CpuSnapshot before = cpu_snapshot();
            facet::SceneDesc scene = load(path);
            auto t0 = Clock::now();
            facet::World world = facet::build_world(scene);
            std::vector<int> frames = pick_frames(scene, o.frames);
            SceneResult sr;
            sr.name = scene.name;
            sr.triangles = world.triangle_count();
            sr.frames = static_cast<int>(frames.size());
            std::cerr << "== " << scene.name << ": " << with_thousands(sr.triangles) << " triangles, "
                      << world.positions.size() << " vertices, " << scene.output.width << "x"
                      << scene.output.height << ", " << frames.size() << " frames (world built in "
                      << fmt(ms_since(t0, Clock::now()), 0) << " ms)\n";
            for (int threads : o.threads) {
                FacetResult f = bench_facet(scene, world, frames, threads);
                std::cerr << "  facet    threads=" << threads << "  render median " << fmt(f.render_ms, 2)
                          << " ms (min " << fmt(f.render_min_ms, 2) << ", max " << fmt(f.render_max_ms, 2)
                          << "), encode median " << fmt(f.encode_ms, 2) << " ms, render+encode median "
                          << fmt(f.total_ms, 2) << " ms, render CPU " << fmt(f.render_cpu_ms, 2)
                          << " ms, png " << f.png_bytes << " bytes\n";
                sr.facet.push_back(f);
            }
            if (o.llvmpipe) {
                for (int lp : o.lp_threads) {
                    GlResult g = run_gl_child(path, o.frames, lp);
                    if (!g.ok) {
                        std::cerr << "  llvmpipe LP_NUM_THREADS=" << lp << "  FAILED: " << g.error << "\n";
                    } else {
                        std::cerr << "  llvmpipe LP_NUM_THREADS=" << lp << "  draw+glFinish median "
                                  << fmt(g.finish_ms, 2) << " ms, +glReadPixels median "
                                  << fmt(g.readback_ms, 2) << " ms (min " << fmt(g.readback_min_ms, 2)
                                  << ", max " << fmt(g.readback_max_ms, 2) << "), CPU "
                                  << fmt(g.readback_cpu_ms, 2) << " ms; llvmpipe raster threads "
                                  << g.raster_threads_seen << "; " << g.renderer << "\n"
                                  << "           check: >= " << g.min_covered
                                  << " pixels differ from the clear colour; vs facet frame "
                                  << frames.front() << ": coverage differs on "
                                  << g.coverage_mismatch_px << " pixels ("
                                  << fmt(100 * g.coverage_mismatch, 3) << "%); where both cover, "
                                  << g.differing << " pixels differ, mean |diff| "
                                  << fmt(g.mean_abs_diff, 3) << "/255, max " << g.max_diff << "/255\n";
                        if (g.min_covered == 0)
                            std::cerr << "  WARNING: llvmpipe produced frames with nothing but the clear "
                                         "colour: its timings do not measure real rendering\n";
                        if (g.raster_threads_seen >= 0 && g.raster_threads_seen != lp)
                            std::cerr << "  WARNING: asked LP_NUM_THREADS=" << lp << " but found "
                                      << g.raster_threads_seen << " llvmpipe raster threads\n";
                    }
                    sr.gl.push_back(g);
                }
            }
            sr.load = load_between(before, cpu_snapshot());
            std::cerr << "  (" << fmt(sr.load.wall_s) << " s; other processes kept "
                      << fmt(sr.load.others_cores, 2) << " cores busy on average)\n";
            results.push_back(std::move(sr));
        }
    } catch (const facet::Error& e) {
        std::cerr << "facet_bench: " << e.what() << "\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "facet_bench: " << e.what() << "\n";
        return 1;
    }

    // The table: facet at N threads beside llvmpipe with LP_NUM_THREADS=N.
    // llvmpipe ms includes glReadPixels, the fair match for facet's image in memory.
    auto gl_for = [](const SceneResult& sr, int lp) -> const GlResult* {
        for (const GlResult& g : sr.gl)
            if (g.lp_threads == lp && g.ok) return &g;
        return nullptr;
    };
    std::cout << "\n| scene | triangles | threads | facet render ms | facet +encode ms | facet Mtri/s "
                 "| llvmpipe ms | llvmpipe Mtri/s | speed ratio |\n"
                 "|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const SceneResult& sr : results) {
        for (const FacetResult& f : sr.facet) {
            const GlResult* g = gl_for(sr, f.threads);
            const double tri = static_cast<double>(sr.triangles);
            const double facet_mtri = tri / (f.render_ms / 1000) / 1e6;
            const double gl_ms = g ? g->readback_ms : NAN;
            const double gl_mtri = g ? tri / (gl_ms / 1000) / 1e6 : NAN;
            std::cout << "| " << sr.name << " | " << with_thousands(sr.triangles) << " | " << f.threads
                      << " | " << fmt(f.render_ms) << " | " << fmt(f.total_ms) << " | "
                      << fmt(facet_mtri, 2) << " | " << fmt(gl_ms) << " | " << fmt(gl_mtri, 2) << " | "
                      << (g ? fmt(gl_ms / f.render_ms, 2) + "x" : std::string("n/a")) << " |\n";
        }
    }
    std::cout << "\nFrames per run: ";
    for (size_t i = 0; i < results.size(); ++i)
        std::cout << (i ? ", " : "") << results[i].name << " " << results[i].frames;
    std::cout << ". ms are medians per frame. llvmpipe ms = draw + glFinish + glReadPixels with "
                 "LP_NUM_THREADS = threads; speed ratio = llvmpipe ms / facet render ms (above 1: "
                 "facet is faster).\n";

    std::cout << "\nfacet detail:\n\n| scene | threads | render ms median (min-max) | encode ms | "
                 "render CPU ms | cores busy | PNG bytes |\n|---|---:|---:|---:|---:|---:|---:|\n";
    for (const SceneResult& sr : results)
        for (const FacetResult& f : sr.facet)
            std::cout << "| " << sr.name << " | " << f.threads << " | " << fmt(f.render_ms) << " ("
                      << fmt(f.render_min_ms) << "-" << fmt(f.render_max_ms) << ") | "
                      << fmt(f.encode_ms) << " | " << fmt(f.render_cpu_ms) << " | "
                      << fmt(f.render_cpu_ms / f.render_ms, 2) << " | " << with_thousands(f.png_bytes)
                      << " |\n";

    std::cout << "\nMachine load while each scene ran (" << std::thread::hardware_concurrency()
              << " logical CPUs; \"others\" = CPU time of other processes / wall time):\n\n"
                 "| scene | wall s | others, cores busy | steal, cores |\n|---|---:|---:|---:|\n";
    for (const SceneResult& sr : results)
        std::cout << "| " << sr.name << " | " << fmt(sr.load.wall_s) << " | " << fmt(sr.load.others_cores, 2)
                  << " | " << fmt(sr.load.steal_cores, 2) << " |\n";

    if (!o.llvmpipe) {
        std::cout << "\nllvmpipe reference not run"
#ifndef FACET_BENCH_HAVE_OSMESA
                     " (facet_bench was built without OSMesa)"
#endif
                     ".\n";
        return 0;
    }
    std::cout << "\nllvmpipe detail (LP_NUM_THREADS=0 rasterizes in the calling thread; N >= 1 adds N "
                 "raster threads beside the thread that runs vertex shading and binning):\n\n"
                 "| scene | LP_NUM_THREADS | draw+glFinish ms | +glReadPixels ms median (min-max) "
                 "| CPU ms | cores busy | raster threads seen | min covered px | px covered by one "
                 "only | px differing (max diff /255) |\n"
                 "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    std::string renderer;
    for (const SceneResult& sr : results)
        for (const GlResult& g : sr.gl) {
            if (!g.ok) {
                std::cout << "| " << sr.name << " | " << g.lp_threads << " | failed: " << g.error
                          << " | | | | | | | |\n";
                continue;
            }
            renderer = g.renderer;
            std::cout << "| " << sr.name << " | " << g.lp_threads << " | " << fmt(g.finish_ms) << " | "
                      << fmt(g.readback_ms) << " (" << fmt(g.readback_min_ms) << "-"
                      << fmt(g.readback_max_ms) << ") | " << fmt(g.readback_cpu_ms) << " | "
                      << fmt(g.readback_cpu_ms / g.readback_ms, 2) << " | " << g.raster_threads_seen
                      << " | " << with_thousands(g.min_covered) << " | "
                      << with_thousands(g.coverage_mismatch_px) << " | " << with_thousands(g.differing)
                      << " (" << g.max_diff << ") |\n";
        }
    if (!renderer.empty())
        std::cout << "\nGL renderer: " << renderer
                  << ". Image check: llvmpipe's first frame against facet's, both as 8-bit linear "
                     "colour.\n";
    return 0;
}
