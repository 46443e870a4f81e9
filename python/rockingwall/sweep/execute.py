"""Run the unfinished runs of a plan on Dask (or in this process) and append each row to the
results file as it arrives."""
import asyncio
import contextlib
import dataclasses
import shutil
import signal
import threading
import time

import cloudpickle
from tqdm import tqdm

from .. import scratch
from ..errors import RockingWallError
from . import engine_task, fmi2sim_task, orphans, provenance, rows
from .store import ResultsFile

# Workers get the fmi2sim run function and the rows it makes by value; they import the installed
# package, which the exact engine needs anyway (its records travel with the tasks; fmi2sim runs
# need fmi2sim, the FMU and the records at the same paths on every worker).
cloudpickle.register_pickle_by_value(fmi2sim_task)
cloudpickle.register_pickle_by_value(rows)


@dataclasses.dataclass
class Outcome:
    planned: int
    skipped: int       # already in the results file, computed from the same inputs
    ran: int
    errors: int        # rows with status 'error'
    unfinished: int    # killed or timed out: run again by the next resume
    seconds: float     # from the first submission to the last row written
    startup_s: float   # starting the LocalCluster / connecting to the scheduler
    resume: object = None  # store.Resume: what was reused, recomputed and set aside

    @property
    def runs_per_s(self):
        return self.ran / self.seconds if self.seconds > 0 else float("nan")


# Meaningful ranges of the execution options, checked before anything starts.
LIMITS = dict(workers=(1, 1024), batch=(1, 100_000))
TIMEOUT_RANGE = (1.0, 7 * 86400.0)


def check_options(workers, batch, timeout):
    """ValueError naming the option and its range (workers = 0 would wait forever for a worker)."""
    for name, value in (("workers", workers), ("batch", batch)):
        low, high = LIMITS[name]
        if isinstance(value, bool) or not isinstance(value, int) or not low <= value <= high:
            raise ValueError(f"--{name} {value!r} is outside [{low}, {high}]")
    if timeout is not None:
        low, high = TIMEOUT_RANGE
        if not low <= float(timeout) <= high:  # also refuses NaN
            raise ValueError(f"--timeout {timeout!r} is outside [{low:g}, {high:g}] s")


def describe(outcome, path):
    """Lines telling what a resume reused, ran again and set aside, and what is left to do."""
    r, lines = outcome.resume, []
    if r is not None and r.stale:
        why = "; ".join(f"{n} {reason}" for reason, n in r.stale.most_common())
        lines.append(f"{sum(r.stale.values())} rows of {path} not reused, computed from other inputs ({why}): run again")
    if r is not None and r.retried:
        lines.append(f"{r.retried} killed or timed-out rows of {path} run again")
    if r is not None and r.bad:
        lines.append(f"{r.bad} damaged lines of {path} set aside (named above); the runs of this plan among them run again")
    if r is not None and r.set_aside:
        lines.append(f"the rows not kept are in {r.set_aside}")
    if outcome.unfinished:
        lines.append(f"{outcome.unfinished} runs were killed or timed out (not finished): "
                     "run the same command again to retry them")
    return lines


def _batches(items, size):
    return [items[i:i + size] for i in range(0, len(items), size)]


def keyed(specs, fmi2sim, fmu, rtol, engine="fmi2sim"):
    """The specs as dicts with the columns that say what each row is computed from."""
    eng = provenance.engine(fmi2sim, fmu, rtol) if engine == "fmi2sim" else provenance.exact_engine()
    out = []
    for s in specs:
        d = dataclasses.asdict(s)
        d.update(eng)
        d["key"] = provenance.run_key(d, eng)
        out.append(d)
    return out


class Terminated(BaseException):
    """SIGTERM or SIGHUP: unwinds like Ctrl-C, so every `finally` (cluster, temporary folders,
    results file) runs."""


@contextlib.contextmanager
def _signals_unwind():
    if threading.current_thread() is not threading.main_thread():
        yield  # handlers can only be set from the main thread
        return

    def handler(signum, frame):
        raise Terminated(signal.Signals(signum).name)
    old = {s: signal.signal(s, handler) for s in (signal.SIGTERM, signal.SIGHUP)}
    try:
        yield
    finally:
        for s, h in old.items():
            signal.signal(s, h)


def _local_stream(todo, fmi2sim, fmu, rtol, tmp_root, timeout, recs):
    for s in todo:
        if recs is None:
            yield [fmi2sim_task.run(s, fmi2sim, fmu, rtol, tmp_root, timeout)]
        else:
            yield engine_task.run_batch([s], recs)


def _submit(client, batch, fmi2sim, fmu, rtol, tmp_root, timeout, recs):
    if recs is None:
        return client.submit(fmi2sim_task.run_batch, batch, fmi2sim, fmu, rtol, tmp_root, timeout, pure=False)
    used = {s["record_sha256"]: recs[s["record_sha256"]] for s in batch if s["record_sha256"] in recs}
    return client.submit(engine_task.run_batch, batch, used, pure=False)


