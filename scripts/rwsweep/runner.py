"""One run of a sweep: fmi2sim with --summary (peaks without the time history), turned into one
row of the results file. Runs on a Dask worker, so it takes and returns plain dicts (a RunSpec as a dict:
workers need not import this project; sweep.py ships this module to them by value);
a failed run becomes a row with status 'error' and fmi2sim's message instead of an exception, so
one bad record cannot stop a sweep."""
import json
import math
import os
import subprocess
import tempfile
import time

# The columns of the results file, in order. Peaks are max |value| over fmi2sim's output rows and
# solver steps.
COLUMNS = ["run_id", "wall", "model", "hinge_law", "kd_kN", "record", "record_pga_g", "scale", "pga_g",
           "status", "message", "peak_s1", "peak_s2", "peak_F_top", "collapsed", "impacts", "end_time",
           "steps", "cpu_s", "elapsed_s"]

TIMEOUT_S = 600.0


def command(spec, fmi2sim, fmu, rtol, summary_path):
    """The fmi2sim command line of a run (also what a user types to repeat one run by hand)."""
    cmd = [str(fmi2sim), str(fmu), "--ag", spec["record_path"], "--ag-scale", repr(float(spec["scale"])),
           "--stop-time", repr(float(spec["stop_time"])), "--rtol", repr(float(rtol)), "--summary", str(summary_path)]
    for name, value in spec["sets"]:
        cmd += ["--set", f"{name}={value}"]
    return cmd


def _row(spec, status, message="", **values):
    row = {c: "" for c in COLUMNS}
    row.update(run_id=spec["run_id"], wall=spec["wall"], model=spec["model"], hinge_law=spec["hinge_law"],
               kd_kN=spec["kd_kN"], record=spec["record"], record_pga_g=spec["record_pga_g"], scale=spec["scale"],
               pga_g=spec["pga_g"], status=status, message=" ".join(message.split()))  # one line in the CSV
    row.update(values)
    return row


def _error_line(stderr):
    """fmi2sim's one-line 'fmi2sim: error: ...' (else the last line it wrote)."""
    lines = [ln for ln in stderr.splitlines() if ln.strip()]
    errors = [ln for ln in lines if "error:" in ln]
    return (errors or lines or ["no message"])[-1]


def run(spec, fmi2sim, fmu, rtol):
    """Simulate one RunSpec; always returns a row."""
    t0 = time.perf_counter()
    if spec["error"]:
        return _row(spec, "error", spec["error"])
    if not (spec["scale"] > 0 and math.isfinite(spec["scale"])):
        return _row(spec, "error", f"scale factor {spec['scale']} (record PGA {spec['record_pga_g']} g)")
    fd, summary = tempfile.mkstemp(prefix="rw_sweep_", suffix=".json")
    os.close(fd)
    try:
        proc = subprocess.run(command(spec, fmi2sim, fmu, rtol, summary), capture_output=True, text=True,
                              timeout=TIMEOUT_S)
        if proc.returncode != 0:
            return _row(spec, "error", f"fmi2sim exit {proc.returncode}: {_error_line(proc.stderr)}",
                        elapsed_s=time.perf_counter() - t0)
        with open(summary) as f:
            res = json.load(f)
        out = res["outputs"]
        return _row(spec, "ok", peak_s1=out["s1"]["max_abs"], peak_s2=out["s2"]["max_abs"],
                    peak_F_top=out["F_top"]["max_abs"], collapsed=bool(out["collapsed"]["final"]),
                    impacts=int(out["impacts"]["final"]), end_time=res["end_time"], steps=res["steps"],
                    cpu_s=res["cpu_seconds"], elapsed_s=time.perf_counter() - t0)
    except subprocess.TimeoutExpired:
        return _row(spec, "error", f"fmi2sim did not finish in {TIMEOUT_S:g} s")
    except (OSError, ValueError, KeyError, TypeError) as exc:  # e.g. an FMU without s1, s2, ...
        return _row(spec, "error", f"{type(exc).__name__}: {exc}")
    finally:
        os.unlink(summary)


def run_batch(specs, fmi2sim, fmu, rtol):
    """Several runs in one Dask task: fewer tasks for the scheduler when runs are short."""
    return [run(s, fmi2sim, fmu, rtol) for s in specs]
