"""RockingWall tied to the Diaphragm FMU, the scene of `rockingwall couple`: the wall's start
values, the tie's largest macro step, the result type (arrays on the communication grid with the
energy balance) and the run through the package's Jacobi master (rockingwall.coupling.jacobi).

The paper's top spring K_d is fixed to the ground at its far end; here its far end is a diaphragm
with mass, stiffness and damping (build/Diaphragm.fmu):

    ground motion ag(t)  --> wall.ag,  diaphragm.ag          [m/s2, + toward +x]
    diaphragm.u          --> wall.u_top                      [m, relative to the ground]
    wall.F_top           --> diaphragm.F_top                 [N/m, force of the spring on the diaphragm]

Inputs are held over each macro step (order 1); the wall's collapse (its fmi2Discard) ends the run.
"""
import math

import numpy as np

from .. import paths, records
from ..names import HINGE_LAWS as LAWS, SUPPORTS as MODELS, paper_wall
from . import energy_guard, jacobi, rules

WALL_OUT = ["s1", "s2", "F_top", "energy", "P_ground", "dissipated"]
DIA_OUT = ["u", "v", "energy", "P_ground", "P_damping"]


# Meaningful ranges of the master's own options (low, high); the macro step is also at most t_end.
T_END_RANGE = (1e-3, 1e5)     # s
MACRO_STEP_DEFAULT_MAX = 1e-3  # s: the default step is the tie's limit, at most this (accuracy)
MACRO_STEP_MIN = 1e-6         # s: 30 s at 1 us is 3e7 exchanges, already hours
RTOL_RANGE = (1e-12, 1e-2)


def check_options(t_end, H, rtol):
    """ValueError naming the option and its range."""
    if not (math.isfinite(t_end) and T_END_RANGE[0] <= t_end <= T_END_RANGE[1]):
        raise ValueError(f"--t-end {t_end!r} is outside [{T_END_RANGE[0]:g}, {T_END_RANGE[1]:g}] s")
    if not (math.isfinite(H) and MACRO_STEP_MIN <= H <= t_end):
        raise ValueError(f"--macro-step {H!r} is outside [{MACRO_STEP_MIN:g}, t_end = {t_end:g}] s")
    if not (math.isfinite(rtol) and RTOL_RANGE[0] <= rtol <= RTOL_RANGE[1]):
        raise ValueError(f"--rtol {rtol!r} is outside [{RTOL_RANGE[0]:g}, {RTOL_RANGE[1]:g}]")


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
    parameters (rules.max_macro_step)."""
    m_w = rules.wall_top_mass(real["W"], real.get("psi", 0.0), real["h"], real.get("g", 9.81))
    return rules.max_macro_step(m_w, dia["m"], real["Kd"], dia["k"])


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
        stored = self["wall_energy"] + self["dia_energy"]
        power_in = self["wall_P_ground"] + self["dia_P_ground"] - self["dia_P_damping"]
        return stored - stored[0] - rules.work(self["time"], power_in) + self["wall_dissipated"]

    def ground_work(self):
        return rules.work(self["time"], self["wall_P_ground"] + self["dia_P_ground"])

    def damping_loss(self):
        return rules.work(self["time"], self["dia_P_damping"])


def assemble(t, wall_rows, dia_rows):
    r = CoupledResult(time=np.asarray(t))
    w, d = np.asarray(wall_rows), np.asarray(dia_rows)
    for i, n in enumerate(WALL_OUT):
        r["wall_" + n] = w[:, i]
    for i, n in enumerate(DIA_OUT):
        r["dia_" + n] = d[:, i]
    return r


class WallAndDiaphragm:
    """The scene for the Jacobi master (rockingwall.coupling.jacobi): the wall steps first, then
    the diaphragm; the wall may fall (its collapse), which ends the run."""

    def __init__(self, wall_fmu, dia_fmu, wall, dia):
        self.wall_fmu, self.dia_fmu, self.wall, self.dia = str(wall_fmu), str(dia_fmu), wall, dia

    def slaves(self):
        return [("wall", self.wall_fmu, self.wall), ("diaphragm", self.dia_fmu, (self.dia, {}))]

    @staticmethod
    def outputs(name):
        return WALL_OUT if name == "wall" else DIA_OUT

    @staticmethod
    def inputs(outputs, ag, fallen):
        return {("wall", "ag"): ag, ("wall", "u_top"): outputs["diaphragm"]["u"],
                ("diaphragm", "ag"): ag, ("diaphragm", "F_top"): outputs["wall"]["F_top"]}

    @staticmethod
    def ground_inputs():
        return [("wall", "ag"), ("diaphragm", "ag")]

    @staticmethod
    def may_fall(name):
        return name == "wall"

    @staticmethod
    def jumps_when_a_slave_falls(key):
        return False  # the run ends when the wall falls


def _point_energy(point, fallen, meta):
    """(input power, damping power, stored energy, impact losses) at a point: CoupledResult's terms."""
    w, d = point.outputs["wall"], point.outputs["diaphragm"]
    return w["P_ground"] + d["P_ground"], d["P_damping"], w["energy"] + d["energy"], w["dissipated"]


