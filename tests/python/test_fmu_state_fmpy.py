"""FMU state through fmpy's FMU2Slave on the packaged binaries: a rolled-back
Co-Simulation step reproduces itself bitwise, and a serialized state set into a second instance
makes it step identically."""
import shutil

import pytest

from fmpy import extract, read_model_description
from fmpy.fmi2 import FMU2Slave

CASES = {
    "RockingWall": dict(integers={"support": 1}, start={"q1": 0.02}, inputs={"ag": 0.05}, outputs=["s1", "energy", "dissipated"]),
    "Diaphragm": dict(integers={}, start={"u": 0.01}, inputs={"F_top": 50.0}, outputs=["u", "v", "energy"]),
    "Building": dict(integers={"nStoreys": 3, "diaphragmLaw": 2}, start={"u_diaph_2": 0.01}, inputs={"ag": 2.0},
                     outputs=["u_diaph_3", "a_diaph_2", "work_storey_1"]),
}


def slave(path, unzipdir, md, case, name):
    vrs = {v.name: v.valueReference for v in md.modelVariables}
    fmu = FMU2Slave(guid=md.guid, unzipDirectory=unzipdir, modelIdentifier=md.coSimulation.modelIdentifier,
                    instanceName=name)
    fmu.instantiate()
    for k, v in case["integers"].items():
        fmu.setInteger([vrs[k]], [v])
    fmu.setReal([vrs[k] for k in case["start"]], list(case["start"].values()))
    fmu.setupExperiment(tolerance=1e-8, startTime=0.0)
    fmu.enterInitializationMode()
    fmu.exitInitializationMode()
    fmu.setReal([vrs[k] for k in case["inputs"]], list(case["inputs"].values()))
    return fmu, [vrs[k] for k in case["outputs"]]


@pytest.mark.parametrize("name", list(CASES))
def test_rollback_and_serialization_through_fmpy(build_dir, name):
    path = str(build_dir / f"{name}.fmu")
    md = read_model_description(path)
    assert md.coSimulation.canGetAndSetFMUstate and md.coSimulation.canSerializeFMUstate
    unzipdir = extract(path)
    try:
        a, outs = slave(path, unzipdir, md, CASES[name], "a")
        b, _ = slave(path, unzipdir, md, CASES[name], "b")
        h = 0.05
        for k in range(20):
            state = a.getFMUstate()
            a.doStep(currentCommunicationPoint=k * h, communicationStepSize=h)
            first = a.getReal(outs)
            a.setFMUstate(state)
            a.doStep(currentCommunicationPoint=k * h, communicationStepSize=h)
            assert a.getReal(outs) == first, f"step {k}"
            a.freeFMUstate(state)
        blob = a.serializeFMUstate(a.getFMUstate())
        b.setFMUstate(b.deSerializeFMUstate(blob))
        for k in range(20, 30):
            a.doStep(currentCommunicationPoint=k * h, communicationStepSize=h)
            b.doStep(currentCommunicationPoint=k * h, communicationStepSize=h)
            assert a.getReal(outs) == b.getReal(outs), f"step {k}"
        for fmu in (a, b):
            fmu.terminate()
            fmu.freeInstance()
    finally:
        shutil.rmtree(unzipdir, ignore_errors=True)
