"""Run the RockingWall FMU with fmpy: one place that maps the reference solver's parameter names
onto the FMU's variables, turns an acceleration signal into fmpy's input table and returns the
outputs as plain numpy arrays."""
import contextlib
from dataclasses import dataclass

import numpy as np
import fmpy.sundials
from fmpy import simulate_fmu


# Known fmpy problem (0.3.32, found here): CVodeSolver.f, the right-hand side CVODE calls, sets
# the time and the states but never applies the inputs; only the root function g does. So inside
# a step the FMU sees the input of the last root evaluation (a lag of up to one step), which for a
# rocking wall under an accelerogram changes peaks and can exhaust CVODE's steps (mxstep).
# fmpy_input_in_rhs() installs, for the duration of a `with` block, a right-hand side that applies
# the input first. simulate() uses it unless told not to (fmpy_input_fix=False); nothing is patched
# on import, and tests/python/test_fmpy_known_issues.py shows the difference, so it will tell us
# when fmpy is fixed.
_FMPY_RHS = fmpy.sundials.CVodeSolver.f


def _rhs_applying_input(self, t, y, ydot, user_data):
    self.input.apply(t)
    return _FMPY_RHS(self, t, y, ydot, user_data)


@contextlib.contextmanager
def fmpy_input_in_rhs(enabled=True):
    """Within the block, fmpy's CVode right-hand side applies the inputs (enabled) or is fmpy's own."""
    saved = fmpy.sundials.CVodeSolver.f
    fmpy.sundials.CVodeSolver.f = _rhs_applying_input if enabled else _FMPY_RHS
    try:
        yield
    finally:
        fmpy.sundials.CVodeSolver.f = saved


from .names import HINGE_LAWS, SUPPORTS  # noqa: E402  (the one copy of the name maps)

# reference-solver (Python) name -> FMU variable name
PARAMETER_NAMES = {
    "h": "h", "b": "b", "W": "W", "psi": "psi", "Kd": "Kd", "er": "er", "g": "g",
    "delta1_ratio": "delta1Ratio", "delta2_a": "delta2A", "delta2_b": "delta2B",
    "hinge_sat": "hingeSat", "rest_rate": "restRate", "pointing": "pointing", "e_base_ratio": "eBaseRatio",
    "e_hinge_ratio": "eHingeRatio", "e_top": "eTop", "psi_weight_only": "psiWeightOnly",
}

OUTPUTS = ["s1", "s2", "F_top", "collapsed", "impacts", "q1", "q2", "dq1", "dq2"]


@dataclass
class FmuRun:
    t: np.ndarray
    s1: np.ndarray
    s2: np.ndarray
    F_top: np.ndarray
    q1: np.ndarray
    q2: np.ndarray
    impacts: int
    collapsed: bool

    @property
    def peak_s1(self):
        return float(np.max(np.abs(self.s1)))

    @property
    def peak_s2(self):
        return float(np.max(np.abs(self.s2)))


def on_grid(t, x, grid, right=None):
    """x(t) of a run on a regular grid. fmpy and fmi2sim record an event instant twice (before
    and after), so duplicate times are dropped first; right=np.nan marks a run that ended early."""
    t_unique, idx = np.unique(t, return_index=True)
    return np.interp(grid, t_unique, np.asarray(x)[idx], right=right)


def start_values(support="flexibleTop", hinge_law="dohertyHinge", q0=None, dq0=None, **params):
    """FMU start values from keyword arguments named as the reference solver or as the FMU names them."""
    values = {"support": SUPPORTS[support], "hingeLaw": HINGE_LAWS[hinge_law]}
    for name, value in params.items():
        values[PARAMETER_NAMES.get(name, name)] = float(value)
    if q0 is not None:
        values["q1"], values["q2"] = map(float, q0)
    if dq0 is not None:
        values["dq1"], values["dq2"] = map(float, dq0)
    return values


def input_table(t, ag, u_top=None):
    """fmpy's input: a structured array, linearly interpolated by fmpy between rows."""
    table = np.zeros(len(t), dtype=[("time", np.float64), ("ag", np.float64), ("u_top", np.float64)])
    table["time"], table["ag"] = t, ag
    table["u_top"] = 0.0 if u_top is None else u_top
    return table


def simulate(fmu, t_end, t_in=None, ag_in=None, rtol=1e-6, output_interval=1e-3,
             solver="CVode", step_size=None, logger=None, progress=None, fmi_type="ModelExchange",
             fmpy_input_fix=True, **kwargs):
    """Simulate the FMU from 0 to t_end with fmpy; kwargs are start_values() arguments.
    fmi_type "CoSimulation" runs the FMU's own CVODE (fmi2DoStep) with communication steps of
    output_interval; rtol then goes to fmi2SetupExperiment and `solver` is not used.
    fmpy_input_fix: apply the inputs in fmpy's CVode right-hand side during this run (see above)."""
    inputs = None if t_in is None else input_table(np.asarray(t_in), np.asarray(ag_in))
    callback = None
    if progress is not None:
        def callback(time, recorder):
            progress(time)
            return True
    with fmpy_input_in_rhs(fmpy_input_fix):
        result = _simulate_fmu(fmu, t_end, solver, step_size, rtol, output_interval, kwargs, inputs, logger,
                               callback, fmi_type)
    return FmuRun(t=result["time"], s1=result["s1"], s2=result["s2"], F_top=result["F_top"],
                  q1=result["q1"], q2=result["q2"], impacts=int(result["impacts"][-1]),
                  collapsed=bool(result["collapsed"][-1]))


def _simulate_fmu(fmu, t_end, solver, step_size, rtol, output_interval, kwargs, inputs, logger, callback, fmi_type):
    return simulate_fmu(
        str(fmu), start_time=0.0, stop_time=t_end, solver=solver, step_size=step_size,
        relative_tolerance=rtol, output_interval=output_interval,
        start_values=start_values(**kwargs), input=inputs, output=OUTPUTS,
        logger=logger, debug_logging=logger is not None, step_finished=callback, fmi_type=fmi_type)
