"""The robustness of a case: the same case run for an ensemble of walls, diaphragms and record
scales drawn within the inputs' plausible uncertainty, so that a chaotic response near collapse
is reported as a probability and a spread, not as one exact number.

Each member multiplies psi (the overburden), W, b, K_d (the diaphragm's stiffness), the record's
scale and, where the scene has them, the diaphragm's mass and damping, the tie and a hysteretic
diaphragm's yield force by exp(s z),
z a standard normal draw truncated at 3 (s: the spread, about the coefficient of variation), and
adds s z to e_r (kept within [0, 1]). The draws come from one seeded generator and are the same
for every case of a study (common random numbers): member k is the same plausible wall under
every record and intensity, so that cases compare member by member and a fragility can be
fitted over the records and the members together. Paper scene: the exact engine, all members in
one C call (engine.run_many); a diaphragm with mass or a building: the scene solver, one run per
member (milliseconds each on its exact engine)."""
import dataclasses
import math

import numpy as np

from . import engine
from .building import monolithic
from .building.trusted_run import BuildingError

# The inputs perturbed, in the order their draws are made. The later ones are drawn after the
# first nine, so that adding one left every member's earlier inputs as they were: a study run
# again gives the same members.
FIRST_FIELDS = ("psi", "W", "b", "er", "Kd", "scale", "diaphragm_mass", "diaphragm_damping", "tie")
LATER_FIELDS = ("diaphragm_yield",)
FIELDS = FIRST_FIELDS + LATER_FIELDS
DIAPHRAGM_FIELDS = ("diaphragm_mass", "diaphragm_damping", "tie")  # scenes (b) and (c) only
HYSTERETIC_FIELDS = ("diaphragm_yield",)  # hysteretic diaphragms only
TRUNCATE = 3.0
FLIP_SHARE = 0.05   # a case is flagged when this share of the ensemble or more disagrees with its nominal run


@dataclasses.dataclass(frozen=True)
class Spreads:
    """The standard deviation of each input's normal draw: of ln(value) (about its coefficient of
    variation), e_r's absolute. Defaults: what an assessor of an existing masonry wall rarely
    knows better than (a measured wall, an estimated roof load, a diaphragm from tables)."""
    psi: float = 0.10               # the overburden: the roof or floor load it stands for
    W: float = 0.05                 # the wall's weight: unit weight and plaster
    b: float = 0.03                 # the thickness: about 7 mm on 230 mm
    er: float = 0.05                # e_r, absolute: tests give 0.75-0.95 for a theoretical 0.86
    Kd: float = 0.30                # the diaphragm's stiffness: tables and span estimates
    scale: float = 0.05             # the record's scale: the intensity it is scaled to
    diaphragm_mass: float = 0.20    # the diaphragm's tributary mass
    diaphragm_damping: float = 0.30 # its damping ratio
    tie: float = 1.0                # the wall-to-diaphragm connection: a factor e either way
    diaphragm_yield: float = 0.30   # a hysteretic diaphragm's yield force: tables, as its stiffness

    @classmethod
    def parse(cls, items):
        """Spreads from 'NAME=VALUE' items (e.g. ['psi=0.2', 'Kd=0.5']), the rest at their defaults."""
        values = {}
        for item in items or ():
            name, sep, value = item.partition("=")
            name = name.strip()
            if not sep or name not in FIELDS:
                raise ValueError(f"--spread {item!r}: write NAME=VALUE, NAME one of {', '.join(FIELDS)}")
            try:
                values[name] = float(value)
            except ValueError:
                raise ValueError(f"--spread {item!r}: {value!r} is not a number") from None
        spreads = cls(**values)
        spreads.check()
        return spreads

    def check(self):
        for name in FIELDS:
            value = getattr(self, name)
            if not 0.0 <= value <= 2.0:
                raise ValueError(f"spread of {name} = {value!r}: must be in [0, 2]")

    def describe(self, fields=FIELDS):
        return ", ".join(f"{n} {getattr(self, n):g}" for n in fields)


