"""The stability matrix: case definitions, one run of a case through fmi2sim and
through fmpy, and the checks every case must pass. scripts/stability.py runs the whole matrix;
tests/python/test_stability.py runs a quick subset. Both import from here, so the cases and the
bounds have one source.

Why this matrix and not the cartesian product (which would be 6 x 4 x 3 x 3 x 6 model/law pairs
x amplitudes x samplings x durations x rtols, ~10^5 runs): the axes act on different things.
K_d sets the stiffness (conditioning), e_r the impacts, psi and h/b the geometry and hinge
capacities, the amplitude the regime (no rocking .. collapse), the sampling the number of input
kinks, the duration the accumulation of error, rtol the solver. So every model/hinge-law pair is
swept one factor at a time around a base case (wall 1 under the paper's Gaussian impulse), and the
corners where two extremes compound are added on their own: a stiff spring at the tightest and
the loosest rtol, a stiff spring under El Centro, 600 s at the finest sampling, collapse with
every model, e_r = 1 for 600 s.

Distinct model/hinge-law pairs: the parapet is a rigid block (hingeLaw does not enter it), and
the simply supported wall uses Doherty's trilinear law for both semi-rigid values
(docs/model.md), so the sweeps run the six pairs that differ; the base case also runs the three
equivalent ones to show they give the same peaks.

Input work (for "never gain energy beyond the work of the input"): the ground acceleration does
work on the wall at the rate P = ag * d(Phi(q))/dt, Phi from the model's equations (the load
vector of Eq. 3.4 for the 2DOF, -(W/2g) D for the simply supported wall, Housner's
-(W/g) R [sin(th) cos(a) + sign(th) sin(a) (1 - cos(th))] for the block). q comes from the
outputs s1, s2 of fmi2sim, ag is interpolated from the input samples like the tools do, and
W_in(t) = sum 1/2 (ag_i + ag_i+1) (Phi_i+1 - Phi_i) over the output rows. Impacts only remove
energy, so E(t) - E(0) - W_in(t) <= 0 up to the error of the run and of this quadrature; the
largest value of it, relative to E(0) + the total absolute input work, is the "energy gain"
reported and bounded. The semiRigidPaper law is not derived from a potential (its hinge
moments depend on the hinge sides), so its `energy` output is not conserved and the gain is
reported for it but not bounded.

Energy loss: where no loss is physical, free rocking with e_r = 1 and no
input, the energy E(t) + dissipated(t) (what hinge closings remove, zero for the semi-rigid hinge)
must stay at E(0). CVODE's error per step accumulates in the energy, mostly as a loss (BDF damps
oscillations a little at every step; released from q1 = 0.01 rad at rtol 1e-6 the wall gained
2.7 % per 100 s instead, which the energy-gain check bounds), so it grows with time and with rtol; measured for the 2DOF wall (q1 = 0.03 rad, e_r = 1, semi-rigid hinge, the
FMU's default K_d = 1e6 N/m per m, the worst of the walls tried) per 100 s: 2.6 % at rtol 1e-6, 0.59 % at 1e-7, 0.18 % at 3e-8, 0.099 % at 1e-8, 0.018 % at 1e-9,
0.0025 % at 1e-10 (at 1e-6 it reached 10 % by 400 s: a wall near its limit then stops short of a
collapse it should reach, or collapses late). fmi2sim's default rtol is therefore 1e-8, and the
bound is ENERGY_LOSS_PER_100S at rtol <= 1e-8.
"""
import dataclasses
import math
import re
import subprocess
import tempfile
import time
from pathlib import Path

import numpy as np

from rockingwall import fmu as rw_fmu
from rwref import Params, inputs

G = 9.81
H = 2.5                        # wall height of the paper's walls [m]
W_PER_B = 6622.0 / 0.15        # weight per metre and per metre of thickness [N/m2]: W scales with b
GAUSS_T = 1.0                  # Gaussian impulse duration [s]; sigma = T/8
SIGMA = GAUSS_T / 8
PAPER_PEAK_G = 0.04 / SIGMA**2 / G   # the paper's D = 0.04 m pulse: peak ag = D/sigma^2 = 0.26 g

