"""RockingWall and the Diaphragm FMU as Model Exchange, integrated together under one CVODE
(fmpy's SUNDIALS binding, fmpy.sundials.CVodeSolver): no macro step. The tie is an algebraic
connection evaluated inside the right-hand side and the root function at every time CVODE asks for:

    diaphragm.u (a state)  --> wall.u_top
    wall.F_top = K_d (s2 - u_top) --> diaphragm.F_top

so the coupling adds no energy of its own (docs/coupling.md). The ground motion is interpolated
linearly in the record (the Co-Simulation masters hold it over each macro step, which tends to the
same as H -> 0). RockingWall's state events (hinges, impacts, collapse) stop CVODE at the root, go
through the FMU's event iteration and restart CVODE; a collapse (the FMU's terminateSimulation)
ends the run, as the wall's fmi2Discard does in the Co-Simulation masters.

run_monolithic() returns a CoupledResult (rockingwall.coupling.wall_diaphragm) on the output grid
(plus each event instant), with the same columns as the Co-Simulation masters, so the same energy
check and summary apply.
"""
import ctypes
import math
import os

import numpy as np

from .. import scratch
from .slaves import CouplingError, FmuLog, close_slaves, fmi_call, value_references
from .wall_diaphragm import DIA_OUT, WALL_OUT, assemble, check_options, wall_start_values

_DOUBLE = ctypes.sizeof(ctypes.c_double)


def _offset(ptr, n):
    """The ctypes double pointer n elements past ptr."""
    return ctypes.cast(ctypes.c_void_p(ctypes.cast(ptr, ctypes.c_void_p).value + n * _DOUBLE),
                       ctypes.POINTER(ctypes.c_double))


class _Model:
    """One Model-Exchange instance (fmpy FMU2Model), its value references and its sizes."""

    def __init__(self, path, name, unzip_root, log):
        from fmpy import extract, read_model_description
        from fmpy.fmi2 import FMU2Model
        md = read_model_description(str(path))
        self.fmu = FMU2Model(guid=md.guid, unzipDirectory=extract(str(path), os.path.join(unzip_root, name)),
                             modelIdentifier=md.modelExchange.modelIdentifier, instanceName=name)
        self.vr, self.nx, self.nz = value_references(md), md.numberOfContinuousStates, md.numberOfEventIndicators
        # what fmi_call's failure messages name
        self.fmu.vr, self.fmu.fmu_path, self.fmu.log = self.vr, str(path), log
        self.fmu.failed, self.fmu.instantiated = False, False


class CoupledSystem:
    """Both FMUs as one ODE for CVODE: the state vector is (wall states, diaphragm states)."""

    def __init__(self, wall, dia, t_in, ag_in):
        self.wall, self.dia = wall, dia
        self.t_in, self.ag_in = t_in, ag_in
        self.time = 0.0
        self.nx, self.nz = wall.nx + dia.nx, wall.nz + dia.nz

    def ground(self, t):
        return float(np.interp(t, self.t_in, self.ag_in, right=0.0))

    def connect(self, t):
        """Time, ground motion and the tie at time t, in the order the connection needs: the
        diaphragm's u is a state, the wall's F_top depends on u_top, the diaphragm reads F_top."""
        w, d = self.wall.fmu, self.dia.fmu
        ag = self.ground(t)
        w.setTime(t)
        d.setTime(t)
        u = d.getReal([self.dia.vr["u"]])[0]
        w.setReal([self.wall.vr["ag"], self.wall.vr["u_top"]], [ag, u])
        F = w.getReal([self.wall.vr["F_top"]])[0]
        d.setReal([self.dia.vr["ag"], self.dia.vr["F_top"]], [ag, F])

    # CVodeSolver's callbacks: ctypes double pointers and their lengths
    def set_time(self, t):
        self.time = t

    def get_x(self, x, nx):
        self.wall.fmu.getContinuousStates(x, self.wall.nx)
        self.dia.fmu.getContinuousStates(_offset(x, self.wall.nx), self.dia.nx)

    def set_x(self, x, nx):
        self.wall.fmu.setContinuousStates(x, self.wall.nx)
        self.dia.fmu.setContinuousStates(_offset(x, self.wall.nx), self.dia.nx)

    def get_dx(self, dx, nx):
        self.connect(self.time)
        self.wall.fmu.getDerivatives(dx, self.wall.nx)
        self.dia.fmu.getDerivatives(_offset(dx, self.wall.nx), self.dia.nx)

    def get_z(self, z, nz):
        self.connect(self.time)
        self.wall.fmu.getEventIndicators(z, self.wall.nz)

    def get_nominals(self, x, nx):
        self.wall.fmu.getNominalsOfContinuousStates(x, self.wall.nx)
        self.dia.fmu.getNominalsOfContinuousStates(_offset(x, self.wall.nx), self.dia.nx)


class _NoInput:
    """CVodeSolver applies an input object in its root function; the system's own connect() does."""

    @staticmethod
    def apply(t):
        return None


def _event_iteration(model):
    """The FMU's event iteration: (terminate, next time event or inf)."""
    fmu = model.fmu
    while True:
        new_states_needed, terminate, _, _, next_defined, next_time = fmu.newDiscreteStates()
        if terminate:
            return True, math.inf
        if not new_states_needed:
            return False, (next_time if next_defined else math.inf)


