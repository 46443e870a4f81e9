"""Out-of-plane walls in a building: Building.fmu plus one RockingWall.fmu per storey, coupled
through FMI 2.0 Co-Simulation by the package's Jacobi master (rockingwall.coupling.jacobi, fmpy
FMU2Slave in this process). The scene, its run and its result.

The wall of storey i stands on floor i-1 (the ground for i = 1) and is tied to floor i:

    wall_i.ag     <- building.a_diaph_{i-1}  (ag of the record for i = 1)   [m/s2, absolute, +x]
    wall_i.u_top  <- building.u_top_i  = y_i - y_{i-1}                      [m, rel. to its base]
    building.F_wall_i  <- wall_i.F_top                                      [N/m, on diaphragm i, +x]
    building.F_above_i <- wall_{i+1}.F_base                                 [N/m, on diaphragm i, +x]
    building.ag   <- ag of the record

Signs (docs/model.md, docs/building.md): F_top = Kd (s2 - u_top) is the force of the wall's spring
on the diaphragm it is tied to, F_base the force the wall puts on its base, both +x; F_wall_i is
the force of the wall below on diaphragm i and F_above_i that of the wall above, +x; the Building
adds them. The F_base of the wall of storey 1 goes into the ground. Each input takes one output,
so the scene is also an SSP 1.0 system (rockingwall.building.ssp).

Second-order coupling (`order=2`): every coupled input gets, besides its value at the
communication point t_k, a first derivative through fmi2SetRealInputDerivatives, so the slave
ramps it linearly over the step (both FMUs declare canInterpolateInputs; the shared FMI layer
passes the slope to the wall's exact engine and to the Building's CVODE stepper). The derivative
is extrapolated by the master from the last two exchanges, (v_k - v_{k-1})/H (the FMUs give no
output derivatives: maxOutputDerivativeOrder = 0); the record's ag gets its exact secant slope
over the step. `order=1` holds every input over the step (the scheme of `rockingwall couple`).
A wall that collapses (its fmi2Discard) falls out of the scene; the building's force inputs then
jump, and their slopes start again from 0.
"""
import dataclasses
import math

import numpy as np

from .. import bounds, paths
from ..coupling import energy_guard, jacobi, rules
from ..coupling.slaves import fmi_call
from ..names import HINGE_LAWS, SUPPORTS, paper_wall

WALL_OUT = ["s1", "s2", "F_top", "F_base", "energy", "P_ground", "dissipated"]
FLOOR_OUT = ["u_diaph", "a_diaph", "u_top", "u_floor", "v_floor", "v_diaph", "work_storey", "work_diaph"]
MAX_STOREYS = 5
MAX_STEPS = 1e7  # macro steps of one run: each keeps a row of every output


@dataclasses.dataclass
class WallSpec:
    """One RockingWall in storey `storey` (1..nStoreys) with its start values."""
    storey: int
    real: dict
    integer: dict = dataclasses.field(default_factory=lambda: {"support": SUPPORTS["flexibleTop"],
                                                                 "hingeLaw": HINGE_LAWS["dohertyHinge"]})

    @property
    def name(self):
        return f"wall_{self.storey}"