# ---- bounds every case must meet (see check()) -------------------------------------------------
STEPS_PER_S = 4000       # CVODE steps per simulated second, on top of one stop per input sample
STEPS_PER_S_STIFF = 200000   # K_d >= 1e9 N/m per m: CVODE must follow the undamped spring mode
STIFF_KD = 1e9
STEPS_PER_EVENT = 40     # and a restart after each event
EVENTS_PER_S = 40        # events per simulated second (impacts, hinge switches, breakpoints)
EVENTS_FIXED = 200
# The rigid 2DOF approaches rest through a chatter of the mid hinge (measured: 6790 events in the
# last 0.25 s of the base case) that ends when restRate closes the hinge; it may do so at every rest.
EVENTS_PER_S_RIGID_2DOF, EVENTS_FIXED_RIGID_2DOF = 400, 10000
# Free rocking with e_r = 1 never settles: impacts and hinge switches at a steady rate (measured
# 49 per second with the stiff default spring K_d = 1e6 N/m per m).
EVENTS_PER_S_FREE = 100
ENERGY_GAIN_MAX = 2e-3   # energy gain beyond the input work, relative (module docstring) ...
ENERGY_GAIN_PER_EVENT = 10   # ... + 10 * rtol per event (each event restarts CVODE at a located root)
ENERGY_LOSS_PER_100S = 2e-3  # free rocking (e_r = 1, no input): relative loss per 100 s (module docstring)
FREE_Q1 = 0.03           # initial rotation of the lower body for free rocking [rad]
PEAK_RTOL_FACTOR = 500   # peaks of fmpy and fmi2sim agree within 500 * rtol (relative) ...
PEAK_ATOL_FACTOR = 500   # ... + 500 * rtol * (nominal 0.01 rad) * h/2 (the states' atol in metres)
SMALL_PEAK_MAX = 1e-6    # 1e-6 g: a semi-rigid wall moves less than a micrometre
SLOW_WALL_S = 2.0        # fmi2sim wall time above which a case is reported "slow"


@dataclasses.dataclass(frozen=True)
class Case:
    name: str
    support: str = "flexibleTop"
    law: str = "semiRigidHinge"
    Kd: float = 5e4          # N/m per m (50 kN/m)
    er: float = 0.86
    psi: float = 0.0
    hb: float = H / 0.15     # h/b (16.7, the paper's walls)
    record: str = "gauss"    # "gauss" (peak `amp_g` in g) or "elcentro" (x amp_g)
    amp_g: float = PAPER_PEAK_G
    dt: float = 0.002        # input sampling [s]
    duration: float = 8.0
    rtol: float = 1e-6
    expect: str = ""         # "still" (rigid: no motion), "small" (semi-rigid: < 1 um), "collapse"
    q1_0: float = 0.0        # initial rotation of the lower body (free rocking) [rad]

    @property
    def params(self):
        b = H / self.hb
        return dict(h=H, b=b, W=W_PER_B * b, psi=self.psi, Kd=self.Kd, er=self.er)

    @property
    def rigid(self):
        return self.law == "rigid" or self.support == "parapet"

    @property
    def stiff(self):
        return self.support == "flexibleTop" and self.Kd >= STIFF_KD

    @property
    def free(self):
        """Free rocking without dissipation: no input and e_r = 1, so no loss of energy is physical
        beyond what hinge closings remove (the `dissipated` output)."""
        return self.er >= 1.0 and self.amp_g == 0.0 and self.record == "gauss"

    @property
    def start_values(self):
        q0 = (self.q1_0, 0.0) if self.q1_0 else None
        return dict(support=self.support, hinge_law=self.law, q0=q0, **self.params)

    @property
    def chaotic(self):
        """No dissipation (e_r = 1): rocking never settles and two correct solvers part for good
        after some impacts, so their later peaks differ by more than any rtol implies."""
        return self.er >= 1.0

    # fmi2sim writes a 2 ms grid (fine enough for the input-work quadrature); fmpy, slow per
    # output step, a 10 ms grid on long runs, a subset of fmi2sim's on which the peaks are compared
    output_interval = 0.002

    @property
    def fmpy_interval(self):
        return 0.002 if self.duration <= 60 else 0.01


