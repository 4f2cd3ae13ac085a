#!/usr/bin/env bash
# Installs what is missing, builds, and runs the test suite with ctest.
#   scripts/test.sh             the default suite (a few minutes on 2 cores)
#   scripts/test.sh --sanitize  the suite again, built by clang with
#                               AddressSanitizer, UndefinedBehaviorSanitizer
#                               and -Werror (in build-sanitize/, which also
#                               builds the fuzz harnesses for scripts/fuzz.sh)
#   scripts/test.sh --long      also the long suites (tagged [long]) and a
#                               minute of each fuzzer (scripts/fuzz.sh)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
mode="${1:-}"
case "$mode" in
    ""|--long|--sanitize) ;;
    *) echo "test.sh: unknown option '$mode' (use --sanitize or --long)" >&2; exit 2 ;;
esac

if [ "$mode" = "--sanitize" ]; then
    build="${FACET_SANITIZE_BUILD_DIR:-$root/build-sanitize}"
    "$root/scripts/setup.sh" --tests --sanitize
    cd "$build"
    # Leaks count as failures too; a report names the file and line.
    export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
    export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
    ctest --output-on-failure -j2
    exit 0
fi

build="${FACET_BUILD_DIR:-$root/build}"
"$root/scripts/setup.sh" --tests
cd "$build"
ctest --output-on-failure -j2
if [ "$mode" = "--long" ]; then
    "$build/tests/facet_tests" "[long]"
    "$root/scripts/fuzz.sh" --seconds 60
fi
