"""An SSP archive read back into the master's scene, with every problem a hand-edited or hostile
file can have named as an SSPError (the file, the component, the reason), never a traceback:

- the archive: not a zip, damaged, no SystemStructure.ssd, not well-formed XML;
- a component's `source`: absolute, holding '..' or a backslash (it could name a file outside the
  archive), not in the archive, larger than FMU_MAX_BYTES, or not a readable FMU;
- two components with one name; a parameter its FMU does not have, given twice, or whose value is
  not a number; a connector without a type; a connection without its ends, to a component or
  connector that does not exist, between different units, or into an input that another
  connection already feeds;
- a scene the master refuses (a wall outside the building's storeys, two walls in one storey, a
  building FMU without the variables the master reads).

Only what the .ssd references is extracted (the FMUs of its components), each resolved and
required inside the extraction folder, with size limits; other members (junk included) are
never written."""
import atexit
import math
import pathlib
import shutil
import xml.etree.ElementTree as ET
import zipfile
import zlib

from .. import scratch
from .scene import FLOOR_OUT, Scene, WallSpec
from .ssp_common import NS, SSPError, fmu_units

SSD = "SystemStructure.ssd"
SSD_MAX_BYTES = 16 << 20       # a system of a few FMUs is kilobytes
FMU_MAX_BYTES = 512 << 20      # one FMU (the wall's is 0.3 MB, the building's 0.2 MB)
TOTAL_MAX_BYTES = 2 << 30      # everything extracted


def read(path, extract_to=None):
    """The Scene of an SSP archive (its FMUs extracted under extract_to, default a temporary folder
    removed when the process ends); SSPError naming what is wrong with it."""
    path = pathlib.Path(path)
    if not path.is_file() or not zipfile.is_zipfile(path):
        raise SSPError(f"{path}: not an SSP archive (zip)")
    try:
        with zipfile.ZipFile(path) as z:
            root = parse_ssd(z, path)
            comps = components(root, path)
            sources = {name: member(c, z, path) for name, c in comps.items()}
            dest = pathlib.Path(extract_to) if extract_to else temporary_folder()
            extract(z, sources, dest, path)
    except (zipfile.BadZipFile, zlib.error, EOFError, NotImplementedError) as exc:
        raise SSPError(f"{path}: damaged archive: {exc}") from None
    return scene_of(root, comps, sources, dest, path)


def temporary_folder():
    """A folder removed when the process ends (the scene's FMUs live there while it runs)."""
    folder = scratch.make("rw_ssp_")
    atexit.register(shutil.rmtree, folder, True)
    return pathlib.Path(folder)


def parse_ssd(z, path):
    try:
        info = z.getinfo(SSD)
    except KeyError:
        raise SSPError(f"{path}: no {SSD} in the archive") from None
    if info.file_size > SSD_MAX_BYTES:
        raise SSPError(f"{path}: {SSD} is {info.file_size} bytes, more than {SSD_MAX_BYTES}")
    try:
        return ET.fromstring(z.read(SSD))
    except ET.ParseError as exc:
        raise SSPError(f"{path}: {SSD} is not well-formed XML: {exc}") from None


def components(root, path):
    """{name: <ssd:Component>}; a component without a name or a source, or a name given twice, is refused."""
    out = {}
    for c in root.findall("ssd:System/ssd:Elements/ssd:Component", NS):
        name = c.get("name")
        if not name or not c.get("source"):
            raise SSPError(f"{path}: a component without a name or a source (name {name!r})")
        if name in out:
            raise SSPError(f"{path}: two components named {name!r}: each component needs its own name")
        out[name] = c
    return out


def member(comp, z, path):
    """The archive member a component's `source` names: relative, inside the archive, present."""
    source, name = comp.get("source"), comp.get("name")
    parts = source.split("/")
    if source.startswith("/") or "\\" in source or ":" in parts[0] or any(p in ("..", "") for p in parts):
        raise SSPError(f"{path}: component {name!r}: its source {source!r} points outside the archive: give a path "
                       "inside it, such as resources/RockingWall.fmu")
    try:
        z.getinfo(source)
    except KeyError:
        raise SSPError(f"{path}: component {name!r}: its FMU {source!r} is not in the archive") from None
    return source


