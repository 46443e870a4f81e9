#!/usr/bin/env bash
# Sets everything up (scripts/setup.sh) and runs all tests:
#   1. the C unit tests (ctest) of the normal build,
#   2. the same C tests built and run again under AddressSanitizer + UndefinedBehaviorSanitizer,
#   3. the Python test suite (pytest): reference solver, FMU through fmpy, fmi2sim.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh

echo "== C unit tests (build/)"
/usr/bin/ctest --test-dir build --output-on-failure

echo "== C unit tests under AddressSanitizer + UndefinedBehaviorSanitizer (build-asan/)"
/usr/bin/cmake -S . -B build-asan -DRW_SANITIZE=ON -DCMAKE_BUILD_TYPE=Debug > /dev/null
/usr/bin/cmake --build build-asan -j2 > /dev/null
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  /usr/bin/ctest --test-dir build-asan --output-on-failure

echo "== Python tests"
.venv/bin/python -m pytest tests/python -q "$@"
