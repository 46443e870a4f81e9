"""Shared pytest setup: import paths and the locations of built artefacts."""
import os
import pathlib
import sys

import pytest

import fmpy.logging

# fmpy 0.3.32's native logger proxy keeps ONE global pointer to the Python logger of the last
# addLoggerProxy call (logging.so: s_logger), while the ctypes closure it points to lives only as
# long as that call's callbacks struct. After a simulate_fmu(..., logger=f) returns, its struct is
# collected, and the next FMU message through fmpy's proxy calls freed memory: SIGILL/SIGSEGV in
# a later test, depending on what reused the memory. Keep every proxied struct alive.
_PROXIED_CALLBACKS = []
_add_logger_proxy = fmpy.logging.addLoggerProxy


def _add_logger_proxy_keeping_the_logger(callbacks):
    _PROXIED_CALLBACKS.append(callbacks)
    return _add_logger_proxy(callbacks)


fmpy.logging.addLoggerProxy = _add_logger_proxy_keeping_the_logger

REPO = pathlib.Path(__file__).resolve().parents[2]
BUILD = pathlib.Path(os.environ.get("RW_BUILD_DIR", REPO / "build"))

# rockingwall and the reference solver rwref are installed into the venv (scripts/setup.sh); the
# developer generators (gen_model_description, stability_cases) are scripts run by path.
sys.path.insert(0, str(REPO / "scripts"))


@pytest.fixture(scope="session")
def repo():
    return REPO


@pytest.fixture(scope="session")
def build_dir():
    return BUILD


def _artefact(name):
    path = BUILD / name
    if not path.exists():
        pytest.fail(f"{path} is missing: build it first (cmake -S . -B build && cmake --build build)")
    return path


@pytest.fixture(scope="session")
def rockingwall_fmu():
    return _artefact("RockingWall.fmu")


@pytest.fixture(scope="session")
def building_fmu():
    return _artefact("Building.fmu")


@pytest.fixture(scope="session")
def ball_fmu():
    """The bouncing ball with analytic bounce times (tests/bouncingball), for fmi2sim's tests."""
    return _artefact("BouncingBall.fmu")


@pytest.fixture(scope="session")
def fmi2sim_exe():
    return _artefact("fmi2sim")


# ---- sweeps (tests/python/sweep_harness.py) ----

@pytest.fixture()
def one_record(tmp_path):
    """A suite folder holding one short pulse record."""
    from sweep_harness import pulse_record  # the tests' folder is on sys.path once conftest is loaded
    d = tmp_path / "suite"
    d.mkdir()
    pulse_record(d / "p1.AT2", 0.10, 0.6)
    return d


@pytest.fixture()
def private_tmp(tmp_path, monkeypatch):
    """A temporary folder of the test's own (TMPDIR for this process and its children), so a
    test can check that a sweep leaves nothing in it."""
    import tempfile
    tmp = tmp_path / "tmpdir"
    tmp.mkdir()
    monkeypatch.setenv("TMPDIR", str(tmp))
    monkeypatch.setattr(tempfile, "tempdir", str(tmp))
    return tmp


@pytest.fixture()
def figures(monkeypatch):
    """Every matplotlib figure saved while the test runs (the plots close them after saving)."""
    import matplotlib.figure
    saved = []
    original = matplotlib.figure.Figure.savefig

    def keep(self, *a, **k):
        saved.append(self)
        return original(self, *a, **k)
    monkeypatch.setattr(matplotlib.figure.Figure, "savefig", keep)
    return saved