def extract(z, sources, dest, path):
    """Copy the referenced members (and nothing else) under dest, each resolved inside it, with
    the sizes counted as they are read (a member's declared size is not trusted)."""
    root = dest.resolve()
    total = 0
    owner = {}
    for name, source in sources.items():
        owner.setdefault(source, name)  # the first component that uses it
    for source in sorted(set(sources.values())):
        target = (dest / source).resolve()
        if root not in target.parents:
            raise SSPError(f"{path}: component {owner[source]!r}: its source {source!r} points outside the archive")
        target.parent.mkdir(parents=True, exist_ok=True)
        written = 0
        with z.open(source) as src, open(target, "wb") as out:
            for block in iter(lambda: src.read(1 << 20), b""):
                written += len(block)
                total += len(block)
                if written > FMU_MAX_BYTES or total > TOTAL_MAX_BYTES:
                    raise SSPError(f"{path}: component {owner[source]!r}: {source!r} is larger than "
                                   f"{FMU_MAX_BYTES} bytes (or the FMUs together than {TOTAL_MAX_BYTES})")
                out.write(block)


def fmu_variables(dest, source, name, path):
    try:
        return fmu_units(dest / source)
    except Exception as exc:  # noqa: BLE001  fmpy's reader raises many kinds on a damaged FMU
        raise SSPError(f"{path}: component {name!r}: its FMU {source!r} cannot be read: "
                       f"{type(exc).__name__}: {exc}") from None


def parameters(comp, variables, path):
    """(Real, Integer) start values of a component, each a variable of its FMU, given once."""
    real, integer = {}, {}
    where = f"{path}: component {comp.get('name')!r}"
    for p in comp.iterfind(".//ssv:Parameter", NS):
        name = p.get("name")
        r, i = p.find("ssv:Real", NS), p.find("ssv:Integer", NS)
        if not name or name in real or name in integer:
            raise SSPError(f"{where}: a parameter without a name, or given twice ({name!r})")
        if name not in variables or variables[name][0] in ("output", "independent"):
            raise SSPError(f"{where}: parameter {name!r} is not a parameter of its FMU")
        text = (r if r is not None else i).get("value") if (r is not None or i is not None) else None
        if r is not None:
            real[name] = number(text, float, f"{where}: parameter {name!r}")
        elif i is not None:
            integer[name] = number(text, int, f"{where}: parameter {name!r}")
        else:
            raise SSPError(f"{where}: parameter {name!r}: only Real and Integer values are read")
    return real, integer


def number(text, kind, where):
    try:
        value = kind(text)
    except (TypeError, ValueError):
        raise SSPError(f"{where}: value {text!r} is not {'a number' if kind is float else 'an integer'}") from None
    if kind is float and not math.isfinite(value):
        raise SSPError(f"{where}: value {text!r} is not a finite number")
    return value


def declared(element, owner, path):
    """{connector: (kind, unit)} of a component (or of the system, owner None)."""
    out = {}
    for c in element.iterfind("ssd:Connectors/ssd:Connector", NS):
        real = c.find("ssc:Real", NS)
        if real is None:
            raise SSPError(f"{path}: connector {c.get('name')!r} of {owner or 'the system'} has no type: "
                           "give it <ssc:Real unit=...>")
        out[c.get("name")] = (c.get("kind"), real.get("unit"))
    return out


def check_end(inst, var, connectors, fmu_vars, where):
    if inst not in connectors:
        raise SSPError(f"{where}: no component named {inst!r}")
    if var not in connectors[inst]:
        raise SSPError(f"{where}: component {inst!r} has no connector {var!r}")
    if var not in fmu_vars[inst]:
        raise SSPError(f"{where}: the FMU of {inst!r} has no variable {var!r}")
    unit, fmu_unit = connectors[inst][var][1], fmu_vars[inst][var][1]
    if unit != fmu_unit:
        raise SSPError(f"{where}: connector {inst}.{var} has unit {unit!r}, its FMU's variable {fmu_unit!r}")
    return unit


