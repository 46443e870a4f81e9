"""rockingwall couple-building: the walls of a building as FMI 2.0 co-simulation, as an FMI tool
runs them: Building.fmu and a RockingWall.fmu per storey, exchanged by a fixed-step Jacobi master
(second-order: inputs ramped over each macro step; --order 1 holds them); the scene also as an
SSP 1.0 file (--ssp). The wall of storey i stands on floor i-1 and is tied to diaphragm i; the
building comes from a building file (--building) or from --storeys, --walls, --wall and --Kd.

Co-simulation has a stability limit: a brick wall standing on a timber floor is past it with
ramped inputs at every macro step, and with held inputs its stiff tie needs a step of microseconds.
A run whose energy residual passes half of the input work ends with an error naming the likely
cause and the remedy, exit status 1, and nothing of it is printed as a result.
`rockingwall building FILE.toml` solves the same building in one integration, stable at any mass
ratio (docs/building-coupling.md says where the limit lies and how the coupling is made).

    rockingwall couple-building --storeys 2 --record elcentro --scale 0.5
    rockingwall couple-building examples/two-storey-brick.toml elcentro --pga 0.3   # as `building` takes it
    rockingwall couple-building --limits --out results   # the stability limit's tables and plot
"""
import argparse
import shlex
import sys

import numpy as np

from .. import outputs, records, scenes
from ..building import building_file, cosim, ssp
from ..building.scene import default_scene, run
from ..coupling.slaves import CouplingError, CouplingUnstable
from ..names import HINGE_LAWS
from ..sweep import suites
from .common import intensity_g, plausible, scale_factor


