"""rockingwall info: every parameter of the wall model with its unit, default and allowed range,
read from the FMU's model description (generated from the one C parameter table)."""
import zipfile
import xml.etree.ElementTree as ET

from . import paths


def parser(sub):
    p = sub.add_parser("info", help="list the parameters with units, defaults and ranges", description=__doc__)
    p.set_defaults(command=main)
    return p


def parameters(fmu=None):
    """[(name, unit, default, min, max, description)] of the FMU's parameters."""
    with zipfile.ZipFile(fmu or paths.wall_fmu()) as z:
        root = ET.fromstring(z.read("modelDescription.xml"))
    rows = []
    for v in root.iter("ScalarVariable"):
        if v.get("causality") != "parameter":
            continue
        kind = next(iter(v))
        rows.append((v.get("name"), kind.get("unit", ""), kind.get("start"), kind.get("min"), kind.get("max"),
                     v.get("description", "")))
    return rows


def main(args):
    print(f"{'name':<12}{'unit':<7}{'default':>9}  {'range':<18}description")
    for name, unit, start, lo, hi, desc in parameters():
        print(f"{name:<12}{unit:<7}{start:>9}  {f'[{lo}, {hi}]':<18}{desc}")
    print("\nUnits: N/m2 is N/m per metre of wall. Values may be given with a unit: '30kN/m/m', '230mm', '14.08kN/m'.")
    return 0
