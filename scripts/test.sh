#!/usr/bin/env bash
# Installs what is missing, builds, and runs the test suite with ctest.
#   scripts/test.sh           the default suite (a few minutes on 2 cores)
#   scripts/test.sh --long    also the long suites (tagged [long])
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build="${FACET_BUILD_DIR:-$root/build}"
"$root/scripts/setup.sh" --tests
cd "$build"
ctest --output-on-failure -j2
if [ "${1:-}" = "--long" ]; then
    "$build/tests/facet_tests" "[long]"
fi