def unstable_message(wall, dia, H):
    """explain() of the energy guard (energy_guard.EnergyGuard) for the wall and its diaphragm."""
    real = wall[0] if isinstance(wall, tuple) else wall
    limit = tie_step_limit(real, {"m": dia.get("m", 2000.0), "k": dia.get("k", 7e5)})

    def explain(t, residual, peak):
        cause = (f"the tie K_d = {real['Kd']:.3g} N/m per m between the wall's top and the diaphragm's "
                 f"{dia.get('m', 2000.0):g} kg/m allows a macro step of {limit:.3g} s, and H = {H:g} s"
                 if H > limit * (1 + 1e-9) else f"the macro step H = {H:g} s")
        return (f"the co-simulation went unstable at t = {t:.4g} s: the energy residual {residual:.3g} J/m passed "
                f"{rules.ENERGY_STOP_SHARE:g} of the ground work ({peak:.3g} J/m): its motion is the coupling's, and "
                f"no peak or collapse of it is a result. Likely cause: {cause}. Remedy: --monolithic (both FMUs under "
                f"one CVODE, no macro step), --macro-step {limit:.3g} or smaller, or the wall under a diaphragm with "
                f"mass in one integration (`rockingwall run --Kd ... --diaphragm-mass ...`; in an FMI tool "
                f"{paths.where('BuildingWithWalls.fmu')})")
    return explain


def run_fmpy(wall_fmu, dia_fmu, t_in, ag_in, t_end, H, wall=None, dia=None, rtol=1e-6, progress=False,
             energy_stop=rules.ENERGY_STOP_SHARE):
    """The fmpy master: the package's Jacobi master (rockingwall.coupling.jacobi) over the wall
    and the diaphragm as Co-Simulation slaves, inputs held over each step. Returns a
    CoupledResult, with collapsed_at the time the wall collapsed (None if it did not). The run
    stops with CouplingUnstable once its energy residual passes energy_stop of the ground work
    (None: never)."""
    check_options(t_end, H, rtol)
    scene = WallAndDiaphragm(wall_fmu, dia_fmu, wall or wall_start_values(), dia or {})
    guard = None if energy_stop is None else energy_guard.EnergyGuard(
        lambda slaves: None, _point_energy, unstable_message(scene.wall, scene.dia, H), energy_stop)
    history = jacobi.run(scene, t_in, ag_in, t_end, H, order=1, rtol=rtol,
                         progress="fmpy master" if progress else None, monitor=guard)
    r = assemble([p.t for p in history.points], [[p.outputs["wall"][x] for x in WALL_OUT] for p in history.points],
                 [[p.outputs["diaphragm"][x] for x in DIA_OUT] for p in history.points])
    r["collapsed_at"] = history.fallen.get("wall")
    return r


def macro_step(wall_real, dia, requested, t_end, monolithic=False):
    """(H, limit, warning or None): the tie's largest step for these wall start values and
    diaphragm parameters, and the step to run: the requested one (with a warning when it exceeds
    the limit), else the limit (choose_macro_step). With monolithic there is no macro step: H is
    the output interval, by default MACRO_STEP_DEFAULT_MAX (at most t_end), and no warning."""
    limit = tie_step_limit(wall_real, dia)
    if monolithic:
        return requested or min(MACRO_STEP_DEFAULT_MAX, t_end), limit, None
    H, warning = choose_macro_step(requested, limit, t_end)
    return H, limit, warning
