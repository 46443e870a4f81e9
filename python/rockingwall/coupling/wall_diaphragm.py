#!/usr/bin/env python3
"""RockingWall coupled to a Diaphragm FMU through FMI 2.0 Co-Simulation.

The paper's top spring K_d is fixed to the ground at its far end; here its far end is a diaphragm
with mass, stiffness and damping (build/Diaphragm.fmu). Both FMUs are Co-Simulation slaves that
integrate themselves with CVODE; a master exchanges their values every macro step H:

    ground motion ag(t)  --> wall.ag,  diaphragm.ag          [m/s2, + toward +x]
    diaphragm.u          --> wall.u_top                      [m, relative to the ground]
    wall.F_top           --> diaphragm.F_top                 [N/m, force of the spring on the diaphragm]

Two independent masters run the same fixed-step Jacobi scheme (every slave steps from t to t+H
with the inputs set at t; after the step the outputs at t+H become the inputs of the next step):
fmpy (FMU2Slave) and libcosim (libcosimpy). The command line runs each master in a child process
(this script with --json), so an FMU that crashes or a libcosim abort ends in a message naming
the master and the signal, not a dead interpreter; every file the child unpacks goes into a
temporary folder removed afterwards. The ground motion is held over each step in both.

    rockingwall couple                                  # wall 1, El Centro x 0.5, fmpy master
    rockingwall couple --master both                    # fmpy and libcosim, and their difference
    rockingwall couple --macro-step 0.005 --t-end 20 --Kd 1e5 --m 2000 --k 7e5 --zeta 0.05
    rockingwall couple --monolithic                     # both FMUs as Model Exchange under one CVODE

The macro step defaults to the largest one the tie K_d allows (coupling_rules.max_macro_step:
H <= c sqrt(m_r/K_d), docs/coupling.md), at most 1 ms; a larger --macro-step (--step) is run with a
warning. A run whose energy residual exceeds --energy-share of the peak ground work (1 %) is
flagged: a warning on stderr, "energy_ok": false in the summary JSON, and exit status 3 with
--strict. --monolithic integrates both FMUs as Model Exchange under one CVODE (no macro step).

Writes results/couple.csv (time, s1, s2, u, F_top and the energy terms), results/couple.png and
results/couple.json (the summary: peaks, step, step limit, energy residual share and flags).
"""
import argparse
import json
import math
import os
import pathlib
import signal
import subprocess
import sys
import tempfile

import numpy as np

from .. import paths, records
from ..names import HINGE_LAWS as LAWS, SUPPORTS as MODELS, paper_wall

from . import rules as coupling_rules

WALL_OUT = ["s1", "s2", "F_top", "energy", "P_ground", "dissipated"]
DIA_OUT = ["u", "v", "energy", "P_ground", "P_damping"]


# Meaningful ranges of the master's own options (low, high); the macro step is also at most t_end.
T_END_RANGE = (1e-3, 1e5)     # s
MACRO_STEP_DEFAULT_MAX = 1e-3  # s: the default step is the tie's limit, at most this (accuracy)
EXIT_FLAGGED = 3               # --strict: the run finished but a safety check failed
MACRO_STEP_MIN = 1e-6         # s: 30 s at 1 us is 3e7 exchanges, already hours
RTOL_RANGE = (1e-12, 1e-2)


class CouplingError(Exception):
    """A slave failed (the FMU, the FMI call and the FMU's own message) or the run did not reach
    its end: never a silent, shortened result."""


def check_options(t_end, H, rtol):
    """ValueError naming the option and its range."""
    if not (math.isfinite(t_end) and T_END_RANGE[0] <= t_end <= T_END_RANGE[1]):
        raise ValueError(f"--t-end {t_end!r} is outside [{T_END_RANGE[0]:g}, {T_END_RANGE[1]:g}] s")
    if not (math.isfinite(H) and MACRO_STEP_MIN <= H <= t_end):
        raise ValueError(f"--macro-step {H!r} is outside [{MACRO_STEP_MIN:g}, t_end = {t_end:g}] s")
    if not (math.isfinite(rtol) and RTOL_RANGE[0] <= rtol <= RTOL_RANGE[1]):
        raise ValueError(f"--rtol {rtol!r} is outside [{RTOL_RANGE[0]:g}, {RTOL_RANGE[1]:g}]")


