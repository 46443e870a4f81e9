"""What every command shares: a wall from the command line, a record, errors as one line."""
import argparse
import pathlib
import sys
import warnings

from .. import bounds, outputs, records
from ..wall import Wall

WALL_FLAGS = {  # flag -> parameter; values may carry units ('30kN/m/m', '230mm')
    "--b": "b", "--h": "h", "--W": "W", "--psi": "psi", "--Kd": "Kd", "--er": "er",
    "--support": "support", "--hinge-law": "hingeLaw",
}


def add_wall_arguments(parser):
    g = parser.add_argument_group("wall (SI units, or a number with its unit: '230mm', '14.08kN/m', '30kN/m/m')")
    g.add_argument("--wall", metavar="PRESET", help="start from the paper's wall: paper1, paper2, paper3 "
                   "(b = 0.15 m, h = 2.5 m, W = 6.622 kN/m, psi = 0, 0.5, 1)")
    g.add_argument("--b", help="thickness [m]")
    g.add_argument("--h", help="height [m]")
    g.add_argument("--W", help="weight per metre of wall [N/m]")
    g.add_argument("--psi", help="overburden ratio Wd/W1 = 2 x overburden / W [1] (W1 = W/2 is ONE body's "
                   "weight; the overburden moves with the top as mass)")
    g.add_argument("--Kd", help="diaphragm (top spring) stiffness [N/m per m of wall]")
    g.add_argument("--er", help="coefficient of restitution at base impacts [1]")
    g.add_argument("--support", help="parapet, simplySupported, flexibleTop (default flexibleTop)")
    g.add_argument("--hinge-law", help="rigid, semiRigidPaper, semiRigidHinge, dohertyHinge (default)")
    g.add_argument("--set", action="append", default=[], metavar="NAME=VALUE",
                   help="any other parameter by name (rockingwall info lists them)")


def wall_from_args(args):
    values = {param: getattr(args, flag[2:].replace("-", "_")) for flag, param in WALL_FLAGS.items()}
    values = {k: v for k, v in values.items() if v is not None}
    for item in args.set:
        name, sep, value = item.partition("=")
        if not sep:
            raise ValueError(f"--set {item!r}: expected NAME=VALUE")
        values[name.strip()] = value.strip()
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        wall = Wall.make(preset=args.wall, **values)
    for w in caught:
        print(f"rockingwall: warning: {w.message}", file=sys.stderr)
    return wall


def add_record_arguments(parser, many=False):
    parser.add_argument("records" if many else "record", nargs="*" if many else "?",
                        default=["elcentro"] if many else "elcentro",
                        help="an .AT2 or .csv file, an ESM, GeoNet, K-NET or COSMOS file (FILE:COMPONENT picks a "
                             "component), 'elcentro' (default) or 'gaussian[:D,T]'")
    parser.add_argument("--csv-units", default="g", choices=["g", "m/s2"], help="units of a CSV record (default g)")
    level = parser.add_mutually_exclusive_group()
    level.add_argument("--scale", type=scale_factor, help="factor on the record as given (> 0)")
    level.add_argument("--pga", type=intensity_g, help="scale the record to this PGA [g] (> 0)")


def scale_factor(text):
    """An argparse type: a factor on a record, finite and > 0."""
    try:
        return bounds.positive(text, "scale factor")
    except ValueError as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None


def intensity_g(text):
    """An argparse type: a target PGA or Sa [g], finite, > 0 and at most bounds.MAX_AG_G."""
    try:
        return bounds.intensity_g(text, "intensity")
    except ValueError as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None


def load_record(spec, units="g"):
    """records.load, the file (if it is one) registered as an input no output may replace."""
    record = records.load(spec, units=units)
    path, _ = records.split_spec(spec)
    outputs.protect(path, "the record")  # a name (elcentro, gaussian) is no file: nothing registered
    return record


def record_from_args(spec, args):
    record = load_record(spec, units=args.csv_units)
    if args.pga is not None:
        return record.to_pga(args.pga)
    return record.scaled(args.scale) if args.scale is not None else record


def output_dir(path, option="--out"):
    """The output folder, created if missing (its parents too); an error if it is a file."""
    out = pathlib.Path(path)
    if out.exists() and not out.is_dir():
        raise ValueError(f"{option} {out}: exists and is not a folder")
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise ValueError(f"{option} {out}: cannot create the folder: {exc.strerror}") from None
    return out


def file_stem(name):
    """A record's name as a file name: letters, digits, '-', '_' and '.' kept, the rest '_'."""
    return "".join(c if c.isalnum() or c in "-_." else "_" for c in name).strip("_") or "record"


def write_atomic(path, write):
    """outputs.write_atomic: whole or not at all, never over an input, the umask's mode."""
    return outputs.write_atomic(path, write, "--out")


def fail(message, code=2):
    print(f"rockingwall: error: {message}", file=sys.stderr)
    return code


class Parser(argparse.ArgumentParser):
    def __init__(self, **kw):
        kw.setdefault("formatter_class", argparse.RawDescriptionHelpFormatter)
        super().__init__(**kw)