@dataclasses.dataclass
class Scene:
    """The building's start values and the walls: what the master runs and the SSP writer writes."""
    building_real: dict
    building_integer: dict
    walls: list
    building_fmu: str = None
    wall_fmu: str = None

    def __post_init__(self):
        self.building_fmu = str(self.building_fmu or paths.building_fmu())
        self.wall_fmu = str(self.wall_fmu or paths.wall_fmu())
        n = self.n_storeys
        if not 1 <= n <= MAX_STOREYS:
            raise ValueError(f"nStoreys {n} is outside 1..{MAX_STOREYS}")
        seen = set()
        for w in self.walls:
            if not 1 <= w.storey <= n:
                raise ValueError(f"a wall in storey {w.storey}: the building has storeys 1..{n}")
            if w.storey in seen:
                raise ValueError(f"two walls in storey {w.storey}: one wall per storey")
            seen.add(w.storey)

    @property
    def n_storeys(self):
        return int(self.building_integer.get("nStoreys", 2))

    def wall_in(self, storey):
        return next((w for w in self.walls if w.storey == storey), None)

    def connections(self):
        """(from instance, from variable, to instance, to variable) of every coupled signal, one
        output to each input."""
        out = []
        for w in sorted(self.walls, key=lambda w: w.storey):
            i = w.storey
            if i > 1:
                out.append(("building", f"a_diaph_{i - 1}", w.name, "ag"))
                out.append((w.name, "F_base", "building", f"F_above_{i - 1}"))
            out.append(("building", f"u_top_{i}", w.name, "u_top"))
            out.append((w.name, "F_top", "building", f"F_wall_{i}"))
        return out

    def ground_inputs(self):
        """(instance, variable) that take the record's ag."""
        return [("building", "ag")] + [(w.name, "ag") for w in self.walls if w.storey == 1]

    # ---- the scene as the Jacobi master runs it (rockingwall.coupling.jacobi) ----
    def slaves(self):
        """The building first, then the walls in their order."""
        return ([("building", self.building_fmu, (self.building_real, self.building_integer))]
                + [(w.name, self.wall_fmu, (w.real, w.integer)) for w in self.walls])

    def outputs(self, name):
        if name == "building":
            return [f"{q}_{i}" for i in range(1, self.n_storeys + 1) for q in FLOOR_OUT]
        return WALL_OUT

    def inputs(self, outputs, ag, fallen):
        """{(instance, variable): value} of every input at a communication point, from the
        outputs. A collapsed wall (in `fallen`) has fallen out: it takes no inputs and puts no
        force."""
        n = self.n_storeys
        b_out = outputs["building"]
        standing = {w.storey: w for w in self.walls if w.name not in fallen}
        values = {("building", "ag"): ag}
        for i in range(1, n + 1):
            below, above = standing.get(i), standing.get(i + 1)
            values[("building", f"F_wall_{i}")] = outputs[below.name]["F_top"] if below else 0.0
            values[("building", f"F_above_{i}")] = outputs[above.name]["F_base"] if above else 0.0
        for i, w in standing.items():
            values[(w.name, "ag")] = ag if i == 1 else b_out[f"a_diaph_{i - 1}"]
            values[(w.name, "u_top")] = b_out[f"u_top_{i}"]
        return values

    @staticmethod
    def may_fall(name):
        return name != "building"

    @staticmethod
    def jumps_when_a_slave_falls(key):
        """A wall fell out: the building's force inputs jump."""
        return key[1].startswith(("F_wall_", "F_above_"))


def default_scene(n_storeys=2, walls=None, wall=1, Kd=None, diaphragm_law=2, hinge_law="dohertyHinge",
                  building=None):
    """A building with the Building FMU's defaults and the paper's wall `wall` in each storey of
    `walls` (default all). Kd defaults to 1e6 N/m per m: the connection between the wall top and
    the diaphragm, stiff next to the diaphragm's own spring."""
    real = dict(building or {})
    integer = {"nStoreys": n_storeys, "diaphragmLaw": diaphragm_law}
    for k in ("storeyLaw",):
        if k in real:
            integer[k] = int(real.pop(k))
    storeys = range(1, n_storeys + 1) if walls is None else walls
    specs = [WallSpec(i, dict(paper_wall(wall), Kd=1e6 if Kd is None else Kd),
                      {"support": SUPPORTS["flexibleTop"], "hingeLaw": HINGE_LAWS[hinge_law]}) for i in storeys]
    return Scene(real, integer, specs)


