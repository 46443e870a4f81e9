"""The one fixed-step Jacobi master over FMI 2.0 Co-Simulation slaves (fmpy FMU2Slave, in this
process), for any scene that says how its slaves are joined: the wall and its diaphragm
(rockingwall.coupling.wall_diaphragm) and the walls of a building (rockingwall.building.scene).

Call order at each communication point t_k = k H, k = 0, 1, ..., n = round(t_end / H):

  1. inputs  the scene computes every coupled input from the slaves' outputs at t_k (at k = 0
             those right after initialisation) and the record's ag(t_k), interpolated linearly
             in the record and 0 after its end;
  2. set     each standing slave, in the scene's order, gets its inputs in one fmi2SetReal; with
             order 2 then their slopes, in one fmi2SetRealInputDerivatives when any is not 0:
             (v_k - v_(k-1)) / H for a coupled input, (ag(t_k + H) - ag(t_k)) / H for an input
             that takes the record (order 1 holds every input over the step);
  3. record  every slave's outputs at t_k, read with these inputs (an output that depends on an
             input algebraically changes with it): the point t_k of the history;
  4. step    (k < n) each standing slave, in the scene's order, from t_k to t_k + H, all with
             the inputs of 2 (Jacobi). A slave the scene lets fall (a wall's fmi2Discard: its
             collapse) leaves the scene at t_k with the outputs it has then, and the slopes of
             the inputs the scene names as jumping then start again from 0; the run ends as
             soon as every slave that may fall has fallen. Any other failure raises
             CouplingError naming the FMU, the call and its last message;
  5. read    every standing slave's outputs at t_k + H, for step 1 of the next point.

An optional monitor watches the run: monitor.start(slaves) once the slaves are initialised,
monitor.check(point, fallen) after 3 at every point; it stops the run by raising (a
CouplingUnstable when the scene's energy balance breaks: rockingwall.coupling.energy_guard).

A scene has: slaves() -> [(name, FMU path, (real start values, integer start values))] in the
order of 2 and 4; outputs(name) -> the output names read from that slave; inputs(outputs, ag,
fallen) -> {(slave, input): value} (outputs: {slave: {output: value}}, fallen: {slave: t});
ground_inputs() -> the (slave, input) pairs that take ag; may_fall(name); and
jumps_when_a_slave_falls((slave, input)) -> bool."""
import dataclasses

import numpy as np

from .. import scratch
from .slaves import FmuLog, close_slaves, failure, fmi_call, initialise, load_slave


@dataclasses.dataclass
class Point:
    """One communication point: its time, the record's ag, every slave's outputs and the inputs
    that were set (the fallen slaves keep the outputs they had when they fell)."""
    t: float
    ag: float
    outputs: dict
    inputs: dict


@dataclasses.dataclass
class History:
    points: list
    fallen: dict          # slave name -> time it fell
    at_end: object = None  # what read_at_end(slaves) returned before the slaves were freed


class _Slopes:
    """The slopes of the coupled inputs over the coming step: extrapolated from the previous
    exchange (order 2) or zero (order 1)."""

    def __init__(self, order, H, jumps):
        self.order, self.H, self.jumps, self.previous = order, H, jumps, None

    def forget_jumps(self):
        """A slave fell: the inputs that jump now get no slope across the jump."""
        if self.previous is not None:
            self.previous = {k: v for k, v in self.previous.items() if not self.jumps(k)}

    def next(self, values):
        if self.order < 2 or self.previous is None:
            out = {k: 0.0 for k in values}
        else:
            out = {k: (v - self.previous[k]) / self.H if k in self.previous else 0.0 for k, v in values.items()}
        self.previous = dict(values)
        return out


