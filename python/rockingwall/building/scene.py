"""Out-of-plane walls in a building: Building.fmu plus one RockingWall.fmu per storey, coupled
through FMI 2.0 Co-Simulation by a fixed-step Jacobi master over fmpy (FMU2Slave, in-process).

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

    rockingwall couple-building --storeys 2 --record elcentro --scale 0.5
"""
import argparse
import dataclasses
import math
import sys
import tempfile

import numpy as np

from .. import paths, records
from ..coupling.wall_diaphragm import CouplingError, _close_slaves, _fmi_call, _FmuLog, _initialise, _load_slave
from ..names import HINGE_LAWS, SUPPORTS, paper_wall

WALL_OUT = ["s1", "s2", "F_top", "F_base", "energy", "P_ground", "dissipated"]
FLOOR_OUT = ["u_diaph", "a_diaph", "u_top", "u_floor", "v_floor", "v_diaph", "work_storey", "work_diaph"]
MAX_STOREYS = 5


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

    def _integral(self, p):
        t = self["time"]
        return np.concatenate([[0.0], np.cumsum(0.5 * (p[1:] + p[:-1]) * np.diff(t))])

    def peak(self, storey, what="s1"):
        return float(np.max(np.abs(self[f"wall_{storey}_{what}"])))

    def energy_terms(self):
        """The scene's energy balance (J/m), each term a time series:
        input = ground work on every FMU in its own frame (the walls' P_ground, the building's
        -ag sum m v) + the work the floors do moving the bases of the walls above storey 1,
        sum (F_top + F_base) v_base; stored = walls' energy (kinetic, gravity, hinges, spring) +
        building's kinetic energy + the work of its springs (elastic energy plus what their
        hysteresis dissipated); damping = building's Rayleigh damping; impacts = the walls'
        `dissipated`. Balance: input = stored - stored(0) + damping + impacts."""
        m = self.meta
        n = m["n_storeys"]
        P_in = -self["ag"] * sum(m["m"][i] * self[f"v_floor_{i + 1}"] + m["md"][i] * self[f"v_diaph_{i + 1}"]
                                 for i in range(n))
        stored = sum(0.5 * m["m"][i] * self[f"v_floor_{i + 1}"] ** 2 + 0.5 * m["md"][i] * self[f"v_diaph_{i + 1}"] ** 2
                     + self[f"work_storey_{i + 1}"] + self[f"work_diaph_{i + 1}"] for i in range(n))
        impacts = np.zeros_like(self["time"])
        for s in m["walls"]:
            P_in = P_in + self[f"wall_{s}_P_ground"]
            if s > 1:
                P_in = P_in + (self[f"wall_{s}_F_top"] + self[f"wall_{s}_F_base"]) * self[f"v_diaph_{s - 1}"]
            stored = stored + self[f"wall_{s}_energy"]
            impacts = impacts + self[f"wall_{s}_dissipated"]
        damping = self._integral(self._damping_power())
        inp = self._integral(P_in)
        return dict(input=inp, stored=stored - stored[0], damping=damping, impacts=impacts - impacts[0],
                    residual=inp - (stored - stored[0]) - damping - (impacts - impacts[0]))

    def _damping_power(self):
        """x'^T C x', C = a0 M + a1 K0 (docs/building.md), from the velocities relative to the ground."""
        m = self.meta
        n, a0, a1 = m["n_storeys"], m["a0"], m["a1"]
        P = np.zeros_like(self["time"])
        for i in range(n):
            vf, vd = self[f"v_floor_{i + 1}"], self[f"v_diaph_{i + 1}"]
            vf_below = self[f"v_floor_{i}"] if i > 0 else 0.0
            P = P + a0 * (m["m"][i] * vf ** 2 + m["md"][i] * vd ** 2)
            P = P + a1 * (m["k"][i] * (vf - vf_below) ** 2 + m["kd"][i] * (vd - vf) ** 2)
        return P


