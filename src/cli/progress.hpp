#pragma once
// Progress of a render: a bar redrawn in place on a terminal, one line per
// frame otherwise (logs of CI jobs and render farms), nothing with --quiet.
#include <chrono>
#include <cstdio>

#include "render/render_job.hpp"

namespace facet {

class ProgressReporter {
  public:
    ProgressReporter(std::FILE* stream, bool quiet);
    void frame_done(const FrameProgress& p);
    void finish();

  private:
    std::FILE* stream_;
    bool quiet_;
    bool terminal_;
    std::chrono::steady_clock::time_point start_;
};

}  // namespace facet
