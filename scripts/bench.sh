#!/usr/bin/env bash
# Builds facet_bench and runs the suite of docs/performance.md: facet against
# OpenGL on Mesa's llvmpipe doing the same shading, scene by scene, render
# only and whole job (files written), 1 and 2 threads.
#   scripts/bench.sh                   the full suite (3-5 minutes on 2 cores, once built)
#   scripts/bench.sh --frames 12       12 frames spread over each scene's range
#   scripts/bench.sh bench/scenes/blob-5k.yaml     one scene
#   FACET_BENCH_SEED=7 scripts/bench.sh            unseen meshes: other blobs
# Any argument is passed to facet_bench (facet_bench --help lists them).
# The blob meshes and their texture are generated into bench/meshes/ (not
# committed) when missing or when FACET_BENCH_SEED differs from the last run.
# FACET_BUILD_DIR picks the build folder (default: build), FACET_BENCH_JOBS
# the parallel build jobs (default: 2). Progress goes to stderr; the markdown
# tables go to stdout and to bench/results/bench-<date>.md, the plot to
# bench/results/bench-<date>.png (neither committed).
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

meshes="$root/bench/meshes"
seed="${FACET_BENCH_SEED:-1}"
if [ ! -f "$meshes/blob-1m.obj" ] || [ "$(cat "$meshes/seed" 2>/dev/null)" != "$seed" ]; then
    "$build/bench/facet_bench" --make-meshes "$meshes" --seed "$seed"
    echo "$seed" > "$meshes/seed"
fi

mkdir -p "$root/bench/results"
stamp=$(date +%Y%m%d-%H%M%S)
log="$root/bench/results/bench-$stamp.md"
plot="$root/bench/results/bench-$stamp.png"
{
    echo "# facet_bench $(date -u '+%Y-%m-%d %H:%M UTC')"
    echo
    echo "- commit: $(git -C "$root" describe --always --dirty 2>/dev/null || echo unknown)"
    echo "- CPU: $(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -1), nproc $(nproc)"
    echo "- kernel: $(uname -r); compiler: $(sed -n 's/^CMAKE_CXX_COMPILER:[A-Z]*=//p' "$build/CMakeCache.txt")"
    echo "- load average before the run: $(cut -d' ' -f1-3 /proc/loadavg)"
    echo "- command: facet_bench $*; blob seed $seed"
    "$build/bench/facet_bench" --plot "$plot" "$@"
    echo
    echo "- load average after the run: $(cut -d' ' -f1-3 /proc/loadavg)"
} | tee "$log"
echo "(saved to ${log#"$root"/} and ${plot#"$root"/})" >&2
