"""The building scene (rockingwall.building.scene.Scene) as an SSP 1.0 file, and back.

An `.ssp` is a zip holding SystemStructure.ssd and the FMUs under resources/. The .ssd has one
system with the record's ground acceleration as its input connector `ag` (it feeds every
component input `ag` that no connection feeds: libcosim's SSP loader takes no connection that
starts at a system connector, so these are not written as connections), one component per FMU
(its connectors with their units, its start values as an inline ParameterSet) and the scene's
connections. `read` (rockingwall.building.ssp_read) checks what a hand-edited or hostile file
can get wrong and names it.

An SSP 1.0 input takes one connection: the building takes the wall below's F_top as F_wall_i and
the wall above's F_base as F_above_i and adds them itself, so a wall in every storey can be written.

A user replaces the Building FMU by putting another FMU into resources/ and pointing the
component's `source` at it: it must have the variables the connections name.
"""
import pathlib
import xml.etree.ElementTree as ET
import zipfile

from ..outputs import write_atomic
from .ssp_common import NS, UNITS, SSPError, fmu_units, q
from .ssp_read import check_building_variables, read

__all__ = ["SSPError", "check_building_variables", "fmu_units", "read", "run_libcosim", "ssd_xml", "write"]

for _p, _u in NS.items():
    ET.register_namespace(_p, _u)


def _connectors(scene):
    """{instance: {connector: (kind, unit)}} of every connection end and ground input."""
    out = {}
    units = {"building": fmu_units(scene.building_fmu)}
    wall_units = fmu_units(scene.wall_fmu)
    for w in scene.walls:
        units[w.name] = wall_units
    ends = [(a, b) for a, b, _, _ in scene.connections()] + [(c, d) for _, _, c, d in scene.connections()]
    for inst, var in ends + scene.ground_inputs():
        causality, unit = units[inst][var]
        out.setdefault(inst, {})[var] = ("input" if causality == "input" else "output", unit)
    return out


def _connector_xml(parent, name, kind, unit):
    c = ET.SubElement(parent, q("ssd", "Connector"), name=name, kind=kind)
    ET.SubElement(c, q("ssc", "Real"), unit=unit)


def _parameters_xml(component, real, integer):
    b = ET.SubElement(ET.SubElement(component, q("ssd", "ParameterBindings")), q("ssd", "ParameterBinding"))
    ps = ET.SubElement(ET.SubElement(b, q("ssd", "ParameterValues")), q("ssv", "ParameterSet"),
                       version="1.0", name=component.get("name") + "_start")
    params = ET.SubElement(ps, q("ssv", "Parameters"))
    for kind, values in (("Real", real), ("Integer", integer)):
        for k, v in values.items():
            p = ET.SubElement(params, q("ssv", "Parameter"), name=k)
            ET.SubElement(p, q("ssv", kind), value=repr(float(v)) if kind == "Real" else str(int(v)))


def _check_single_sources(scene):
    ends = [(c, d) for _, _, c, d in scene.connections()]
    for end in set(ends):
        if ends.count(end) > 1:
            raise SSPError(f"{end[0]}.{end[1]} takes {ends.count(end)} connections: an SSP 1.0 input takes one")


def ssd_xml(scene, sources):
    """The SystemStructure.ssd of `scene` as an ElementTree root; sources: {instance: path in the zip}."""
    _check_single_sources(scene)
    root = ET.Element(q("ssd", "SystemStructureDescription"), version="1.0", name="RockingWallBuilding")
    system = ET.SubElement(root, q("ssd", "System"), name="scene")
    _connector_xml(ET.SubElement(system, q("ssd", "Connectors")), "ag", "input", "m/s2")
    elements = ET.SubElement(system, q("ssd", "Elements"))
    connectors = _connectors(scene)
    starts = {"building": (scene.building_real, scene.building_integer)}
    starts.update({w.name: (w.real, w.integer) for w in scene.walls})
    for inst, (real, integer) in starts.items():
        comp = ET.SubElement(elements, q("ssd", "Component"), name=inst, type="application/x-fmu-sharedlibrary",
                             source=sources[inst])
        cons = ET.SubElement(comp, q("ssd", "Connectors"))
        for name, (kind, unit) in connectors.get(inst, {}).items():
            _connector_xml(cons, name, kind, unit)
        _parameters_xml(comp, real, integer)
    conns = ET.SubElement(system, q("ssd", "Connections"))
    for a, b, c, d in scene.connections():
        ET.SubElement(conns, q("ssd", "Connection"), startElement=a, startConnector=b, endElement=c, endConnector=d)
    units = ET.SubElement(root, q("ssd", "Units"))
    for name, exps in UNITS.items():
        ET.SubElement(ET.SubElement(units, q("ssc", "Unit"), name=name), q("ssc", "BaseUnit"),
                      **{k: str(v) for k, v in exps.items()})
    ET.indent(root)
    return root