def signal(case):
    if case.record == "elcentro":
        rec = inputs.el_centro(case.amp_g)
        if case.duration > rec.t[-1]:   # zeros after the record
            rec = inputs.Signal(np.append(rec.t, case.duration), np.append(rec.a, 0.0))
        return rec
    D = case.amp_g * G * SIGMA**2
    return inputs.sampled(inputs.gaussian(D, GAUSS_T), case.duration, case.dt)


# ---- the matrix ---------------------------------------------------------------------------------
PAIRS = [("parapet", "rigid"), ("simplySupported", "rigid"), ("simplySupported", "semiRigidHinge"),
         ("flexibleTop", "rigid"), ("flexibleTop", "semiRigidPaper"), ("flexibleTop", "semiRigidHinge"),
         ("flexibleTop", "dohertyHinge")]
EQUIVALENT_PAIRS = [("parapet", "semiRigidPaper"), ("parapet", "semiRigidHinge"),
                    ("simplySupported", "semiRigidPaper")]
AXES = {
    "Kd": [0.0, 1e2, 1e5, 1e7, 1e9, 1e12],
    "er": [0.0, 0.3, 0.86, 1.0],
    "psi": [0.0, 1.0, 5.0],
    "hb": [5.0, 17.0, 40.0],
    "amp_g": [1e-6, 0.05, PAPER_PEAK_G, 1.0, 3.0],
    "dt": [0.0005, 0.002, 0.01, 0.05],
    "duration": [8.0, 60.0, 600.0],
    "rtol": [1e-3, 1e-4, 1e-6, 1e-8, 1e-10],
}


def label(model, law):
    short = {"parapet": "para", "simplySupported": "ss", "flexibleTop": "2dof"}[model]
    return short if model == "parapet" else f"{short}-{law}"


def expectation(model, law, amp_g):
    if amp_g <= 1e-6:
        return "still" if (law == "rigid" or model == "parapet") else "small"
    return "collapse" if amp_g >= 3.0 else ""


def matrix():
    """Every distinct model/law pair swept one factor at a time, plus the corners."""
    cases = []
    for model, law in PAIRS:
        base = Case(f"{label(model, law)} base", model, law)
        cases.append(base)
        for axis, values in AXES.items():
            if axis == "Kd" and model != "flexibleTop":
                continue  # no top spring in the 1DOF models
            for v in values:
                if math.isclose(v, getattr(base, axis), rel_tol=0.02):
                    continue
                c = dataclasses.replace(base, name=f"{label(model, law)} {axis}={v:g}", **{axis: v})
                if axis == "amp_g":
                    c = dataclasses.replace(c, expect=expectation(model, law, v))
                cases.append(c)
        cases.append(Case(f"{label(model, law)} El Centro x0.5", model, law, record="elcentro",
                          amp_g=0.5, duration=60.0))
    for model, law in EQUIVALENT_PAIRS:
        same = label(model, "rigid" if model == "parapet" else "semiRigidHinge")
        cases.append(Case(f"{model} {law} base (= {same} base)", model, law))
    for law in ("rigid", "semiRigidHinge"):
        t = label("flexibleTop", law)
        cases += [Case(f"{t} Kd=1e12 rtol=1e-10", "flexibleTop", law, Kd=1e12, rtol=1e-10),
                  Case(f"{t} Kd=1e12 rtol=1e-3", "flexibleTop", law, Kd=1e12, rtol=1e-3),
                  Case(f"{t} Kd=1e12 El Centro x0.5", "flexibleTop", law, Kd=1e12, record="elcentro",
                       amp_g=0.5, duration=60.0),
                  Case(f"{t} 600 s dt=0.0005", "flexibleTop", law, duration=600.0, dt=0.0005),
                  Case(f"{t} er=1 600 s", "flexibleTop", law, er=1.0, duration=600.0),
                  Case(f"{t} 1e-6 g rtol=1e-10", "flexibleTop", law, amp_g=1e-6, rtol=1e-10,
                       expect=expectation("flexibleTop", law, 1e-6))]
    for law in ("semiRigidPaper", "dohertyHinge"):  # with semiRigidHinge's above: every law a stiff tie is held for
        cases.append(Case(f"{label('flexibleTop', law)} Kd=1e12 El Centro x0.5", "flexibleTop", law, Kd=1e12,
                          record="elcentro", amp_g=0.5, duration=60.0))
    cases += free_rocking()
    return cases


