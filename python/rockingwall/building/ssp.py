"""The building scene (rockingwall.building.scene.Scene) as an SSP 1.0 file, and back.

An `.ssp` is a zip holding SystemStructure.ssd and the FMUs under resources/. The .ssd has one
system with the record's ground acceleration as its input connector `ag` (it feeds every
component input `ag` that no connection feeds: libcosim's SSP loader takes no connection that
starts at a system connector, so these are not written as connections), one component per FMU
(its connectors with their units, its start values as an inline ParameterSet) and the scene's
connections. `read` checks what a hand-edited file can get wrong and names it: a component whose
FMU is missing from the archive, a connection to a connector the component or its FMU does not
have, a unit that differs between the two ends of a connection or from the FMU's own variable.

An SSP 1.0 input takes one connection: the building takes the wall below's F_top as F_wall_i and
the wall above's F_base as F_above_i and adds them itself, so a wall in every storey can be written.

A user replaces the Building FMU by putting another FMU into resources/ and pointing the
component's `source` at it: it must have the variables the connections name.
"""
import atexit
import pathlib
import shutil
import xml.etree.ElementTree as ET
import zipfile

from .. import scratch
from ..outputs import write_atomic
from .scene import FLOOR_OUT, Scene, WallSpec

NS = {"ssd": "http://ssp-standard.org/SSP1/SystemStructureDescription",
      "ssc": "http://ssp-standard.org/SSP1/SystemStructureCommon",
      "ssv": "http://ssp-standard.org/SSP1/SystemStructureParameterValues"}
for _p, _u in NS.items():
    ET.register_namespace(_p, _u)

# SI base-unit exponents of the units the connectors use (SSP's ssc:BaseUnit)
UNITS = {"m": {"m": 1}, "m/s2": {"m": 1, "s": -2}, "N/m": {"kg": 1, "s": -2}}


class SSPError(ValueError):
    """A malformed or unsupported SSP file, with the reason."""


def _q(prefix, tag):
    return f"{{{NS[prefix]}}}{tag}"


def _fmu_units(fmu):
    from fmpy import read_model_description
    md = read_model_description(str(fmu))
    return {v.name: (v.causality, v.unit or (v.declaredType.unit if v.declaredType is not None else None))
            for v in md.modelVariables}


def _connectors(scene):
    """{instance: {connector: (kind, unit)}} of every connection end and ground input."""
    out = {}
    units = {"building": _fmu_units(scene.building_fmu)}
    wall_units = _fmu_units(scene.wall_fmu)
    for w in scene.walls:
        units[w.name] = wall_units
    ends = [(a, b) for a, b, _, _ in scene.connections()] + [(c, d) for _, _, c, d in scene.connections()]
    for inst, var in ends + scene.ground_inputs():
        causality, unit = units[inst][var]
        out.setdefault(inst, {})[var] = ("input" if causality == "input" else "output", unit)
    return out


def _connector_xml(parent, name, kind, unit):
    c = ET.SubElement(parent, _q("ssd", "Connector"), name=name, kind=kind)
    ET.SubElement(c, _q("ssc", "Real"), unit=unit)


def _parameters_xml(component, real, integer):
    b = ET.SubElement(ET.SubElement(component, _q("ssd", "ParameterBindings")), _q("ssd", "ParameterBinding"))
    ps = ET.SubElement(ET.SubElement(b, _q("ssd", "ParameterValues")), _q("ssv", "ParameterSet"),
                       version="1.0", name=component.get("name") + "_start")
    params = ET.SubElement(ps, _q("ssv", "Parameters"))
    for kind, values in (("Real", real), ("Integer", integer)):
        for k, v in values.items():
            p = ET.SubElement(params, _q("ssv", "Parameter"), name=k)
            ET.SubElement(p, _q("ssv", kind), value=repr(float(v)) if kind == "Real" else str(int(v)))


