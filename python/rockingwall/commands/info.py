"""rockingwall info: every parameter of the wall model with its unit, default and allowed range,
read from the FMU's model description (generated from the one C parameter table)."""
from ..fmu_parameters import parameters


def parser(sub):
    p = sub.add_parser("info", help="list the parameters with units, defaults and ranges", description=__doc__)
    p.set_defaults(command=main)
    return p


def main(args):
    rows = parameters()
    ranges = [f"[{lo}, {hi}]" for _, _, _, lo, hi, _ in rows]
    width = max(len("name"), *(len(row[0]) for row in rows)) + 2
    span = max(len("range"), *map(len, ranges)) + 2  # a column as wide as its widest range
    print(f"{'name':<{width}}{'unit':<7}{'default':>9}  {'range':<{span}}description")
    for (name, unit, start, _, _, desc), limits in zip(rows, ranges):
        print(f"{name:<{width}}{unit:<7}{start:>9}  {limits:<{span}}{desc}")
    print("\nUnits: N/m2 is N/m per metre of wall. Values may be given with a unit: '30kN/m/m', '230mm', '14.08kN/m', "
          "a ratio (unit 1) in percent: '20 %'.")
    return 0