def free_rocking():
    """e_r = 1, no input, released from q1 = FREE_Q1: the energy-loss check (module docstring), at
    fmi2sim's default rtol 1e-8 for 100 s and 400 s, for each pair that conserves energy."""
    cases = []
    for model, law in PAIRS:
        if law == "semiRigidPaper":
            continue  # not derived from a potential: its energy is not conserved
        for duration in (100.0, 400.0) if model == "flexibleTop" and law == "semiRigidHinge" else (100.0,):
            cases.append(Case(f"{label(model, law)} free er=1 {duration:g} s", model, law, er=1.0, amp_g=0.0,
                              duration=duration, rtol=1e-8, q1_0=FREE_Q1, dt=0.05))
    # the FMU's default spring (1e6 N/m per m) loses most: 0.099 % per 100 s at rtol 1e-8
    cases.append(Case("2dof-semiRigidHinge free er=1 Kd=1e6 100 s", er=1.0, amp_g=0.0, Kd=1e6, duration=100.0,
                      rtol=1e-8, q1_0=FREE_Q1, dt=0.05))
    return cases


# ---- running a case -----------------------------------------------------------------------------
@dataclasses.dataclass
class Outcome:
    case: Case
    steps: int = 0
    events: int = 0
    sim_wall: float = 0.0
    fmpy_wall: float = 0.0
    finite: bool = True
    energy_gain: float = 0.0      # relative, see the module docstring
    energy_loss: float = 0.0      # relative, beyond the model's own dissipation
    collapsed: bool = False
    fmpy_collapsed: bool = False
    end_time: float = 0.0
    peak_s1: float = 0.0
    peak_s2: float = 0.0
    peak_diff: float = 0.0        # largest |fmpy - fmi2sim| of the two peaks [m]
    peak_tol: float = 0.0         # what rtol implies for it [m]
    impacts: int = 0
    error: str = ""
    fmpy_error: str = ""          # fmpy could not run it (a limit of fmpy, not of the FMU)


def run_fmi2sim(exe, fmu, case, sig, workdir):
    inp, out = Path(workdir) / "in.csv", Path(workdir) / "out.csv"
    np.savetxt(inp, np.column_stack([sig.t, sig.a]), delimiter=",", header="time,ag", comments="",
               fmt="%.17g")
    sets = rw_fmu.start_values(**case.start_values)
    args = [str(exe), str(fmu), "--input", str(inp), "--rtol", repr(case.rtol), "--stop-time",
            repr(case.duration), "--output-interval", repr(case.output_interval), "--output", str(out),
            "--stats"]
    for name, v in sets.items():
        args += ["--set", f"{name}={v!r}" if isinstance(v, float) else f"{name}={v}"]
    t0 = time.perf_counter()
    proc = subprocess.run(args, capture_output=True, text=True, timeout=1800)
    wall = time.perf_counter() - t0
    if proc.returncode != 0:
        raise RuntimeError(f"fmi2sim failed: {proc.stderr.strip()}")
    m = re.search(r"steps (\d+),.*events (\d+)", proc.stderr)
    data = np.loadtxt(out, delimiter=",", skiprows=1, ndmin=2)
    names = out.open().readline().strip().split(",")
    return {n: data[:, i] for i, n in enumerate(names)}, int(m.group(1)), int(m.group(2)), wall


