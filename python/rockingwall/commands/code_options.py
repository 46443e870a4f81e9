"""The code checks' options (docs/codes.md), shared by `rockingwall assess` and `rockingwall
building`: --code, the site and the wall's place, each with units, checked before any run."""
from .. import assessment_codes, assessment_codes_building


def add_code_arguments(p):
    g = p.add_argument_group("code checks beside the time histories (docs/codes.md; values with units, "
                             "e.g. '5.8m', '0.25g', '0.3s')")
    g.add_argument("--code", nargs="+", choices=assessment_codes.CODES, metavar="CODE",
                   help="add each code's capacity, demand and verdict: nzsee (NZSEE C8 with NZS 1170.5; a "
                        "parapet's check for --support parapet), ntc (NTC 2018, Circolare C8.7.1), asce41 "
                        "(ASCE 41-17 h/t)")
    for flag, (attr, unit, _, text) in assessment_codes.OPTIONS.items():
        g.add_argument(flag, dest=attr, metavar=assessment_codes.METAVARS[unit], help=text)


def code_checks(args, pgas, wall=None, building=None):
    """The code checks of --code on the wall, per hazard (None without --code; assessment_codes.
    checks_by_hazard), or on every storey's wall of the building (assessment_codes_building.
    checks_by_storey); every option checked before any run; pgas [g]: the cases' PGAs."""
    given = [flag for flag, (attr, *_) in assessment_codes.OPTIONS.items() if getattr(args, attr, None) is not None]
    if not getattr(args, "code", None):
        if given:
            raise ValueError(f"{given[0]} is an input of the code checks: give --code too")
        return None
    values = assessment_codes.option_values(args)
    if building is not None:
        return assessment_codes_building.checks_by_storey(building, args.code, values, pgas, given)
    return assessment_codes.checks_by_hazard(wall, args.code, values, pgas, given)