@dataclasses.dataclass(frozen=True)
class Ensemble:
    """size members drawn from seed (the same members for every case), with these spreads."""
    size: int = 100
    seed: int = 1
    spreads: Spreads = Spreads()

    def __post_init__(self):
        if not 2 <= int(self.size) <= 100000:
            raise ValueError(f"ensemble size {self.size!r}: must be an integer in [2, 100000]")
        self.spreads.check()

    def factors(self, storeys=1):
        """{field: array (size, storeys)}: the factor on each input (for er: the value to add)."""
        rng = np.random.default_rng(self.seed)
        z = np.concatenate([rng.standard_normal((self.size, storeys, len(FIRST_FIELDS))),
                            rng.standard_normal((self.size, storeys, len(LATER_FIELDS)))], axis=2)
        z = np.clip(z, -TRUNCATE, TRUNCATE)
        out = {}
        for i, name in enumerate(FIELDS):
            s = getattr(self.spreads, name)
            out[name] = s * z[:, :, i] if name == "er" else np.exp(s * z[:, :, i])
        return out

    def describe(self, fields=FIELDS):
        """the ensemble and the spreads of `fields` (those the scene has: a paper scene has no
        diaphragm mass, damping or tie to perturb)"""
        return f"{self.size} members, seed {self.seed}; spreads: {self.spreads.describe(fields)}"


@dataclasses.dataclass
class Members:
    """The runs of one case's ensemble (arrays over the members; a failed run has NaN peaks and
    failed True): peaks [m] and [N/m], collapse and its time, each member wall's b and Delta_u."""
    peak_s1: np.ndarray
    peak_s2: np.ndarray
    peak_F_top: np.ndarray
    collapsed: np.ndarray
    t_collapse: np.ndarray
    b: np.ndarray
    delta_u: np.ndarray
    failed: np.ndarray

    def peaks(self):
        return {"peak_s1": self.peak_s1, "peak_s2": self.peak_s2, "peak_F_top": self.peak_F_top,
                "collapsed": self.collapsed}


def _delta_u(params):
    """Delta_u [m] of one member's wall by the C model (the smaller direction's), NaN for a wall
    that cannot stand (its run fails too)."""
    try:
        return engine.delta_u(**params)
    except ValueError:
        return math.nan


def _delta_u_of_members(fixed, walls, n):
    """Delta_u [m] of every member: the fixed parameters with the member's perturbed ones."""
    return np.array([_delta_u({**fixed, **{k: float(np.broadcast_to(v, (n,))[j]) for k, v in walls.items()}})
                     for j in range(n)])


def member_walls(params, factors, storey=0):
    """{name: array}: the wall parameters of every member (the nominal's `params`, perturbed)."""
    f = {k: v[:, storey] for k, v in factors.items()}
    walls = {"psi": params["psi"] * f["psi"], "W": params["W"] * f["W"], "b": params["b"] * f["b"],
             "er": np.clip(params["er"] + f["er"], 0.0, 1.0)}
    if int(params["support"]) == 3:
        walls["Kd"] = params["Kd"] * f["Kd"]
    return walls


def wall_members(params, record, ensemble, t_end):
    """The ensemble of a wall on its own (the paper's scene): one C call for every member."""
    if not engine.covers(params):
        raise ValueError(f"the ensemble runs on the exact engine, which takes parapets up to b/h = "
                         f"{engine.PARAPET_MAX_B_OVER_H} (its small-rotation form); this one has b/h = "
                         f"{params['b'] / params['h']:.3g}: run it without an ensemble (--ensemble 0)")
    factors = ensemble.factors()
    walls = member_walls(params, factors)
    fixed = {k: v for k, v in params.items() if k not in walls}
    out = engine.run_many(record.t, record.ag, scale=factors["scale"][:, 0], t_end=t_end, **fixed, **walls)
    failed = (out["code"] != 0) & ~np.isfinite(out["peak_s1"])
    kd = walls.get("Kd", 0.0)
    f_top = np.asarray(kd) * out["peak_s2"] if int(params["support"]) == 3 else np.zeros(ensemble.size)
    return Members(out["peak_s1"], out["peak_s2"], f_top, out["collapsed"] & ~failed, out["t_collapse"],
                   walls["b"], _delta_u_of_members(fixed, walls, ensemble.size), failed)


