"""The libcosim master (libcosimpy) over the wall and the Diaphragm FMU: the same fixed-step
Jacobi scheme as the package's own master, the ground motion held over each step, libcosim
connecting u -> u_top and F_top -> F_top. libcosim aborts the process on some FMU errors: run it
in a child process (rockingwall.coupling.isolation)."""
import pathlib

import numpy as np

from .slaves import CouplingError, value_references
from .wall_diaphragm import DIA_OUT, WALL_OUT, assemble, check_options, wall_start_values


def run_libcosim(wall_fmu, dia_fmu, t_in, ag_in, t_end, H, wall=None, dia=None):
    """The libcosim master (libcosimpy) with the same Jacobi scheme: call it in a subprocess
    (rockingwall.coupling.isolation): libcosim aborts the process on some FMU errors."""
    from fmpy import read_model_description
    from libcosimpy.CosimExecution import CosimExecution
    from libcosimpy.CosimManipulator import CosimManipulator
    from libcosimpy.CosimObserver import CosimObserver
    from libcosimpy.CosimLogging import CosimLogLevel, log_output_level
    from libcosimpy.CosimSlave import CosimLocalSlave

    check_options(t_end, H, 1e-6)
    log_output_level(CosimLogLevel.WARNING)  # its trace of every FMU event would fill the parent's pipe
    real, integer = wall or wall_start_values()
    wv, dv = value_references(read_model_description(str(wall_fmu))), value_references(read_model_description(str(dia_fmu)))
    ex = CosimExecution.from_step_size(step_size=int(round(H * 1e9)))  # nanoseconds
    iw = ex.add_local_slave(CosimLocalSlave(fmu_path=str(pathlib.Path(wall_fmu).resolve()), instance_name="wall"))
    idia = ex.add_local_slave(CosimLocalSlave(fmu_path=str(pathlib.Path(dia_fmu).resolve()), instance_name="diaphragm"))
    for k, v in real.items():
        ex.real_initial_value(iw, wv[k], v)
    for k, v in integer.items():
        ex.integer_initial_value(iw, wv[k], v)
    for k, v in (dia or {}).items():
        ex.real_initial_value(idia, dv[k], v)
    ex.connect_real_variables(idia, dv["u"], iw, wv["u_top"])
    ex.connect_real_variables(iw, wv["F_top"], idia, dv["F_top"])
    override = CosimManipulator.create_override()
    ex.add_manipulator(manipulator=override)
    observer = CosimObserver.create_last_value()
    ex.add_observer(observer=observer)
    # libcosim initialises the slaves inside its first step and its observer has values only
    # after a step: row 0 is the state at rest both slaves start from (every output 0)
    n = int(round(t_end / H))
    times, wall_rows, dia_rows = [0.0], [[0.0] * len(WALL_OUT)], [[0.0] * len(DIA_OUT)]
    collapsed_at = None
    for k in range(n):
        ag = float(np.interp(k * H, t_in, ag_in, right=0.0))
        override.slave_real_values(iw, [wv["ag"]], [ag])  # held over the step, as in run_fmpy
        override.slave_real_values(idia, [dv["ag"]], [ag])
        if not ex.step():
            message = _libcosim_error()
            # libcosim reports a slave's fmi2Discard as "<instance>: Step not complete" (its
            # observer keeps the values of the last good step, so the wall's `collapsed` output
            # cannot be read there): from the wall it is the collapse that ends its run, as in
            # run_fmpy; anything else is a failure
            if "wall: Step not complete" in message:
                collapsed_at = k * H
                break
            raise CouplingError(f"libcosim master: the step from t = {k * H:.6g} s failed before t_end = "
                                f"{t_end:g} s: {message}")
        times.append((k + 1) * H)
        wall_rows.append(observer.last_real_values(iw, [wv[x] for x in WALL_OUT]))
        dia_rows.append(observer.last_real_values(idia, [dv[x] for x in DIA_OUT]))
    if collapsed_at is None and abs(times[-1] - n * H) > 1e-9 * max(1.0, t_end):
        raise CouplingError(f"libcosim master: the run ended at t = {times[-1]:.6g} s, not at t_end = {t_end:g} s")
    r = assemble(times, wall_rows, dia_rows)
    r["collapsed_at"] = collapsed_at
    return r


def _libcosim_error():
    from libcosimpy._internal import get_last_error_message
    return get_last_error_message() or "no message from libcosim"
