"""The assessment of a building's walls (`rockingwall assess --building FILE`): every record at
every intensity run through the scene solver once for the whole building, a row per storey's wall
with its limit states (each storey's own Delta_u), its ensemble (every storey's wall, diaphragm
and tie perturbed, rockingwall.ensemble) and a fragility per storey."""
import numpy as np

from . import ensemble as ens
from . import limits, robustness
from .assessment import case_row, collect, run_parallel
from .building import monolithic
from .wall import Wall

STOREY_COLUMN = "storey"


def storey_walls(building):
    """A Wall per storey (its parameters as the scene runs it, tied to its diaphragm; None for a
    storey without one)."""
    return [Wall.make(warn=False, **p) if (p := building.wall_parameters(i)) else None
            for i in range(len(building.storeys))]


def storey_states(building, limit_texts):
    """The limit states of every storey's wall (thresholds in Delta_u or b are each wall's own;
    None for a storey without one)."""
    return [limits.parse_all(limit_texts, wall) if wall else None for wall in storey_walls(building)]


def case_runs(states, ensemble=None):
    """(fewest, most) scene runs of one case of run_cases: its nominal run (and its tie-force run,
    where a limit state asks for one) and its members'."""
    tie_forces = asks_tie_forces(states)
    return ens.with_members(monolithic.respond_runs(**_nominal_checks(tie_forces)), ensemble, tie_forces)


def _nominal_checks(tie_forces):
    return dict(filter_floor=False, tie_forces=tie_forces)


def asks_tie_forces(states):
    """Whether any storey's limit states are on F_top (one more run each, where asked for)."""
    return any(limits.ask_tie_force(st) for st in states if st)


def run_cases(building, lvs, states, ensemble=None):
    """One row per record at an intensity level (lvs: assessment.levels()) and storey, and the
    ensemble outcomes of each row."""
    walls = storey_walls(building)
    tie_forces = asks_tie_forces(states)

    def one(lv):
        result, _ = monolithic.simulate_building(building, lv.record, **_nominal_checks(tie_forces))
        members = (ens.building_members(building, lv.record, ensemble, float(lv.record.t[-1]), tie_forces)
                   if ensemble is not None else [None] * len(walls))
        rows = []
        for s, wall, st, m in zip(result.storeys, walls, states, members):
            if wall is None:  # a storey without a wall has no limit state to reach
                continue
            peaks = dict(peak_s1=s.peak_s1_m, peak_s2=s.peak_s2_m, peak_F_top=s.tie_force_or_nan, collapsed=s.collapsed)
            summary = ens.summarize(m, st, robustness.nominal_outcome(st, peaks)) if m is not None else None
            row = case_row(lv, {STOREY_COLUMN: s.storey}, "building", peaks, s.t_collapse_s or np.nan, s.impacts,
                           wall.delta_u, st, summary)
            rows.append((row, ens.reached(m, st) if m is not None else None))
        return rows

    return collect(run_parallel(one, lvs))
