"""Run the unfinished runs of a plan on Dask (or in this process) and append each row to the
results file as it arrives."""
import dataclasses
import time

import cloudpickle
from tqdm import tqdm

from . import runner
from .store import ResultsFile

# Workers get the run function by value, so a Dask cluster started elsewhere (--scheduler) needs
# neither this repository nor its scripts on its Python path: only fmi2sim, the FMU and the
# records at the same paths.
cloudpickle.register_pickle_by_value(runner)


@dataclasses.dataclass
class Outcome:
    planned: int
    skipped: int       # already in the results file
    ran: int
    errors: int
    seconds: float     # from the first submission to the last row written
    startup_s: float   # starting the LocalCluster / connecting to the scheduler

    @property
    def runs_per_s(self):
        return self.ran / self.seconds if self.seconds > 0 else float("nan")


def _batches(items, size):
    return [items[i:i + size] for i in range(0, len(items), size)]


def execute(specs, results_path, fmi2sim, fmu, rtol, scheduler=None, workers=2, batch=1, progress=True):
    """scheduler: None -> a LocalCluster of `workers` single-threaded worker processes;
    'synchronous' -> one after another in this process; else the address of a running Dask
    scheduler, used as it is."""
    store = ResultsFile(results_path)
    done = store.finished()
    todo = [dataclasses.asdict(s) for s in specs if s.run_id not in done]
    errors = 0
    bar = tqdm(total=len(todo), desc="runs", unit="run", disable=not progress, smoothing=0.05)
    client = cluster = None
    t_start = time.perf_counter()
    try:
        if scheduler == "synchronous":
            startup = 0.0
            t0 = time.perf_counter()
            stream = ([runner.run(s, fmi2sim, fmu, rtol)] for s in todo)
        else:
            from dask.distributed import Client, LocalCluster, as_completed
            if todo:
                if scheduler:
                    client = Client(scheduler)
                else:
                    cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                                           dashboard_address=":0")  # any free port: never clash
                    client = Client(cluster)
            startup = time.perf_counter() - t_start
            t0 = time.perf_counter()
            futures = [client.submit(runner.run_batch, b, fmi2sim, fmu, rtol, pure=False)
                       for b in _batches(todo, max(1, batch))] if todo else []
            stream = (f.result() for f in as_completed(futures))
        for rows in stream:
            for row in rows:
                store.append(row)
                errors += row["status"] != "ok"
            bar.update(len(rows))
        seconds = time.perf_counter() - t0
    finally:
        bar.close()
        store.close()
        if client is not None:
            client.close()
        if cluster is not None:
            cluster.close()
    return Outcome(len(specs), len(specs) - len(todo), len(todo), errors, seconds, startup)
