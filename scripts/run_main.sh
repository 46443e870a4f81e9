#!/usr/bin/env bash
# Sets everything up (scripts/setup.sh), then runs the main job: wall 1 under El Centro 1940
# at 50 % through the RockingWall FMU; prints peak displacements, writes results/main_elcentro.csv
# and results/main_elcentro.png. Extra arguments go to scripts/main_job.py (see --help).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
exec .venv/bin/python scripts/main_job.py "$@"
