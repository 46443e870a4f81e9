"""Where a building's runs under one record go. The main run, the sensitivity check's two scaled
runs and the floors' and ties' sampled runs need nothing of each other, so `rockingwall building`
gives them to threads: the engines release the GIL, and each run takes a core of its own.
Elsewhere (a Dask worker, which already has its core) they run one after another in the caller's
thread (InOrder), and a run that fails stops the ones after it."""
import concurrent.futures
import contextlib
import functools
import os

# threads for a building's runs: a core each, at most 4 (as assess's threads for its cases)
MAX_THREADS = 4


class _Deferred:
    """A task run in the caller's thread when its result is first asked for (an Executor's future)."""

    def __init__(self, task):
        self._task = task
        self._outcome = None

    def result(self):
        if self._outcome is None:
            try:
                self._outcome = (self._task(), None)
            except Exception as error:   # kept, so that asking again raises it again, not a rerun
                self._outcome = (None, error)
        value, error = self._outcome
        if error is not None:
            raise error
        return value


class InOrder:
    """An executor's submit without threads: each task runs when its result is asked for."""

    def submit(self, fn, *args, **kwargs):
        return _Deferred(functools.partial(fn, *args, **kwargs))


@contextlib.contextmanager
def threads():
    """A thread pool with a thread per core (at most MAX_THREADS). On the way out after an error,
    the runs not yet started are dropped and those under way finish (a thread cannot be stopped)."""
    pool = concurrent.futures.ThreadPoolExecutor(min(MAX_THREADS, os.cpu_count() or 1))
    try:
        yield pool
    finally:
        pool.shutdown(wait=True, cancel_futures=True)
