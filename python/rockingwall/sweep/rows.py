"""The rows of a sweep's results file: its columns, the statuses of a run and how a row is made.

Statuses: 'ok'; 'error' when the engine, fmi2sim or the record refused the run, which the same
inputs would do again; 'killed' (a signal: the OOM killer, a dead Dask worker) and 'timeout',
which say nothing about the inputs and are retried when the sweep is resumed."""
import math

# The columns of the results file, in order. Peaks are max |value| over the run. The last columns
# say what the row was computed from (rockingwall.sweep.provenance).
COLUMNS = ["run_id", "wall", "model", "hinge_law", "kd_kN", "record", "record_pga_g", "scale", "pga_g",
           "status", "message", "peak_s1", "peak_s2", "peak_F_top", "collapsed", "impacts", "end_time",
           "steps", "cpu_s", "elapsed_s",
           "key", "record_sha256", "engine", "fmi2sim_sha256", "fmu_guid", "fmu_sha256", "rtol"]
PROVENANCE = COLUMNS[COLUMNS.index("key"):]

OK, ERROR, KILLED, TIMEOUT = "ok", "error", "killed", "timeout"
STATUSES = (OK, ERROR, KILLED, TIMEOUT)
RETRIED = (KILLED, TIMEOUT)   # not finished: run again on resume
BUILDING_MODEL = "building"   # the model of a building sweep's rows, whose peak_F_top stays empty


def make_row(spec, status, message="", **values):
    """The row of one run (a RunSpec as a dict) with its status, one-line message and values."""
    row = {c: "" for c in COLUMNS}
    row.update(run_id=spec["run_id"], wall=spec["wall"], model=spec["model"], hinge_law=spec["hinge_law"],
               kd_kN=spec["kd_kN"], record=spec["record"], record_pga_g=spec["record_pga_g"], scale=spec["scale"],
               pga_g=spec["pga_g"], status=status, message=" ".join(message.split()))  # one line in the CSV
    row.update({c: spec.get(c, "") for c in PROVENANCE})
    row.update(values)
    return row


def killed_row(spec, message):
    """The row of a run that never returned (its Dask worker died)."""
    return make_row(spec, KILLED, message)


def refusal(spec):
    """The 'error' row of a run that cannot start (its record unreadable, its scale factor not a
    positive number), else None."""
    if spec["error"]:
        return make_row(spec, ERROR, spec["error"])
    if not (spec["scale"] > 0 and math.isfinite(spec["scale"])):
        return make_row(spec, ERROR, f"scale factor {spec['scale']} (record PGA {spec['record_pga_g']} g)")
    return None