def vrs(md):
    return {v.name: v.valueReference for v in md.modelVariables}


class _FmuLog:
    """The FMUs' log messages of warning level and above, kept to name the cause of a failure."""

    def __init__(self):
        self.messages = []
        self._keep = []

    def callbacks(self):
        from ctypes import byref
        from fmpy import calloc, free
        from fmpy.fmi2 import (fmi2CallbackAllocateMemoryTYPE, fmi2CallbackFreeMemoryTYPE, fmi2CallbackFunctions,
                               fmi2CallbackLoggerTYPE)
        from fmpy.logging import addLoggerProxy

        def logger(env, instance, status, category, message):
            if status >= 1:  # fmi2Warning and worse
                self.messages.append(f"{(instance or b'').decode(errors='replace')}: "
                                     f"{(message or b'').decode(errors='replace')}")
        cb = fmi2CallbackFunctions()
        cb.logger = fmi2CallbackLoggerTYPE(logger)
        cb.allocateMemory = fmi2CallbackAllocateMemoryTYPE(calloc)
        cb.freeMemory = fmi2CallbackFreeMemoryTYPE(free)
        addLoggerProxy(byref(cb))  # formats the FMU's printf-style arguments
        self._keep.append(cb)  # each FMU holds a pointer to its callbacks until freeInstance
        return cb

    def last(self, instance):
        mine = [m for m in self.messages if m.startswith(instance + ":")]
        return mine[-1] if mine else f"{instance}: no message logged"


def _status_name(status):
    names = ["ok", "warning", "discard", "error", "fatal", "pending"]
    return names[status] if 0 <= status < len(names) else f"status {status}"


def _fmi_call(slave, what, fn, *args):
    """fn(*args), an FMI call of `slave`, with a failure turned into a CouplingError naming the FMU,
    the call and the FMU's own last message."""
    from fmpy.fmi1 import FMICallException
    try:
        return fn(*args)
    except FMICallException as exc:
        slave.failed = True
        raise CouplingError(f"{slave.fmu_path} ({slave.instanceName}): {exc.function} returned "
                            f"{_status_name(exc.status)} {what}: {slave.log.last(slave.instanceName)}") from None
    except Exception as exc:  # fmpy raises a bare Exception when fmi2Instantiate returns NULL
        slave.failed = True
        raise CouplingError(f"{slave.fmu_path} ({slave.instanceName}) {what}: {exc}: "
                            f"{slave.log.last(slave.instanceName)}") from None


def _load_slave(path, name, unzip_root, log):
    """One Co-Simulation slave, its FMU unpacked under unzip_root (removed by the caller)."""
    from fmpy import extract, read_model_description
    from fmpy.fmi2 import FMU2Slave
    md = read_model_description(str(path))
    s = FMU2Slave(guid=md.guid, unzipDirectory=extract(str(path), os.path.join(unzip_root, name)),
                  modelIdentifier=md.coSimulation.modelIdentifier, instanceName=name)
    s.vr, s.fmu_path, s.log, s.failed, s.instantiated = vrs(md), str(path), log, False, False
    return s


def _initialise(s, start, rtol):
    """Instantiate and initialise a slave with its start values."""
    real, integer = start
    _fmi_call(s, "at instantiation", s.instantiate, False, s.log.callbacks())
    s.instantiated = True
    _fmi_call(s, "at setup", s.setupExperiment, rtol, 0.0)
    _fmi_call(s, "setting the start values", s.setReal, [s.vr[k] for k in real], list(real.values()))
    _fmi_call(s, "setting the start values", s.setInteger, [s.vr[k] for k in integer], list(integer.values()))
    _fmi_call(s, "at initialisation", s.enterInitializationMode)
    _fmi_call(s, "at initialisation", s.exitInitializationMode)


def _close_slaves(slaves):
    """Terminate the slaves that did not fail (a failed one may not be terminated) and free all;
    an error here never hides the one that ended the run."""
    for s in slaves:
        if not s.instantiated:
            continue
        try:
            if not s.failed:
                s.terminate()
        except Exception as exc:  # noqa: BLE001  reported, not raised: the run's result stands
            print(f"couple.py: warning: {s.fmu_path} ({s.instanceName}): fmi2Terminate failed: {exc}", file=sys.stderr)
        try:
            s.freeInstance()
        except Exception:  # noqa: BLE001
            pass


