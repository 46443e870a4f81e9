"""The engine library as a process loads it. It must start no thread of its own: the exact scene
engine's LAPACK is the reference one, where a threaded BLAS (OpenBLAS, which Debian's alternatives
prefer wherever it is installed) starts its pool as it loads, and the pool's spare thread spins
while a run works: a run's CPU time about doubled, and a benchmark's ratios with it."""
import os
import subprocess
import sys

from rockingwall import paths

COUNT_THREADS = ("import ctypes, os, sys; before = len(os.listdir('/proc/self/task')); ctypes.CDLL(sys.argv[1]); "
                 "print(before, len(os.listdir('/proc/self/task')))")
BLAS_SETTINGS = ("OPENBLAS_NUM_THREADS", "GOTO_NUM_THREADS", "OMP_NUM_THREADS")


def threads_started_by(library, python=sys.executable):
    """How many threads a fresh Python process has more after loading `library` (no BLAS settings in
    its environment)"""
    env = {k: v for k, v in os.environ.items() if k not in BLAS_SETTINGS}
    out = subprocess.run([str(python), "-c", COUNT_THREADS, str(library)], capture_output=True, text=True,
                         env=env, check=True, timeout=60).stdout.split()
    before, after = map(int, out)
    return after - before


def test_loading_the_engine_library_starts_no_thread():
    assert threads_started_by(paths.engine_library()) == 0
