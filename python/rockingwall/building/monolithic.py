"""A building's walls, ties, diaphragms and floors in one integration (the scene solver,
rockingwall.scene_engine): stable at any mass ratio, each wall with its own event rules. The
response per storey, the energy balance checked, and what the scene leaves out."""
import dataclasses
import math

import numpy as np

from .. import engine, limits, scene_engine
from . import floor_acc, tie_force
from .concurrent_runs import InOrder
from .trusted_run import check_energy

# The sensitivity check: the record scaled by 1 -/+ this, far below any record's accuracy. Impacts
# through a stiff tie can make a building's motion sensitive: on two storeys tied at 1e9 N/m per m
# such a change moves the peaks by several %, the same change of CVODES's tolerance does, and no
# solver's digits then say more than the spread (docs/your-building.md, "Tie").
SENSITIVITY_PERTURBATION = 1e-9
# the record's scales of the check's two runs
SENSITIVITY_SCALES = (1.0 - SENSITIVITY_PERTURBATION, 1.0 + SENSITIVITY_PERTURBATION)
# A peak that moves by more than this share under the perturbation is reported as sensitive.
SENSITIVITY_SHARE = 0.01


@dataclasses.dataclass(frozen=True)
class StoreyResult:
    """One storey's wall and diaphragm: peaks [m] of s1, s2 relative to the wall's own base, Delta_u
    [m], collapse and its time [s] (None if standing), the diaphragm's peak displacement relative
    to its supports [m], the peak absolute acceleration of the floor the wall stands on [m/s2]:
    low-pass filtered at floor_acc.CUTOFF_HZ (None where not computed), and raw (which grows with
    the tie's stiffness: the jolt of the walls' impacts)."""
    storey: int
    peak_s1_m: float
    peak_s2_m: float
    delta_u_m: float
    collapsed: bool
    t_collapse_s: float
    diaphragm_peak_m: float
    base_peak_acc_m_s2: float
    impacts: int
    base_peak_acc_raw_m_s2: float = None
    tie_force_N_per_m: float = None      # the tie's force on the diaphragm filtered at 25 Hz; None: not computed or collapsed
    tie_force_raw_N_per_m: float = None  # the same unfiltered (it grows with the tie's stiffness)
    wall: bool = True  # False: a storey without a face-loaded wall (its wall's peaks NaN; its diaphragm's real)

    @property
    def tie_force_or_nan(self):
        """tie_force_N_per_m, NaN where not computed or collapsed (for arrays of runs)."""
        return math.nan if self.tie_force_N_per_m is None else self.tie_force_N_per_m

    @property
    def s1_over_delta_u(self):
        return self.peak_s1_m / self.delta_u_m

    def to_dict(self):
        """For JSON: a collapsed wall's peaks and s1/Delta_u are None, as the table's '-' (the run
        stops at its instability point: they are no displacements; its collapse is t_collapse_s)."""
        d = dataclasses.asdict(self)
        d["s1_over_Delta_u"] = self.s1_over_delta_u
        d["near_collapse"] = limits.near_collapse(self.s1_over_delta_u, self.collapsed)
        if self.collapsed or not self.wall:
            d.update(peak_s1_m=None, peak_s2_m=None, s1_over_Delta_u=None)
        if not self.wall:
            d.update(delta_u_m=None, impacts=None, near_collapse=False)
        return d


@dataclasses.dataclass(frozen=True)
class BuildingResult:
    """The response of every storey under one record, the solver that ran and the energy balance
    (input work, viscous and impact losses [J/m], the largest residual over the run as a share of
    the largest input work)."""
    record: str
    storeys: tuple
    solver: str
    work_ground_J_m: float
    work_damping_J_m: float
    event_losses_J_m: float
    residual_share: float
    steps: int
    events: int
    peak_sensitivity: float = None   # the largest share a peak moved under the check; None: not run
    floor_sample_dt_s: float = None  # the sampling of the floor's filtered acceleration; None: not computed
    floor_resolved: bool = None      # False: even the finest sampling left the filtered peaks apart
    tie_sample_dt_s: float = None    # the sampling of the ties' filtered forces; None: not computed
    tie_resolved: bool = None        # False: even the finest sampling left the filtered forces apart

    @property
    def sensitive(self):
        return self.peak_sensitivity is not None and self.peak_sensitivity > SENSITIVITY_SHARE

    def to_dict(self):
        return {"record": self.record, "solver": self.solver, "storeys": [s.to_dict() for s in self.storeys],
                "peak_sensitivity": self.peak_sensitivity, "sensitive": self.sensitive,
                "floor_acc": {"cutoff_hz": floor_acc.CUTOFF_HZ, "sample_dt_s": self.floor_sample_dt_s,
                              "resolved": self.floor_resolved},
                "tie_force": {"cutoff_hz": floor_acc.CUTOFF_HZ, "sample_dt_s": self.tie_sample_dt_s,
                              "resolved": self.tie_resolved},
                "energy": {"ground_work_J_per_m": self.work_ground_J_m, "damping_J_per_m": self.work_damping_J_m,
                           "event_losses_J_per_m": self.event_losses_J_m, "residual_share": self.residual_share}}


