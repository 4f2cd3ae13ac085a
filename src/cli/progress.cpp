#include "cli/progress.hpp"

#include <unistd.h>

#include <string>

namespace facet {

ProgressReporter::ProgressReporter(std::FILE* stream, bool quiet)
    : stream_(stream),
      quiet_(quiet),
      terminal_(::isatty(::fileno(stream)) != 0),
      start_(std::chrono::steady_clock::now()) {}

void ProgressReporter::frame_done(const FrameProgress& p) {
    if (quiet_) return;
    double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    double eta = p.done > 0
                     ? elapsed / static_cast<double>(p.done) * static_cast<double>(p.total - p.done)
                     : 0;
    if (terminal_) {
        constexpr int kWidth = 30;
        int filled = static_cast<int>(kWidth * p.done / p.total);
        std::string bar(static_cast<size_t>(filled), '#');
        bar.append(static_cast<size_t>(kWidth - filled), '.');
        std::fprintf(stream_, "\r[%s] %zu/%zu  frame %d  %.1f ms  eta %.0f s ", bar.c_str(), p.done,
                     p.total, p.frame, p.render_ms, eta);
    } else {
        std::fprintf(stream_, "frame %d (%zu/%zu) rendered in %.1f ms\n", p.frame, p.done, p.total,
                     p.render_ms);
    }
    std::fflush(stream_);
}

void ProgressReporter::finish() {
    if (!quiet_ && terminal_) std::fprintf(stream_, "\n");
}

}  // namespace facet
