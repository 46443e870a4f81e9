"""simulate(wall, record): one wall under one record, by the exact engine (default), fmi2sim
(CVODE) or fmpy, with the peaks, the collapse and the time history in SI units; with a diaphragm
that has mass (`diaphragm=`), the wall under it by the scene solver. Every result names its scene
(rockingwall.scenes) and what that scene leaves out."""
import dataclasses
import os
import types

import numpy as np
import pandas as pd

from . import bounds, fmi2sim, limits, names, paths, robustness, scenes, scratch
from . import ensemble as ens
from . import engine as engine_module  # `engine` is simulate()'s argument
from .building import floor_acc, monolithic, reports
from .building.description import TIE_DEFAULT
from .records import G_STD
from .wall import Wall

ENGINES = ("exact", "fmi2sim", "fmpy")
PARAPET_ON_CVODE = (f"fmi2sim (a parapet with b/h > {engine_module.PARAPET_MAX_B_OVER_H}: beyond the exact "
                    "engine's small-rotation form)")
TAIL_S = 0.0  # the run ends with the record; a free-vibration tail is asked for with `tail`


@dataclasses.dataclass(frozen=True)
class TieForce:
    """Under a diaphragm with mass, peak_F_top is the tie's force low-pass filtered at
    floor_acc.CUTOFF_HZ (building/tie_force.py): its raw peak [N/m], which grows with the tie's
    stiffness, on samples every sample_dt_s [s]; resolved False where even the finest sampling left
    the filtered peak depending on it."""
    raw_peak_N_per_m: float
    sample_dt_s: float
    resolved: bool

    def to_dict(self):
        return dict(dataclasses.asdict(self), cutoff_hz=floor_acc.CUTOFF_HZ)


@dataclasses.dataclass
class Result:
    """Peaks [m] of the mid-height (s1) and top (s2) displacements, collapse, impacts, and the
    time history (DataFrame: time [s], ag [m/s^2], s1 [m], s2 [m], and under a diaphragm with mass
    its displacement relative to its supports `diaphragm` [m] and F_top_25Hz [N/m], the tie's force
    filtered as peak_F_top is) on the output grid; NaN for the wall after its collapse."""
    wall: Wall
    record: str
    engine: str
    peak_s1: float
    peak_s2: float
    peak_F_top: float   # N/m: the largest force of the tie on the diaphragm (under a diaphragm with mass: TieForce)
    collapsed: bool
    t_collapse: float
    impacts: int
    history: pd.DataFrame
    scene: scenes.Scene = None
    pga_g: float = float("nan")   # the record's PGA as run [g]
    ensemble: object = None       # an ensemble.Summary where simulate(..., ensemble=...) ran one
    peak_sensitivity: float = None  # the sensitivity check's (monolithic.peak_sensitivity); None: not made (fmi2sim, fmpy)
    tie_force: object = None        # under a diaphragm with mass: how peak_F_top was found (TieForce)

    @property
    def sensitive(self):
        """The sensitivity check found the peaks move by more than monolithic.SENSITIVITY_SHARE."""
        return self.peak_sensitivity is not None and self.peak_sensitivity > monolithic.SENSITIVITY_SHARE

    @property
    def s1_over_delta_u(self):
        """Peak s1 over Delta_u, the 1DOF's instability displacement (1 = at the limit)."""
        return self.peak_s1 / self.wall.delta_u

    def peaks(self):
        """The numbers users print: a dict with units in the keys; a collapsed wall's peaks, s1/Delta_u
        and tie force None, as the table's '-' (the run stops at its instability point: they are no
        displacements; its collapse is t_collapse_s); near_collapse (limits.NEAR_COLLAPSE_NOTE)."""
        fallen = self.collapsed
        return {"peak_s1_m": None if fallen else self.peak_s1, "peak_s2_m": None if fallen else self.peak_s2,
                "peak_F_top_N_per_m": None if fallen else self.peak_F_top,
                "s1_over_Delta_u": None if fallen else self.s1_over_delta_u,
                "collapsed": self.collapsed, "t_collapse_s": self.t_collapse, "impacts": self.impacts,
                "near_collapse": limits.near_collapse(self.s1_over_delta_u, fallen)}

    def summary(self, fmt="md"):
        """The report table of this run (fmt 'md' or 'text'): PGA, peaks, s1/0.6 Delta_u, limit
        states reached, the ensemble's collapse probability and spread if one ran, the scene."""
        from . import report_table
        return report_table.result_summary(self, fmt)


