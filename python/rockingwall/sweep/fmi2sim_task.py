"""One run of a sweep through fmi2sim with --summary (peaks without the time history), turned into
one row of the results file (rockingwall.sweep.rows). Runs on a Dask worker, so it takes and
returns plain dicts (a RunSpec as a dict: the sweep ships this module to its workers by value;
they import the installed package for the fmi2sim command line); a failed run becomes a row
instead of an exception, so one bad record cannot stop a sweep."""
import json
import os
import shutil
import subprocess
import tempfile
import time

from .. import scratch
from .rows import ERROR, KILLED, OK, TIMEOUT, make_row, refusal

TIMEOUT_S = 600.0


def command(spec, fmi2sim, fmu, rtol, summary_path):
    """The fmi2sim command line of a run (also what a user types to repeat one run by hand)."""
    from rockingwall.fmi2sim import command as fmi2sim_command  # the one copy; workers have the package
    return fmi2sim_command(fmu, ag=spec["record_path"], ag_scale=float(spec["scale"]),
                           stop_time=float(spec["stop_time"]), rtol=float(rtol), summary=summary_path,
                           sets=spec["sets"], executable=fmi2sim)


def _error_line(stderr):
    """fmi2sim's one-line 'fmi2sim: error: ...' (else the last line it wrote)."""
    lines = [ln for ln in stderr.splitlines() if ln.strip()]
    errors = [ln for ln in lines if "error:" in ln]
    return (errors or lines or ["no message"])[-1]


RUN_PREFIX = "run_"  # a run's folder in the sweep's: fmi2sim's command line names it (its summary file)


def _run_dir(tmp_root):
    """A private folder for one run, inside the sweep's folder when this machine has it (a
    LocalCluster), so whatever a killed run leaves is removed with the sweep's folder, and an
    fmi2sim its killed worker left running is found by its command line (orphans.stop_orphans)."""
    root = tmp_root if tmp_root and os.path.isdir(tmp_root) else None
    return tempfile.mkdtemp(prefix=RUN_PREFIX, dir=root) if root else scratch.make("rw_sweep_run_")


def _run_child(cmd, env, timeout):
    """subprocess.run that never leaves its child running when the wait ends early (a timeout,
    Ctrl-C, SIGTERM)."""
    with subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, errors="replace",
                          env=env) as proc:
        try:
            out, err = proc.communicate(timeout=timeout)
        except BaseException:  # a timeout, Ctrl-C, SIGTERM: never leave the child running
            proc.kill()
            proc.wait()
            raise
    return subprocess.CompletedProcess(cmd, proc.returncode, out, err)


def _simulate(spec, fmi2sim, fmu, rtol, tmp, timeout, t0):
    summary = os.path.join(tmp, "summary.json")
    # TMPDIR: fmi2sim unpacks the FMU into this run's folder, so a run killed before it could
    # clean up leaves nothing behind once the folder is removed
    env = dict(os.environ, TMPDIR=tmp)
    proc = _run_child(command(spec, fmi2sim, fmu, rtol, summary), env, timeout)
    if proc.returncode < 0:  # a signal: the OOM killer, a timeout of the caller, ...
        return make_row(spec, KILLED, f"fmi2sim killed by signal {-proc.returncode}: {_error_line(proc.stderr)}",
                    elapsed_s=time.perf_counter() - t0)
    if proc.returncode != 0:
        return make_row(spec, ERROR, f"fmi2sim exit {proc.returncode}: {_error_line(proc.stderr)}",
                    elapsed_s=time.perf_counter() - t0)
    with open(summary) as f:
        res = json.load(f)
    out = res["outputs"]
    return make_row(spec, OK, peak_s1=out["s1"]["max_abs"], peak_s2=out["s2"]["max_abs"],
                peak_F_top=out["F_top"]["max_abs"], collapsed=bool(out["collapsed"]["final"]),
                impacts=int(out["impacts"]["final"]), end_time=res["end_time"], steps=res["steps"],
                cpu_s=res["cpu_seconds"], elapsed_s=time.perf_counter() - t0)


def run(spec, fmi2sim, fmu, rtol, tmp_root=None, timeout=None):
    """Simulate one RunSpec; always returns a row."""
    t0 = time.perf_counter()
    timeout = TIMEOUT_S if timeout is None else timeout
    refused = refusal(spec)
    if refused:
        return refused
    tmp = _run_dir(tmp_root)
    try:
        return _simulate(spec, fmi2sim, fmu, rtol, tmp, timeout, t0)
    except subprocess.TimeoutExpired:
        return make_row(spec, TIMEOUT, f"fmi2sim did not finish in {timeout:g} s", elapsed_s=time.perf_counter() - t0)
    except (OSError, ValueError, KeyError, TypeError) as exc:  # e.g. an FMU without s1, s2, ...
        return make_row(spec, ERROR, f"{type(exc).__name__}: {exc}")
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


def run_batch(specs, fmi2sim, fmu, rtol, tmp_root=None, timeout=None):
    """Several runs in one Dask task: fewer tasks for the scheduler when runs are short."""
    return [run(s, fmi2sim, fmu, rtol, tmp_root, timeout) for s in specs]
