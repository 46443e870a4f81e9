"""fmi2sim, the CVODE host for any FMI 2.0 Model-Exchange FMU, run from Python: the one place that
builds its command line (floats written with repr, so no digit is lost) and reads its results
from the `--summary` JSON it writes (never from its standard error, which is for people)."""
import json
import os
import pathlib
import subprocess

from . import paths, scratch
from .errors import RockingWallError


class Fmi2simError(RockingWallError, RuntimeError):
    """fmi2sim refused or failed a run; the message is its one-line error."""

    def __init__(self, returncode, message):
        super().__init__(message)
        self.returncode = returncode


def command(fmu, *, ag=None, ag_scale=None, input_csv=None, stop_time=None, rtol=None, solver=None,
            sets=(), summary=None, output=None, output_interval=None, executable=None):
    """The argument list of one fmi2sim run (also what a user types to repeat it by hand).
    sets: (name, value) pairs for --set."""
    cmd = [str(executable or paths.fmi2sim()), str(fmu)]
    options = [("--ag", ag), ("--ag-scale", ag_scale), ("--input", input_csv), ("--stop-time", stop_time),
               ("--rtol", rtol), ("--solver", solver), ("--output-interval", output_interval),
               ("--summary", summary), ("--output", output)]
    for flag, value in options:
        if value is not None:
            cmd += [flag, _text(value)]
    for name, value in sets:
        cmd += ["--set", f"{name}={_text(value)}"]
    return cmd


def _text(value):
    return repr(float(value)) if isinstance(value, float) else str(value)


def error_line(stderr):
    """fmi2sim's one-line 'fmi2sim: error: ...' (else the last line it wrote)."""
    lines = [ln for ln in stderr.splitlines() if ln.strip()]
    errors = [ln for ln in lines if "error:" in ln]
    return (errors or lines or ["no message"])[-1]


def run(fmu, *, timeout=None, env=None, **options):
    """Run fmi2sim and return its summary (dict: 'outputs' with max_abs/final per output,
    'end_time', 'steps', 'cpu_seconds', ...). Raises Fmi2simError with its message."""
    with scratch.folder("rw_fmi2sim_") as tmp:
        summary = pathlib.Path(tmp) / "summary.json"
        cmd = command(fmu, summary=summary, **options)
        proc = subprocess.run(cmd, capture_output=True, text=True, errors="replace", timeout=timeout,
                              env=dict(os.environ, TMPDIR=tmp, **(env or {})))
        if proc.returncode != 0:
            raise Fmi2simError(proc.returncode, error_line(proc.stderr))
        return json.loads(summary.read_text())
