#include "cli/progress.hpp"

#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "cli/options.hpp"
#include "core/number_text.hpp"
#include "core/plain_text.hpp"

namespace facet {
namespace {

int terminal_width(std::FILE* stream) {
    winsize size{};
    if (::ioctl(::fileno(stream), TIOCGWINSZ, &size) == 0 && size.ws_col > 0) return size.ws_col;
    // COLUMNS as the terminal would give it (ws_col is 16 bits); anything
    // else in it is ignored, as an unset COLUMNS is.
    if (const char* columns = std::getenv("COLUMNS"))
        if (const std::optional<long long> n = read_whole_number(columns);
            n && *n > 0 && *n <= 65535)
            return static_cast<int>(*n);
    return 80;
}

std::string format(const char* pattern, double a, double b = 0) {
    char text[64];
    std::snprintf(text, sizeof text, pattern, a, b);
    return text;
}

}  // namespace

std::string clock_text(double seconds) {
    const long s = std::max(0L, std::lround(seconds));
    char text[32];
    std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
    return text;
}

ProgressReporter::ProgressReporter(std::FILE* stream, bool quiet, int width)
    : stream_(stream),
      quiet_(quiet),
      terminal_(::isatty(::fileno(stream)) != 0),
      width_(width > 0 ? width : terminal_width(stream)),
      start_(std::chrono::steady_clock::now()) {}

ProgressReporter::~ProgressReporter() {
    if (bar_open_) std::fprintf(stream_, "\n");
}

double ProgressReporter::elapsed() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void ProgressReporter::start(size_t total, const std::string& what) {
    total_ = total;
    start_ = std::chrono::steady_clock::now();
    if (quiet_) return;
    if (terminal_) {
        frame_done({0, 0, total, 0, "", 1});
        return;
    }
    std::fprintf(stream_, "rendering %s: %s\n", what.c_str(),
                 count_of(total, "image", "images").c_str());
    std::fflush(stream_);
}

// "[#####.....] 12/72 17% frame 12 side 6.3 fps 0:00:02 eta 0:00:10", fitted
// to the terminal's width less one column (a full line would wrap): the
// frame, the rate and the elapsed time give way first, then the bar.
std::string ProgressReporter::bar_line(const FrameProgress& p) const {
    const double seconds = elapsed();
    const double fps = seconds > 0 ? static_cast<double>(p.done) / seconds : 0;
    const double eta =
        p.done > 0 ? seconds / static_cast<double>(p.done) * static_cast<double>(p.total - p.done)
                   : 0;
    const int percent = p.total ? static_cast<int>(100 * p.done / p.total) : 100;
    std::string frame_part, rate_part, elapsed_part, eta_part;
    if (p.done > 0) {
        frame_part = " frame ";
        frame_part += std::to_string(p.frame);
        if (p.cameras > 1) frame_part += ' ' + p.camera;
        rate_part = format(" %.1f fps", fps);
        elapsed_part = ' ' + clock_text(seconds);
        eta_part = " eta ";
        eta_part += clock_text(eta);
    }
    std::string head = ' ' + std::to_string(p.done);
    head += '/';
    head += std::to_string(p.total);
    head += ' ' + std::to_string(percent) + '%';
    std::string* optional[] = {&frame_part, &rate_part, &elapsed_part, &eta_part};
    const int room = width_ - 1;
    constexpr int kMinBar = 10;
    auto length = [&] {
        return head.size() + frame_part.size() + rate_part.size() + elapsed_part.size() +
               eta_part.size();
    };
    for (std::string* part : optional)
        if (static_cast<int>(length()) + 2 + kMinBar > room) part->clear();
    const std::string text = head + frame_part + rate_part + elapsed_part + eta_part;
    const int bar_width = std::min(30, room - static_cast<int>(text.size()) - 2);
    if (bar_width < 5) return text.substr(0, static_cast<size_t>(std::max(0, room)));
    const int filled = p.total ? static_cast<int>(bar_width * p.done / p.total) : bar_width;
    std::string line = "[";
    line.append(static_cast<size_t>(filled), '#');
    line.append(static_cast<size_t>(bar_width - filled), '.');
    line += ']';
    return line + text;
}

void ProgressReporter::frame_done(const FrameProgress& p) {
    done_ = p.done;
    // In logs the line comes when the image's files are written (frame_written).
    if (quiet_ || !terminal_) return;
    // \r and erase-to-end: the line is redrawn in place, never appended.
    std::fprintf(stream_, "\r%s\033[K", bar_line(p).c_str());
    bar_open_ = true;
    std::fflush(stream_);
}

void ProgressReporter::frame_written(const FrameWritten& w) {
    ++written_;
    if (quiet_ || terminal_) return;
    const double seconds = elapsed();
    const double eta = seconds / static_cast<double>(written_) *
                       static_cast<double>(total_ - std::min(total_, written_));
    const std::string files = comma_list(w.files);
    std::fprintf(
        stream_,
        "[%s] frame %d%s%s (%zu/%zu, %d%%) rendered in %.1f ms, wrote %s in %.1f ms, eta %s\n",
        clock_text(seconds).c_str(), w.frame, w.camera.empty() ? "" : " camera ", w.camera.c_str(),
        written_, total_, total_ ? static_cast<int>(100 * written_ / total_) : 100, w.render_ms,
        files.empty() ? "nothing" : files.c_str(), w.encode_ms, clock_text(eta).c_str());
    std::fflush(stream_);
}

void ProgressReporter::finish() {
    if (quiet_) return;
    if (terminal_) std::fprintf(stream_, "\n");
    bar_open_ = false;
    const double seconds = elapsed();
    std::fprintf(stream_, "rendered %s in %s", count_of(done_, "image", "images").c_str(),
                 clock_text(seconds).c_str());
    if (done_ > 0)
        std::fprintf(stream_, " (%s per image, %s)",
                     format(seconds / static_cast<double>(done_) < 1 ? "%.0f ms" : "%.2f s",
                            seconds / static_cast<double>(done_) < 1
                                ? 1000 * seconds / static_cast<double>(done_)
                                : seconds / static_cast<double>(done_))
                         .c_str(),
                     format("%.1f fps", static_cast<double>(done_) / seconds).c_str());
    std::fprintf(stream_, "\n");
    std::fflush(stream_);
}

}  // namespace facet