def storey_spec(wall_params, diaphragm, in_plane=None, law=None):
    """One storey of the scene: the wall's parameters (None: no wall), its diaphragm (a
    description.Diaphragm) under the building's law (None: its own) and its in-plane walls (None: rigid)."""
    d = diaphragm
    Fyd, alphad = d.spring_under(law or d.law)
    values = dict(wall=wall_params, md=d.mass, kd=d.stiffness, cd=d.dashpot, Fyd=Fyd, alphad=alphad)
    if in_plane is not None:
        values.update(m=in_plane.mass, k=in_plane.stiffness,
                      cs=2.0 * in_plane.damping * math.sqrt(in_plane.stiffness * in_plane.mass))
    return scene_engine.StoreySpec(**values)


def building_spec(building):
    """The scene solver's Spec of a description.Building."""
    law = building.diaphragm_law
    storeys = tuple(storey_spec(building.wall_parameters(i), s.diaphragm, s.in_plane, law)
                    for i, s in enumerate(building.storeys))
    return scene_engine.Spec(storeys=storeys, rigid_in_plane=building.rigid_in_plane,
                             diaphragm_law=law, **building.hysteresis())


def wall_under_diaphragm_spec(wall_params, diaphragm, tie):
    """The scene of one wall (its full parameter set, the tie as its Kd) under a diaphragm with
    mass whose supports move with the ground."""
    return scene_engine.Spec(storeys=(storey_spec(dict(wall_params, Kd=tie, support=3), diaphragm),),
                             diaphragm_law=diaphragm.law, **diaphragm.hysteresis())


def _peaks(r):
    """The peaks a storey reports, a collapsed wall's as infinite (a change of verdict is total)."""
    return np.where(np.concatenate([r.collapsed, r.collapsed]), np.inf, np.concatenate([r.peak_s1, r.peak_s2]))


def scaled_run(spec, record, scale, t_end, rtol, solver):
    """A run under the record scaled by `scale` (the sensitivity check's), its energy checked."""
    run = scene_engine.run(spec, record.t, record.ag * scale, t_end=t_end, rtol=rtol, engine=solver)
    check_energy(run, f"{record.name} scaled by {scale:.9f} (the sensitivity check)")
    return run


def peak_sensitivity(r, scaled):
    """The largest relative change of a wall's peak s1 or s2 from the run r to the scaled runs (1.0
    where a wall's collapse changes)."""
    base = _peaks(r)
    worst = 0.0
    for run in scaled:
        other = _peaks(run)
        with np.errstate(invalid="ignore"):
            change = np.where(np.isinf(base) | np.isinf(other), np.where(base == other, 0.0, 1.0),
                              np.abs(other - base) / np.maximum(np.abs(base), 1e-12))
        worst = max(worst, float(np.max(change)))
    return worst


def storey_results(r, wall_params_list, floor=None, ties=None):
    """Each storey's StoreyResult from a scene_engine.Result, its floors' and ties' sampled and
    filtered histories (floor_acc.Sampled; None: not computed)."""
    storeys = []
    for i, params in enumerate(wall_params_list):
        collapsed, wall = bool(r.collapsed[i]), params is not None
        tie, tie_raw = (None, None) if ties is None or collapsed or not wall else (float(ties.filtered_peak[i]),
                                                                                       float(ties.raw_peak[i]))
        storeys.append(StoreyResult(
            storey=i + 1, peak_s1_m=float(r.peak_s1[i]) if wall else math.nan,
            peak_s2_m=float(r.peak_s2[i]) if wall else math.nan,
            delta_u_m=engine.delta_u(**params) if wall else math.nan,
            collapsed=collapsed, t_collapse_s=float(r.t_collapse[i]) if collapsed else None,
            diaphragm_peak_m=float(r.peak_diaphragm[i]),
            base_peak_acc_m_s2=None if floor is None else float(floor.filtered_peak[i]),
            base_peak_acc_raw_m_s2=float(r.peak_base_acc[i]), impacts=int(r.impacts[i]),
            tie_force_N_per_m=tie, tie_force_raw_N_per_m=tie_raw, wall=wall))
    return tuple(storeys)


# The main run's histories on the output grid. Not the floors' accelerations or the ties' forces:
# raw on a coarse grid the tie's ringing aliases into them (Histories has them filtered).
SCENE_HISTORIES = ("s1", "s2", "diaphragm")


