#!/usr/bin/env bash
# Builds the libFuzzer harnesses (tests/fuzz/) with clang, AddressSanitizer
# and UndefinedBehaviorSanitizer in build-sanitize/, and runs each for a while.
#
#   scripts/fuzz.sh                    each harness for 60 s
#   scripts/fuzz.sh --seconds 600 obj  one harness, longer
#
# Harnesses: scene (scene and style loader), obj, gltf, texture,
# environment (.hdr and .exr environment maps), ply, assimp (STL, FBX,
# Collada, 3DS), manifest (the manifest and run-journal reader), override
# (-D values applied to a scene). Seeds: the
# checked-in corpus tests/fuzz/corpus/TARGET, the regression inputs, and
# scenes/, styles/ and assimp's test models. New finds go to
# build-sanitize/corpus/TARGET and stay there: the checked-in corpus is the
# small hand-made one (tests/fuzz/make_corpus.py). A crash, a hang (over
# 10 s) or a runaway allocation (over 2 GB) stops the run: its input is
# saved under
# build-sanitize/findings/, and once fixed it belongs in
# tests/fuzz/regressions/TARGET/, which the normal suite replays.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
seconds=60
targets=()
while [ $# -gt 0 ]; do
    case "$1" in
        --seconds) seconds="${2:?--seconds needs a number}"; shift 2 ;;
        scene|obj|gltf|texture|environment|ply|assimp|manifest|override) targets+=("$1"); shift ;;
        *) echo "fuzz.sh: unknown argument '$1' (harnesses: scene obj gltf texture environment ply assimp manifest override)" >&2; exit 2 ;;
    esac
done
[ ${#targets[@]} -gt 0 ] || targets=(scene obj gltf texture environment ply assimp manifest override)
case "$seconds" in ''|*[!0-9]*) echo "fuzz.sh: --seconds needs a whole number" >&2; exit 2 ;; esac

# The sanitizer build (scripts/setup.sh --sanitize) has the harnesses.
build="${FACET_SANITIZE_BUILD_DIR:-$root/build-sanitize}"
"$root/scripts/setup.sh" --tests --sanitize

models=/usr/share/assimp/models
seeds_for() {
    case "$1" in
        scene) echo "$root/scenes $root/styles $root/tests/scenes" ;;
        obj) echo "$models/OBJ" ;;
        gltf) echo "$models/glTF2 $models/glTF $root/tests/assets" ;;
        texture) echo "$models/OBJ $models/glTF2/BoxTextured-glTF" ;;
        ply) echo "$models/PLY" ;;
        environment) ;;
        assimp) echo "$build/assimp-seeds" ;;
        manifest|override) ;;
    esac
}

# A freed block waits in AddressSanitizer's quarantine so that a late use
# of it is caught. The default quarantine (256 MB) and an allocator that
# keeps freed pages made the harnesses' RSS climb towards the RSS limit
# over a long run (docs/hardening.md): a 16 MB quarantine still catches a
# use soon after the free, and freed pages go back to the system.
export ASAN_OPTIONS=detect_leaks=1:quarantine_size_mb=16:thread_local_quarantine_size_kb=256:allocator_release_to_os_interval_ms=500
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# Leaks inside libassimp itself are not facet's (tests/fuzz/lsan_suppressions.txt).
export LSAN_OPTIONS=suppressions=$root/tests/fuzz/lsan_suppressions.txt
# The assimp harness reads a byte that names the file, then the file:
# assimp's own STL, FBX, Collada and 3DS test models (up to 256 KB) are its
# seeds, each after its format's byte (tests/fuzz/fuzz_targets.cpp).
if [[ " ${targets[*]} " == *" assimp "* ]]; then
    mkdir -p "$build/assimp-seeds"
    byte=0
    for format in STL FBX Collada 3DS; do
        if [ -d "$models/$format" ]; then
            find "$models/$format" -type f -size -256k -print0 |
                while IFS= read -r -d '' model; do
                    { printf "\\$(printf '%03o' "$byte")"; cat "$model"; } \
                        >"$build/assimp-seeds/$format-$(basename "$model")"
                done
        fi
        byte=$((byte + 1))
    done
fi
status=0
for t in "${targets[@]}"; do
    found="$build/corpus/$t"
    mkdir -p "$found" "$build/findings"
    # The checked-in corpus and regressions (a harness may have none yet),
    # then the seeds found on this machine.
    seeds=()
    for s in "$root/tests/fuzz/corpus/$t" "$root/tests/fuzz/regressions/$t" $(seeds_for "$t"); do
        [ -e "$s" ] && seeds+=("$s")
    done
    echo "fuzz: $t for ${seconds}s" >&2
    if ! "$build/tests/fuzz/fuzz_$t" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
            -max_len=262144 -print_final_stats=1 -artifact_prefix="$build/findings/$t-" \
            "$found" "${seeds[@]}" >"$build/fuzz-$t.log" 2>&1; then
        tail -n 60 "$build/fuzz-$t.log" >&2
        echo "fuzz: $t found a problem; its input is in $build/findings/ (log: $build/fuzz-$t.log)" >&2
        status=1
        continue
    fi
    grep -E "stat::number_of_executed_units|cov:" "$build/fuzz-$t.log" | tail -n 2 >&2 || true
done
exit $status