def _dask_stream(client, todo, batch, fmi2sim, fmu, rtol, tmp_root, timeout, recs):
    """Rows as batches finish. A batch whose worker died (Dask gives up after its retries) becomes
    'killed' rows, which the next resume runs again, instead of ending the sweep."""
    from dask.distributed import as_completed
    futures = {_submit(client, b, fmi2sim, fmu, rtol, tmp_root, timeout, recs): b
               for b in _batches(todo, max(1, batch))}
    for f in as_completed(futures):
        try:
            yield f.result()
        except Exception as exc:  # KilledWorker, a worker lost with its task, ...
            yield [rows.killed_row(s, f"Dask task did not return: {type(exc).__name__}: {exc}") for s in futures[f]]


@contextlib.contextmanager
def _client(scheduler, workers, tmp_root):
    import dask
    from dask.distributed import Client, LocalCluster
    client = cluster = None
    try:
        try:
            if scheduler:
                client = Client(scheduler)
            else:
                # the cluster keeps its scratch space in the sweep's folder, removed with it
                with dask.config.set({"temporary-directory": tmp_root}):
                    cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                                           dashboard_address=":0", local_directory=tmp_root)  # any free port
                client = Client(cluster)
        except (RuntimeError, OSError, TimeoutError, asyncio.TimeoutError) as exc:  # e.g. "Nanny failed to start"
            where = f"the Dask scheduler at {scheduler}" if scheduler else f"a Dask LocalCluster of {workers} workers"
            raise ClusterError(f"could not start {where}: {type(exc).__name__}: {exc}; nothing was run: run the "
                               "command again") from None
        yield client
    finally:
        if client is not None:
            client.close()
        if cluster is not None:
            cluster.close()


class ClusterError(RockingWallError):
    """The Dask cluster could not be started or reached: nothing ran."""


def _rm_tree(path):
    # a run still being torn down may add a file while the tree is removed: try again once
    for _ in range(2):
        shutil.rmtree(path, ignore_errors=True)


def execute(specs, results_path, fmi2sim=None, fmu=None, rtol=None, scheduler=None, workers=2, batch=1, progress=True,
            timeout=None, engine="fmi2sim"):
    """engine: 'fmi2sim' (a subprocess per run, fmi2sim and the FMU at the same paths on every
    worker) or 'exact' (the exact engine in the worker's process; records travel with the tasks).
    scheduler: None -> a LocalCluster of `workers` single-threaded worker processes;
    'synchronous' -> one after another in this process; else the address of a running Dask
    scheduler, used as it is. Holds the results file's lock throughout."""
    check_options(workers if scheduler is None else 1, batch, timeout)
    planned = keyed(specs, fmi2sim, fmu, rtol, engine)
    with _signals_unwind(), ResultsFile(results_path) as store:
        resume = store.resume({d["run_id"]: {c: d.get(c, "") for c in rows.PROVENANCE} for d in planned})
        todo = [d for d in planned if d["run_id"] not in resume.done]
        counts = dict(errors=0, unfinished=0)
        startup = seconds = 0.0
        if todo:
            recs = engine_task.load_records(todo) if engine == "exact" else None
            startup, seconds = _run_all(store, todo, counts, fmi2sim, fmu, rtol, scheduler, workers, batch,
                                        progress, timeout, recs)
    return Outcome(len(specs), len(specs) - len(todo), len(todo), counts["errors"], counts["unfinished"],
                   seconds, startup, resume)


def _run_all(store, todo, counts, fmi2sim, fmu, rtol, scheduler, workers, batch, progress, timeout, recs):
    """Runs todo, appending rows; returns (start-up seconds, running seconds)."""
    tmp_root = scratch.make("rw_sweep_")  # every run's files, whatever ends the sweep
    bar = tqdm(total=len(todo), desc="runs", unit="run", disable=not progress, smoothing=0.05)
    t_start = time.perf_counter()
    try:
        with contextlib.ExitStack() as stack:
            if scheduler == "synchronous":
                startup, t0 = 0.0, time.perf_counter()
                stream = _local_stream(todo, fmi2sim, fmu, rtol, tmp_root, timeout, recs)
            else:
                client = stack.enter_context(_client(scheduler, workers, tmp_root))
                startup, t0 = time.perf_counter() - t_start, time.perf_counter()
                stream = _dask_stream(client, todo, batch, fmi2sim, fmu, rtol, tmp_root, timeout, recs)
            for batch_rows in stream:
                for row in batch_rows:
                    store.append(row)
                    counts["errors"] += row["status"] == rows.ERROR
                    counts["unfinished"] += row["status"] in rows.RETRIED
                bar.update(len(batch_rows))
            return startup, time.perf_counter() - t0
    finally:
        bar.close()
        orphans.stop_orphans(tmp_root)
        _rm_tree(tmp_root)
