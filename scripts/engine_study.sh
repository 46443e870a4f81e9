#!/usr/bin/env bash
# The exact engine against fmi2sim (CVODE at rtol 1e-10, 1e-12 where they disagree) on more random
# scenes than the test run's 200: walls, hinge laws, K_d, records and intensities drawn from each
# scene's seed (tests/python/engine_scenes.py), with the tests' own checks
# (tests/python/test_engine.py). Not part of CI; needs the build (scripts/run_tests.sh makes it).
#
#   scripts/engine_study.sh [FIRST [LAST]]   (seeds FIRST to LAST - 1; default 200 1200, the 1 000
#                                             scenes after the test run's; about 2 minutes)
set -euo pipefail
cd "$(dirname "$0")/.."

case "${1:-}" in
  -h|--help) sed -n '2,8p' "$0"; exit 0 ;;
esac
first=${1:-200}
last=${2:-}
case "$first${last:-0}" in
  *[!0-9]*) echo "engine_study.sh: FIRST and LAST must be whole numbers, got '$first' '$last' (see --help)" >&2
            exit 2 ;;
esac
last=${last:-$((first + 1000))}
if [ "$last" -le "$first" ]; then
  echo "engine_study.sh: LAST ($last) must be above FIRST ($first)" >&2
  exit 2
fi
RW_ENGINE_SCENES="$first:$last" exec .venv/bin/python -m pytest tests/python/test_engine.py -k random_scene \
  -q -p no:cacheprovider