@dataclasses.dataclass(frozen=True)
class Histories:
    """A building run's histories on the output grid asked for: the scene's (scene_engine.Result,
    with SCENE_HISTORIES) and, where computed, the floors' accelerations [m/s2] and the ties' forces
    [N/m] from their dense samples filtered at floor_acc.CUTOFF_HZ (rows: the scene's times; None:
    not computed or no grid)."""
    scene: object
    floor_acc: np.ndarray = None
    tie_force: np.ndarray = None


def sampled(spec, record, t_end, rtol, solver, floor, ties):
    """(the floors' accelerations, the ties' forces) sampled and filtered (floor_acc.Sampled, or None
    where not asked for): both from one run where both are."""
    if floor and ties:
        both = floor_acc.sample_histories(spec, record, ("base_acc", "tie"),
                                          "the floors' accelerations and the ties' forces", t_end, rtol, solver)
        return both["base_acc"], both["tie"]
    return (floor_acc.sample(spec, record, t_end, rtol, solver) if floor else None,
            tie_force.sample(spec, record, t_end, rtol, solver) if ties else None)


def respond_runs(check_sensitivity=False, filter_floor=True, tie_forces=False):
    """(fewest, most) scene runs respond makes with these options: the main run, the sensitivity
    check's two, and the dense run for the floors or the ties, which floor_acc.sample_histories
    repeats at a finer sampling up to floor_acc.REFINEMENTS times."""
    dense = bool(filter_floor or tie_forces)
    fewest = 1 + len(SENSITIVITY_SCALES) * bool(check_sensitivity) + dense
    return fewest, fewest + floor_acc.REFINEMENTS * dense


def respond(spec, wall_params_list, record, t_end=None, rtol=1e-8, t_out=None, solver=None, check_sensitivity=False,
            filter_floor=True, executor=None, tie_forces=False):
    """Runs a Spec under a record: (BuildingResult, Histories).
    solver: 'exact', 'cvode' (CVODES at rtol), or None: the exact engine where it covers the scene.
    check_sensitivity: also run the record scaled by 1 -/+ SENSITIVITY_PERTURBATION (two more
    runs) and give the largest change of a peak (BuildingResult.peak_sensitivity). filter_floor:
    the floors' filtered peak acceleration; else base_peak_acc_m_s2 is None. tie_forces: each
    standing wall's tie force filtered at 25 Hz. Either or both: one more run on a dense grid
    (sampled). executor: where those runs go
    (concurrent_runs.threads(): side by side; None: one after another); every run's energy balance
    is checked, the main run's first."""
    pool = executor or InOrder()
    solver = scene_engine.engine_for(spec, solver)
    main = pool.submit(scene_engine.run, spec, record.t, record.ag, t_end=t_end, rtol=rtol, t_out=t_out, engine=solver,
                       histories=SCENE_HISTORIES)
    dense = pool.submit(sampled, spec, record, t_end, rtol, solver, filter_floor, tie_forces) \
        if filter_floor or tie_forces else None
    scaled = [pool.submit(scaled_run, spec, record, scale, t_end, rtol, solver)
              for scale in (SENSITIVITY_SCALES if check_sensitivity else ())]
    r = main.result()
    share = check_energy(r, record.name)
    floor, ties = dense.result() if dense else (None, None)
    result = BuildingResult(record=record.name, storeys=storey_results(r, wall_params_list, floor, ties),
                            solver=r.engine,
                            work_ground_J_m=r.work_ground, work_damping_J_m=r.work_damping,
                            event_losses_J_m=r.event_losses, residual_share=share, steps=r.steps, events=r.events,
                            peak_sensitivity=peak_sensitivity(r, [f.result() for f in scaled]) if scaled else None,
                            floor_sample_dt_s=floor.dt if floor else None,
                            floor_resolved=floor.resolved if floor else None,
                            tie_sample_dt_s=ties.dt if ties else None, tie_resolved=ties.resolved if ties else None)
    on_grid = [None if sampled is None or t_out is None else sampled.at(r.t) for sampled in (floor, ties)]
    return result, Histories(r, *on_grid)


def simulate_building(building, record, t_end=None, rtol=1e-8, output_interval=None, solver=None,
                      check_sensitivity=False, filter_floor=True, executor=None, tie_forces=False):
    """The response of every storey of a description.Building under a Record (solver,
    check_sensitivity, filter_floor, executor, tie_forces: as respond's)."""
    t_out = None
    if output_interval:
        end = float(record.t[-1]) if t_end is None else float(t_end)
        t_out = np.linspace(float(record.t[0]), end, int(round((end - record.t[0]) / output_interval)) + 1)
    params = [building.wall_parameters(i) for i in range(len(building.storeys))]
    return respond(building_spec(building), params, record, t_end=t_end, rtol=rtol, t_out=t_out, solver=solver,
                   check_sensitivity=check_sensitivity, filter_floor=filter_floor, executor=executor,
                   tie_forces=tie_forces)
