#pragma once
// Wall time since a moment, in milliseconds: for the figures facet reports
// (render and encode times, the thread study, the preview), never for what
// it computes.
#include <chrono>

namespace facet {

inline double ms_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

}  // namespace facet