def write(scene, path):
    """Write `scene` as the SSP 1.0 archive `path` (the FMUs copied under resources/)."""
    sources = {"building": "resources/" + pathlib.Path(scene.building_fmu).name}
    sources.update({w.name: "resources/" + pathlib.Path(scene.wall_fmu).name for w in scene.walls})
    root = ssd_xml(scene, sources)
    members = {scene.building_fmu: sources["building"], scene.wall_fmu: "resources/" + pathlib.Path(scene.wall_fmu).name}

    def zip_into(tmp):
        with zipfile.ZipFile(tmp, "w", zipfile.ZIP_DEFLATED) as z:
            z.writestr("SystemStructure.ssd", ET.tostring(root, encoding="UTF-8", xml_declaration=True))
            for src, arc in members.items():
                z.write(src, arc)
    write_atomic(path, zip_into, "the SSP file", inputs=[(scene.building_fmu, "the building FMU"),
                                                         (scene.wall_fmu, "the wall FMU")])
    return path


def run_libcosim(ssp_path, record, t_end, H, outputs):
    """The scene of an SSP archive under libcosim (its own SSP loader), the record's ag set on the
    inputs the system connector `ag` feeds with an override manipulator, held over each step.
    outputs: [(instance, variable)]; returns {"time": [...], (instance, variable): [...]}.
    Call it in a child process: libcosim aborts the process on some FMU errors."""
    import numpy as np
    from libcosimpy.CosimExecution import CosimExecution
    from libcosimpy.CosimLogging import CosimLogLevel, log_output_level
    from libcosimpy.CosimManipulator import CosimManipulator
    from libcosimpy.CosimObserver import CosimObserver
    log_output_level(CosimLogLevel.WARNING)
    with zipfile.ZipFile(ssp_path) as z:
        root = ET.fromstring(z.read("SystemStructure.ssd"))
    fed = {(c.get("endElement"), c.get("endConnector")) for c in root.iterfind("ssd:System/ssd:Connections/ssd:Connection", NS)}
    ground = [(comp.get("name"), "ag") for comp in root.iterfind("ssd:System/ssd:Elements/ssd:Component", NS)
              if (comp.get("name"), "ag") not in fed]
    ex = CosimExecution.from_ssp_file(str(pathlib.Path(ssp_path).resolve()), step_size=int(round(H * 1e9)))
    index = {s.name.decode(): s.index for s in ex.slave_infos()}
    vr = {}
    for name, i in index.items():
        vr[name] = {v.name.decode(): v.reference for v in ex.slave_variables(i)}
    override, observer = CosimManipulator.create_override(), CosimObserver.create_last_value()
    ex.add_manipulator(manipulator=override)
    ex.add_observer(observer=observer)
    out = {"time": [0.0], **{o: [0.0] for o in outputs}}  # libcosim initialises in its first step: rest
    t_in, ag_in = np.asarray(record.t, float), np.asarray(record.ag, float)
    for k in range(int(round(t_end / H))):
        ag = float(np.interp(k * H, t_in, ag_in, right=0.0))
        for inst, var in ground:
            override.slave_real_values(index[inst], [vr[inst][var]], [ag])
        if not ex.step():
            from libcosimpy._internal import get_last_error_message
            raise RuntimeError(f"libcosim: the step from t = {k * H:.6g} s failed: {get_last_error_message()}")
        out["time"].append((k + 1) * H)
        for inst, var in outputs:
            out[(inst, var)].append(observer.last_real_values(index[inst], [vr[inst][var]])[0])
    return out
