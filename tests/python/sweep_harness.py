"""Sweeps in the tests: a short pulse record, the command line of a small fmi2sim sweep, its
results read back, and an fmi2sim stand-in. Shared by the sweep test files (their fixtures
one_record and private_tmp are in conftest.py)."""
import numpy as np
import pandas as pd

from rockingwall.sweep import suites


def pulse_record(path, amp_g, period, n_cycles=3, dt=0.01, tail=1.0):
    """A short sine burst in g as an AT2 file: rocks the wall in a fraction of a second of CPU."""
    t = np.arange(0.0, n_cycles * period + tail, dt)
    acc = np.where(t < n_cycles * period, amp_g * np.sin(2 * np.pi * t / period), 0.0)
    suites.write_at2(path, acc, dt, f"test pulse {amp_g} g, {period} s")
    return acc


def sweep_args(suite, out, fmi2sim, fmu, *extra):
    return ["--suite", str(suite), "--kd", "50", "--scales", "1", "--tail", "1", "--scheduler", "synchronous", "--engine", "fmi2sim",
            "--no-progress", "--out", str(out), "--fmi2sim", str(fmi2sim), "--fmu", str(fmu), *map(str, extra)]


def rows(path):
    return pd.read_csv(path)


def fake_fmi2sim(path, real, action):
    """An fmi2sim stand-in: runs `action` (shell) while the file MARKER beside it exists, then the
    real fmi2sim. Its content does not change when the marker goes, so neither does its hash."""
    marker = path.with_name("MARKER")
    path.write_text(f'#!/bin/sh\nif [ -e "{marker}" ]; then\n{action}\nfi\nexec "{real}" "$@"\n')
    path.chmod(0o755)
    marker.touch()
    return marker
