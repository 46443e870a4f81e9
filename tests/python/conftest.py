"""Shared pytest setup: import paths and the locations of built artefacts."""
import os
import pathlib
import sys

import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]
BUILD = pathlib.Path(os.environ.get("RW_BUILD_DIR", REPO / "build"))

# The reference solver is a plain package under reference/ (no install step needed).
sys.path.insert(0, str(REPO / "reference"))
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
def fmi2sim_exe():
    return _artefact("fmi2sim")