def wall_start_values(wall=1, Kd=1e5, hinge_law="dohertyHinge", er=0.86, overrides=None):
    """Real and Integer start values of RockingWall for one of the paper's walls, with the
    parameters in `overrides` ({name: value}, e.g. from --set b=0.23) replacing the wall's."""
    real = dict(paper_wall(wall), Kd=Kd, er=er)
    real.update(overrides or {})
    return real, {"support": MODELS["flexibleTop"], "hingeLaw": LAWS[hinge_law]}


def parse_settings(items):
    """{name: value in SI} from --set NAME=VALUE items, as every other command reads them: a Real
    parameter of RockingWall, a number in its SI unit or with a unit ('14.08kN/m', '230mm'), inside
    the model's range. ValueError naming the item and what is wrong with it."""
    from ..engine import parameter_table
    from ..units import parse
    table = {name: row for name, row in parameter_table().items() if not row.is_integer}
    out = {}
    for item in items or []:
        name, sep, value = (part.strip() for part in item.partition("="))
        if not sep or not name:
            raise ValueError(f"--set {item!r}: expected NAME=VALUE (a Real parameter of RockingWall)")
        if name not in table:
            raise ValueError(f"--set {item!r}: {name!r} is not a Real parameter of RockingWall "
                             f"(known: {', '.join(table)}; the law is --hinge-law)")
        try:
            out[name] = parse(value, table[name].unit, name)
            table[name].check(out[name])
        except ValueError as exc:
            raise ValueError(f"--set {item!r}: {exc}") from None
    return out


def tie_step_limit(real, dia):
    """The largest macro step the tie K_d allows for these wall start values and diaphragm
    parameters (coupling_rules.max_macro_step)."""
    m_w = coupling_rules.wall_top_mass(real["W"], real.get("psi", 0.0), real["h"], real.get("g", 9.81))
    return coupling_rules.max_macro_step(m_w, dia["m"], real["Kd"], dia["k"])


def choose_macro_step(requested, limit, t_end):
    """(H, warning or None): the requested step, with a warning when it exceeds the tie's limit;
    without a request, the limit (at most MACRO_STEP_DEFAULT_MAX) rounded down to divide t_end."""
    if requested is not None:
        if requested > limit * (1 + 1e-9):
            return requested, (f"--macro-step {requested:g} s exceeds the step the tie allows, {limit:.3g} s "
                               f"(K_d against the wall's and the diaphragm's masses, docs/coupling.md): the "
                               f"coupling may pump energy into the tie and the result may be wrong; use "
                               f"--macro-step {limit:.3g} or smaller, or --monolithic")
        return requested, None
    H = min(limit, MACRO_STEP_DEFAULT_MAX, t_end)
    return t_end / math.ceil(t_end / H - 1e-9), None


def ground_motion(record="elcentro", scale=0.5):
    rec = records.load(record).scaled(scale)
    return np.asarray(rec.t, float), np.asarray(rec.ag, float)


class CoupledResult(dict):
    """Arrays on the communication grid: time, wall_*, dia_* and the energy balance."""

    def energy_residual(self):
        """(E_wall + E_dia)(t) - E(0) - ground work + damping + impact losses: the energy the
        coupled system made or lost unaccounted for (trapezoidal work integrals)."""
        t = self["time"]
        stored = self["wall_energy"] + self["dia_energy"]
        power_in = self["wall_P_ground"] + self["dia_P_ground"] - self["dia_P_damping"]
        work = np.concatenate([[0.0], np.cumsum(0.5 * (power_in[1:] + power_in[:-1]) * np.diff(t))])
        return stored - stored[0] - work + self["wall_dissipated"]

    def _work(self, p):
        return np.concatenate([[0.0], np.cumsum(0.5 * (p[1:] + p[:-1]) * np.diff(self["time"]))])

    def ground_work(self):
        return self._work(self["wall_P_ground"] + self["dia_P_ground"])

    def damping_loss(self):
        return self._work(self["dia_P_damping"])