class SceneResult(dict):
    """Arrays on the communication grid: time, ag, wall_<i>_<out>, <out>_<i> of the building's
    floors, F_wall_<i>, and the energy balance of the whole scene."""

    def peak(self, storey, what="s1"):
        return float(np.max(np.abs(self[f"wall_{storey}_{what}"])))

    def energy_terms(self):
        """The scene's energy balance (J/m), each term a time series:
        input = ground work on every FMU in its own frame (the walls' P_ground, the building's
        -ag sum m v) + the work the floors do moving the bases of the walls above storey 1,
        sum (F_top + F_base) v_base; stored = walls' energy (kinetic, gravity, hinges, spring) +
        building's kinetic energy + the work of its springs (elastic energy plus what their
        hysteresis dissipated); damping = building's Rayleigh damping and dashpots; impacts = the
        walls' `dissipated`. Balance: input = stored - stored(0) + damping + impacts. It holds up
        to the first collapse (a fallen wall's outputs stay at its collapse)."""
        walls = self.meta["walls"]
        P_in, P_damping, stored, impacts = energy_parts(self.__getitem__, self.meta, walls, walls)
        damping = rules.work(self["time"], P_damping)
        inp = rules.work(self["time"], P_in)
        return dict(input=inp, stored=stored - stored[0], damping=damping, impacts=impacts - impacts[0],
                    residual=inp - (stored - stored[0]) - damping - (impacts - impacts[0]))


def energy_parts(get, meta, powered, walls):
    """(input power, damping power, stored energy, impact losses) of the scene from its outputs
    (get(name) by SceneResult's names, arrays or numbers): the walls of `powered` take power
    (standing), those of `walls` hold energy (a fallen wall keeps what it had when it fell).
    Damping: x'^T C x', C = a0 M + a1 K0 + the dashpots cs, cd (docs/building.md), from the
    velocities relative to the ground."""
    n, a0, a1 = meta["n_storeys"], meta["a0"], meta["a1"]
    P_in = -get("ag") * sum(meta["m"][i] * get(f"v_floor_{i + 1}") + meta["md"][i] * get(f"v_diaph_{i + 1}")
                            for i in range(n))
    stored, P_damping, impacts = 0.0, 0.0, 0.0
    for i in range(n):
        vf, vd = get(f"v_floor_{i + 1}"), get(f"v_diaph_{i + 1}")
        vf_below = get(f"v_floor_{i}") if i > 0 else 0.0
        stored = stored + 0.5 * meta["m"][i] * vf ** 2 + 0.5 * meta["md"][i] * vd ** 2 \
            + get(f"work_storey_{i + 1}") + get(f"work_diaph_{i + 1}")
        P_damping = P_damping + a0 * (meta["m"][i] * vf ** 2 + meta["md"][i] * vd ** 2) \
            + (a1 * meta["k"][i] + meta["cs"][i]) * (vf - vf_below) ** 2 \
            + (a1 * meta["kd"][i] + meta["cd"][i]) * (vd - vf) ** 2
    for s in walls:
        stored = stored + get(f"wall_{s}_energy")
        impacts = impacts + get(f"wall_{s}_dissipated")
    for s in powered:
        P_in = P_in + get(f"wall_{s}_P_ground")
        if s > 1:
            P_in = P_in + (get(f"wall_{s}_F_top") + get(f"wall_{s}_F_base")) * get(f"v_diaph_{s - 1}")
    return P_in, P_damping, stored, impacts


def _building_meta(b, n):
    """The building's masses, stiffnesses and Rayleigh coefficients as the FMU holds them."""
    per_floor = ("m", "md", "k", "kd") + tuple(q for q in ("cs", "cd") if f"{q}_1" in b.vr)
    names = [f"{q}_{i + 1}" for i in range(n) for q in per_floor] + ["rayleighMass", "rayleighStiffness"]
    v = dict(zip(names, fmi_call(b, "reading the parameters", b.getReal, [b.vr[x] for x in names])))
    # a Building without dashpots (an SSP's replacement FMU from before them) has none
    return dict(n_storeys=n, a0=v["rayleighMass"], a1=v["rayleighStiffness"],
                **{q: [v.get(f"{q}_{i + 1}", 0.0) for i in range(n)] for q in ("m", "md", "k", "kd", "cs", "cd")})


def remedy():
    """What to run instead of an unstable building co-simulation (couple_building names the file)."""
    return ("run the building as one integration instead: `rockingwall building FILE.toml` (stable at any mass "
            f"ratio), or in an FMI tool {paths.where('BuildingWithWalls.fmu')} (walls, ties, diaphragms and floors "
            "as the states of one FMU)")