def phi(case, t, s1, s2):
    """Phi(q) with P_ground = ag dPhi/dt (module docstring), from the outputs s1, s2."""
    p = Params(support=case.support, hinge_law=case.law, **case.params)
    q1 = 2 * s1 / p.h
    if case.support == "parapet":
        return -(p.W / p.g) * p.R * (np.sin(q1) * math.cos(p.alpha)
                                     + np.sign(q1) * math.sin(p.alpha) * (1 - np.cos(q1)))
    if case.support == "simplySupported":
        return -(p.W / (2 * p.g)) * s1
    q2 = 2 * s2 / p.h - q1
    pa = p.p_per_ag
    return pa[0] * q1 + pa[1] * q2


def energy_gain(case, sig, d):
    """max_t (E(t) - E(0) - W_in(t)) / (E(0) + total |input work|)."""
    t, E = d["time"], d["energy"]
    ag = np.interp(t, sig.t, sig.a)
    dw = 0.5 * (ag[1:] + ag[:-1]) * np.diff(phi(case, t, d["s1"], d["s2"]))
    w_in = np.concatenate([[0.0], np.cumsum(dw)])
    scale = abs(E[0]) + np.sum(np.abs(dw))
    gain = np.max(E - E[0] - w_in)
    return float(gain / scale) if scale > 0 else float(gain)


def energy_loss(case, sig, d):
    """max_t (E(0) + W_in(t) - dissipated(t) - E(t)) / (E(0) + total |input work|): energy lost
    beyond what the model says it dissipated (impacts, hinge closings)."""
    t, E = d["time"], d["energy"]
    ag = np.interp(t, sig.t, sig.a)
    dw = 0.5 * (ag[1:] + ag[:-1]) * np.diff(phi(case, t, d["s1"], d["s2"]))
    w_in = np.concatenate([[0.0], np.cumsum(dw)])
    scale = abs(E[0]) + np.sum(np.abs(dw))
    loss = np.max(E[0] + w_in - d["dissipated"] - E)
    return float(loss / scale) if scale > 0 else float(loss)


def energy_loss_bound(case):
    return ENERGY_LOSS_PER_100S * max(1.0, case.duration / 100.0)


def peak_tol(case, peak):
    return PEAK_RTOL_FACTOR * case.rtol * peak + PEAK_ATOL_FACTOR * case.rtol * 0.01 * H / 2


def run_case(case, exe, fmu, with_fmpy=True):
    """Run `case` through fmi2sim (and fmpy); measure, do not judge (check() judges)."""
    o = Outcome(case)
    sig = signal(case)
    try:
        with tempfile.TemporaryDirectory() as wd:
            d, o.steps, o.events, o.sim_wall = run_fmi2sim(exe, fmu, case, sig, wd)
    except RuntimeError as exc:
        o.error = str(exc)
        return o
    o.finite = bool(all(np.all(np.isfinite(d[k])) for k in ("s1", "s2", "energy", "F_top")))
    o.collapsed = bool(d["collapsed"][-1])
    o.end_time = float(d["time"][-1])
    o.impacts = int(d["impacts"][-1])
    o.energy_gain = energy_gain(case, sig, d) if o.finite else math.inf
    o.energy_loss = energy_loss(case, sig, d) if o.finite else math.inf
    grid = np.arange(0.0, o.end_time + 1e-9, case.output_interval)
    o.peak_s1 = float(np.max(np.abs(rw_fmu.on_grid(d["time"], d["s1"], grid))))
    o.peak_s2 = float(np.max(np.abs(rw_fmu.on_grid(d["time"], d["s2"], grid))))
    if not with_fmpy:
        return o
    t0 = time.perf_counter()
    try:
        fm = rw_fmu.simulate(fmu, case.duration, sig.t, sig.a, rtol=case.rtol,
                             output_interval=case.fmpy_interval, **case.start_values)
    except Exception as exc:  # fmpy raises plain Exceptions for solver failures
        o.fmpy_error = f"fmpy failed: {str(exc).split(':')[-1].strip()}"
        return o
    o.fmpy_wall = time.perf_counter() - t0
    o.fmpy_collapsed = fm.collapsed
    grid = np.arange(0.0, min(fm.t[-1], o.end_time) + 1e-9, case.fmpy_interval)
    p1 = float(np.max(np.abs(rw_fmu.on_grid(fm.t, fm.s1, grid))))
    p2 = float(np.max(np.abs(rw_fmu.on_grid(fm.t, fm.s2, grid))))
    s1 = float(np.max(np.abs(rw_fmu.on_grid(d["time"], d["s1"], grid))))
    s2 = float(np.max(np.abs(rw_fmu.on_grid(d["time"], d["s2"], grid))))
    o.peak_diff = max(abs(p1 - s1), abs(p2 - s2))
    o.peak_tol = peak_tol(case, max(s1, s2))
    return o


