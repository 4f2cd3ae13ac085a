#pragma once
// Progress of a render, as the tools people trust show it: on a terminal a
// bar redrawn in place that fits the terminal's width (it never wraps, so
// it never scrolls), with percentage, frames per second, elapsed time and
// ETA as h:mm:ss; elsewhere (CI and farm logs) one line per image with the
// same figures; nothing with --quiet. A summary line ends the run.
#include <chrono>
#include <cstdio>
#include <string>

#include "job/render_job.hpp"

namespace facet {

// "0:00:07", "1:02:03": whole seconds, never negative.
std::string clock_text(double seconds);

class ProgressReporter {
  public:
    // `width`: the terminal's columns, 0 to ask the terminal (COLUMNS, else 80).
    ProgressReporter(std::FILE* stream, bool quiet, int width = 0);
    // Ends a bar that finish() did not (an error or an interrupt), so the
    // message that follows starts on a line of its own.
    ~ProgressReporter();
    // Shown before the first frame, so a slow first frame is not silence.
    void start(size_t total, const std::string& what);
    void frame_done(const FrameProgress& p);
    // In logs, the one line per image: written when its files are.
    void frame_written(const FrameWritten& w);
    void finish();

  private:
    double elapsed() const;
    std::string bar_line(const FrameProgress& p) const;

    std::FILE* stream_;
    bool quiet_;
    bool terminal_;
    int width_;
    size_t total_ = 0, done_ = 0, written_ = 0;
    bool bar_open_ = false;  // a bar is drawn and its line not ended
    std::chrono::steady_clock::time_point start_;
};

}  // namespace facet
