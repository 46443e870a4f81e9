#!/usr/bin/env bash
# Sets everything up (scripts/setup.sh) and runs all tests:
#   1. the C unit tests (ctest) of the normal build,
#   2. the same C tests built and run again under AddressSanitizer + UndefinedBehaviorSanitizer,
#   3. fmpy simulating the sanitizer build of the FMU (ASan runtime preloaded into Python), and
#      fmi2sim's tests against the sanitizer build (fmi2sim and the FMUs it loads built with ASan),
#   4. the Python test suite (pytest): reference solver, FMU through fmpy, fmi2sim (also valgrind).
# The normal build also cross-compiles the FMUs' win64 binaries and runs their tests under wine
# (setup.sh --with-windows installs mingw-w64 and wine64); the sanitizer build does not.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh --with-windows

echo "== C unit tests (build/)"
/usr/bin/ctest --test-dir build --output-on-failure

echo "== C unit tests under AddressSanitizer + UndefinedBehaviorSanitizer (build-asan/)"
/usr/bin/cmake -S . -B build-asan -DRW_SANITIZE=ON -DRW_WIN64=OFF -DCMAKE_BUILD_TYPE=Debug > /dev/null
/usr/bin/cmake --build build-asan -j2 > /dev/null
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  /usr/bin/ctest --test-dir build-asan --output-on-failure

echo "== the FMU under AddressSanitizer + UndefinedBehaviorSanitizer, simulated through fmpy"
RW_ASAN_BUILD_DIR=build-asan .venv/bin/python -m pytest tests/python/test_fmu_asan.py tests/python/test_fmi3_asan.py -q -p no:cacheprovider

echo "== fmi2sim under AddressSanitizer + UndefinedBehaviorSanitizer"
ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 RW_BUILD_DIR=build-asan \
  .venv/bin/python -m pytest tests/python/test_fmi2sim.py tests/python/test_fmi2sim_bad_input.py \
  tests/python/test_fmi2sim_hostile_io.py tests/python/test_fmi2sim_hostile_fmus.py \
  tests/python/test_fmi2sim_hostile_names.py tests/python/test_fmi2sim_discrete_inputs.py -q -p no:cacheprovider

echo "== Python tests"
.venv/bin/python -m pytest tests/python -q "$@"