def _wall_collapsed(system):
    """RockingWall's `collapsed` output: set at the event where the wall passes its instability
    point (its terminateSimulation follows a moment later, as a time event)."""
    return bool(system.wall.fmu.getBoolean([system.wall.vr["collapsed"]])[0])


def _events(system, t):
    """Event mode for both FMUs at t: (terminate, next time event)."""
    terminate, next_time = False, math.inf
    for m in (system.wall, system.dia):
        m.fmu.enterEventMode()
        system.connect(t)
        stop, t_ev = _event_iteration(m)
        terminate, next_time = terminate or stop, min(next_time, t_ev)
        m.fmu.enterContinuousTimeMode()
    return terminate or _wall_collapsed(system), next_time


def _initialise(model, start, rtol):
    real, integer = start
    fmu = model.fmu
    fmu.instantiate(callbacks=fmu.log.callbacks())
    fmu.instantiated = True
    fmu.setupExperiment(tolerance=rtol, startTime=0.0)
    if real:
        fmu.setReal([model.vr[k] for k in real], list(real.values()))
    if integer:
        fmu.setInteger([model.vr[k] for k in integer], list(integer.values()))
    fmu.enterInitializationMode()
    fmu.exitInitializationMode()


def _record(system, times, wall_rows, dia_rows, t):
    system.connect(t)
    times.append(t)
    wall_rows.append(system.wall.fmu.getReal([system.wall.vr[x] for x in WALL_OUT]))
    dia_rows.append(system.dia.fmu.getReal([system.dia.vr[x] for x in DIA_OUT]))


def run_monolithic(wall_fmu, dia_fmu, t_in, ag_in, t_end, wall=None, dia=None, rtol=1e-6, output_interval=1e-3):
    """The coupled system under one CVODE (see the module's docstring); CouplingError with the
    FMU's message when an FMI call fails or CVODE gives up."""
    check_options(t_end, output_interval, rtol)
    log, models = FmuLog(), []
    with scratch.folder("rw_couple_me_") as unzip_root:
        try:
            for path, name, start in [(wall_fmu, "wall", wall or wall_start_values()),
                                      (dia_fmu, "diaphragm", (dia or {}, {}))]:
                models.append(_Model(path, name, unzip_root, log))
                fmi_call(models[-1].fmu, "at initialisation", _initialise, models[-1], start, rtol)
            return _integrate(CoupledSystem(*models, np.asarray(t_in, float), np.asarray(ag_in, float)),
                              t_end, rtol, output_interval)
        finally:
            close_slaves([m.fmu for m in models])


def _integrate(system, t_end, rtol, output_interval):
    """CVODE over the coupled states from 0 to t_end, stopping at state, step and time events;
    the run ends at the wall's collapse (collapsed_at, as the Co-Simulation masters report it)."""
    from fmpy.sundials import CVodeSolver
    next_time = math.inf
    system.connect(0.0)
    for m in (system.wall, system.dia):
        stop, t_ev = _event_iteration(m)
        if stop:
            raise CouplingError(f"{m.fmu.instanceName}: terminated at initialisation")
        next_time = min(next_time, t_ev)
        m.fmu.enterContinuousTimeMode()
    system.connect(0.0)
    solver = CVodeSolver(nx=system.nx, nz=system.nz, get_x=system.get_x, set_x=system.set_x,
                         get_dx=system.get_dx, get_z=system.get_z, get_nominals=system.get_nominals,
                         set_time=system.set_time, input=_NoInput(), startTime=0.0,
                         maxStep=output_interval, relativeTolerance=rtol, maxNumSteps=100000)
    n_out = int(round(t_end / output_interval))
    times, wall_rows, dia_rows = [], [], []
    _record(system, times, wall_rows, dia_rows, 0.0)
    t, k, collapsed_at = 0.0, 1, None
    while k <= n_out:
        t_out = min(k * output_interval, t_end)
        t_next = min(t_out, next_time)
        try:
            state_event, _, t = solver.step(t, t_next)
        except RuntimeError as exc:
            raise CouplingError(f"monolithic: CVODE failed at t = {t:.6g} s: {exc}: "
                                       f"{system.wall.fmu.log.last('wall')}") from None
        system.set_time(t)
        system.set_x(solver.px, system.nx)  # the states CVODE reached (step() also sets them)
        time_event = t >= next_time - 1e-12 * max(1.0, t_end)
        step_event, terminate = False, False
        for m in (system.wall, system.dia):
            m.fmu.setTime(t)
            ev, term = m.fmu.completedIntegratorStep()
            step_event, terminate = step_event or ev, terminate or term
        if state_event or step_event or time_event or terminate:
            _record(system, times, wall_rows, dia_rows, t)  # just before the event
            if not terminate:
                terminate, next_time = _events(system, t)
            _record(system, times, wall_rows, dia_rows, t)  # just after
            if terminate:
                collapsed_at = t
                break
            solver.reset(t)
        if t >= t_out - 1e-12 * max(1.0, t_end):
            if times[-1] != t:
                _record(system, times, wall_rows, dia_rows, t)
            k += 1
    r = assemble(times, wall_rows, dia_rows)
    r["collapsed_at"] = collapsed_at
    return r