def _assemble(t, wall_rows, dia_rows):
    r = CoupledResult(time=np.asarray(t))
    w, d = np.asarray(wall_rows), np.asarray(dia_rows)
    for i, n in enumerate(WALL_OUT):
        r["wall_" + n] = w[:, i]
    for i, n in enumerate(DIA_OUT):
        r["dia_" + n] = d[:, i]
    return r


def run_fmpy(wall_fmu, dia_fmu, t_in, ag_in, t_end, H, wall=None, dia=None, rtol=1e-6, progress=False):
    """The fmpy master: fixed-step Jacobi over two Co-Simulation slaves. Both FMUs are unpacked into
    one temporary folder, removed however the run ends."""
    check_options(t_end, H, rtol)
    log, slaves = _FmuLog(), []
    with tempfile.TemporaryDirectory(prefix="couple_fmus_") as unzip_root:
        try:
            for path, name, start in [(wall_fmu, "wall", wall or wall_start_values()),
                                      (dia_fmu, "diaphragm", (dia or {}, {}))]:
                slaves.append(_load_slave(path, name, unzip_root, log))  # listed first: always freed
                _initialise(slaves[-1], start, rtol)
            return _jacobi_fmpy(*slaves, t_in, ag_in, t_end, H, progress)
        finally:
            _close_slaves(slaves)


def _jacobi_fmpy(w, d, t_in, ag_in, t_end, H, progress):
    from fmpy.fmi1 import FMICallException
    from fmpy.fmi2 import fmi2Discard
    n = int(round(t_end / H))
    times, wall_rows, dia_rows = [], [], []
    u = _fmi_call(d, "at t = 0", d.getReal, [d.vr["u"]])[0]
    _fmi_call(w, "at t = 0", w.setReal, [w.vr["u_top"]], [u])
    F = _fmi_call(w, "at t = 0", w.getReal, [w.vr["F_top"]])[0]
    steps = range(n)
    if progress:
        from tqdm import tqdm
        steps = tqdm(steps, desc="fmpy master", unit="step", mininterval=1.0)
    collapsed_at = None
    for k in steps:
        t = k * H
        at = f"at t = {t:.6g} s"
        ag = float(np.interp(t, t_in, ag_in, right=0.0))
        _fmi_call(w, at, w.setReal, [w.vr["ag"], w.vr["u_top"]], [ag, u])
        _fmi_call(d, at, d.setReal, [d.vr["ag"], d.vr["F_top"]], [ag, F])
        times.append(t)
        wall_rows.append(_fmi_call(w, at, w.getReal, [w.vr[x] for x in WALL_OUT]))
        dia_rows.append(_fmi_call(d, at, d.getReal, [d.vr[x] for x in DIA_OUT]))
        try:
            w.doStep(currentCommunicationPoint=t, communicationStepSize=H)
        except FMICallException as exc:
            if exc.status != fmi2Discard:  # an error, not the collapse the FMU ends a run with
                _fmi_call(w, at, _raise, exc)
            collapsed_at = t
            break
        _fmi_call(d, at, d.doStep, t, H)
        F = _fmi_call(w, at, w.getReal, [w.vr["F_top"]])[0]  # with the u_top of the step (Jacobi)
        u = _fmi_call(d, at, d.getReal, [d.vr["u"]])[0]
    else:
        times.append(n * H)
        w.setReal([w.vr["u_top"]], [u])
        d.setReal([d.vr["F_top"]], [F])
        wall_rows.append(w.getReal([w.vr[x] for x in WALL_OUT]))
        dia_rows.append(d.getReal([d.vr[x] for x in DIA_OUT]))
    r = _assemble(times, wall_rows, dia_rows)
    r["collapsed_at"] = collapsed_at
    return r


def _raise(exc):
    raise exc