def simulate(wall, record, engine="exact", stop_time=None, tail=TAIL_S, output_interval=0.01, rtol=1e-8,
             diaphragm=None, tie=TIE_DEFAULT, ensemble=None):
    """Simulate `wall` (a Wall) under `record` (a Record, accelerations in m/s^2).
    stop_time [s]: default the record's end plus `tail`. engine: 'exact' (event-driven, in this
    process), 'fmi2sim' (CVODE BDF at rtol) or 'fmpy' (the FMU's Model Exchange under fmpy's CVode).
    diaphragm: a building.description.Diaphragm (its stiffness, mass, damping): the wall tied to it
    by `tie` [N/m per m] on the scene solver (engine 'exact' only: the FMU and fmi2sim hold the
    paper's scene; ValueError otherwise). The wall's own K_d is then not
    used: the diaphragm's stiffness and the tie take its place, and the result's scene names both.
    None: the paper's scene, the wall's top spring K_d ending at a fixed point.
    ensemble: an ensemble.Ensemble (or its size): the run's robustness, the same case for walls
    perturbed within the inputs' uncertainty (on the exact engine or the scene solver, whatever
    `engine`), summarised in the result's `ensemble` (rockingwall.ensemble)."""
    result = _simulate(wall, record, engine, stop_time, tail, output_interval, rtol, diaphragm, tie)
    result.pga_g = record.pga / G_STD
    if ensemble is not None:
        t_end = run_end(record, stop_time, tail)
        result.ensemble = robustness.of_result(result, record, t_end, ensemble, diaphragm, tie)
    return result


def _simulate(wall, record, engine, stop_time, tail, output_interval, rtol, diaphragm, tie):
    if engine not in ENGINES:
        raise ValueError(f"engine {engine!r}: choose one of {', '.join(ENGINES)}")
    t_end = run_end(record, stop_time, tail)
    grid = output_grid(float(record.t[0]), t_end, output_interval)
    if diaphragm is not None:
        if engine != "exact":
            raise ValueError(f"engine {engine!r} runs the paper's scene (the top spring to a fixed point); a wall "
                             "under a diaphragm with mass runs on the scene solver: leave the engine at 'exact'")
        return _under_diaphragm(wall, record, t_end, grid, rtol, diaphragm, tie)
    if engine == "exact" and not engine_module.covers(wall.params):
        engine = PARAPET_ON_CVODE  # beyond the engine's small-rotation form: said in the result
    run = {"exact": _exact, "fmi2sim": _fmi2sim, "fmpy": _fmpy, PARAPET_ON_CVODE: _fmi2sim}[engine]
    peak_s1, peak_s2, collapsed, t_collapse, impacts, s1, s2 = run(wall, record, t_end, grid, rtol, output_interval)
    history = pd.DataFrame({"time": grid, "ag": np.interp(grid, record.t, record.ag), "s1": s1, "s2": s2})
    sensitivity = _sensitivity(wall, record, t_end, peak_s1, peak_s2, collapsed) if engine == "exact" else None
    return Result(wall, record.name, engine, peak_s1, peak_s2, engine_module.peak_F_top(wall.params, peak_s2),
                  collapsed, t_collapse, impacts, history, scenes.paper(wall.params), peak_sensitivity=sensitivity)


def _sensitivity(wall, record, t_end, peak_s1, peak_s2, collapsed):
    """The sensitivity check of the building's runs on the exact engine (two more runs of about a
    millisecond): the largest relative change of peak s1 or s2 under the record scaled by 1 -/+
    monolithic.SENSITIVITY_PERTURBATION, 1.0 where the collapse changes."""
    def peaks(s1, s2, fell):
        return types.SimpleNamespace(peak_s1=np.array([s1]), peak_s2=np.array([s2]), collapsed=np.array([fell]))
    scaled = [engine_module.run(record.t, record.ag * scale, t_end=t_end, **wall.params)
              for scale in monolithic.SENSITIVITY_SCALES]
    return monolithic.peak_sensitivity(peaks(peak_s1, peak_s2, collapsed),
                                       [peaks(r.peak_s1, r.peak_s2, r.collapsed) for r in scaled])


# what a run of a wall under a diaphragm with mass checks beside its peaks: the sensitivity to the
# record's scale and the tie force (each its own runs: monolithic.respond_runs)
DIAPHRAGM_CHECKS = dict(filter_floor=False, check_sensitivity=True, tie_forces=True)


def under_diaphragm_runs(ensemble=None, states=()):
    """(fewest, most) scene runs of one simulate() of a wall under a diaphragm with mass: its own
    (DIAPHRAGM_CHECKS) and, with an ensemble, its members' (their tie forces too where one of the
    limit states `states` is on F_top)."""
    return ens.with_members(monolithic.respond_runs(**DIAPHRAGM_CHECKS), ensemble, limits.ask_tie_force(states))


def _under_diaphragm(wall, record, t_end, grid, rtol, diaphragm, tie):
    spec = monolithic.wall_under_diaphragm_spec(wall.params, diaphragm, tie)
    result, h = monolithic.respond(spec, [wall.params], record, t_end=t_end, rtol=rtol, t_out=grid,
                                   **DIAPHRAGM_CHECKS)
    (s,) = result.storeys
    history = pd.DataFrame({"time": grid, "ag": np.interp(grid, record.t, record.ag), "s1": h.scene.s1[:, 0],
                            "s2": h.scene.s2[:, 0], "diaphragm": h.scene.diaphragm[:, 0],
                            "F_top_25Hz": h.tie_force[:, 0]})
    if s.collapsed:  # as the exact engine's history: no wall after its collapse (the diaphragm moves on)
        reports.blank_after_collapse(history, s.t_collapse_s, ["s1", "s2", "F_top_25Hz"])
    force, found = float("nan"), None
    if not s.collapsed:  # a toppled wall's connection force is no demand: it fell
        force = s.tie_force_N_per_m
        found = TieForce(raw_peak_N_per_m=s.tie_force_raw_N_per_m, sample_dt_s=result.tie_sample_dt_s,
                         resolved=result.tie_resolved)
    return Result(wall, record.name, f"scene ({result.solver})", s.peak_s1_m, s.peak_s2_m, force, s.collapsed,
                  s.t_collapse_s if s.collapsed else float("nan"), s.impacts, history, scenes.diaphragm(diaphragm, tie),
                  peak_sensitivity=result.peak_sensitivity, tie_force=found)


