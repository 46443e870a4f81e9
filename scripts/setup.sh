#!/usr/bin/env bash
# Sets up everything RockingWall needs on a Debian machine, idempotently:
#   1. Debian packages (compiler, CMake, SUNDIALS CVODE, LAPACK, libxml2, libzip, valgrind, Python venv),
#   2. the Python virtual environment .venv/ with the pinned requirements,
#   3. the CMake build in build/ (the FMUs and fmi2sim).
# Each step is skipped when already done, so running it again is cheap.
# --with-windows also installs the mingw-w64 cross compiler and wine64, which build and test the
# FMUs' win64 binaries (docs/windows.md; scripts/run_tests.sh passes it).
set -euo pipefail
cd "$(dirname "$0")/.."

APT_PACKAGES=(build-essential cmake pkg-config python3 python3-venv python3-pip
              libsundials-dev liblapack-dev libxml2-dev libzip-dev valgrind zip unzip)
case "${1:-}" in
  --with-windows) APT_PACKAGES+=(mingw-w64 wine64) ;;
  "") ;;
  *) echo "usage: scripts/setup.sh [--with-windows]" >&2; exit 2 ;;
esac

as_root() {
  if [ "$(id -u)" -eq 0 ]; then "$@"; else sudo "$@"; fi
}

missing=()
for pkg in "${APT_PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed" || missing+=("$pkg")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing Debian packages: ${missing[*]}"
  as_root apt-get update -qq
  as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${missing[@]}"
fi

# Python packages from PyPI, pinned. quakeio declares OpenSees as a dependency, but the module we
# use (quakeio.elcentro) needs only numpy, so it is installed without its dependencies.
if [ ! -x .venv/bin/python ]; then
  echo "setup: creating .venv"
  python3 -m venv .venv
fi
stamp=.venv/.requirements.sha256
want=$(cat requirements.txt requirements-nodeps.txt | sha256sum | cut -d' ' -f1)
if [ ! -f "$stamp" ] || [ "$(cat "$stamp")" != "$want" ]; then
  echo "setup: installing Python requirements into .venv"
  .venv/bin/python -m pip install -q --upgrade pip
  .venv/bin/python -m pip install -q -r requirements.txt
  .venv/bin/python -m pip install -q --no-deps -r requirements-nodeps.txt
  echo "$want" > "$stamp"
fi

# The package rockingwall (python/rockingwall) and the reference solver rwref (reference/), both
# editable: the package finds the compiled parts in build/ (rockingwall/paths.py). `pip install .`
# (without -e) is what a user elsewhere runs: it builds with CMake and installs the binaries too.
# The editable install maps the package's modules as they were when it was made: it is made again
# when a module is added, moved or removed (the stamp is the list of the packages' files).
layout=$(find python/rockingwall reference/rwref -name '*.py' | LC_ALL=C sort | sha256sum | cut -d' ' -f1)
if ! .venv/bin/python -c "import rockingwall, rwref" 2>/dev/null || [ "$(cat .venv/.layout.sha256 2>/dev/null)" != "$layout" ]; then
  echo "setup: installing the packages rockingwall and rwref into .venv (editable)"
  .venv/bin/python -m pip install -q --no-build-isolation --no-deps -e . -Cwheel.cmake=false
  .venv/bin/python -m pip install -q --no-build-isolation --no-deps -e reference
  echo "$layout" > .venv/.layout.sha256
fi

# The CMake build (Debian's cmake, not the one fmpy pulls into the venv).
/usr/bin/cmake -S . -B build -DCMAKE_BUILD_TYPE=Release > build.log 2>&1 || { cat build.log; exit 1; }
/usr/bin/cmake --build build -j2 >> build.log 2>&1 || { cat build.log; exit 1; }
rm -f build.log
echo "setup: ready (build/RockingWall.fmu, build/fmi2sim)"
