"""The code checks beside a building's runs (`rockingwall assess --building`, `rockingwall building
--code`): NZSEE C8, NTC 2018 and ASCE 41-17 on every storey's wall, each where it stands in the
building, as columns of that storey's cases or lines after the building's table.

Where a wall is: it spans from the floor below to the diaphragm above, so C8's h_i and the
Circolare's z are its mid-height (the average of those two floors' heights, as an assessor takes
h_i = 5.8 m for a 3.6-m wall on a 4-m ground storey); h_n and H are the roof's height (the top of
the last storey) unless --building-height says otherwise; ASCE 41's storey follows from the
wall's place (first, top, other, or the wall of a one-storey building). Each check takes the wall
the scene runs (its overburden, and the walls above as weight only), and assumes, as the codes do,
stiff diaphragms: the time histories beside it have the building's own."""
import math

import pandas as pd

from . import assessment_codes
from .assessment_building import STOREY_COLUMN, storey_walls

# options that place one wall: in a building each storey's wall has its own place
PLACE_OPTIONS = ("--attachment-height", "--asce-storey")


def wall_places(building, building_height=None):
    """[(h_i, h_n, ASCE 41 storey)] per storey [m]: h_i the wall's mid-height above the ground, h_n
    the roof's height or building_height (at least the roof's)."""
    bases, top = [], 0.0
    for s in building.storeys:
        bases.append(top)
        top += s.height
    h_n = top if building_height is None else building_height
    if h_n < top - 1e-9:
        raise ValueError(f"--building-height = {h_n:g} m: below the top of the building's walls ({top:g} m)")
    n = len(building.storeys)
    places = []
    for i, (base, s) in enumerate(zip(bases, building.storeys)):
        storey = ("one_storey_building" if n == 1 else "first_storey" if i == 0 else
                  "top_storey" if i == n - 1 else "other_storey")
        places.append((base + s.height / 2.0, h_n, storey))
    return places


def checks_by_storey(building, codes, values, pgas=(), given=()):
    """[{hazard key: CodeChecks}] per storey (assessment_codes.checks_by_hazard on each storey's
    wall at its place; None for a storey without a wall); values: assessment_codes.option_values;
    given: the options the user gave."""
    placed = [flag for flag in PLACE_OPTIONS if flag in given]
    if placed:
        raise ValueError(f"{placed[0]}: with --building each storey's wall takes its own place from the "
                         "building file (its mid-height, and its storey for ASCE 41)")
    out = []
    for wall, (h_i, h_n, storey) in zip(storey_walls(building), wall_places(building, values["building_height"])):
        at = dict(values, attachment_height=h_i, building_height=h_n, asce_storey=storey)
        out.append(assessment_codes.checks_by_hazard(wall, codes, at, pgas, given) if wall else None)
    return out


def add_to_cases(cases, per_storey):
    """cases (a row per record, level and storey) with each storey's code columns and flags."""
    parts = [assessment_codes.add_to_cases(cases[cases[STOREY_COLUMN] == i], by_pga)
             for i, by_pga in enumerate(per_storey, 1) if by_pga is not None]
    return pd.concat(parts).loc[cases.index]


def head_lines(per_storey):
    """The report's lines on the codes, storey by storey."""
    lines = []
    for i, by_pga in enumerate(per_storey, 1):
        if by_pga is None:
            continue
        lines.append(f"codes on storey {i}'s wall:")
        for key, checks in by_pga.items():
            if key is not None:
                lines.append(f"  code hazard at PGA {key:g} g (each case's):")
            lines += ["  " + line for line in assessment_codes.checks_lines(checks)]
    lines.append("each wall at its mid-height in the building; the codes assume stiff diaphragms, the time histories "
                 f"have the building's own; {assessment_codes.UNCONSERVATIVE_MEANING}")
    return lines


def to_json(per_storey):
    """The checks as plain data: one entry per storey and hazard, with its storey (1 = ground)."""
    return [dict(storey=i, **assessment_codes.checks_json(checks))
            for i, by_pga in enumerate(per_storey, 1) if by_pga is not None for checks in by_pga.values()]


def unconservative(per_storey, results, pgas):
    """[(record, storey, [code labels], collapsed)] where a code passes a wall that the building's
    run (monolithic.BuildingResult, one per record at pgas [g]) collapses or takes past the code's
    usable displacement."""
    out = []
    for result, pga in zip(results, pgas):
        for s, by_pga in zip(result.storeys, per_storey):
            if by_pga is None:
                continue
            flags = assessment_codes.unconservative(assessment_codes.checks_at(by_pga, pga),
                                                    math.nan if s.collapsed else s.peak_s1_m, s.collapsed)
            codes = [assessment_codes.LABELS[c] for c, flagged in flags.items() if flagged]
            if codes:
                out.append((result.record, s.storey, codes, bool(s.collapsed)))
    return out


def unconservative_lines(per_storey, results, pgas):
    """One line per storey and record where a code is unconservative, or one saying none is."""
    rows = unconservative(per_storey, results, pgas)
    if not rows:
        return ["UNCONSERVATIVE: none (no code passes a wall that its run collapses or takes past the code's "
                "usable displacement)"]
    return [f"UNCONSERVATIVE: {record}, storey {storey}: passed by {', '.join(codes)}; the run "
            + ("collapses it" if collapsed else "takes it past the code's usable displacement")
            for record, storey, codes, collapsed in rows]


def unconservative_json(per_storey, results, pgas):
    """unconservative() as plain data: [{"record", "storey", "codes", "collapsed"}]."""
    return [{"record": record, "storey": storey, "codes": codes, "collapsed": collapsed}
            for record, storey, codes, collapsed in unconservative(per_storey, results, pgas)]