def run(scene, t_in, ag_in, t_end, H, order=1, rtol=1e-6, progress=None, read_at_end=None, monitor=None):
    """Load and initialise the scene's slaves (their FMUs unpacked into one temporary folder,
    removed however the run ends), run the scheme of the module's docstring from 0 to t_end with
    macro step H, and free the slaves. progress: a label for a progress bar (None: no bar);
    monitor: see the module's docstring. Returns a History; read_at_end(slaves) is called before
    the slaves are freed."""
    log, slaves = FmuLog(), {}
    with scratch.folder("rw_jacobi_") as unzip_root:
        try:
            for name, path, start in scene.slaves():
                slaves[name] = load_slave(path, name, unzip_root, log)  # listed first: always freed
                initialise(slaves[name], start, rtol)
            if monitor is not None:
                monitor.start(slaves)
            history = exchange(scene, slaves, np.asarray(t_in, float), np.asarray(ag_in, float), t_end, H, order,
                               progress, monitor)
            if read_at_end is not None:
                history.at_end = read_at_end(slaves)
            return history
        finally:
            close_slaves(list(slaves.values()))


def _read(scene, name, slave, at):
    names = scene.outputs(name)
    return dict(zip(names, fmi_call(slave, at, slave.getReal, [slave.vr[x] for x in names])))


def _set_inputs(slaves, values, slopes, ground_keys, ground_slope, at):
    """Set every input of each slave, then its slope (the record's own slope for the inputs that
    take ag)."""
    for name, s in slaves.items():
        keys = [k for k in values if k[0] == name]
        vr = [s.vr[k[1]] for k in keys]
        fmi_call(s, at, s.setReal, vr, [values[k] for k in keys])
        d = [ground_slope if k in ground_keys else slopes[k] for k in keys]
        if any(x != 0.0 for x in d):  # after setReal, which holds an input until told otherwise
            fmi_call(s, at, s.setRealInputDerivatives, vr, [1] * len(vr), d)


def exchange(scene, slaves, t_in, ag_in, t_end, H, order=1, progress=None, monitor=None):
    """The scheme of the module's docstring over initialised slaves ({name: slave}, in the
    scene's order); returns a History."""
    from fmpy.fmi1 import FMICallException
    from fmpy.fmi2 import fmi2Discard
    n = int(round(t_end / H))
    ground_keys = set(scene.ground_inputs())
    may_fall = {name for name in slaves if scene.may_fall(name)}
    slopes = _Slopes(order, H, scene.jumps_when_a_slave_falls)
    points, fallen = [], {}
    outputs = {name: _read(scene, name, s, "at t = 0") for name, s in slaves.items()}

    def ag_at(t):
        return float(np.interp(t, t_in, ag_in, right=0.0))

    steps = range(n + 1)
    if progress:
        from tqdm import tqdm
        steps = tqdm(steps, desc=progress, unit="step", mininterval=1.0)
    for k in steps:
        t = k * H
        at = f"at t = {t:.6g} s"
        ag = ag_at(t)
        standing = {name: s for name, s in slaves.items() if name not in fallen}
        values = scene.inputs(outputs, ag, fallen)
        ag_slope = (ag_at(t + H) - ag) / H if order == 2 else 0.0
        _set_inputs(standing, values, slopes.next(values), ground_keys, ag_slope, at)
        outputs.update({name: _read(scene, name, s, at) for name, s in standing.items()})
        points.append(Point(t, ag, dict(outputs), values))
        if monitor is not None:
            monitor.check(points[-1], fallen)
        if k == n:
            break
        for name, s in standing.items():
            try:
                s.doStep(currentCommunicationPoint=t, communicationStepSize=H)
            except FMICallException as exc:
                if exc.status != fmi2Discard or name not in may_fall:  # an error, not a wall's collapse
                    raise failure(s, at, exc) from None
                fallen[name] = t
                outputs[name] = _read(scene, name, s, at)  # at the collapse
                slopes.forget_jumps()
                if may_fall <= fallen.keys():
                    break
        if may_fall and may_fall <= fallen.keys():
            break  # every slave that may fall has fallen: nothing of interest remains
        outputs.update({name: _read(scene, name, s, at) for name, s in slaves.items() if name not in fallen})
    return History(points, fallen)
