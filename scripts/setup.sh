#!/usr/bin/env bash
# Installs the Debian packages facet needs (only those missing), then
# configures and builds it (Release, -j2): the program alone, and with
# --tests or --bench everything. Safe to run again: a second run with
# nothing to do takes about a second.
#
#   scripts/setup.sh            build dependencies, then build
#   scripts/setup.sh --tests    also the test data (assimp-testmodels),
#                               strace (counts the files a run opens),
#                               scikit-image (checks facet's SSIM),
#                               chromium (opens compare's HTML report headless),
#                               dpkg-dev and file (the CPack package test),
#                               slurm-wlm (a one-host Slurm cluster runs a farm
#                               job: scripts/slurm-test.sh) and python3-yaml
#                               (runs the Open Job Description template),
#                               openimageio-tools (oiiotool reads the
#                               pass EXRs back: docs/passes.md), and
#                               xvfb, xdotool and x11-apps (xwd): the
#                               preview window's test on a virtual display
#                               (docs/preview.md), and npm's
#                               @gltf-transform/cli (makes the WebP, AVIF,
#                               instanced and quantized variants of the
#                               glTF test files, as real pipelines do)
#   scripts/setup.sh --bench    also Mesa's OSMesa for the llvmpipe reference
#   scripts/setup.sh --sanitize also clang and its sanitizer and libFuzzer
#                               runtimes, and a second build by clang with
#                               ASan, UBSan, -Werror and the fuzz harnesses
#                               in build-sanitize/ (scripts/test.sh
#                               --sanitize, scripts/fuzz.sh)
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build="${FACET_BUILD_DIR:-$root/build}"
# When this run began: the stamp ./facet checks (written at the end, with
# this time, so a file edited during the build still counts as newer).
started=$(mktemp)
trap 'rm -f "$started"' EXIT
sanitize=0
tests=0
bench=0

packages=(g++ cmake make pkg-config ccache
          libyaml-cpp-dev libtinygltf-dev libtinyobjloader-dev nlohmann-json3-dev libstb-dev
          libopenexr-dev libimath-dev libglm-dev libcli11-dev catch2 libpng-dev
          libdeflate-dev zlib1g-dev libssl-dev libmeshoptimizer-dev libdraco-dev libassimp-dev
          libavcodec-dev libavformat-dev libavutil-dev libswscale-dev
          libsdl2-dev libimgui-dev libgl-dev libgl1-mesa-dri libwebp-dev libavif-dev)
for arg in "$@"; do
    case "$arg" in
        --tests) tests=1; packages+=(time strace assimp-testmodels python3-skimage python3-yaml chromium dpkg-dev file slurm-wlm gltfpack openimageio-tools
                            xvfb xdotool x11-apps) ;;
        --bench) packages+=(libosmesa6-dev); bench=1 ;;
        --sanitize) packages+=(clang libclang-rt-dev llvm); sanitize=1 ;;
        *) echo "setup.sh: unknown option '$arg' (use --tests, --bench or --sanitize)" >&2; exit 2 ;;
    esac
done

if [ "$(id -u)" -eq 0 ]; then sudo=(); else sudo=(sudo); fi
missing=()
for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
    echo "setup: installing ${missing[*]}" >&2
    if [ ${#sudo[@]} -gt 0 ] && ! command -v sudo >/dev/null; then
        echo "setup: need root to install: apt-get install ${missing[*]}" >&2; exit 1
    fi
    export DEBIAN_FRONTEND=noninteractive
    "${sudo[@]}" apt-get update -qq
    "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# Test tools from npm, into the machine's global prefix; npm itself comes
# from Debian when the machine has no Node.js.
if [ "$tests" = 1 ] && ! command -v gltf-transform >/dev/null; then
    if ! command -v npm >/dev/null; then
        echo "setup: installing npm" >&2
        "${sudo[@]}" apt-get update -qq
        DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends npm >/dev/null
    fi
    # 4.3 is the last release that runs on Debian 12's Node.js 18.
    echo "setup: installing @gltf-transform/cli from npm" >&2
    if ! npm install -g --no-fund --no-audit @gltf-transform/cli@4.3.0 >/dev/null; then
        echo "setup: warning: npm could not install @gltf-transform/cli: the tests that make" \
             "files with it will report skipped" >&2
    fi
fi

if [ ! -f "$build/CMakeCache.txt" ]; then
    echo "setup: configuring and building facet in $build (a few minutes the first time)" >&2
    cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
elif [ ${#missing[@]} -gt 0 ] ||
     { [ "$bench" = 1 ] && grep -q '^OSMesa_LIBRARY:FILEPATH=.*NOTFOUND' "$build/CMakeCache.txt"; }; then
    # A package installed into an existing build, by this run or by anything
    # else since (OSMesa for --bench, say), is found only when CMake looks
    # again (it looks again for what it did not find).
    cmake -S "$root" -B "$build" >/dev/null
fi
# The program alone for ./facet (a newcomer's first render); the tests and
# benchmarks too when they are asked for.
targets=(--target facet)
if [ "$tests" = 1 ] || [ "$bench" = 1 ]; then targets=(); fi
log="$build/build.log"
if ! cmake --build "$build" -j2 "${targets[@]}" >"$log" 2>&1; then
    tail -n 40 "$log" >&2
    echo "setup: build failed (full log: $log)" >&2
    exit 1
fi
# ./facet runs the program directly while no file it is built from is newer.
touch -r "$started" "$build/setup.stamp"

if [ "$sanitize" = 1 ]; then
    sbuild="${FACET_SANITIZE_BUILD_DIR:-$root/build-sanitize}"
    if [ ! -f "$sbuild/CMakeCache.txt" ]; then
        echo "setup: configuring the clang sanitizer build in $sbuild" >&2
        CC=clang CXX=clang++ cmake -S "$root" -B "$sbuild" -DCMAKE_BUILD_TYPE=Sanitize \
            -DCMAKE_CXX_FLAGS="-O1 -gline-tables-only" -DFACET_SANITIZE=ON -DFACET_FUZZ=ON \
            -DFACET_WERROR=ON -DFACET_BUILD_BENCH=OFF >/dev/null
    fi
    if ! cmake --build "$sbuild" -j2 >"$sbuild/build.log" 2>&1; then
        tail -n 40 "$sbuild/build.log" >&2
        echo "setup: sanitizer build failed (full log: $sbuild/build.log)" >&2
        exit 1
    fi
fi
