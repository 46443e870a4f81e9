"""What every command shares: a wall from the command line, a record, errors as one line."""
import argparse
import pathlib
import re
import sys
import warnings

from .. import bounds, intensity, outputs, records, units
from ..building.building_file import RANGES
from ..building.description import DAMPING_DEFAULT, POST_YIELD_DEFAULT, TIE_DEFAULT, Diaphragm
from ..names import SPRING_LAWS, SUPPORTS
from ..wall import PlausibilityWarning, Wall

WALL_FLAGS = {  # flag -> parameter; values may carry units ('30kN/m/m', '230mm')
    "--b": "b", "--h": "h", "--W": "W", "--psi": "psi", "--Kd": "Kd", "--er": "er",
    "--support": "support", "--hinge-law": "hingeLaw",
    "--pointing": "pointing", "--e-top": "eTop", "--psi-weight-only": "psiWeightOnly",
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
    g.add_argument("--pointing", help="depth of recessed mortar pointing on each face [m]: the effective "
                   "thickness is b - 2 x pointing (NZSEE C8)")
    g.add_argument("--e-top", help="eccentricity of the overburden (psi) from the centreline [m], positive "
                   "toward the inner face (joists bearing on it; outward: --e-top=-20mm); the reactions' "
                   "eccentricities: --set eBaseRatio=.. --set eHingeRatio=..")
    g.add_argument("--psi-weight-only", help="weight-only overburden ratio Wo/W1 [1]: the weight of the walls "
                   "above, whose mass their own equations carry (not moving with the top as mass, unlike --psi)")
    g.add_argument("--set", action="append", default=[], metavar="NAME=VALUE",
                   help="any other parameter by name (rockingwall info lists them)")


def wall_given(args):
    """Did the command line give any of the wall's options?"""
    return args.wall is not None or bool(args.set) or any(
        getattr(args, flag[2:].replace("-", "_")) is not None for flag in WALL_FLAGS)


def wall_from_args(args):
    values = {param: getattr(args, flag[2:].replace("-", "_")) for flag, param in WALL_FLAGS.items()}
    values = {k: v for k, v in values.items() if v is not None}
    for item in args.set:
        name, sep, value = item.partition("=")
        if not sep:
            raise ValueError(f"--set {item!r}: expected NAME=VALUE")
        values[name.strip()] = value.strip()
    return plausible(lambda: Wall.make(preset=args.wall, **values), args)


def add_strict_argument(parser):
    parser.add_argument("--strict", action="store_true",
                        help="every plausibility warning (a unit slip in the wall, K_d or the record) is an error "
                             "(exit 2)")


def warn(message, args):
    """A plausibility warning on standard error, or with --strict an error (ValueError: exit 2)."""
    if getattr(args, "strict", False):
        raise ValueError(f"{message} (--strict: plausibility warnings are errors)")
    print(f"rockingwall: warning: {message}", file=sys.stderr)


def plausible(make, args):
    """make()'s result, its plausibility warnings passed to warn() (errors with --strict); any other
    warning (a library's deprecation, say) goes on as it came, under the filters in force, and is
    never a plausibility error."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", PlausibilityWarning)
        value = make()
    for w in caught:
        if issubclass(w.category, PlausibilityWarning):
            warn(str(w.message), args)
        else:
            warnings.warn_explicit(w.message, w.category, w.filename, w.lineno, source=w.source)
    return value


def check_record(record, args):
    """The record as it will run: a PGA outside the plausible range warns (or fails with --strict)."""
    message = intensity.pga_warning(record)
    if message:
        warn(message, args)
    return record


def add_diaphragm_arguments(parser):
    g = parser.add_argument_group(
        "a diaphragm with mass (the wall tied to it, its supports on the ground); without "
        "--diaphragm-mass the top spring K_d ends at a fixed point (the paper's scene)")
    g.add_argument("--diaphragm-mass", help="the diaphragm's mass per metre of wall, e.g. 200kg/m")
    g.add_argument("--diaphragm-damping",
                   help=f"its damping ratio, e.g. 0.05 or 5%% (default {DAMPING_DEFAULT:g}); its stiffness is --Kd")
    g.add_argument("--tie", help=f"the wall-to-diaphragm connection [N/m per m] (default {TIE_DEFAULT:g})")
    g.add_argument("--diaphragm-law", choices=list(SPRING_LAWS), default="linear",
                   help="its force law (default linear); all of them run on the exact engine; boucWenPinched "
                        "takes timber's pinching (docs/your-building.md)")
    g.add_argument("--diaphragm-yield", help="a hysteretic diaphragm's yield force per metre of wall, e.g. 2kN/m")
    g.add_argument("--diaphragm-post-yield",
                   help=f"its post-yield stiffness ratio in [0, 1] (default {POST_YIELD_DEFAULT:g})")


DIAPHRAGM_OPTIONS = ("diaphragm_mass", "diaphragm_damping", "tie", "diaphragm_yield", "diaphragm_post_yield")


def diaphragm_given(args):
    """Whether any diaphragm option is given (a building file describes its own)."""
    return any(getattr(args, name) is not None for name in DIAPHRAGM_OPTIONS) or args.diaphragm_law != "linear"


def diaphragm_from_args(args, wall):
    """(Diaphragm or None, tie [N/m per m]) from the diaphragm options and the wall's K_d as the
    diaphragm's stiffness; the same ranges as the building file's."""
    tie = units.parse(args.tie, "N/m2", "--tie") if args.tie else TIE_DEFAULT
    damping = (units.parse(args.diaphragm_damping, "1", "--diaphragm-damping") if args.diaphragm_damping is not None
               else DAMPING_DEFAULT)
    if args.diaphragm_mass is None:
        given = [f"--{name.replace('_', '-')}" for name in DIAPHRAGM_OPTIONS if getattr(args, name) is not None]
        if given or args.diaphragm_law != "linear":
            option = given[0] if given else f"--diaphragm-law {args.diaphragm_law}"
            raise ValueError(f"{option} is of a diaphragm with mass: give --diaphragm-mass too")
        return None, tie
    if int(wall.params["support"]) != SUPPORTS["flexibleTop"]:
        raise ValueError("--diaphragm-mass: a diaphragm holds the wall's top (support flexibleTop)")
    mass = _in_range(units.parse(args.diaphragm_mass, "kg/m", "--diaphragm-mass"), "mass", "--diaphragm-mass",
                     " kg/m")
    _in_range(damping, "damping", "--diaphragm-damping", "", " (a ratio: 5 % is 0.05 or 5%)")
    _in_range(tie, "tie", "--tie", " N/m per m")
    return Diaphragm(stiffness=wall.params["Kd"], mass=mass, damping=damping, **_diaphragm_law(args)), tie


def _diaphragm_law(args):
    """The Diaphragm fields of --diaphragm-law, --diaphragm-yield and --diaphragm-post-yield."""
    law = args.diaphragm_law
    if law == "linear":
        for given, option in ((args.diaphragm_yield, "--diaphragm-yield"),
                              (args.diaphragm_post_yield, "--diaphragm-post-yield")):
            if given is not None:
                raise ValueError(f"{option} is of a hysteretic diaphragm: give --diaphragm-law too "
                                 f"({', '.join(k for k in SPRING_LAWS if k != 'linear')})")
        return {}
    if args.diaphragm_yield is None:
        raise ValueError(f"--diaphragm-law {law}: give its yield force too (--diaphragm-yield, e.g. 2kN/m)")
    yield_force = _in_range(units.parse(args.diaphragm_yield, "N/m", "--diaphragm-yield"), "yield_force",
                            "--diaphragm-yield", " N/m")
    post_yield = (_in_range(units.parse(args.diaphragm_post_yield, "1", "--diaphragm-post-yield"), "post_yield",
                            "--diaphragm-post-yield", "") if args.diaphragm_post_yield is not None
                  else POST_YIELD_DEFAULT)
    return {"law": law, "yield_force": yield_force, "post_yield": post_yield}


def _in_range(value, key, option, unit, hint=""):
    """value, if within the building file's range for `key`."""
    low, high = RANGES[key]
    if not low <= value <= high:
        raise ValueError(f"{option} {value:g}{unit}: must be in [{low:g}, {high:g}]{unit}{hint}")
    return value


def slow_scene_note(spec, runs, what):
    """What the runs of a scene the exact engine does not cover will cost, said before they start
    (None where it covers it): CVODES takes seconds a run where the exact engine takes
    milliseconds. spec: the scene solver's Spec; runs: (fewest, most) of them (most: where every
    dense run is refined); what: the scene ('a building with linear diaphragms'); the note gives
    the exact engine's reason."""
    from .. import scene_engine  # the scene solver's library: only for the scenes it runs
    covered, why = scene_engine.exact_covers(spec)
    if covered:
        return None
    fewest, most = runs
    count = f"{fewest} run{'' if fewest == 1 else 's'}" if fewest == most else f"{fewest} to {most} runs"
    return f"{count} of {what}, on CVODES: seconds a run ({why})"


def diaphragm_slow_note(wall, diaphragm, tie, scenes_per_case=1, states=()):
    """slow_scene_note of a wall under `diaphragm` as a function (cases, ensemble), each case run
    for `scenes_per_case` diaphragms (assess's K_d values) with its checks and its members
    (api.under_diaphragm_runs; `states`: the limit states); None for the paper's scene (the exact
    engine, or fmi2sim by choice)."""
    if diaphragm is None:
        return None
    from .. import api  # the scene solver: only for a diaphragm with mass
    from ..building import monolithic
    spec = monolithic.wall_under_diaphragm_spec(wall.params, diaphragm, tie)
    what = f"a wall under a {diaphragm.law} diaphragm"

    def note_for(cases, ensemble):
        per_case = api.under_diaphragm_runs(ensemble, states)
        return slow_scene_note(spec, tuple(cases * scenes_per_case * n for n in per_case), what)
    return note_for


def note(message):
    """A note on stderr, before the work it is about (nothing for None)."""
    if message:
        print(f"rockingwall: note: {message}", file=sys.stderr)


def add_record_arguments(parser, many=False):
    parser.add_argument("records" if many else "record", nargs="*" if many else "?",
                        default=["elcentro"] if many else "elcentro",
                        help="an .AT2 or .csv file, an ESM, GeoNet, K-NET or COSMOS file (FILE:COMPONENT picks a "
                             "component), 'elcentro' (default) or 'gaussian[:D,T]'")
    parser.add_argument("--csv-units", default="g", choices=list(records.CSV_UNITS),
                        help="units of a CSV record's accelerations (default g)")
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


def records_before_lists(argv, list_options):
    """argv with the records a user wrote after a list of numbers moved in front of the options:
    `assess --pga 0.2 0.35 fema` means the record fema, but argparse gives every token after
    --pga to it ('intensity 'fema': not a number'). A list of `list_options` ends at the first
    token that is no number (it does not start with a digit or a point; '30kN/m/m' is a number),
    and what follows it up to the next option is positional. A token that starts like a number and
    is none ('0.2x') stays in the list and is refused there, as before."""
    argv = list(argv)
    moved, k, in_list = [], 1, False
    while k < len(argv):
        token = argv[k]
        if token == "--":
            break
        if token.startswith("-") and not _starts_like_number(token):
            in_list = token in list_options  # '--pga=0.1' is a whole option: what follows is no list
        elif in_list and not _starts_like_number(token):
            moved.append(argv.pop(k))
            continue
        k += 1
    return argv[:1] + moved + argv[1:]


def _starts_like_number(token):
    return bool(re.match(r"[-+]?(\d|\.\d)", token))


def load_record(spec, units="g"):
    """records.load, the file (if it is one) registered as an input no output may replace."""
    record = records.load(spec, units=units)
    path, _ = records.split_spec(spec)
    outputs.protect(path, "the record")  # a name (elcentro, gaussian) is no file: nothing registered
    return record


def record_from_args(spec, args):
    record = load_record(spec, units=args.csv_units)
    if args.pga is not None:
        record = record.to_pga(args.pga)
    elif args.scale is not None:
        record = record.scaled(args.scale)
    return check_record(record, args)


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


def folders_to_make(path):
    """The folders output_dir(path) would create, deepest first (remove_empty_folders after a failure)."""
    missing, p = [], pathlib.Path(path).absolute()
    while not p.exists() and p != p.parent:
        missing.append(p)
        p = p.parent
    return missing


def remove_empty_folders(folders):
    """Removes the folders a failed command made that are still empty, deepest first: it leaves nothing."""
    for folder in folders:
        try:
            folder.rmdir()
        except OSError:  # not empty (something else wrote there), or gone: left as it is
            continue


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


def add_ensemble_arguments(parser, default):
    from ..ensemble import FIELDS, Spreads
    g = parser.add_argument_group(
        "robustness: the case run again for an ensemble of walls within the inputs' uncertainty (docs/robustness.md)")
    g.add_argument("--ensemble", type=int, default=default, metavar="N",
                   help=f"members per case (default {default}{': none' if not default else '; 0: none'})")
    g.add_argument("--seed", type=int, default=1, help="the ensemble's seed (default 1): the same members every run")
    defaults = Spreads()
    g.add_argument("--spread", action="append", default=[], metavar="NAME=VALUE",
                   help="an input's spread (repeatable): the standard deviation of ln(value) (e_r: of the value); "
                        "defaults " + ", ".join(f"{n}={getattr(defaults, n):g}" for n in FIELDS))


def ensemble_from_args(args):
    """The ensemble the options ask for, or None (--ensemble 0)."""
    from ..ensemble import Ensemble, Spreads
    if args.ensemble == 0:
        if args.spread:
            raise ValueError("--spread: give an ensemble size (--ensemble N) too")
        return None
    return Ensemble(size=args.ensemble, seed=args.seed, spreads=Spreads.parse(args.spread))
