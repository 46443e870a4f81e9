#!/usr/bin/env bash
# Fuzzes fmi2sim's input readers (host/input_table.c: CSV and PEER .AT2) with libFuzzer under
# AddressSanitizer + UndefinedBehaviorSanitizer, for a bounded time per target. Not part of CI.
#
#   scripts/fuzz.sh [--time SECONDS]     (default 60 s per target)
#
# Builds the targets with clang into build-fuzz/ (installs the Debian package clang if missing),
# starts from the small seeds in tests/fuzz/corpus/<target>/ (the corpus the fuzzer grows stays in
# build-fuzz/, out of the repository), and copies every crashing input into
# tests/fuzz/regressions/, which ctest replays in every test run (test fuzz_regressions).
set -euo pipefail
cd "$(dirname "$0")/.."

seconds=60
while [ $# -gt 0 ]; do
  case "$1" in
    --time) seconds="$2"; shift 2 ;;
    -h|--help) sed -n '2,11p' "$0"; exit 0 ;;
    *) echo "fuzz.sh: unknown option '$1' (see --help)" >&2; exit 2 ;;
  esac
done

if ! command -v clang > /dev/null; then
  echo "== installing clang (Debian package)"
  if [ "$(id -u)" -eq 0 ]; then apt-get install -y -q clang; else sudo apt-get install -y -q clang; fi
fi

out=build-fuzz
mkdir -p "$out"
flags=(-g -O1 -std=c99 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined -Ihost -Itests/fuzz)
found=0
for target in csv at2; do
  echo "== building fuzz_$target"
  clang "${flags[@]}" -o "$out/fuzz_$target" tests/fuzz/fuzz_$target.c tests/fuzz/harness.c host/input_table.c -lm
  mkdir -p "$out/corpus_$target" "$out/crashes_$target"
  echo "== fuzzing the $target reader for $seconds s"
  # -max_len: input files of a few kB reach every branch; -timeout: a single input must not hang
  set +e
  UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 "$out/fuzz_$target" -max_total_time="$seconds" \
    -max_len=4096 -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
    -artifact_prefix="$out/crashes_$target/" "$out/corpus_$target" "tests/fuzz/corpus/$target" \
    2> "$out/fuzz_$target.log"
  rc=$?
  set -e
  grep -E "^stat::(number_of_executed_units|average_exec_per_sec|new_units_added|peak_rss_mb)" "$out/fuzz_$target.log" || true
  for crash in "$out/crashes_$target"/*; do
    [ -e "$crash" ] || continue
    name="tests/fuzz/regressions/$target-$(basename "$crash")"
    cp "$crash" "$name"
    echo "crashing input kept as $name"
    found=$((found + 1))
  done
  if [ $rc -ne 0 ]; then
    echo "fuzz_$target stopped with status $rc; the report is in $out/fuzz_$target.log" >&2
    grep -m 5 -E "ERROR|runtime error|SUMMARY" "$out/fuzz_$target.log" >&2 || true
  fi
done
echo "== $found crashing input(s) found; replay them with: ctest --test-dir build -R fuzz_regressions"
[ "$found" -eq 0 ]