def diaphragm_members(params, diaphragm, tie, record, ensemble, t_end, with_tie_force=False):
    """The ensemble of a wall tied to a diaphragm with mass (scene b): the diaphragm's stiffness,
    mass and damping (a hysteretic one's yield force) and the tie perturbed too; one scene run per
    member, and with_tie_force one more for each standing member's tie force (tie_force.sample, as
    the nominal run's; else NaN)."""
    factors = ensemble.factors()
    walls = member_walls(params, factors)
    runs = []
    for k in range(ensemble.size):
        wall = dict(params, **{name: float(v[k]) for name, v in walls.items() if name != "Kd"})
        d = _member_diaphragm(diaphragm, {name: v[k, 0] for name, v in factors.items()})
        member_tie = tie * factors["tie"][k, 0]
        spec = monolithic.wall_under_diaphragm_spec(wall, d, member_tie)
        runs.append(_scene_run(spec, [wall], record, factors["scale"][k, 0], t_end, with_tie_force))
    fixed = {k: v for k, v in params.items() if k not in walls}
    return _collect(runs, dict(walls, delta_u=_delta_u_of_members(fixed, walls, ensemble.size)), 0)


def building_members(building, record, ensemble, t_end, with_tie_force=False):
    """The ensemble of a building (scene c): [Members per storey]. Every storey's wall (psi via
    its overburden, W, b, e_r), diaphragm (stiffness, mass, damping; a hysteretic one's yield force)
    and tie perturbed, each storey by its own draws; the in-plane walls as given. with_tie_force: each
    standing wall's tie force too (one more run per member), else NaN. A storey without a wall has
    its diaphragm perturbed, and its Members hold NaN."""
    n = len(building.storeys)
    factors = ensemble.factors(n)
    runs, walls_per_storey = [], [dict() for _ in range(n)]
    for k in range(ensemble.size):
        storeys = []
        for i, s in enumerate(building.storeys):
            f = {name: v[k, i] for name, v in factors.items()}
            wall = _member_wall(s.wall, f) if s.wall else None
            storeys.append(dataclasses.replace(s, wall=wall, diaphragm=_member_diaphragm(s.diaphragm, f),
                                               tie=s.tie * f["tie"]))
        member = dataclasses.replace(building, storeys=tuple(storeys))
        params = [member.wall_parameters(i) for i in range(n)]
        for i, p in enumerate(params):
            walls_per_storey[i].setdefault("b", []).append(p["b"] if p else math.nan)
            walls_per_storey[i].setdefault("delta_u", []).append(_delta_u(p) if p else math.nan)
        runs.append(_scene_run(monolithic.building_spec(member), params, record, factors["scale"][k, 0], t_end,
                               with_tie_force))
    return [_collect(runs, {k: np.array(v) for k, v in walls_per_storey[i].items()}, i) for i in range(n)]


def _member_diaphragm(diaphragm, f):
    """A member's diaphragm: its stiffness, mass and damping (at most 2) by the member's factors f,
    a hysteretic one's yield force too."""
    d = dataclasses.replace(diaphragm, stiffness=diaphragm.stiffness * f["Kd"],
                            mass=diaphragm.mass * f["diaphragm_mass"],
                            damping=min(2.0, diaphragm.damping * f["diaphragm_damping"]))
    return d if d.law == "linear" else dataclasses.replace(d, yield_force=d.yield_force * f["diaphragm_yield"])


def _member_wall(wall, f):
    """A member's wall: the building file's wall layer with the member's factors f."""
    b = wall.b * f["b"]  # the overburden bears at the same fraction of it (on the face stays on it)
    return dataclasses.replace(wall, b=b, W=wall.W * f["W"],
                               e_top=math.copysign(min(abs(wall.e_top) * f["b"], b / 2), wall.e_top),
                               overburden=wall.overburden * f["psi"], e_r=float(np.clip(wall.e_r + f["er"], 0.0, 1.0)))


def with_members(own, ensemble, with_tie_force=False):
    """(fewest, most) scene runs of a case of scene (b) or (c): its own `own` (fewest, most) and
    each member's of `ensemble` (None: none; monolithic.respond_runs of a member's checks)."""
    size = ensemble.size if ensemble is not None else 0
    member = monolithic.respond_runs(**_member_checks(with_tie_force))
    return tuple(n + size * m for n, m in zip(own, member))


def _member_checks(with_tie_force):
    return dict(filter_floor=False, tie_forces=with_tie_force)