def run_libcosim(wall_fmu, dia_fmu, t_in, ag_in, t_end, H, wall=None, dia=None):
    """The libcosim master (libcosimpy) with the same Jacobi scheme: call it in a subprocess
    (run_libcosim_subprocess), libcosim aborts the process on some FMU errors."""
    from fmpy import read_model_description
    from libcosimpy.CosimExecution import CosimExecution
    from libcosimpy.CosimManipulator import CosimManipulator
    from libcosimpy.CosimObserver import CosimObserver
    from libcosimpy.CosimLogging import CosimLogLevel, log_output_level
    from libcosimpy.CosimSlave import CosimLocalSlave

    check_options(t_end, H, 1e-6)
    log_output_level(CosimLogLevel.WARNING)  # its trace of every FMU event would fill the parent's pipe
    real, integer = wall or wall_start_values()
    wv, dv = vrs(read_model_description(str(wall_fmu))), vrs(read_model_description(str(dia_fmu)))
    ex = CosimExecution.from_step_size(step_size=int(round(H * 1e9)))  # nanoseconds
    iw = ex.add_local_slave(CosimLocalSlave(fmu_path=str(pathlib.Path(wall_fmu).resolve()), instance_name="wall"))
    idia = ex.add_local_slave(CosimLocalSlave(fmu_path=str(pathlib.Path(dia_fmu).resolve()), instance_name="diaphragm"))
    for k, v in real.items():
        ex.real_initial_value(iw, wv[k], v)
    for k, v in integer.items():
        ex.integer_initial_value(iw, wv[k], v)
    for k, v in (dia or {}).items():
        ex.real_initial_value(idia, dv[k], v)
    ex.connect_real_variables(idia, dv["u"], iw, wv["u_top"])
    ex.connect_real_variables(iw, wv["F_top"], idia, dv["F_top"])
    override = CosimManipulator.create_override()
    ex.add_manipulator(manipulator=override)
    observer = CosimObserver.create_last_value()
    ex.add_observer(observer=observer)
    # libcosim initialises the slaves inside its first step and its observer has values only
    # after a step: row 0 is the state at rest both slaves start from (every output 0)
    n = int(round(t_end / H))
    times, wall_rows, dia_rows = [0.0], [[0.0] * len(WALL_OUT)], [[0.0] * len(DIA_OUT)]
    collapsed_at = None
    for k in range(n):
        ag = float(np.interp(k * H, t_in, ag_in, right=0.0))
        override.slave_real_values(iw, [wv["ag"]], [ag])  # held over the step, as in run_fmpy
        override.slave_real_values(idia, [dv["ag"]], [ag])
        if not ex.step():
            message = _libcosim_error()
            # libcosim reports a slave's fmi2Discard as "<instance>: Step not complete" (its
            # observer keeps the values of the last good step, so the wall's `collapsed` output
            # cannot be read there): from the wall it is the collapse that ends its run, as in
            # run_fmpy; anything else is a failure
            if "wall: Step not complete" in message:
                collapsed_at = k * H
                break
            raise CouplingError(f"libcosim master: the step from t = {k * H:.6g} s failed before t_end = "
                                f"{t_end:g} s: {message}")
        times.append((k + 1) * H)
        wall_rows.append(observer.last_real_values(iw, [wv[x] for x in WALL_OUT]))
        dia_rows.append(observer.last_real_values(idia, [dv[x] for x in DIA_OUT]))
    if collapsed_at is None and abs(times[-1] - n * H) > 1e-9 * max(1.0, t_end):
        raise CouplingError(f"libcosim master: the run ended at t = {times[-1]:.6g} s, not at t_end = {t_end:g} s")
    r = _assemble(times, wall_rows, dia_rows)
    r["collapsed_at"] = collapsed_at
    return r


def _libcosim_error():
    from libcosimpy._internal import get_last_error_message
    return get_last_error_message() or "no message from libcosim"


def run_master_subprocess(master, args_list, out_json):
    """Run one master of this script in a fresh process (an FMU that crashes, or libcosim aborting,
    ends that process only) with its own temporary folder, removed afterwards with whatever the
    child unpacked, even when it was killed. Returns the CompletedProcess."""
    cmd = [sys.executable, "-m", "rockingwall", "couple", "--master", master, "--json", str(out_json)]
    with tempfile.TemporaryDirectory(prefix="couple_") as tmp:
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
    own = [ln for ln in lines if ln.startswith("couple.py: error:")]
    if own:
        return own[-1][len("couple.py: error: "):]
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


def save_csv(r, path):
    cols = ["time", "wall_s1", "wall_s2", "dia_u", "wall_F_top", "wall_energy", "dia_energy",
            "wall_P_ground", "dia_P_ground", "dia_P_damping", "wall_dissipated"]
    data = np.column_stack([r[c] for c in cols] + [r.energy_residual()])
    np.savetxt(path, data, delimiter=",", header=",".join(cols + ["energy_residual"]), comments="")


