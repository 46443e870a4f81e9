"""The FMU built with AddressSanitizer + UndefinedBehaviorSanitizer (build-asan/RockingWall.fmu),
simulated through fmpy in a child Python with the ASan runtime preloaded: Model-Exchange runs
with input, events and collapse, a Co-Simulation run, and calls fmpy makes with bad values, must end with no sanitizer report.

Runs when RW_ASAN_BUILD_DIR names the sanitizer build (scripts/run_tests.sh sets it after
building build-asan); the plain pytest run skips it. Leak detection is off because CPython itself
leaks at exit; UBSan halts on the first error."""
import os
import pathlib
import subprocess
import sys

import pytest

ASAN_DIR = os.environ.get("RW_ASAN_BUILD_DIR")
REPO = pathlib.Path(__file__).resolve().parents[2]

CHILD = r"""
import ctypes
import sys
import fmpy, fmpy.fmi2, fmpy.simulation
# fmpy hands the FMU glibc's calloc/free looked up in libc.so.6 itself, which bypasses ASan's
# allocator: the FMU's instance memory would be invisible to it. Take them from the global scope
# instead, where the preloaded ASan runtime comes first.
g = ctypes.CDLL(None)
g.calloc.argtypes, g.calloc.restype = [ctypes.c_size_t, ctypes.c_size_t], ctypes.c_void_p
g.free.argtypes, g.free.restype = [ctypes.c_void_p], None
for mod in (fmpy, fmpy.fmi2, fmpy.simulation):
    mod.calloc, mod.free = g.calloc, g.free
fmpy.fmi2.defaultCallbacks.allocateMemory = fmpy.fmi2.fmi2CallbackAllocateMemoryTYPE(g.calloc)
fmpy.fmi2.defaultCallbacks.freeMemory = fmpy.fmi2.fmi2CallbackFreeMemoryTYPE(g.free)
import numpy as np
from rockingwall import fmu as rw_fmu
from rwref import inputs
fmu = {fmu!r}
sig = inputs.sampled(inputs.gaussian(0.04, 1.0), 4.0, 0.002)
for model, law in [("flexibleTop", "semiRigidHinge"), ("flexibleTop", "rigid"), ("parapet", "rigid"),
                   ("simplySupported", "semiRigidHinge")]:
    r = rw_fmu.simulate(fmu, 4.0, sig.t, sig.a, rtol=1e-6, support=model, hinge_law=law, Kd=5e4)
    assert np.all(np.isfinite(r.s1)) and r.peak_s1 > 0, (model, law)
    print("RUN", model, law, r.peak_s1, r.impacts, r.collapsed)
# Co-Simulation: CVODE inside the FMU, events located inside the steps
r = rw_fmu.simulate(fmu, 4.0, sig.t, sig.a, rtol=1e-6, output_interval=5e-3, fmi_type="CoSimulation", Kd=5e4)
assert np.all(np.isfinite(r.s1)) and r.peak_s1 > 0
print("RUN CoSimulation", r.peak_s1, r.impacts)
for bad in [dict(h=-1.0), dict(er=2.0), dict(b=3.0)]:   # rejected by the FMU: fmpy raises
    try:
        rw_fmu.simulate(fmu, 1.0, sig.t, sig.a, **bad)
    except Exception as exc:
        print("REJECTED", bad, type(exc).__name__)
    else:
        raise SystemExit(f"bad parameters accepted: {{bad}}")
print("DONE")
"""


def asan_runtime():
    lib = subprocess.run(["gcc", "-print-file-name=libasan.so"], capture_output=True, text=True).stdout.strip()
    return lib if os.path.isabs(lib) and os.path.exists(lib) else None


def run_child(fmu):
    env = dict(os.environ, LD_PRELOAD=asan_runtime(), ASAN_OPTIONS="detect_leaks=0:abort_on_error=0",
               UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1")
    code = CHILD.format(scripts=str(REPO / "scripts"), reference=str(REPO / "reference"), fmu=str(fmu))
    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, timeout=600)


@pytest.mark.skipif(not ASAN_DIR, reason="set RW_ASAN_BUILD_DIR to the sanitizer build (scripts/run_tests.sh does)")
def test_fmpy_simulation_of_the_asan_fmu_is_clean():
    fmu = pathlib.Path(ASAN_DIR) / "RockingWall.fmu"
    assert fmu.exists(), f"{fmu} is missing: build it with -DRW_SANITIZE=ON"
    assert asan_runtime(), "libasan.so not found (gcc -print-file-name=libasan.so)"
    proc = run_child(fmu)
    print(proc.stdout)
    for report in ("AddressSanitizer", "runtime error:", "LeakSanitizer"):
        assert report not in proc.stderr, proc.stderr[-4000:]
    assert proc.returncode == 0, proc.stderr[-4000:]
    assert proc.stdout.count("RUN ") == 5 and proc.stdout.count("REJECTED") == 3 and "DONE" in proc.stdout


CHILD_BUILDING_WITH_WALLS = CHILD.split("import numpy as np")[0] + r"""
import numpy as np
from fmpy import simulate_fmu
t = np.arange(0.0, 3.0, 0.002)
ag = 3.0 * np.sin(6.0 * t) * (t < 1.5)
sig = np.array(list(zip(t, ag)), dtype=[("time", float), ("ag", float)])
start = dict(nStoreys=2, W_1=25200.0, b_1=0.35, h_1=4.0, psi_1=0.254, W_2=14904.0, b_2=0.23, h_2=3.6, psi_2=0.2013,
             md_1=600.0, kd_1=6e4, md_2=200.0, kd_2=2e4)
for fmi_type in ("ModelExchange", "CoSimulation"):
    r = simulate_fmu({fmu!r}, fmi_type=fmi_type, stop_time=3.0, output_interval=5e-3, start_values=start, input=sig,
                     output=["s1_1", "s1_2", "collapsed_2", "energy_residual"])
    assert np.all(np.isfinite(r["s1_2"])) and np.abs(r["s1_2"]).max() > 0
    print("RUN", fmi_type, np.abs(r["s1_2"]).max())
try:
    simulate_fmu({fmu!r}, stop_time=0.1, start_values=dict(h_1=0.1))
except Exception as exc:
    print("REJECTED", type(exc).__name__)
print("DONE")
"""


@pytest.mark.skipif(not ASAN_DIR, reason="set RW_ASAN_BUILD_DIR to the sanitizer build (scripts/run_tests.sh does)")
@pytest.mark.parametrize("folder", ["", "fmi3"])
def test_fmpy_simulation_of_the_asan_building_with_walls_is_clean(folder):
    fmu = pathlib.Path(ASAN_DIR) / folder / "BuildingWithWalls.fmu"
    assert fmu.exists(), f"{fmu} is missing: build it with -DRW_SANITIZE=ON"
    env = dict(os.environ, LD_PRELOAD=asan_runtime(), ASAN_OPTIONS="detect_leaks=0:abort_on_error=0",
               UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1")
    proc = subprocess.run([sys.executable, "-c", CHILD_BUILDING_WITH_WALLS.format(fmu=str(fmu))], capture_output=True,
                          text=True, env=env, timeout=600)
    print(proc.stdout)
    for report in ("AddressSanitizer", "runtime error:", "LeakSanitizer"):
        assert report not in proc.stderr, proc.stderr[-4000:]
    assert proc.returncode == 0, proc.stderr[-4000:]
    assert proc.stdout.count("RUN ") == 2 and "REJECTED" in proc.stdout and "DONE" in proc.stdout