def _scene_run(spec, params, record, scale, t_end, with_tie_force=False):
    """(peak_s1, peak_s2, peak_F_top, collapsed, t_collapse) per storey, or None for a run that
    failed (the solver refused it or its energy balance did not close). with_tie_force: the
    standing walls' tie forces from a second run (tie_force.sample), else NaN."""
    member = dataclasses.replace(record, ag=record.ag * float(scale))
    try:
        result, _ = monolithic.respond(spec, params, member, t_end=t_end, **_member_checks(with_tie_force))
    except (BuildingError, RuntimeError):
        return None
    return [(s.peak_s1_m, s.peak_s2_m, s.tie_force_or_nan, s.collapsed,
             s.t_collapse_s if s.collapsed else np.nan) for s in result.storeys]


def _collect(runs, walls, storey):
    rows = [r[storey] if r is not None else (np.nan, np.nan, np.nan, False, np.nan) for r in runs]
    s1, s2, f, collapsed, t_c = (np.array(col) for col in zip(*rows))
    failed = np.array([r is None for r in runs])
    b = np.asarray(walls["b"], dtype=float)
    return Members(s1.astype(float), s2.astype(float), f.astype(float), collapsed.astype(bool), t_c.astype(float),
                   b, np.asarray(walls["delta_u"], dtype=float), failed)


@dataclasses.dataclass(frozen=True)
class Summary:
    """What a case's ensemble says: its size and failed runs, the probability of collapse and of
    each limit state, the 16/50/84 % peaks of s1 and s2 [m] (inf where that share of the
    ensemble collapses: a collapsed wall's peak is no displacement) and whether the nominal run's
    outcome flips inside the ensemble."""
    size: int
    failed: int
    collapse_probability: float
    limit_probabilities: dict
    s1_percentiles: tuple
    s2_percentiles: tuple
    flips: bool

    def to_dict(self):
        return {"size": self.size, "failed": self.failed, "collapse_probability": self.collapse_probability,
                "limit_state_probabilities": dict(self.limit_probabilities),
                "s1_p16_m": self.s1_percentiles[0], "s1_p50_m": self.s1_percentiles[1],
                "s1_p84_m": self.s1_percentiles[2], "s2_p16_m": self.s2_percentiles[0],
                "s2_p50_m": self.s2_percentiles[1], "s2_p84_m": self.s2_percentiles[2], "flips": self.flips}


def reached(members, states):
    """{state name: bool array, 'collapsed': bool array} over the members that ran; a state whose
    quantity no member has (the tie force of scene runs) is left out."""
    ok = ~members.failed
    peaks = {k: v[ok] for k, v in members.peaks().items()}
    out = {s.name: s.exceeded_many(peaks, members.b[ok], members.delta_u[ok]) for s in states
           if np.isfinite(peaks[f"peak_{s.quantity}"]).any() or peaks["collapsed"].all()}
    out["collapsed"] = peaks["collapsed"]
    return out


def summarize(members, states, nominal):
    """A Summary of Members under the limit states; nominal: {name: reached} of the nominal run,
    with 'collapsed'."""
    ok = ~members.failed
    outcome = reached(members, states)
    probability = {s.name: float(outcome[s.name].mean()) if s.name in outcome and ok.any() else np.nan
                   for s in states}
    collapse = float(outcome["collapsed"].mean()) if ok.any() else np.nan
    flips = any(r.size and np.mean(r != bool(nominal[name])) >= FLIP_SHARE for name, r in outcome.items())
    demand = [np.where(members.collapsed[ok], np.inf, q[ok]) for q in (members.peak_s1, members.peak_s2)]
    s1, s2 = (percentiles(d) for d in demand)
    return Summary(int(members.failed.size), int(members.failed.sum()), collapse, probability, s1, s2, bool(flips))


def percentiles(values, q=(16, 50, 84)):
    """Percentiles (linear interpolation) where a percentile at or beside an infinite value is inf."""
    v = np.sort(np.asarray(values, dtype=float))
    if not v.size:
        return tuple(np.nan for _ in q)
    out = []
    for p in q:
        pos = p / 100 * (v.size - 1)
        lo, hi = int(np.floor(pos)), int(np.ceil(pos))
        out.append(np.inf if np.isinf(v[hi]) else float(v[lo] + (v[hi] - v[lo]) * (pos - lo)))
    return tuple(out)
