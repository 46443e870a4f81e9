"""One run of a sweep on the exact engine, in the worker's own process (no subprocess): the
record's samples travel with the task, so workers need the installed `rockingwall` package and
nothing on a shared file system. Rows have the columns of rockingwall.sweep.rows."""
import time

import numpy as np

from . import building_runs
from .rows import ERROR, OK, make_row, refusal


def _params(spec):
    return {name: (int(value) if name in ("support", "hingeLaw") else float(value)) for name, value in spec["sets"]}


def run(spec, record):
    """Simulate one RunSpec (a dict) on `record` = (t, ag [m/s^2] as given); always returns a row."""
    from rockingwall import engine  # imported on the worker: the installed package
    t0, c0 = time.perf_counter(), time.process_time()
    refused = refusal(spec)
    if refused:
        return refused
    t, ag = record
    if spec["model"] == building_runs.MODEL:
        return _building_row(spec, record, t0, c0)
    try:
        r = engine.run(t, np.asarray(ag) * float(spec["scale"]), t_end=float(spec["stop_time"]), **_params(spec))
    except (engine.EngineError, ValueError, KeyError) as exc:
        return make_row(spec, ERROR, str(exc))
    params = _params(spec)
    peak_f_top = engine.peak_F_top(params, r.peak_s2) if "Kd" in params else 0.0  # u_top = 0 in a sweep
    return make_row(spec, OK, peak_s1=r.peak_s1, peak_s2=r.peak_s2, peak_F_top=peak_f_top, collapsed=bool(r.collapsed), impacts=int(r.impacts),
                end_time=r.t_reached, steps=r.steps, cpu_s=time.process_time() - c0,
                elapsed_s=time.perf_counter() - t0)


def _building_row(spec, record, t0, c0):
    """The row of one storey of a building run (building_runs): its wall's peaks and collapse. Its
    peak_F_top stays empty: the tie's force, filtered as an engineer reads it, takes one more run
    (`rockingwall building`, `assess --building`), and a 0 would read as a tie that carries nothing."""
    from rockingwall.building.trusted_run import BuildingError
    from rockingwall.scene_engine import SceneError
    try:
        s, result = building_runs.storey_result(spec, record)
    except (BuildingError, SceneError, ValueError) as exc:
        return make_row(spec, ERROR, str(exc))
    return make_row(spec, OK, peak_s1=s.peak_s1_m, peak_s2=s.peak_s2_m, peak_F_top="", collapsed=s.collapsed,
                    impacts=s.impacts, end_time=float(spec["stop_time"]), steps=result.steps,
                    cpu_s=time.process_time() - c0, elapsed_s=time.perf_counter() - t0)


def run_batch(specs, records):
    """Several runs in one task; records: {record_sha256: (t, ag)} for the records they use."""
    return [run(s, records.get(s["record_sha256"])) for s in specs]


def load_records(specs):
    """{record_sha256: (t, ag)} read once per record on the planning side (the one AT2 reader);
    a record that cannot be read turns its runs into 'error' rows with the file, line and problem."""
    from rockingwall import records as rec
    out, failed = {}, {}
    for s in specs:
        sha, path = s["record_sha256"], s["record_path"]
        if s["error"] or sha in out:
            continue
        if path in failed:
            s["error"] = failed[path]
            continue
        try:
            r = rec.read_at2(path)
            out[sha] = (r.t, r.ag)
        except rec.RecordError as exc:
            failed[path] = s["error"] = str(exc)
    return out