def _building_meta(b, n):
    """The building's masses, stiffnesses and Rayleigh coefficients as the FMU holds them."""
    names = [f"{q}_{i + 1}" for i in range(n) for q in ("m", "md", "k", "kd")] + ["rayleighMass", "rayleighStiffness"]
    v = dict(zip(names, _fmi_call(b, "reading the parameters", b.getReal, [b.vr[x] for x in names])))
    return dict(n_storeys=n, m=[v[f"m_{i + 1}"] for i in range(n)], md=[v[f"md_{i + 1}"] for i in range(n)],
                k=[v[f"k_{i + 1}"] for i in range(n)], kd=[v[f"kd_{i + 1}"] for i in range(n)],
                a0=v["rayleighMass"], a1=v["rayleighStiffness"])


class _Exchange:
    """The coupled inputs of every slave at one communication point, and their slopes over the
    step: extrapolated from the previous exchange (order 2) or zero (order 1)."""

    def __init__(self, order, H):
        self.order, self.H, self.previous = order, H, None

    def forget_forces(self):
        """A wall fell out: the building's force inputs jump; no slope across the jump."""
        if self.previous is not None:
            self.previous = {k: v for k, v in self.previous.items() if not k[1].startswith(("F_wall_", "F_above_"))}

    def slopes(self, values):
        if self.order < 2 or self.previous is None:
            out = {k: 0.0 for k in values}
        else:
            out = {k: (v - self.previous[k]) / self.H if k in self.previous else 0.0 for k, v in values.items()}
        self.previous = dict(values)
        return out


def _coupled_inputs(scene, b_out, w_out, ag, collapsed=()):
    """{(instance, variable): value} of every input at a communication point, from the outputs.
    A collapsed wall (in `collapsed`) has fallen out: it takes no inputs and puts no force."""
    n = scene.n_storeys
    standing = {w.storey: w for w in scene.walls if w.name not in collapsed}
    values = {("building", "ag"): ag}
    for i in range(1, n + 1):
        below, above = standing.get(i), standing.get(i + 1)
        values[("building", f"F_wall_{i}")] = w_out[below.name]["F_top"] if below else 0.0
        values[("building", f"F_above_{i}")] = w_out[above.name]["F_base"] if above else 0.0
    for i, w in standing.items():
        values[(w.name, "ag")] = ag if i == 1 else b_out[f"a_diaph_{i - 1}"]
        values[(w.name, "u_top")] = b_out[f"u_top_{i}"]
    return values


def _set_inputs(slaves, values, slopes, ground_keys, ground_slope, at):
    """Set every input, then its slope (the record's own slope for the inputs that take ag)."""
    for name, s in slaves.items():
        keys = [k for k in values if k[0] == name]
        vr = [s.vr[k[1]] for k in keys]
        _fmi_call(s, at, s.setReal, vr, [values[k] for k in keys])
        d = [ground_slope if k in ground_keys else slopes[k] for k in keys]
        if any(x != 0.0 for x in d):  # after setReal, which holds an input until told otherwise
            _fmi_call(s, at, s.setRealInputDerivatives, vr, [1] * len(vr), d)


def _read(slaves, scene, w_last=None, collapsed=()):
    """The building's floor outputs and the walls' outputs; a collapsed wall keeps its last ones."""
    b = slaves["building"]
    n = scene.n_storeys
    names = [f"{q}_{i}" for i in range(1, n + 1) for q in FLOOR_OUT]
    b_out = dict(zip(names, b.getReal([b.vr[x] for x in names])))
    w_out = {w.name: (w_last[w.name] if w.name in collapsed else
                      dict(zip(WALL_OUT, slaves[w.name].getReal([slaves[w.name].vr[x] for x in WALL_OUT]))))
             for w in scene.walls}
    return b_out, w_out


