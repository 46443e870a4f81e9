"""Sweeps of a building (a building file, docs/your-building.md): one run per storey, record and
intensity, the storey's wall as a row like a wall sweep's (its wall named '<building>: storey i',
model 'building'). The building file's text travels with each run (in its `sets`, so it is part of
the run's key: an edited file makes its rows stale on resume) and the whole building is solved in
one integration on the worker; the storeys of one record and intensity share that solution."""
import functools
import itertools
import math
import warnings

import numpy as np

from .. import scenes
from ..building import building_file
from ..wall import PlausibilityWarning
from .rows import BUILDING_MODEL as MODEL
from .run_spec import RunSpec

# What a row holds, part of each run's key: rows of an earlier format are computed again on resume.
# 2: peak_F_top left empty (1 wrote 0 there, which reads as a tie that carries nothing).
ROW_FORMAT = "2"


def _fmt(x):
    return f"{x:.6g}"


def _quiet(read, *args):
    """read(*args) without the building file's unit-slip warnings: expand() gave them once, where
    the sweep is planned."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", PlausibilityWarning)
        return read(*args)


def read_text(path):
    """The building file's text (its content is what a run depends on), checked by reading it."""
    building = building_file.read(path)
    with open(path, encoding="utf-8-sig") as fh:
        return building, fh.read()


def expand(grid, suite):
    """The RunSpecs of the building of grid['building'] over a record suite and the intensities."""
    building, text = read_text(grid["building"])
    specs = []
    for rec in suite:  # the storeys of one record and intensity side by side: one building solution
        if grid["pga_g"]:
            pairs, tag = [(p / rec.pga_g if rec.pga_g > 0 else math.nan, float(p)) for p in grid["pga_g"]], "pga"
        else:
            pairs, tag = [(float(s), float(s) * rec.pga_g) for s in grid["scales"]], "x"
        walled = [(i + 1, building.storeys[i]) for i in building.walled()]  # a storey without a wall: no row
        for (scale, pga), (i, storey) in itertools.product(pairs, walled):
            level = pga if tag == "pga" else scale
            run_id = f"b{building.name}|storey{i}|{rec.name}|{tag}{_fmt(level)}|tail{_fmt(grid['tail'])}"
            sets = (("building", text), ("storey", str(i)), ("row_format", ROW_FORMAT))
            specs.append(RunSpec(run_id, f"{building.name}: storey {i}", MODEL, storey.wall.hinge_law,
                                 storey.diaphragm.stiffness / 1e3, rec.name, rec.path, rec.pga_g, scale, pga,
                                 rec.duration + float(grid["tail"]), sets, rec.error, rec.sha256))
    return specs


def describe(grid, suite, specs):
    building, _ = _quiet(read_text, grid["building"])
    levels = f"target PGA [g] {grid['pga_g']}" if grid["pga_g"] else f"scale factors {grid['scales']}"
    return "\n".join([building.describe(), scenes.building(building).text(),
                      f"records: {len(suite)} from '{grid['suite']}'", levels,
                      f"{len(specs)} runs ({len(building.walled())} walls per record and intensity, "
                      "one building solution each)"])


@functools.lru_cache(maxsize=8)
def _solve(text, record_sha, scale, stop_time, t_bytes, ag_bytes):
    """The building's response under the scaled record, kept for the other storeys of the run."""
    from ..building import monolithic
    from ..records import Record
    building = _quiet(building_file.parse, text, "building file")
    t, ag = np.frombuffer(t_bytes), np.frombuffer(ag_bytes)
    result, _ = monolithic.simulate_building(building, Record(record_sha, t, ag * scale), t_end=stop_time,
                                             filter_floor=False)
    return result


def storey_result(spec, record):
    """The StoreyResult of the spec's storey under `record` = (t, ag as given)."""
    params = dict(spec["sets"])
    t, ag = (np.ascontiguousarray(a, dtype=np.float64) for a in record)
    result = _solve(params["building"], spec["record_sha256"], float(spec["scale"]), float(spec["stop_time"]),
                    t.tobytes(), ag.tobytes())
    return result.storeys[int(params["storey"]) - 1], result