# ---- the checks ---------------------------------------------------------------------------------
def bounds(case):
    n_samples = int(round(case.duration / case.dt)) if case.record == "gauss" else int(case.duration / 0.02)
    if case.support == "flexibleTop" and case.law == "rigid":
        events = EVENTS_PER_S_RIGID_2DOF * case.duration + EVENTS_FIXED_RIGID_2DOF
    elif case.free:
        events = EVENTS_PER_S_FREE * case.duration + EVENTS_FIXED
    else:
        events = EVENTS_PER_S * case.duration + EVENTS_FIXED
    per_s = STEPS_PER_S_STIFF if case.stiff else STEPS_PER_S
    return events, per_s * case.duration + 2 * n_samples + STEPS_PER_EVENT * events


def energy_bound(o):
    return ENERGY_GAIN_MAX + ENERGY_GAIN_PER_EVENT * o.case.rtol * o.events


def check(o, with_fmpy=True):
    """The list of broken promises of one outcome ([] = the case passes)."""
    c, bad = o.case, []
    if o.error:
        return [o.error]
    max_events, max_steps = bounds(c)
    if o.events > max_events:
        bad.append(f"{o.events} events > bound {max_events:.0f}")
    if o.steps > max_steps:
        bad.append(f"{o.steps} steps > bound {max_steps:.0f}")
    if not o.finite:
        bad.append("NaN or infinity in the outputs")
    if c.law != "semiRigidPaper" and o.energy_gain > energy_bound(o):
        bad.append(f"energy gain {o.energy_gain:.2e} > {energy_bound(o):.1e}")
    if c.free and c.law != "semiRigidPaper" and o.energy_loss > energy_loss_bound(c):
        bad.append(f"energy loss {o.energy_loss:.2e} > {energy_loss_bound(c):.1e} (free rocking, e_r = 1)")
    if o.end_time < c.duration - 1e-6 and not o.collapsed:
        bad.append(f"stopped at t = {o.end_time:g} without reporting collapse")
    if c.expect == "collapse" and not o.collapsed:
        bad.append("expected collapse, none reported")
    if c.expect == "still" and (o.peak_s1 != 0.0 or o.peak_s2 != 0.0 or o.impacts != 0):
        bad.append(f"rigid wall moved under 1e-6 g (peak {o.peak_s1:.2e} m, {o.impacts} impacts)")
    if c.expect == "small" and not (0.0 < o.peak_s1 < SMALL_PEAK_MAX):
        bad.append(f"semi-rigid wall under 1e-6 g: peak s1 {o.peak_s1:.2e} m not in (0, {SMALL_PEAK_MAX:g})")
    if with_fmpy and not o.fmpy_error:
        if o.fmpy_collapsed != o.collapsed:
            bad.append(f"collapse: fmi2sim {o.collapsed}, fmpy {o.fmpy_collapsed}")
        if o.peak_diff > o.peak_tol and not c.chaotic:
            bad.append(f"fmpy vs fmi2sim peaks differ by {o.peak_diff:.2e} m > {o.peak_tol:.2e} m")
    return bad