def run(scene, record, t_end, H, order=2, rtol=1e-8):
    """The fmpy master over `scene` under `record` (a rockingwall.records.Record, ag in m/s2) to
    t_end with macro step H. Returns a SceneResult. A wall that collapses (its fmi2Discard) falls
    out of the scene: from then on it takes no inputs and puts no force on the building, its
    outputs stay at the collapse; result["collapsed"] = {storey: t}, result["collapsed_at"] the
    first (None if none), and the energy terms hold up to then only. Any other failure raises
    CouplingError."""
    if not (math.isfinite(H) and 1e-6 <= H <= t_end):
        raise ValueError(f"macro step {H!r} is outside [1e-6, t_end = {t_end:g}] s")
    if order not in (1, 2):
        raise ValueError(f"coupling order {order!r}: 1 (inputs held) or 2 (inputs ramped)")
    log, slaves = _FmuLog(), {}
    with tempfile.TemporaryDirectory(prefix="building_scene_") as unzip_root:
        try:
            slaves["building"] = _load_slave(scene.building_fmu, "building", unzip_root, log)
            _initialise(slaves["building"], (scene.building_real, scene.building_integer), rtol)
            for w in scene.walls:
                slaves[w.name] = _load_slave(scene.wall_fmu, w.name, unzip_root, log)
                _initialise(slaves[w.name], (w.real, w.integer), rtol)
            return _jacobi(scene, slaves, np.asarray(record.t, float), np.asarray(record.ag, float), t_end, H, order)
        finally:
            _close_slaves(list(slaves.values()))


def _jacobi(scene, slaves, t_in, ag_in, t_end, H, order):
    from fmpy.fmi1 import FMICallException
    from fmpy.fmi2 import fmi2Discard
    ground_keys = set(scene.ground_inputs())
    n_steps = int(round(t_end / H))
    exchange = _Exchange(order, H)
    rows, collapsed = [], {}
    b_out, w_out = _read(slaves, scene)

    def ag_at(t):
        return float(np.interp(t, t_in, ag_in, right=0.0))

    for k in range(n_steps + 1):
        t = k * H
        at = f"at t = {t:.6g} s"
        ag = ag_at(t)
        values = _coupled_inputs(scene, b_out, w_out, ag, collapsed)
        slopes = exchange.slopes(values)
        ag_slope = (ag_at(t + H) - ag) / H if order == 2 else 0.0
        standing = {n: s for n, s in slaves.items() if n not in collapsed}
        _set_inputs(standing, values, slopes, ground_keys, ag_slope, at)
        b_out, w_out = _read(slaves, scene, w_out, collapsed)  # outputs with these inputs (algebraic ones change)
        rows.append(_row(t, ag, b_out, w_out, values))
        if k == n_steps:
            break
        for name, s in standing.items():
            try:
                s.doStep(currentCommunicationPoint=t, communicationStepSize=H)
            except FMICallException as exc:
                if exc.status != fmi2Discard or name == "building":  # an error, not a wall's collapse
                    _fmi_call(s, at, _raise, exc)
                collapsed[name] = t
                w_out[name] = dict(zip(WALL_OUT, s.getReal([s.vr[x] for x in WALL_OUT])))  # at the collapse
                exchange.forget_forces()
        if collapsed and len(collapsed) == len(scene.walls):
            break  # every wall fell: nothing of interest remains
        b_out, w_out = _read(slaves, scene, w_out, collapsed)
    r = SceneResult({key: np.asarray([row.get(key, np.nan) for row in rows]) for key in rows[0]})
    r["collapsed_at"] = min(collapsed.values()) if collapsed else None
    r["collapsed"] = {int(name.split("_")[1]): t for name, t in collapsed.items()}
    r.meta = dict(_building_meta(slaves["building"], scene.n_storeys), walls=[w.storey for w in scene.walls])
    return r


def _row(t, ag, b_out, w_out, values):
    row = {"time": t, "ag": ag}
    row.update(b_out)
    for name, out in w_out.items():
        row.update({f"{name}_{q}": v for q, v in out.items()})
    row.update({f"{k[0]}_{k[1]}_in": v for k, v in values.items()})
    return row


