"""Each master of `rockingwall couple` in a child process of its own (this package's command line
with --json): an FMU that crashes, or libcosim aborting, ends that process only, with a message
naming the master and the signal, not a dead interpreter; every file the child unpacks goes into
a temporary folder removed afterwards. The parent passes its options on and reads the child's
result arrays back from a JSON file."""
import json
import os
import pathlib
import signal
import subprocess
import sys

import numpy as np

from .. import scratch, strict_json
from . import libcosim, monolithic
from .slaves import CouplingError
from .wall_diaphragm import CoupledResult, ground_motion, parse_settings, run_fmpy, wall_start_values

PROG = "rockingwall couple"
ERROR = f"{PROG}: error: "  # how a master's process says why it failed (commands.couple)


def run_master_subprocess(master, args_list, out_json):
    """Run one master of `rockingwall couple` in a fresh process (an FMU that crashes, or libcosim aborting,
    ends that process only) with its own temporary folder, removed afterwards with whatever the
    child unpacked, even when it was killed. Returns the CompletedProcess."""
    cmd = [sys.executable, "-m", "rockingwall", "couple", "--master", master, "--json", str(out_json)]
    with scratch.folder("rw_couple_") as tmp:
        return subprocess.run(cmd + list(args_list), capture_output=True, text=True, errors="replace",
                              timeout=1800, env=dict(os.environ, TMPDIR=tmp))


def run_libcosim_subprocess(args_list, out_json):
    """The libcosim master in a fresh process (see run_master_subprocess)."""
    return run_master_subprocess("libcosim", args_list, out_json)


def child_failure(master, proc, fmus):
    """The message for a master's process that failed, the real error first: its own error line
    when it wrote one, else the last error an FMU or libcosim logged, then how the process ended
    (a signal: an FMU crashed, or libcosim aborted on an error it threw from a thread)."""
    lines = [ln.strip() for ln in proc.stderr.splitlines() if ln.strip()]
    own = [ln for ln in lines if ln.startswith(ERROR)]
    if own:
        return own[-1][len(ERROR):]
    logged = [ln for ln in lines if "what():" in ln or "[error]" in ln]
    cause = logged[-1].split("what():")[-1].strip()[-500:] if logged else ""
    if proc.returncode < 0:
        sig = signal.Signals(-proc.returncode)
        how = (f"the {master} master aborted (signal {sig.value}, {sig.name})" if sig == signal.SIGABRT and cause
               else f"the {master} master died with signal {sig.value} ({sig.name}): an FMU crashed")
    else:
        how = f"the {master} master failed (exit {proc.returncode})"
    where = f"wall {fmus[0]}, diaphragm {fmus[1]}"
    if cause:
        return f"{cause} ({how}; {where})"
    return f"{how} ({where})" + (f"; last output: {lines[-1][-500:]}" if lines else "")


def run_in_this_process(a):
    """One master's CoupledResult, run in this process (the child's side of run_master_subprocess);
    `a`: the options of `rockingwall couple`."""
    t_in, ag_in = ground_motion(a.record, a.scale)
    wall = wall_start_values(a.wall, a.Kd, a.hinge_law, overrides=parse_settings(a.set))
    dia = {"m": a.m, "k": a.k, "zeta": a.zeta}
    if a.master == "monolithic":
        return monolithic.run_monolithic(a.wall_fmu, a.diaphragm_fmu, t_in, ag_in, a.t_end, wall, dia,
                                         rtol=a.rtol, output_interval=a.macro_step)
    if a.master == "libcosim":
        return libcosim.run_libcosim(a.wall_fmu, a.diaphragm_fmu, t_in, ag_in, a.t_end, a.macro_step, wall, dia)
    return run_fmpy(a.wall_fmu, a.diaphragm_fmu, t_in, ag_in, a.t_end, a.macro_step, wall, dia, a.rtol)


def _passthrough(a):
    """The parent's options as command-line arguments for a child."""
    out = []
    for k, v in vars(a).items():
        if k in ("master", "json", "out", "plot", "summary", "strict", "monolithic") or v is None:
            continue
        for item in (v if isinstance(v, list) else [v]):
            out.append(f"--{k.replace('_', '-')}={item}")
    return out


def run_child(master, a):
    """A master's result, run in a child process; CouplingError with the child's real error."""
    with scratch.folder("rw_couple_result_") as tmp:
        out_json = pathlib.Path(tmp) / f"{master}.json"
        proc = run_master_subprocess(master, _passthrough(a), out_json)
        if proc.returncode != 0 or not out_json.exists():
            raise CouplingError(child_failure(master, proc, (a.wall_fmu, a.diaphragm_fmu)))
        data = json.loads(out_json.read_text())
    r = CoupledResult({k: _array(v) for k, v in data.items() if k != "collapsed_at"})
    r["collapsed_at"] = data.get("collapsed_at")
    return r


def _array(values):
    """An array read back from the child's JSON: null (a non-finite number) becomes NaN."""
    a = np.asarray(values)
    return np.asarray(values, dtype=float) if a.dtype == object else a


def write_result(r, path):
    """The child's result arrays (and collapsed_at) as strict JSON (NaN written as null), for run_child."""
    strict_json.write({k: (np.asarray(v).tolist() if v is not None else None) for k, v in r.items()}, path)
