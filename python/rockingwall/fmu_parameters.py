"""The wall FMU's parameters as its model description declares them (generated from the one C
parameter table): name, unit, default, range and description."""
import xml.etree.ElementTree as ET
import zipfile

from . import paths


def parameters(fmu=None):
    """[(name, unit, default, min, max, description)] of the wall's parameters in the FMU."""
    with zipfile.ZipFile(fmu or paths.wall_fmu()) as z:
        root = ET.fromstring(z.read("modelDescription.xml"))
    rows = []
    for v in root.iter("ScalarVariable"):
        if v.get("causality") != "parameter":
            continue
        kind = next(iter(v))
        if kind.get("min") is None:  # the record's (agFile, agScale): the FMU's, not the wall's
            continue
        rows.append((v.get("name"), kind.get("unit", ""), kind.get("start"), kind.get("min"), kind.get("max"),
                     v.get("description", "")))
    return rows
