"""`pip install .` into a fresh virtual environment, as a user elsewhere would (no editable
install, no RW_BUILD_DIR, run from another folder): the CMake build runs, the FMUs, fmi2sim and
the engine library land inside the package, and the `rockingwall` command it installs gives the
peaks the development tree gives."""
import json
import os
import pathlib
import subprocess
import sys
import venv

import pytest

import rockingwall as rw
from test_engine_library import threads_started_by

REPO = pathlib.Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def fresh_env(tmp_path_factory):
    root = tmp_path_factory.mktemp("fresh")
    venv.create(root / "venv", with_pip=True)
    python = root / "venv" / "bin" / "python"
    env = {k: v for k, v in os.environ.items() if k not in ("RW_BUILD_DIR", "RW_ENGINE_LIB", "PYTHONPATH")}
    proc = subprocess.run([str(python), "-m", "pip", "install", "-q", str(REPO)], capture_output=True, text=True,
                          env=env, cwd=root, timeout=1800)
    assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-5000:]
    return root, python, env


def test_pip_install_gives_a_working_command(fresh_env):
    root, python, env = fresh_env
    where = subprocess.run([str(python), "-c", "from rockingwall import paths; print(paths.build_dir())"],
                           capture_output=True, text=True, env=env, cwd=root, check=True).stdout.strip()
    assert "site-packages" in where and where.endswith("_bin")
    for part in ("RockingWall.fmu", "Diaphragm.fmu", "Building.fmu", "BuildingWithWalls.fmu", "fmi3/RockingWall.fmu",
                 "fmi3/BuildingWithWalls.fmu", "fmi2sim", "librwengine.so"):
        assert (pathlib.Path(where) / part).is_file(), part
    assert threads_started_by(pathlib.Path(where) / "librwengine.so", python) == 0  # its LAPACK found as built
    command = root / "venv" / "bin" / "rockingwall"
    proc = subprocess.run([str(command), "run", "--wall", "paper1", "--Kd", "50kN/m/m", "gaussian", "--json"],
                          capture_output=True, text=True, env=env, cwd=root, timeout=300)
    assert proc.returncode == 0, proc.stderr
    installed = json.loads(proc.stdout)["runs"][0]
    here = rw.simulate(rw.Wall.make("paper1", Kd=50e3), rw.gaussian())
    assert installed["peak_s1_m"] == pytest.approx(here.peak_s1, rel=1e-9)
    assert installed["impacts"] == here.impacts
    proc = subprocess.run([str(command), "run", "--wall", "paper1", "--engine", "fmi2sim", "gaussian", "--json"],
                          capture_output=True, text=True, env=env, cwd=root, timeout=300)
    assert proc.returncode == 0, proc.stderr  # the installed fmi2sim and FMU run too
