#!/usr/bin/env bash
# Builds facet_bench and runs the whole comparison: facet against OpenGL on
# Mesa's llvmpipe, bench/scenes/{small,medium,large}.yaml, 1920x1080,
# 48-frame turntable, 1 and 2 threads (docs/performance.md).
#   scripts/bench.sh                   the full run (a few minutes on 2 cores)
#   scripts/bench.sh --frames 12       12 frames spread over the turntable
#   scripts/bench.sh bench/scenes/small.yaml     one scene
# Any argument is passed to facet_bench (facet_bench --help lists them).
# FACET_BUILD_DIR picks the build folder (default: build), FACET_BENCH_JOBS
# the parallel build jobs (default: 2). Progress goes to stderr; the markdown
# tables go to stdout and to bench/results/bench-<date>.md (not committed).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build="${FACET_BUILD_DIR:-$root/build}"
jobs="${FACET_BENCH_JOBS:-2}"

if [ ! -f "$build/CMakeCache.txt" ]; then
    cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release
fi
build_type=$(sed -n 's/^CMAKE_BUILD_TYPE:[A-Z]*=//p' "$build/CMakeCache.txt")
if [ "$build_type" != "Release" ]; then
    echo "warning: $build is a '$build_type' build; benchmark figures want Release" >&2
fi
cmake --build "$build" -j"$jobs" --target facet_bench

mkdir -p "$root/bench/results"
log="$root/bench/results/bench-$(date +%Y%m%d-%H%M%S).md"
{
    echo "# facet_bench $(date -u '+%Y-%m-%d %H:%M UTC')"
    echo
    echo "- commit: $(git -C "$root" describe --always --dirty 2>/dev/null || echo unknown)"
    echo "- CPU: $(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -1), nproc $(nproc)"
    echo "- kernel: $(uname -r); compiler: $(sed -n 's/^CMAKE_CXX_COMPILER:[A-Z]*=//p' "$build/CMakeCache.txt")"
    echo "- load average before the run: $(cut -d' ' -f1-3 /proc/loadavg)"
    echo "- command: facet_bench $*"
    "$build/bench/facet_bench" "$@"
    echo
    echo "- load average after the run: $(cut -d' ' -f1-3 /proc/loadavg)"
} | tee "$log"
echo "(saved to ${log#"$root"/})" >&2
