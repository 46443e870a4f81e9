"""FMI 2.0 FMUs as fmpy instances for the masters: loading, start values, FMI calls whose failure
names the FMU, the call and the FMU's own last message (CouplingError), and closing.

Each instance carries what the failure messages need: `vr` (value references by name),
`fmu_path`, `log` (an FmuLog), `failed` and `instantiated`."""
import os
import sys

from ..errors import RockingWallError


class CouplingError(RockingWallError):
    """A slave failed (the FMU, the FMI call and the FMU's own message) or the run did not reach
    its end: never a silent, shortened result."""


class CouplingUnstable(CouplingError):
    """The coupled run's energy balance broke past the stop bound (rules.ENERGY_STOP_SHARE): the
    scheme, not the physics, drove the motion. The message names the likely cause and the remedy;
    nothing of such a run is a result."""


def value_references(model_description):
    """{variable name: value reference} of an fmpy model description."""
    return {v.name: v.valueReference for v in model_description.modelVariables}


class FmuLog:
    """The FMUs' log messages of warning level and above, kept to name the cause of a failure."""

    def __init__(self):
        self.messages = []
        self._keep = []

    def callbacks(self):
        from ctypes import byref
        from fmpy import calloc, free
        from fmpy.fmi2 import (fmi2CallbackAllocateMemoryTYPE, fmi2CallbackFreeMemoryTYPE, fmi2CallbackFunctions,
                               fmi2CallbackLoggerTYPE)
        from fmpy.logging import addLoggerProxy

        def logger(env, instance, status, category, message):
            if status >= 1:  # fmi2Warning and worse
                self.messages.append(f"{(instance or b'').decode(errors='replace')}: "
                                     f"{(message or b'').decode(errors='replace')}")
        cb = fmi2CallbackFunctions()
        cb.logger = fmi2CallbackLoggerTYPE(logger)
        cb.allocateMemory = fmi2CallbackAllocateMemoryTYPE(calloc)
        cb.freeMemory = fmi2CallbackFreeMemoryTYPE(free)
        addLoggerProxy(byref(cb))  # formats the FMU's printf-style arguments
        self._keep.append(cb)  # each FMU holds a pointer to its callbacks until freeInstance
        return cb

    def last(self, instance):
        mine = [m for m in self.messages if m.startswith(instance + ":")]
        return mine[-1] if mine else f"{instance}: no message logged"


def _status_name(status):
    names = ["ok", "warning", "discard", "error", "fatal", "pending"]
    return names[status] if 0 <= status < len(names) else f"status {status}"


def failure(slave, what, exc):
    """The CouplingError for an exception of an FMI call of `slave` (marked failed: it may not be
    terminated), naming the FMU, the call and the FMU's own last message."""
    from fmpy.fmi1 import FMICallException
    slave.failed = True
    last = slave.log.last(slave.instanceName)
    if isinstance(exc, FMICallException):
        return CouplingError(f"{slave.fmu_path} ({slave.instanceName}): {exc.function} returned "
                             f"{_status_name(exc.status)} {what}: {last}")
    # fmpy raises a bare Exception when fmi2Instantiate returns NULL
    return CouplingError(f"{slave.fmu_path} ({slave.instanceName}) {what}: {exc}: {last}")


def fmi_call(slave, what, fn, *args):
    """fn(*args), an FMI call of `slave`, with a failure turned into a CouplingError (failure())."""
    try:
        return fn(*args)
    except Exception as exc:  # noqa: BLE001  every failure of the call is reported as the FMU's
        raise failure(slave, what, exc) from None


def load_slave(path, name, unzip_root, log):
    """One Co-Simulation slave, its FMU unpacked under unzip_root (removed by the caller)."""
    from fmpy import extract, read_model_description
    from fmpy.fmi2 import FMU2Slave
    md = read_model_description(str(path))
    s = FMU2Slave(guid=md.guid, unzipDirectory=extract(str(path), os.path.join(unzip_root, name)),
                  modelIdentifier=md.coSimulation.modelIdentifier, instanceName=name)
    s.vr, s.fmu_path, s.log, s.failed, s.instantiated = value_references(md), str(path), log, False, False
    return s


def initialise(s, start, rtol):
    """Instantiate and initialise a slave with its start values (real, integer)."""
    real, integer = start
    fmi_call(s, "at instantiation", s.instantiate, False, s.log.callbacks())
    s.instantiated = True
    fmi_call(s, "at setup", s.setupExperiment, rtol, 0.0)
    fmi_call(s, "setting the start values", s.setReal, [s.vr[k] for k in real], list(real.values()))
    fmi_call(s, "setting the start values", s.setInteger, [s.vr[k] for k in integer], list(integer.values()))
    fmi_call(s, "at initialisation", s.enterInitializationMode)
    fmi_call(s, "at initialisation", s.exitInitializationMode)


def close_slaves(slaves):
    """Terminate the slaves that did not fail (a failed one may not be terminated) and free all;
    an error here never hides the one that ended the run."""
    for s in slaves:
        if not s.instantiated:
            continue
        try:
            if not s.failed:
                s.terminate()
        except Exception as exc:  # noqa: BLE001  reported, not raised: the run's result stands
            print(f"rockingwall: warning: {s.fmu_path} ({s.instanceName}): fmi2Terminate failed: {exc}", file=sys.stderr)
        try:
            s.freeInstance()
        except Exception:  # noqa: BLE001
            pass