def storeys_of(root, connectors, fmu_vars, path):
    """Check every connection; {wall component: its storey} from the building.u_top_i feeding it."""
    storeys, fed = {}, {}
    for k, con in enumerate(root.iterfind("ssd:System/ssd:Connections/ssd:Connection", NS)):
        a, b, c, d = con.get("startElement"), con.get("startConnector"), con.get("endElement"), con.get("endConnector")
        where = f"{path}: connection {k + 1} ({a or 'system'}.{b} -> {c or 'system'}.{d})"
        if not b or not d:
            raise SSPError(f"{where}: a connection needs its startConnector and endConnector")
        u1, u2 = check_end(a, b, connectors, fmu_vars, where), check_end(c, d, connectors, fmu_vars, where)
        if u1 != u2:
            raise SSPError(f"{where}: unit mismatch, {u1!r} -> {u2!r}")
        if (c, d) in fed:
            raise SSPError(f"{where}: {c}.{d} is already fed by connection {fed[(c, d)]}: an SSP 1.0 input takes one")
        fed[(c, d)] = k + 1
        if a == "building" and b.startswith("u_top_") and c != "building":
            digits = b[len("u_top_"):]
            if not digits.isdigit():
                raise SSPError(f"{where}: {b!r} names no storey (u_top_1, u_top_2, ...)")
            storeys[c] = int(digits)
    return storeys


def check_building_variables(scene, variables, path):
    """The building FMU (perhaps a user's replacement) has every variable the master reads."""
    n = scene.n_storeys
    needed = ["ag", "rayleighMass", "rayleighStiffness"] + [
        f"{q}_{i}" for i in range(1, n + 1) for q in FLOOR_OUT + ["F_wall", "F_above", "m", "md", "k", "kd"]]
    missing = [v for v in needed if v not in variables]
    if missing:
        raise SSPError(f"{path}: the building's FMU lacks variables the master reads: {', '.join(missing[:8])}"
                       + (f" and {len(missing) - 8} more" if len(missing) > 8 else ""))


def scene_of(root, comps, sources, dest, path):
    if "building" not in comps:
        raise SSPError(f"{path}: no component named 'building'")
    connectors = {n: declared(c, f"component {n!r}", path) for n, c in comps.items()}
    system = root.find("ssd:System", NS)
    connectors[None] = declared(system, None, path) if system is not None else {}
    fmu_vars = {n: fmu_variables(dest, sources[n], n, path) for n in comps}
    fmu_vars[None] = connectors[None]
    storeys = storeys_of(root, connectors, fmu_vars, path)
    walls = []
    for name in comps:
        if name == "building":
            continue
        if name not in storeys:
            raise SSPError(f"{path}: component {name!r} takes no building.u_top_i: which storey is it in?")
        walls.append(WallSpec(storeys[name], *parameters(comps[name], fmu_vars[name], path)))
    b_real, b_int = parameters(comps["building"], fmu_vars["building"], path)
    wall_sources = {sources[w] for w in storeys}
    if len(wall_sources) > 1:
        raise SSPError(f"{path}: the walls use different FMUs {sorted(wall_sources)}; this master takes one")
    try:
        scene = Scene(b_real, b_int, walls, building_fmu=str(dest / sources["building"]),
                      wall_fmu=str(dest / wall_sources.pop()) if wall_sources else None)
    except ValueError as exc:
        raise SSPError(f"{path}: a scene the master cannot run: {exc}") from None
    check_building_variables(scene, fmu_vars["building"], path)
    names = {w.storey: w.name for w in walls}
    for w, storey in storeys.items():
        if w != names[storey]:
            raise SSPError(f"{path}: the wall of storey {storey} must be named {names[storey]!r}, not {w!r}")
    return scene