def plot(r, path, title, other=None):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(3, 1, figsize=(9, 7), sharex=True)
    t = r["time"]
    ax[0].plot(t, 1e3 * r["wall_s1"], label="s1 (mid-height)")
    ax[0].plot(t, 1e3 * r["wall_s2"], label="s2 (top)")
    ax[0].plot(t, 1e3 * r["dia_u"], label="u (diaphragm)")
    if other is not None:
        ax[0].plot(other["time"], 1e3 * other["wall_s1"], "k:", lw=1, label="s1, libcosim master")
    ax[0].set_ylabel("displacement [mm]")
    ax[0].legend(loc="upper right", fontsize=8)
    ax[1].plot(t, r["wall_F_top"] / 1e3)
    ax[1].set_ylabel("F_top [kN/m]")
    ax[2].plot(t, r.ground_work(), label="ground work")
    ax[2].plot(t, r["wall_energy"] + r["dia_energy"], label="stored (wall + diaphragm)")
    ax[2].plot(t, r["wall_dissipated"], label="lost in impacts")
    ax[2].plot(t, r.damping_loss(), label="lost in diaphragm damping")
    ax[2].plot(t, r.energy_residual(), label="residual")
    ax[2].set_ylabel("energy [J/m]")
    ax[2].set_xlabel("time [s]")
    ax[2].legend(loc="upper left", fontsize=8)
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def _stiffness(text):
    """A stiffness per metre of wall in N/m per m, from a bare number or a value with its unit."""
    from ..units import parse
    return parse(text, "N/m2", "stiffness")


