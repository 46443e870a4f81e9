"""ModelStructure of both FMUs against finite differences.

For every output and every state derivative, each continuous state and each Real input is
perturbed in turn through fmpy's low-level FMU2Model API (Model Exchange, continuous-time mode)
and the unknown is read again. A dependency that finite differences see and ModelStructure does
not declare is an error (an importer such as PyFMI reads `dependencies` literally and would miss
it); a declared dependency that no operating point shows is only reported.

RockingWall is probed at every model/hingeLaw combination (they change the equations), each at
two operating points (both hinge sides)."""
import ctypes
import itertools
import shutil

import pytest

from fmpy import extract, read_model_description
from fmpy.fmi2 import FMU2Model

# relative threshold below which a change counts as round-off
ROUND_OFF = 1e-11

# RockingWall operating points: states (q1, q2, dq1, dq2) and inputs, chosen off every event
# surface so that one mode holds around them
RW_POINTS = [
    dict(states=(0.012, -0.004, 0.03, -0.02), inputs=dict(ag=0.7, u_top=0.002)),
    dict(states=(-0.008, 0.006, -0.05, 0.04), inputs=dict(ag=-1.3, u_top=-0.003)),
]
# (model, hingeLaw): every combination of the parameters that change the structure
RW_STRUCTURES = list(itertools.product([1, 2, 3], [1, 2, 3, 4]))  # support x hingeLaw
DG_POINTS = [
    dict(states=(0.004, -0.03), inputs=dict(ag=0.5, F_top=120.0)),
    dict(states=(-0.01, 0.2), inputs=dict(ag=-2.0, F_top=-800.0)),
]


class Probe:
    """One Model-Exchange instance in continuous-time mode at an operating point."""

    def __init__(self, fmu_path, integers, states, inputs):
        self.md = read_model_description(str(fmu_path))
        self.dir = extract(str(fmu_path))
        self.fmu = FMU2Model(guid=self.md.guid, unzipDirectory=self.dir,
                             modelIdentifier=self.md.modelExchange.modelIdentifier, instanceName="probe")
        self.vars = {v.name: v for v in self.md.modelVariables}
        self.states = [d.variable.derivative for d in self.md.derivatives]
        self.nx = len(self.states)
        self.inputs = [v for v in self.md.modelVariables if v.causality == "input" and v.type == "Real"]
        f = self.fmu
        f.instantiate()
        f.setupExperiment(startTime=0.0)
        f.enterInitializationMode()
        for name, value in integers.items():
            f.setInteger([self.vars[name].valueReference], [value])
        # the operating point as start values, so the modes are decided for it
        f.setReal([s.valueReference for s in self.states], list(states))
        f.setReal([self.vars[n].valueReference for n in inputs], list(inputs.values()))
        f.exitInitializationMode()
        while f.newDiscreteStates()[0]:  # newDiscreteStatesNeeded
            pass
        f.enterContinuousTimeMode()
        self.x0 = list(states)
        # every input set at each evaluation (a probed input must not keep its perturbed value)
        self.u0 = {v.valueReference: 0.0 for v in self.inputs}
        self.u0.update({self.vars[n].valueReference: v for n, v in inputs.items()})

    def close(self):
        self.fmu.terminate()
        self.fmu.freeInstance()
        shutil.rmtree(self.dir, ignore_errors=True)

    def evaluate(self, x, u):
        """{name: value} of every output and every state derivative at states x, inputs u."""
        f = self.fmu
        xs = (ctypes.c_double * self.nx)(*x)
        f.setContinuousStates(xs, self.nx)
        f.setReal(list(u), list(u.values()))
        dx = (ctypes.c_double * self.nx)()
        f.getDerivatives(dx, self.nx)
        values = {("der", d.variable.name): dx[i] for i, d in enumerate(self.md.derivatives)}
        for o in self.md.outputs:
            v = o.variable
            get = {"Real": f.getReal, "Integer": f.getInteger, "Boolean": f.getBoolean}[v.type]
            values[("out", v.name)] = float(get([v.valueReference])[0])
        return values

    def dependencies(self):
        """{(kind, unknown): set of state/input names it depends on here}."""
        base = self.evaluate(self.x0, self.u0)
        found = {k: set() for k in base}
        probes = [(s.name, i, None) for i, s in enumerate(self.states)] + [(v.name, None, v.valueReference) for v in self.inputs]
        for name, i, vr in probes:
            x, u = list(self.x0), dict(self.u0)
            if i is not None:
                nominal = float(self.states[i].nominal or 1.0)
                x[i] += 1e-4 * max(abs(x[i]), nominal)
            else:
                u[vr] = u.get(vr, 0.0) + 1e-3 * max(abs(u.get(vr, 0.0)), 1.0)
            moved = self.evaluate(x, u)
            for k, v0 in base.items():
                if abs(moved[k] - v0) > ROUND_OFF * max(abs(v0), abs(moved[k]), 1e-300):
                    found[k].add(name)
        self.evaluate(self.x0, self.u0)
        return found


def declared(md):
    """{(kind, unknown): set of names} from ModelStructure; None = depends on everything."""
    out = {}
    for kind, unknowns in (("out", md.outputs), ("der", md.derivatives)):
        for unk in unknowns:
            deps = unk.dependencies
            out[(kind, unk.variable.name)] = None if deps is None else {d.name for d in deps}
    return out


def compare(fmu_path, cases):
    md = read_model_description(str(fmu_path))
    decl = declared(md)
    missing, seen = [], {k: set() for k in decl}
    for integers, point in cases:
        probe = Probe(fmu_path, integers, point["states"], point["inputs"])
        try:
            found = probe.dependencies()
        finally:
            probe.close()
        for key, names in found.items():
            seen[key] |= names
            if decl[key] is not None and names - decl[key]:
                missing.append(f"{key[0]} {key[1]} depends on {sorted(names - decl[key])} "
                               f"(declared {sorted(decl[key])}) at {integers} {point}")
    extra = {k: sorted(decl[k] - seen[k]) for k in decl if decl[k] is not None and decl[k] - seen[k]}
    return missing, extra


def test_rockingwall_model_structure(rockingwall_fmu):
    cases = [(dict(support=m, hingeLaw=law), p) for (m, law) in RW_STRUCTURES for p in RW_POINTS]
    missing, extra = compare(rockingwall_fmu, cases)
    if extra:
        print("RockingWall: declared but not seen at any operating point:", extra)
    assert not missing, "\n".join(missing)


def test_diaphragm_model_structure(build_dir):
    missing, extra = compare(build_dir / "Diaphragm.fmu", [({}, p) for p in DG_POINTS])
    if extra:
        print("Diaphragm: declared but not seen at any operating point:", extra)
    assert not missing, "\n".join(missing)