def parse_args(argv):
    ap = argparse.ArgumentParser(prog="rockingwall couple-building", description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--storeys", type=int, default=2, help="nStoreys of the building, 1..5")
    ap.add_argument("--walls", help="comma-separated storeys with a wall (default: every storey)")
    ap.add_argument("--wall", type=int, default=1, choices=[1, 2, 3], help="the paper's wall")
    ap.add_argument("--Kd", type=float, default=1e6, help="wall-to-diaphragm connection, N/m per m")
    ap.add_argument("--hinge-law", default="dohertyHinge", choices=list(HINGE_LAWS))
    ap.add_argument("--diaphragm-law", type=int, default=2, choices=[0, 1, 2, 3],
                    help="0 linear, 1 Bouc-Wen, 2 Bouc-Wen with pinching (timber), 3 bilinear")
    ap.add_argument("file", nargs="?", metavar="FILE.toml",
                    help="the building file, as `rockingwall building FILE.toml RECORD` takes it (or --building)")
    ap.add_argument("record_given", nargs="?", metavar="RECORD", help="the record (or --record)")
    ap.add_argument("--record", help="'elcentro' (default), 'gaussian[:D,T]' or an .AT2/.csv file")
    ap.add_argument("--building", metavar="FILE.toml",
                    help="the building file (docs/your-building.md): the Building FMU's parameters from its storeys, "
                         "a RockingWall FMU per wall (instead of --storeys, --walls, --wall, --Kd, --diaphragm-law)")
    ap.add_argument("--scale", type=scale_factor, default=None, help="factor on the record (> 0, default 0.5)")
    ap.add_argument("--pga", type=intensity_g, default=None, help="scales the record to this PGA [g] instead")
    ap.add_argument("--macro-step", type=float, default=1e-3, help="H [s]")
    ap.add_argument("--t-end", type=float, default=None, help="[s], default the record's duration")
    ap.add_argument("--order", type=int, default=2, choices=[1, 2],
                    help="2: inputs ramped with extrapolated derivatives; 1: inputs held")
    ap.add_argument("--ssp", help="also write the scene as an SSP 1.0 file here")
    ap.add_argument("--from-ssp", help="run the scene of this SSP file instead of the options above")
    ap.add_argument("--limits", action="store_true",
                    help="measure the stability limit of docs/building-coupling.md (tables and plot)")
    ap.add_argument("--example", action="store_true",
                    help="generate the worked example of docs/building-coupling.md (plot and table)")
    ap.add_argument("--out", default="results", metavar="DIR",
                    help="folder for --limits' and --example's plot (default results/; docs/img: the document's)")
    ap.add_argument("--records-cache", help="folder of the converted FEMA P695 far-field records "
                                            "(default: the one `rockingwall sweep` uses)")
    a = ap.parse_args(argv)
    for given, option in ((a.file, "building"), (a.record_given, "record")):
        if given is not None and getattr(a, option) is not None:
            ap.error(f"the {option} is given twice: {given!r} and --{option} {getattr(a, option)!r}")
        setattr(a, option, getattr(a, option) if given is None else given)
    a.record = a.record or "elcentro"
    return a


def _record(a):
    if a.scale is not None and a.pga is not None:
        raise ValueError("give --scale or --pga, not both")
    rec = records.load(a.record)
    if a.pga is not None:
        if not (a.pga > 0 and np.isfinite(a.pga)):
            raise ValueError(f"--pga {a.pga!r} must be a positive number of g")
        return rec.to_pga(a.pga)
    return rec.scaled(0.5 if a.scale is None else a.scale)


def _remedy(a):
    """The command that runs the same building, record and intensity in one integration (the building
    file's name where there is one)."""
    intensity = f" --pga {a.pga:g}" if a.pga is not None else f" --scale {a.scale:g}" if a.scale is not None else ""
    building = shlex.quote(a.building) if a.building else "FILE.toml"
    return f"`rockingwall building {building} {shlex.quote(a.record)}{intensity}`"


def main(argv=None):
    a = parse_args(argv)
    try:
        if a.example:
            from ..building import example  # scipy and the engine: only the example needs them
            return example.main(a.records_cache or suites.fema_cache(), a.out)
        outputs.protect(a.from_ssp, "the --from-ssp file")
        outputs.protect(a.building, "the building file")
        outputs.protect(records.split_spec(a.record)[0], "the record")
        if a.ssp:
            outputs.check_target(a.ssp, "--ssp")
        if a.limits:
            from ..building import limits
            return limits.main(a.out)
        if a.building and a.from_ssp:
            raise ValueError("give --building or --from-ssp, not both")
        if a.building:
            description = plausible(lambda: building_file.read(a.building), a)
            scene, named = cosim.scene_of(description), scenes.building(description)
        elif a.from_ssp:
            scene = ssp.read(a.from_ssp)
            named = scenes.coupled_building(scene.n_storeys, [w.storey for w in scene.walls], None, None, a.from_ssp)
        else:
            walls = [int(x) for x in a.walls.split(",")] if a.walls else None
            scene = default_scene(a.storeys, walls, a.wall, a.Kd, a.diaphragm_law, a.hinge_law)
            named = scenes.coupled_building(scene.n_storeys, [w.storey for w in scene.walls], a.wall, a.diaphragm_law)
        if a.ssp:
            ssp.write(scene, a.ssp)
            print(f"wrote {a.ssp}")
        rec = _record(a)
        t_end = a.t_end or float(rec.t[-1])
        r = run(scene, rec, t_end, a.macro_step, a.order)
    except CouplingUnstable as exc:
        print(f"couple-building: error: {str(exc).replace('`rockingwall building FILE.toml`', _remedy(a))}",
              file=sys.stderr)
        return 1
    except (ValueError, OSError, CouplingError) as exc:  # refused input: 2; a failed run or file: 1
        print(f"couple-building: error: {exc}", file=sys.stderr)
        return 2 if isinstance(exc, ValueError) else 1
    print(named.text() + f"\nsolved by co-simulation: Building.fmu and a RockingWall.fmu per wall, Jacobi, "
                         f"H = {a.macro_step:g} s, inputs of order {a.order}")
    for w in scene.walls:  # a collapsed wall's peaks are the state it fell from, not a displacement
        t = r["collapsed"].get(w.storey)
        print(f"wall in storey {w.storey}: " + (f"collapsed at t = {t:.3f} s and fell out of the scene" if t is not None
                                               else f"peak s1 {r.peak(w.storey, 's1'):.5f} m, "
                                                    f"s2 {r.peak(w.storey, 's2'):.5f} m"))
    e = r.energy_terms()
    upto = r["time"] <= (r["collapsed_at"] if r["collapsed_at"] is not None else np.inf)
    print(f"energy (up to the first collapse): max |residual| {np.abs(e['residual'][upto]).max():.4g} J/m "
          f"of max input {np.abs(e['input'][upto]).max():.4g} J/m")
    return 0
