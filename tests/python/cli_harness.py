"""Running `rockingwall` as users do (a child process) and checking that a refusal is one clear
line: shared by the hostile-input tests of the command line."""
import os
import subprocess
import sys

import numpy as np

NOT_CLEAR = ("Traceback", "Exception ignored", "Error:", "MemoryError")


def cli(*args, cwd=None, env=None, timeout=600, **kw):
    return subprocess.run([sys.executable, "-m", "rockingwall", *map(str, args)], capture_output=True, text=True,
                          timeout=timeout, cwd=cwd, env=env, **kw)


def assert_refused(proc, *needles, code=2):
    """Exit status `code`, one 'rockingwall...error:' line holding every needle, no traceback."""
    assert proc.returncode == code, (proc.returncode, proc.stderr[-3000:])
    errors = [ln for ln in proc.stderr.splitlines() if "error:" in ln and ln.startswith(("rockingwall", "usage", "couple"))]
    assert len(errors) == 1, proc.stderr[-3000:]
    for bad in NOT_CLEAR:
        assert bad not in proc.stderr.replace(errors[0], ""), proc.stderr[-3000:]
    for needle in needles:
        assert str(needle) in errors[0], (needle, errors[0])
    return errors[0]


def write_csv_record(path, t, ag_g, header="time,ag", encoding="utf-8"):
    """A two-column CSV record (time [s], acceleration [g])."""
    lines = [header] + [f"{a!r},{b!r}" for a, b in zip(map(float, t), map(float, ag_g))]
    with open(path, "w", encoding=encoding, newline="\n") as f:
        f.write("\n".join(lines) + "\n")
    return path


def pulse(path, duration=3.0, dt=0.01, amp_g=0.3):
    """A sine pulse record of `duration` seconds that makes the default wall rock."""
    t = np.arange(0.0, duration + dt / 2, dt)
    return write_csv_record(path, t, amp_g * np.sin(2 * np.pi * t / 0.8) * (t < 0.6 * duration))


def quiet_env(**extra):
    return dict(os.environ, PYTHONWARNINGS="ignore", **extra)
