#include "bench_report.hpp"

#include <algorithm>
#include <cstdio>
#include <map>
#include <sstream>
#include <thread>

#include <sys/resource.h>
#include <unistd.h>

#include "job/labels.hpp"
#include "job/plot.hpp"
#include "output/atomic_file.hpp"
#include "output/encoders.hpp"

namespace facet_bench {

CpuSnapshot cpu_snapshot() {
    CpuSnapshot s;
    if (std::FILE* f = std::fopen("/proc/stat", "r")) {
        unsigned long long v[8] = {};
        if (std::fscanf(f, "cpu %llu %llu %llu %llu %llu %llu %llu %llu", &v[0], &v[1], &v[2],
                        &v[3], &v[4], &v[5], &v[6], &v[7]) == 8) {
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

Load load_between(const CpuSnapshot& a, const CpuSnapshot& b) {
    Load l;
    l.wall_s = std::chrono::duration<double>(b.when - a.when).count();
    if (l.wall_s > 0 && b.busy_s > 0) {
        l.others_cores = std::max(0.0, (b.busy_s - a.busy_s) - (b.ours_s - a.ours_s)) / l.wall_s;
        l.steal_cores = (b.steal_s - a.steal_s) / l.wall_s;
    }
    return l;
}

namespace {

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

std::string ratio(double slow, double fast) {
    if (std::isnan(slow) || std::isnan(fast) || fast <= 0) return "n/a";
    return fmt(slow / fast, 2) + "x";
}

const FacetRun* run_at(const SceneResult& sr, int threads) {
    for (const FacetRun& r : sr.render)
        if (r.threads == threads) return &r;
    return nullptr;
}

const GlResult* gl_at(const SceneResult& sr, int lp, bool specialised) {
    for (const GlResult& g : sr.gl)
        if (g.lp_threads == lp && g.specialised == specialised && g.ok) return &g;
    return nullptr;
}

}  // namespace

std::string describe(const FacetRun& run) {
    return fmt(run.ms.median, 2) + " ms/frame (min " + fmt(run.ms.min, 2) + ", max " +
           fmt(run.ms.max, 2) + "), CPU " + fmt(run.cpu_ms, 2) + " ms/frame";
}

std::string describe(const GlResult& g) {
    if (!g.ok) return "FAILED: " + g.error;
    std::string s = "render " + fmt(g.render_ms.median, 2) + " ms/frame (CPU " +
                    fmt(g.render_cpu_ms, 2) + "), job " + fmt(g.job_ms.median, 2) +
                    " ms/frame (CPU " + fmt(g.job_cpu_ms, 2) + "); " + g.features +
                    "; check: " + with_thousands(g.coverage_mismatch_px) +
                    " px covered by one only, " + with_thousands(g.differing) +
                    " px differ by > 8/255, mean |diff| " + fmt(g.mean_abs_diff, 2) + "/255, max " +
                    std::to_string(g.max_abs_diff) + "/255";
    if (g.min_covered == 0) s += "; WARNING: frames with nothing drawn";
    return s;
}

std::string format_gl_result(const GlResult& r) {
    auto word = [](std::string s) {
        for (char& c : s)
            if (c == ' ' || c == '=') c = '_';
        return s;
    };
    char line[2048];
    std::snprintf(line, sizeof line,
                  "render_ms=%.4f render_min_ms=%.4f render_max_ms=%.4f render_cpu_ms=%.4f "
                  "job_ms=%.4f job_min_ms=%.4f job_max_ms=%.4f job_cpu_ms=%.4f raster_threads=%d "
                  "min_covered=%zu coverage_mismatch_px=%zu differing=%zu mean_abs_diff=%.4f "
                  "max_abs_diff=%d renderer=%s features=%s",
                  r.render_ms.median, r.render_ms.min, r.render_ms.max, r.render_cpu_ms,
                  r.job_ms.median, r.job_ms.min, r.job_ms.max, r.job_cpu_ms, r.raster_threads_seen,
                  r.min_covered, r.coverage_mismatch_px, r.differing, r.mean_abs_diff,
                  r.max_abs_diff, word(r.renderer).c_str(), word(r.features).c_str());
    return line;
}

GlResult parse_gl_result(const std::string& line, int lp_threads, bool specialised) {
    GlResult r;
    r.lp_threads = lp_threads;
    r.specialised = specialised;
    std::map<std::string, std::string> kv;
    std::stringstream ss(line);
    std::string tok;
    while (ss >> tok) {
        const auto eq = tok.find('=');
        if (eq != std::string::npos) kv[tok.substr(0, eq)] = tok.substr(eq + 1);
    }
    if (kv.count("error")) {
        r.error = kv["error"];
        return r;
    }
    auto number = [&](const char* key) { return std::stod(kv.at(key)); };
    auto text = [&](const char* key) {
        std::string s = kv.at(key);
        for (char& c : s)
            if (c == '_') c = ' ';
        return s;
    };
    r.render_ms = {number("render_ms"), number("render_min_ms"), number("render_max_ms")};
    r.render_cpu_ms = number("render_cpu_ms");
    r.job_ms = {number("job_ms"), number("job_min_ms"), number("job_max_ms")};
    r.job_cpu_ms = number("job_cpu_ms");
    r.raster_threads_seen = static_cast<int>(number("raster_threads"));
    r.min_covered = static_cast<size_t>(number("min_covered"));
    r.coverage_mismatch_px = static_cast<size_t>(number("coverage_mismatch_px"));
    r.differing = static_cast<size_t>(number("differing"));
    r.mean_abs_diff = number("mean_abs_diff");
    r.max_abs_diff = static_cast<int>(number("max_abs_diff"));
    r.renderer = text("renderer");
    r.features = text("features");
    r.ok = true;
    return r;
}

std::string report_markdown(const std::vector<SceneResult>& results,
                            const std::vector<int>& threads, const std::vector<int>& lp_threads) {
    std::ostringstream out;
    const int most = *std::max_element(threads.begin(), threads.end());
    const int lp = lp_threads.empty() ? most : lp_threads.back();
    out << "\n### facet against llvmpipe, " << most << " threads (LP_NUM_THREADS=" << lp
        << ")\n\n| scene | triangles | size | render ms: facet | llvmpipe | ratio | llvmpipe "
           "general | ratio | whole job ms: facet | llvmpipe + libpng | ratio | general + libpng "
           "| ratio | CPU ms/frame, job: facet | llvmpipe |\n"
           "|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const SceneResult& sr : results) {
        const FacetRun* f = run_at(sr, most);
        const GlResult* g = gl_at(sr, lp, true);
        const GlResult* general = gl_at(sr, lp, false);
        const double facet_ms = f ? f->ms.median : NAN, facet_job = sr.job_png.ms.median;
        const double gr = g ? g->render_ms.median : NAN, gj = g ? g->job_ms.median : NAN;
        const double nr = general ? general->render_ms.median : NAN;
        const double nj = general ? general->job_ms.median : NAN;
        out << "| " << sr.name << " | " << with_thousands(sr.triangles) << " | " << sr.size << " | "
            << fmt(facet_ms) << " | " << fmt(gr) << " | " << ratio(gr, facet_ms) << " | " << fmt(nr)
            << " | " << ratio(nr, facet_ms) << " | " << fmt(facet_job) << " | " << fmt(gj) << " | "
            << ratio(gj, facet_job) << " | " << fmt(nj) << " | " << ratio(nj, facet_job) << " | "
            << fmt(sr.job_png.cpu_ms) << " | " << fmt(g ? g->job_cpu_ms : NAN) << " |\n";
    }
    out << "\nllvmpipe: its shaders written for each scene (lights unrolled, what the scene "
           "fixes compiled in); llvmpipe general: one program looping over uniform lights. "
           "Ratio = llvmpipe ms / facet ms: above 1, facet is faster. Render: the image and its "
           "depth in memory (llvmpipe: draw, glFinish, read back colour and depth). Whole job: "
           "PNG files on disk (facet: `facet render` with passes [color], formats [png]; "
           "llvmpipe: the same frames plus libpng at zlib level 1). ms are medians per frame.\n";

    out << "\n### All outputs: PNG and EXR, colour and depth (" << most
        << " threads)\n\n| scene | render ms | whole job ms | job / render | CPU ms/frame |\n"
           "|---|---:|---:|---:|---:|\n";
    for (const SceneResult& sr : results) {
        const FacetRun* f = run_at(sr, most);
        out << "| " << sr.name << " | " << fmt(f ? f->ms.median : NAN) << " | "
            << fmt(sr.job_all.ms.median) << " | "
            << (f ? fmt(sr.job_all.ms.median / f->ms.median, 2) : std::string("n/a")) << " | "
            << fmt(sr.job_all.cpu_ms) << " |\n";
    }

    out << "\n### facet render detail\n\n| scene | threads | ms median (min-max) | CPU ms | "
           "cores busy | speed-up |\n|---|---:|---:|---:|---:|---:|\n";
    for (const SceneResult& sr : results)
        for (const FacetRun& f : sr.render) {
            const FacetRun* one = run_at(sr, 1);
            out << "| " << sr.name << " | " << f.threads << " | " << fmt(f.ms.median) << " ("
                << fmt(f.ms.min) << "-" << fmt(f.ms.max) << ") | " << fmt(f.cpu_ms) << " | "
                << fmt(f.cpu_ms / f.ms.median, 2) << " | "
                << (one ? fmt(one->ms.median / f.ms.median, 2) + "x" : std::string("n/a"))
                << " |\n";
        }

    bool any_gl = false;
    for (const SceneResult& sr : results) any_gl = any_gl || !sr.gl.empty();
    if (any_gl) {
        out << "\n### llvmpipe detail\n\n| scene | shaders | LP_NUM_THREADS | what it draws | "
               "render ms (min-max) | CPU ms | job ms | job CPU ms | raster threads | px covered "
               "by one only | px differing > 8/255 | mean abs diff /255 |\n"
               "|---|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
        std::string renderer;
        for (const SceneResult& sr : results)
            for (const GlResult& g : sr.gl) {
                const char* shaders = g.specialised ? "specialised" : "general";
                if (!g.ok) {
                    out << "| " << sr.name << " | " << shaders << " | " << g.lp_threads
                        << " | failed: " << g.error << " | | | | | | | | |\n";
                    continue;
                }
                renderer = g.renderer;
                out << "| " << sr.name << " | " << shaders << " | " << g.lp_threads << " | "
                    << g.features << " | " << fmt(g.render_ms.median) << " ("
                    << fmt(g.render_ms.min) << "-" << fmt(g.render_ms.max) << ") | "
                    << fmt(g.render_cpu_ms) << " | " << fmt(g.job_ms.median) << " | "
                    << fmt(g.job_cpu_ms) << " | " << g.raster_threads_seen << " | "
                    << with_thousands(g.coverage_mismatch_px) << " | "
                    << with_thousands(g.differing) << " | " << fmt(g.mean_abs_diff, 2) << " |\n";
            }
        if (!renderer.empty()) out << "\nGL renderer: " << renderer << ".\n";
    }

    out << "\n### Machine load while each scene ran (" << std::thread::hardware_concurrency()
        << " logical CPUs)\n\n| scene | wall s | others, cores busy | steal, cores |\n"
           "|---|---:|---:|---:|\n";
    for (const SceneResult& sr : results)
        out << "| " << sr.name << " | " << fmt(sr.load.wall_s) << " | "
            << fmt(sr.load.others_cores, 2) << " | " << fmt(sr.load.steal_cores, 2) << " |\n";
    return out.str();
}

void write_report_plot(const std::string& path, const std::vector<SceneResult>& results) {
    facet::PlotPanel panel;
    panel.title = "llvmpipe time / facet time, per scene (above 2: the goal)";
    panel.x_label = "scene (numbered below)";
    panel.y_label = "speed ratio";
    panel.integer_x = true;
    facet::PlotSeries render{"render only", {}, {0.15f, 0.35f, 0.75f}, false};
    facet::PlotSeries general{"render only, general peer", {}, {0.55f, 0.7f, 0.95f}, false};
    facet::PlotSeries job{"whole job (PNG)", {}, {0.85f, 0.35f, 0.1f}, false};
    facet::PlotSeries goal{"goal: 2x", {}, {0.3f, 0.3f, 0.3f}, true};
    std::vector<std::string> legend(1);  // rows of eight scenes
    for (size_t i = 0; i < results.size(); ++i) {
        const SceneResult& sr = results[i];
        const double x = static_cast<double>(i + 1);
        const FacetRun* f = nullptr;
        for (const FacetRun& r : sr.render)
            if (!f || r.threads > f->threads) f = &r;
        // The last LP_NUM_THREADS value's, as the table's.
        const int lp = sr.gl.empty() ? 0 : sr.gl.back().lp_threads;
        const GlResult* g = gl_at(sr, lp, true);
        const GlResult* g_general = gl_at(sr, lp, false);
        if (f && g) render.points.push_back({x, g->render_ms.median / f->ms.median});
        if (f && g_general)
            general.points.push_back({x, g_general->render_ms.median / f->ms.median});
        if (g) job.points.push_back({x, g->job_ms.median / sr.job_png.ms.median});
        goal.points.push_back({x, 2.0});
        if (i > 0 && i % 8 == 0) legend.emplace_back();
        legend.back() += std::to_string(i + 1) + " " + sr.name + "   ";
    }
    panel.series = {render, general, job, goal};
    const int width = 1200, height = 560, band = 60;
    facet::ColorImage image(width, height + band, glm::vec4(1, 1, 1, 1));
    facet::draw_plot(image, 0, 0, width, height, panel);
    for (size_t row = 0; row < legend.size(); ++row)
        facet::draw_label(image, 20, height + 10 + 20 * static_cast<int>(row), legend[row],
                          glm::vec3(0.1f), 1);
    facet::write_file_atomically(path, facet::encode_png_color(image, 6));
}

}  // namespace facet_bench