def parse_args(argv):
    ap = argparse.ArgumentParser(prog="rockingwall couple", description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--wall-fmu", help="default: the installed RockingWall.fmu")
    ap.add_argument("--diaphragm-fmu", help="default: the installed Diaphragm.fmu")
    ap.add_argument("--record", default="elcentro", help="'elcentro' (quakeio) or a PEER .AT2 file")
    ap.add_argument("--scale", type=float, default=0.5)
    ap.add_argument("--wall", type=int, default=1, choices=[1, 2, 3], help="the paper's wall")
    ap.add_argument("--Kd", type=_stiffness, default=1e5,
                    help="wall-to-diaphragm spring, N/m per m of wall, or with a unit (100kN/m/m)")
    ap.add_argument("--hinge-law", default="dohertyHinge", choices=list(LAWS))
    ap.add_argument("--m", type=float, default=2000.0, help="diaphragm mass, kg per m of wall")
    ap.add_argument("--k", type=_stiffness, default=7e5,
                    help="diaphragm stiffness, N/m per m of wall, or with a unit (700kN/m/m)")
    ap.add_argument("--zeta", type=float, default=0.05)
    ap.add_argument("--macro-step", "--step", dest="macro_step", type=float, default=None,
                    help=f"communication step H [s], in [{MACRO_STEP_MIN:g}, t_end]; default: the largest "
                         f"step the tie K_d allows (docs/coupling.md), at most {MACRO_STEP_DEFAULT_MAX:g} s; "
                         f"a larger one runs with a warning")
    ap.add_argument("--set", action="append", default=[], metavar="NAME=VALUE",
                    help="a Real parameter of RockingWall (b, h, W, psi, er, ...) replacing the --wall's, in SI or "
                         "with its unit (W=14.08kN/m, b=230mm); repeatable")
    ap.add_argument("--energy-share", type=float, default=coupling_rules.ENERGY_SHARE_MAX,
                    help="flag the run when max |energy residual| exceeds this share of max |ground work| "
                         f"(default {coupling_rules.ENERGY_SHARE_MAX:g})")
    ap.add_argument("--strict", action="store_true",
                    help=f"exit with status {EXIT_FLAGGED} when the run is flagged (energy residual too large, "
                         f"or a macro step above the tie's limit)")
    ap.add_argument("--monolithic", action="store_true",
                    help="both FMUs as Model Exchange under one CVODE (fmpy.sundials): no macro step "
                         f"(--macro-step is then the output interval, default {MACRO_STEP_DEFAULT_MAX:g} s)")
    ap.add_argument("--summary", default=None,
                    help="the summary JSON (default: --out with the suffix .json)")
    ap.add_argument("--t-end", type=float, default=30.0, help=f"[s], in [{T_END_RANGE[0]:g}, {T_END_RANGE[1]:g}]")
    ap.add_argument("--rtol", type=float, default=1e-6, help=f"the slaves' tolerance, in [{RTOL_RANGE[0]:g}, {RTOL_RANGE[1]:g}]")
    ap.add_argument("--master", choices=["fmpy", "libcosim", "both", "monolithic"], default="fmpy",
                    help="fmpy or libcosim (Co-Simulation), both; monolithic is what --monolithic runs")
    ap.add_argument("--out", default="results/couple.csv")
    ap.add_argument("--plot", default="results/couple.png")
    ap.add_argument("--json", help="run one master in this process and write its result arrays as JSON "
                                   "(how the command line runs each master in a child process)")
    a = ap.parse_args(argv)
    a.wall_fmu = a.wall_fmu or str(paths.wall_fmu())
    a.diaphragm_fmu = a.diaphragm_fmu or str(paths.diaphragm_fmu())
    return a


def run_here(a):
    """One master in this process (the child's side of run_master_subprocess)."""
    t_in, ag_in = ground_motion(a.record, a.scale)
    wall = wall_start_values(a.wall, a.Kd, a.hinge_law, overrides=parse_settings(a.set))
    dia = {"m": a.m, "k": a.k, "zeta": a.zeta}
    if a.master == "monolithic":
        from . import monolithic as couple_monolithic
        return couple_monolithic.run_monolithic(a.wall_fmu, a.diaphragm_fmu, t_in, ag_in, a.t_end, wall, dia,
                                                rtol=a.rtol, output_interval=a.macro_step)
    if a.master == "libcosim":
        return run_libcosim(a.wall_fmu, a.diaphragm_fmu, t_in, ag_in, a.t_end, a.macro_step, wall, dia)
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
    with tempfile.TemporaryDirectory(prefix="couple_result_") as tmp:
        out_json = pathlib.Path(tmp) / f"{master}.json"
        proc = run_master_subprocess(master, _passthrough(a), out_json)
        if proc.returncode != 0 or not out_json.exists():
            raise CouplingError(child_failure(master, proc, (a.wall_fmu, a.diaphragm_fmu)))
        data = json.loads(out_json.read_text())
    r = CoupledResult({k: np.asarray(v) for k, v in data.items() if k != "collapsed_at"})
    r["collapsed_at"] = data.get("collapsed_at")
    return r


def report(master, r, a):
    end = (f", wall collapsed at t = {r['collapsed_at']:.3f} s" if r.get("collapsed_at") is not None
           else f", to t = {r['time'][-1]:g} s")
    step = "no macro step (one CVODE)" if master == "monolithic" else f"H = {a.macro_step:g} s"
    print(f"{master} master, {step}: peak s1 {np.abs(r['wall_s1']).max():.5f} m, "
          f"s2 {np.abs(r['wall_s2']).max():.5f} m, diaphragm u {np.abs(r['dia_u']).max():.5f} m{end}")


def summary(r, a, master, step_limit, step_warning):
    """The run's summary: peaks, the step and its limit, the energy residual's share and the flags
    (energy_ok, step_ok, flagged)."""
    share, energy_ok = coupling_rules.energy_check(r.energy_residual(), r.ground_work(), a.energy_share)
    return {
        "master": master,
        "macro_step": None if master == "monolithic" else a.macro_step,
        "macro_step_limit": step_limit,
        "step_ok": step_warning is None,
        "peak_s1": float(np.abs(r["wall_s1"]).max()), "peak_s2": float(np.abs(r["wall_s2"]).max()),
        "peak_u": float(np.abs(r["dia_u"]).max()), "peak_F_top": float(np.abs(r["wall_F_top"]).max()),
        "collapsed_at": r.get("collapsed_at"),
        "energy_residual_max": float(np.abs(r.energy_residual()).max()),
        "ground_work_max": float(np.abs(r.ground_work()).max()),
        "energy_residual_share": share if math.isfinite(share) else None,
        "energy_share_max": a.energy_share,
        "energy_ok": energy_ok,
        "flagged": not (energy_ok and step_warning is None),
    }


def resolve_macro_step(a):
    """(limit, warning): sets a.macro_step (the tie's limit by default), warns on stderr when a
    requested step exceeds the limit."""
    wall_real, _ = wall_start_values(a.wall, a.Kd, a.hinge_law, overrides=parse_settings(a.set))
    limit = tie_step_limit(wall_real, {"m": a.m, "k": a.k, "zeta": a.zeta})
    if a.monolithic:  # no macro step: --macro-step is only the output interval there
        a.macro_step = a.macro_step or min(MACRO_STEP_DEFAULT_MAX, a.t_end)
        return limit, None
    a.macro_step, warning = choose_macro_step(a.macro_step, limit, a.t_end)
    return limit, warning  # printed after the run: a failure's own error comes first


def main(argv=None):
    a = parse_args(argv)
    step_warning = None
    try:
        if a.json:  # the child: one master here, its arrays to the parent
            check_options(a.t_end, a.macro_step, a.rtol)
            r = run_here(a)
            pathlib.Path(a.json).write_text(json.dumps({k: (np.asarray(v).tolist() if v is not None else None)
                                                        for k, v in r.items()}))
            return 0
        if not (math.isfinite(a.energy_share) and a.energy_share > 0):
            raise ValueError(f"--energy-share {a.energy_share!r} must be a positive number")
        if a.monolithic and a.master != "fmpy":
            raise ValueError("--monolithic runs one CVODE over both FMUs: it takes no --master")
        check_options(a.t_end, a.macro_step if a.macro_step is not None else min(a.t_end, 1e-3), a.rtol)
        limit, step_warning = resolve_macro_step(a)
        check_options(a.t_end, a.macro_step, a.rtol)
        masters = ["monolithic"] if a.monolithic else ["fmpy", "libcosim"] if a.master == "both" else [a.master]
        results = {m: run_child(m, a) for m in masters}
    except (ValueError, OSError, CouplingError) as exc:
        print(f"couple.py: error: {exc}", file=sys.stderr)
        if step_warning:
            print(f"couple.py: warning: {step_warning}", file=sys.stderr)
        return 2 if isinstance(exc, ValueError) and not isinstance(exc, CouplingError) else 1
    if step_warning:
        print(f"couple.py: warning: {step_warning}", file=sys.stderr)
    r = results[masters[0]]
    pathlib.Path(a.out).parent.mkdir(parents=True, exist_ok=True)
    save_csv(r, a.out)
    title = (f"Wall {a.wall} + diaphragm (m = {a.m:g} kg/m, k = {a.k:g} N/m2, zeta = {a.zeta:g}), "
             f"K_d = {a.Kd:g} N/m2, " + ("monolithic" if a.monolithic else f"H = {a.macro_step:g} s"))
    plot(r, a.plot, title, results.get("libcosim") if len(masters) == 2 else None)
    for m in masters:
        report(m, results[m], a)
    info = summary(r, a, masters[0], limit, step_warning)
    summary_path = pathlib.Path(a.summary or pathlib.Path(a.out).with_suffix(".json"))
    summary_path.write_text(json.dumps(info, indent=1) + "\n")
    print(f"energy: max |residual| {info['energy_residual_max']:.4g} J/m against "
          f"max |ground work| {info['ground_work_max']:.4g} J/m")
    if not info["energy_ok"]:
        share = info["energy_residual_share"]
        print(f"couple.py: warning: ENERGY CHECK FAILED: the energy residual is "
              f"{'unbounded' if share is None else f'{100 * share:.3g} %'} of the ground work, above "
              f"{100 * a.energy_share:g} %: the coupled result is not to be trusted (a smaller --macro-step, "
              f"or --monolithic)", file=sys.stderr)
    if len(masters) == 2:
        other = results["libcosim"]
        n = min(len(r["time"]), len(other["time"]))
        print(f"max |s1 fmpy - s1 libcosim| = {np.abs(r['wall_s1'][:n] - other['wall_s1'][:n]).max():.3g} m")
    print(f"wrote {a.out}, {a.plot} and {summary_path}" + ("  [FLAGGED: see the warnings]" if info["flagged"] else ""))
    return EXIT_FLAGGED if (a.strict and info["flagged"]) else 0


if __name__ == "__main__":
    sys.exit(main())