def _raise(exc):
    raise exc


def observed_orders(H_list, peaks, reference):
    """log2 of successive error ratios of peaks against the reference, for halving H."""
    err = np.abs(np.asarray(peaks) - reference)
    return [math.log(err[i] / err[i + 1], H_list[i] / H_list[i + 1]) for i in range(len(err) - 1)]


# ---- command line ---------------------------------------------------------------------------------

def parse_args(argv):
    ap = argparse.ArgumentParser(prog="rockingwall couple-building", description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--storeys", type=int, default=2, help="nStoreys of the building, 1..5")
    ap.add_argument("--walls", help="comma-separated storeys with a wall (default: every storey)")
    ap.add_argument("--wall", type=int, default=1, choices=[1, 2, 3], help="the paper's wall")
    ap.add_argument("--Kd", type=float, default=1e6, help="wall-to-diaphragm connection, N/m per m")
    ap.add_argument("--hinge-law", default="dohertyHinge", choices=list(HINGE_LAWS))
    ap.add_argument("--diaphragm-law", type=int, default=2, choices=[0, 1, 2],
                    help="0 linear, 1 Bouc-Wen, 2 Bouc-Wen with pinching (timber)")
    ap.add_argument("--record", default="elcentro", help="'elcentro', 'gaussian[:D,T]' or an .AT2/.csv file")
    ap.add_argument("--scale", type=float, default=0.5)
    ap.add_argument("--macro-step", type=float, default=1e-3, help="H [s]")
    ap.add_argument("--t-end", type=float, default=None, help="[s], default the record's duration")
    ap.add_argument("--order", type=int, default=2, choices=[1, 2],
                    help="2: inputs ramped with extrapolated derivatives; 1: inputs held")
    ap.add_argument("--ssp", help="also write the scene as an SSP 1.0 file here")
    ap.add_argument("--from-ssp", help="run the scene of this SSP file instead of the options above")
    ap.add_argument("--example", action="store_true",
                    help="generate the worked example of docs/building-coupling.md (plot and table)")
    ap.add_argument("--records-cache", help="folder of the converted FEMA P695 far-field records "
                                            "(default: the one `rockingwall sweep` uses)")
    return ap.parse_args(argv)


def main(argv=None):
    a = parse_args(argv)
    try:
        if a.example:
            from . import example as building_example
            from ..sweep import suites
            return building_example.main(a.records_cache or suites.fema_cache())
        if a.from_ssp:
            from . import ssp
            scene = ssp.read(a.from_ssp)
        else:
            walls = [int(x) for x in a.walls.split(",")] if a.walls else None
            scene = default_scene(a.storeys, walls, a.wall, a.Kd, a.diaphragm_law, a.hinge_law)
        if a.ssp:
            from . import ssp
            ssp.write(scene, a.ssp)
            print(f"wrote {a.ssp}")
        rec = records.load(a.record).scaled(a.scale)
        t_end = a.t_end or float(rec.t[-1])
        r = run(scene, rec, t_end, a.macro_step, a.order)
    except (ValueError, OSError, CouplingError) as exc:
        print(f"couple-building: error: {exc}", file=sys.stderr)
        return 1
    for w in scene.walls:
        print(f"wall in storey {w.storey}: peak s1 {r.peak(w.storey, 's1'):.5f} m, s2 {r.peak(w.storey, 's2'):.5f} m")
    e = r.energy_terms()
    upto = r["time"] <= (r["collapsed_at"] if r["collapsed_at"] is not None else np.inf)
    print(f"energy (up to the first collapse): max |residual| {np.abs(e['residual'][upto]).max():.4g} J/m "
          f"of max input {np.abs(e['input'][upto]).max():.4g} J/m")
    for storey, t in sorted(r["collapsed"].items()):
        print(f"the wall in storey {storey} collapsed at t = {t:.3f} s and fell out of the scene")
    return 0


if __name__ == "__main__":
    sys.exit(main())