def run_end(record, stop_time, tail):
    """The run's end [s]: stop_time, else the record's end plus `tail` (>= 0). The run starts at
    t = 0, so a record must too (or later: the FMU holds its first value until then)."""
    where = record.label
    if record.t[0] < 0:
        raise ValueError(f"{where}: the record starts at t = {record.t[0]:g} s, before the run starts (t = 0): "
                         "shift its times")
    if stop_time is None:
        if not (np.isfinite(tail) and tail >= 0):
            raise ValueError(f"--tail {tail!r} s: the free vibration after the record must be a finite number >= 0")
        t_end = float(record.t[-1] + tail)
    else:
        t_end = float(stop_time)
    bounds.run_length(0.0, t_end, f"{where}: stop time")
    return t_end


def output_grid(t0, t_end, interval):
    """Output times every `interval` from t0, the last one exactly t_end (never past it: the
    engine refuses an output time after the end, and float steps can overshoot)."""
    if not (np.isfinite(interval) and interval > 0):
        raise ValueError(f"output interval {interval!r} s: must be a finite number > 0")
    n = int(np.floor((t_end - t0) / interval * (1 + 1e-12)))  # whole intervals inside [t0, t_end]
    if n + 2 > bounds.MAX_OUTPUT_ROWS:
        raise ValueError(f"output grid of {n + 1} rows (every {interval:g} s over {t_end - t0:g} s): more than "
                         f"{bounds.MAX_OUTPUT_ROWS} rows; give a larger output interval")
    grid = t0 + np.arange(n + 1) * interval
    grid = grid[grid < t_end - 1e-9 * interval]  # the end is appended exactly, once
    return np.append(grid, t_end)


def _exact(wall, record, t_end, grid, rtol, output_interval):
    try:
        r = engine_module.run(record.t, record.ag, t_end=t_end, t_out=grid, **wall.params)
    except engine_module.EngineError as exc:
        if exc.code != engine_module.UNSUPPORTED:
            raise
        raise engine_module.EngineError(exc.code, f"{exc.detail}: run it with --engine fmi2sim "
                                                  "(engine='fmi2sim' in Python)") from None
    return r.peak_s1, r.peak_s2, r.collapsed, r.t_collapse, r.impacts, r.s1, r.s2


def _sets(wall):
    return [(k, int(v) if k in ("support", "hingeLaw") else float(v)) for k, v in wall.params.items()]


def _fmi2sim(wall, record, t_end, grid, rtol, output_interval):
    with scratch.folder("rw_simulate_") as tmp:
        table = os.path.join(tmp, "input.csv")
        pd.DataFrame({"time": record.t, "ag": record.ag}).to_csv(table, index=False, float_format="%.17g")
        out = os.path.join(tmp, "out.csv")
        summary = fmi2sim.run(paths.wall_fmu(), input_csv=table, stop_time=t_end, rtol=rtol,
                              output_interval=output_interval, sets=_sets(wall), output=out)
        data = pd.read_csv(out)
    o = summary["outputs"]
    collapsed = bool(o["collapsed"]["final"])
    t_unique, idx = np.unique(data["time"].to_numpy(), return_index=True)
    s1 = np.interp(grid, t_unique, data["s1"].to_numpy()[idx], right=np.nan)
    s2 = np.interp(grid, t_unique, data["s2"].to_numpy()[idx], right=np.nan)
    t_collapse = float(summary["end_time"]) if collapsed else float("nan")
    return (o["s1"]["max_abs"], o["s2"]["max_abs"], collapsed, t_collapse, int(o["impacts"]["final"]), s1, s2)


def _fmpy(wall, record, t_end, grid, rtol, output_interval):
    from . import fmu
    p = dict(wall.params)
    support, law = names.SUPPORT_NAMES[int(p.pop("support"))], names.HINGE_LAW_NAMES[int(p.pop("hingeLaw"))]
    run = fmu.simulate(paths.wall_fmu(), t_end, record.t, record.ag, rtol=rtol,
                                 output_interval=output_interval, support=support, hinge_law=law, **p)
    s1, s2 = fmu.on_grid(run.t, run.s1, grid, right=np.nan), fmu.on_grid(run.t, run.s2, grid, right=np.nan)
    t_collapse = float(run.t[-1]) if run.collapsed else float("nan")
    return run.peak_s1, run.peak_s2, run.collapsed, t_collapse, run.impacts, s1, s2