def _guard(scene, H, order, share):
    """The energy guard of a building run (rockingwall.coupling.energy_guard)."""
    walls = [w.storey for w in scene.walls]

    def parts(point, fallen, meta):
        row = _row(point)
        standing = [s for s in walls if f"wall_{s}" not in fallen]
        return energy_parts(row.__getitem__, meta, standing, walls)

    def explain(t, residual, peak):
        try:
            cause = rules.scene_stability(scene, H, order).cause()
        except (KeyError, ValueError, OSError, np.linalg.LinAlgError):  # a building FMU the prediction cannot read
            cause = ""
        cause = cause or (f"the macro step H = {1e3 * H:g} ms or the mass ratios of the walls to the diaphragms they "
                          f"stand on (the prediction about rest finds none: the motion may have left the walls' "
                          f"elastic range)")
        return (f"the co-simulation went unstable at t = {t:.4g} s: the energy residual {residual:.3g} J/m passed "
                f"{share:g} of the input work ({peak:.3g} J/m): its motion is the coupling's, not the building's, and "
                f"no peak or collapse of it is a result. Likely cause: {cause}. Remedy: {remedy()}")

    return energy_guard.EnergyGuard(lambda slaves: _building_meta(slaves["building"], scene.n_storeys), parts,
                                    explain, share)


def run(scene, record, t_end, H, order=2, rtol=1e-8, energy_stop=rules.ENERGY_STOP_SHARE):
    """The Jacobi master (rockingwall.coupling.jacobi) over `scene` under `record` (a
    rockingwall.records.Record, ag in m/s2) to t_end with macro step H. Returns a SceneResult. A
    wall that collapses (its fmi2Discard) falls out of the scene: from then on it takes no inputs
    and puts no force on the building, its outputs stay at the collapse; result["collapsed"] =
    {storey: t}, result["collapsed_at"] the first (None if none), and the energy terms hold up to
    then only. The run stops with CouplingUnstable (its cause and the remedy in the message) once
    its energy residual passes energy_stop of the input work (None: never; for studies of the
    scheme itself). Any other failure raises CouplingError."""
    bounds.run_length(0.0, t_end, "the coupled scene's end time")
    if not (math.isfinite(H) and 1e-6 <= H <= t_end):
        raise ValueError(f"macro step {H!r} is outside [1e-6, t_end = {t_end:g}] s")
    if t_end / H > MAX_STEPS:
        raise ValueError(f"{t_end:g} s in macro steps of {H:g} s are {t_end / H:.3g} steps, more than {MAX_STEPS:g}: "
                         "a larger --macro-step or a shorter --t-end")
    if order not in (1, 2):
        raise ValueError(f"coupling order {order!r}: 1 (inputs held) or 2 (inputs ramped)")
    guard = None if energy_stop is None else _guard(scene, H, order, energy_stop)
    history = jacobi.run(scene, record.t, record.ag, t_end, H, order=order, rtol=rtol,
                         read_at_end=lambda slaves: _building_meta(slaves["building"], scene.n_storeys),
                         monitor=guard)
    rows = [_row(p) for p in history.points]
    r = SceneResult({key: np.asarray([row.get(key, np.nan) for row in rows]) for key in rows[0]})
    r["collapsed_at"] = min(history.fallen.values()) if history.fallen else None
    r["collapsed"] = {int(name.split("_")[1]): t for name, t in history.fallen.items()}
    r.meta = dict(history.at_end, walls=[w.storey for w in scene.walls])
    r.energy_share_max = None if guard is None else guard.max_share
    return r


def _row(point):
    """One row of the result: time, ag, the building's outputs as they are named, each wall's as
    wall_<i>_<output>, each input set as <instance>_<variable>_in."""
    row = {"time": point.t, "ag": point.ag}
    row.update(point.outputs["building"])
    for name, out in point.outputs.items():
        if name != "building":
            row.update({f"{name}_{q}": v for q, v in out.items()})
    row.update({f"{k[0]}_{k[1]}_in": v for k, v in point.inputs.items()})
    return row


def observed_orders(H_list, peaks, reference):
    """log2 of successive error ratios of peaks against the reference, for halving H."""
    err = np.abs(np.asarray(peaks) - reference)
    return [math.log(err[i] / err[i + 1], H_list[i] / H_list[i + 1]) for i in range(len(err) - 1)]
