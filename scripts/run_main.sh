#!/usr/bin/env bash
# Sets everything up (scripts/setup.sh), then runs the main job: wall 1 under El Centro 1940
# at 50 % (rockingwall demo); prints peak displacements, writes results/main_elcentro.csv
# and results/main_elcentro.png. Extra arguments go to `rockingwall demo` (see --help).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
exec .venv/bin/rockingwall demo "$@"