def _check_single_sources(scene):
    ends = [(c, d) for _, _, c, d in scene.connections()]
    for end in set(ends):
        if ends.count(end) > 1:
            raise SSPError(f"{end[0]}.{end[1]} takes {ends.count(end)} connections: an SSP 1.0 input takes one")


def ssd_xml(scene, sources):
    """The SystemStructure.ssd of `scene` as an ElementTree root; sources: {instance: path in the zip}."""
    _check_single_sources(scene)
    root = ET.Element(_q("ssd", "SystemStructureDescription"), version="1.0", name="RockingWallBuilding")
    system = ET.SubElement(root, _q("ssd", "System"), name="scene")
    _connector_xml(ET.SubElement(system, _q("ssd", "Connectors")), "ag", "input", "m/s2")
    elements = ET.SubElement(system, _q("ssd", "Elements"))
    connectors = _connectors(scene)
    starts = {"building": (scene.building_real, scene.building_integer)}
    starts.update({w.name: (w.real, w.integer) for w in scene.walls})
    for inst, (real, integer) in starts.items():
        comp = ET.SubElement(elements, _q("ssd", "Component"), name=inst, type="application/x-fmu-sharedlibrary",
                             source=sources[inst])
        cons = ET.SubElement(comp, _q("ssd", "Connectors"))
        for name, (kind, unit) in connectors.get(inst, {}).items():
            _connector_xml(cons, name, kind, unit)
        _parameters_xml(comp, real, integer)
    conns = ET.SubElement(system, _q("ssd", "Connections"))
    for a, b, c, d in scene.connections():
        ET.SubElement(conns, _q("ssd", "Connection"), startElement=a, startConnector=b, endElement=c, endConnector=d)
    units = ET.SubElement(root, _q("ssd", "Units"))
    for name, exps in UNITS.items():
        ET.SubElement(ET.SubElement(units, _q("ssc", "Unit"), name=name), _q("ssc", "BaseUnit"),
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


# ---- reading --------------------------------------------------------------------------------------

def _parameters(comp):
    real, integer = {}, {}
    for p in comp.iterfind(".//ssv:Parameter", NS):
        r, i = p.find("ssv:Real", NS), p.find("ssv:Integer", NS)
        if r is not None:
            real[p.get("name")] = float(r.get("value"))
        elif i is not None:
            integer[p.get("name")] = int(i.get("value"))
        else:
            raise SSPError(f"parameter {p.get('name')!r} of {comp.get('name')}: only Real and Integer values are read")
    return real, integer


def _declared(comp):
    return {c.get("name"): (c.get("kind"), (c.find("ssc:Real", NS).get("unit") if c.find("ssc:Real", NS) is not None
                                            else None))
            for c in comp.iterfind("ssd:Connectors/ssd:Connector", NS)}


def _check_end(inst, var, declared, fmu_vars, where):
    if inst not in declared:
        raise SSPError(f"{where}: no component named {inst!r}")
    if var not in declared[inst]:
        raise SSPError(f"{where}: component {inst!r} has no connector {var!r}")
    if var not in fmu_vars[inst]:
        raise SSPError(f"{where}: the FMU of {inst!r} has no variable {var!r}")
    unit, fmu_unit = declared[inst][var][1], fmu_vars[inst][var][1]
    if unit != fmu_unit:
        raise SSPError(f"{where}: connector {inst}.{var} has unit {unit!r}, its FMU's variable {fmu_unit!r}")
    return unit


def _temporary_folder():
    """A folder removed when the process ends (the scene's FMUs live there while it runs)."""
    folder = scratch.make("rw_ssp_")
    atexit.register(shutil.rmtree, folder, True)
    return folder


def read(path, extract_to=None):
    """The Scene of an SSP archive (its FMUs extracted under extract_to, default a temporary folder
    removed when the process ends); SSPError naming what is wrong with it."""
    path = pathlib.Path(path)
    if not zipfile.is_zipfile(path):
        raise SSPError(f"{path}: not an SSP archive (zip)")
    dest = pathlib.Path(extract_to or _temporary_folder())
    with zipfile.ZipFile(path) as z:
        names = set(z.namelist())
        if "SystemStructure.ssd" not in names:
            raise SSPError(f"{path}: no SystemStructure.ssd in the archive")
        try:
            root = ET.fromstring(z.read("SystemStructure.ssd"))
        except ET.ParseError as exc:
            raise SSPError(f"{path}: SystemStructure.ssd is not well-formed XML: {exc}") from None
        comps = root.findall("ssd:System/ssd:Elements/ssd:Component", NS)
        for c in comps:
            if c.get("source") not in names:
                raise SSPError(f"{path}: component {c.get('name')!r}: its FMU {c.get('source')!r} is not in the archive")
        z.extractall(dest)
    return _scene(root, {c.get("name"): c for c in comps}, dest, path)


def _check_building_variables(scene, variables, path):
    """The building FMU (perhaps a user's replacement) has every variable the master reads."""
    n = scene.n_storeys
    needed = ["ag", "rayleighMass", "rayleighStiffness"] + [
        f"{q}_{i}" for i in range(1, n + 1) for q in FLOOR_OUT + ["F_wall", "F_above", "m", "md", "k", "kd"]]
    missing = [v for v in needed if v not in variables]
    if missing:
        raise SSPError(f"{path}: the building's FMU lacks variables the master reads: {', '.join(missing[:8])}"
                       + (f" and {len(missing) - 8} more" if len(missing) > 8 else ""))


def _scene(root, comps, dest, path):
    if "building" not in comps:
        raise SSPError(f"{path}: no component named 'building'")
    declared = {n: _declared(c) for n, c in comps.items()}
    declared[None] = {c.get("name"): (c.get("kind"), c.find("ssc:Real", NS).get("unit"))
                      for c in root.iterfind("ssd:System/ssd:Connectors/ssd:Connector", NS)}
    fmu_vars = {n: _fmu_units(dest / c.get("source")) for n, c in comps.items()}
    fmu_vars[None] = declared[None]
    storeys = {}
    for k, con in enumerate(root.iterfind("ssd:System/ssd:Connections/ssd:Connection", NS)):
        a, b, c, d = con.get("startElement"), con.get("startConnector"), con.get("endElement"), con.get("endConnector")
        where = f"{path}: connection {k + 1} ({a or 'system'}.{b} -> {c}.{d})"
        u1, u2 = _check_end(a, b, declared, fmu_vars, where), _check_end(c, d, declared, fmu_vars, where)
        if u1 != u2:
            raise SSPError(f"{where}: unit mismatch, {u1!r} -> {u2!r}")
        if a == "building" and b.startswith("u_top_") and c != "building":
            storeys[c] = int(b.rsplit("_", 1)[1])
    walls = []
    for name in comps:
        if name == "building":
            continue
        if name not in storeys:
            raise SSPError(f"{path}: component {name!r} takes no building.u_top_i: which storey is it in?")
        real, integer = _parameters(comps[name])
        walls.append(WallSpec(storeys[name], real, integer))
    b_real, b_int = _parameters(comps["building"])
    wall_sources = {comps[w].get("source") for w in storeys}
    if len(wall_sources) > 1:
        raise SSPError(f"{path}: the walls use different FMUs {sorted(wall_sources)}; this master takes one")
    scene = Scene(b_real, b_int, walls, building_fmu=str(dest / comps["building"].get("source")),
                  wall_fmu=str(dest / wall_sources.pop()) if wall_sources else None)
    _check_building_variables(scene, fmu_vars["building"], path)
    names = {w.storey: w.name for w in walls}
    for w, storey in storeys.items():
        if w != names[storey]:
            raise SSPError(f"{path}: the wall of storey {storey} must be named {names[storey]!r}, not {w!r}")
    return scene


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
