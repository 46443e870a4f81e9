"""The FMI 3.0 RockingWall FMU built with AddressSanitizer + UndefinedBehaviorSanitizer
(build-asan/fmi3/RockingWall.fmu), simulated through fmpy in a child Python with the ASan runtime
preloaded: the same runs as test_fmu_asan.py's for the FMI 2.0 FMU (Model Exchange with input,
events and collapse, Co-Simulation, parameters the FMU rejects) must end with no sanitizer report.

Runs when RW_ASAN_BUILD_DIR names the sanitizer build (scripts/run_tests.sh sets it after
building build-asan); the plain pytest run skips it."""
import os
import pathlib

import pytest

from test_fmu_asan import asan_runtime, run_child

ASAN_DIR = os.environ.get("RW_ASAN_BUILD_DIR")


@pytest.mark.skipif(not ASAN_DIR, reason="set RW_ASAN_BUILD_DIR to the sanitizer build (scripts/run_tests.sh does)")
def test_fmpy_simulation_of_the_asan_fmi3_fmu_is_clean():
    fmu = pathlib.Path(ASAN_DIR) / "fmi3" / "RockingWall.fmu"
    assert fmu.exists(), f"{fmu} is missing: build it with -DRW_SANITIZE=ON"
    assert asan_runtime(), "libasan.so not found (gcc -print-file-name=libasan.so)"
    proc = run_child(fmu)
    print(proc.stdout)
    for report in ("AddressSanitizer", "runtime error:", "LeakSanitizer"):
        assert report not in proc.stderr, proc.stderr[-4000:]
    assert proc.returncode == 0, proc.stderr[-4000:]
    assert proc.stdout.count("RUN ") == 5 and proc.stdout.count("REJECTED") == 3 and "DONE" in proc.stdout
