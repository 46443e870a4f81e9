"""rockingwall assess: one wall (or the walls of a building) under one or more records, at several
intensities and diaphragm stiffnesses; per case the record's PGA, the peaks with units,
s1/Delta_u, the limit states reached, collapse, and the case's robustness (the probability of
collapse and of each limit state in an ensemble of walls within the inputs' uncertainty, the
16/50/84 % peaks, a flag where the outcome flips); per limit state a fragility with its
uncertainty; IDA 'resurrections' reported.

  rockingwall assess --b 230mm --h 3.2 --W 14.08kN/m --psi 0.2 --kd-values 30kN/m/m 100kN/m/m \\
      --pga 0.1 0.2 0.35 0.5 fema --out results/assess
  rockingwall assess --building house.toml fema --pga 0.2 0.35 0.5 --table md

Records: .AT2 or .csv files, 'elcentro', 'gaussian[:D,T]', or 'fema' (the 44 FEMA P695 far-field
components). Intensities: --pga (each record scaled to each PGA, g), --sa with --sa-period (to
each Sa(T, 5 %), g) or --scale (factors on the records as given). Each run lasts its record.
--code nzsee ntc asce41 adds each code's capacity, demand and verdict to every case (docs/codes.md);
with --building, each storey's wall is checked at its own place in the building.
Writes cases.csv, one IDA plot per record (<record>.png), fragility.png, fragility.csv (codes.json
with --code) and manifest.json (the run's files; "complete": true once all are in place). The
folder then holds this run's files only: those of an earlier assessment it does not write again are
removed (unless edited since), other files are left alone."""
import dataclasses
import sys

from tqdm import tqdm

from .. import (assessment, assessment_building, assessment_codes, assessment_codes_building, assessment_report,
               engine, intensity, limits, records, scenes, strict_json, units)
from ..api import ENGINES, PARAPET_ON_CVODE
from ..ensemble import DIAPHRAGM_FIELDS, FIELDS as SPREAD_FIELDS, HYSTERETIC_FIELDS
from ..names import SUPPORTS
from ..output_folder import MANIFEST, OutputFolder
from . import common as cc
from .code_options import add_code_arguments, code_checks


# the options that take a list of numbers: the records may follow them (cc.records_before_lists)
NUMBER_LISTS = ("--pga", "--sa", "--scale", "--kd-values")


def parser(sub):
    p = sub.add_parser("assess", help="a wall's assessment: records x intensities x K_d, limit states, fragility",
                       description=__doc__, formatter_class=cc.Parser().formatter_class)
    cc.add_wall_arguments(p)
    cc.add_diaphragm_arguments(p)
    p.add_argument("--building", metavar="FILE", help="assess every storey's wall of the building in FILE (TOML, "
                   "docs/your-building.md) instead of one wall")
    p.add_argument("records", nargs="+", help="records: files, elcentro, gaussian[:D,T] or fema")
    p.add_argument("--csv-units", default="g", choices=list(records.CSV_UNITS),
                   help="units of a CSV record's accelerations (default g)")
    level = p.add_mutually_exclusive_group(required=True)
    level.add_argument("--pga", type=cc.intensity_g, nargs="+", help="target PGAs [g]")
    level.add_argument("--sa", type=cc.intensity_g, nargs="+", help="target Sa(T, 5 %%) [g] at --sa-period")
    level.add_argument("--scale", type=cc.scale_factor, nargs="+", help="factors on the records as given")
    p.add_argument("--sa-period", type=float, help="T [s] of Sa (e.g. the diaphragm's period); also reported")
    p.add_argument("--kd-values", nargs="+", help="diaphragm stiffnesses (default: the wall's K_d), e.g. 30kN/m/m")
    p.add_argument("--limit", action="append", metavar="'NAME: Q >= VALUE'",
                   help="a limit state (repeatable), Q one of s1, s2, F_top; VALUE e.g. 50mm, 10kN/m, 0.6*Delta_u; "
                        f"checked besides {'; '.join(limits.DEFAULTS)} and collapse")
    p.add_argument("--engine", default="exact", choices=ENGINES, help="the nominal runs' engine (the ensembles run "
                   "on the exact engine or the scene solver)")
    p.add_argument("--table", default="text", choices=["text", "md"],
                   help="the cases as aligned text (default) or a Markdown table to paste into a report")
    p.add_argument("--out", default="results/assess", help="output folder (created if missing)")
    cc.add_ensemble_arguments(p, default=100)
    cc.add_strict_argument(p)
    add_code_arguments(p)
    p.set_defaults(command=main)
    return p


@dataclasses.dataclass
class Study:
    """What the command runs: run(levels, ensemble) -> (cases, outcomes); the limit states (per
    storey for a building), the report's head lines, the scene, the plots' title, the group column,
    the wall (None for a building), the building (None for a wall), the inputs an ensemble
    perturbs in this scene, and for a scene off the exact engine what its runs cost."""
    run: object
    states: list
    head: list
    scene_text: str
    title: str
    column: str
    wall: object = None
    building: object = None
    spread_fields: tuple = SPREAD_FIELDS
    slow_note: object = None  # slow_note(levels, ensemble): what CVODES will cost, or None


def output_names(recs, codes):
    names = ["cases.csv", "fragility.csv", "fragility.png"] + [f"{cc.file_stem(r.name)}.png" for r in recs]
    return names + (["codes.json"] if codes is not None else [])


def main(args):
    if args.sa and not args.sa_period:
        raise ValueError("--sa needs --sa-period")
    ensemble = cc.ensemble_from_args(args)
    study = building_study(args) if args.building else wall_study(args)
    study.head.append(f"ensemble: {ensemble.describe(study.spread_fields)}; FLIPS: the nominal outcome differs in at least 5 % of it"
                      if ensemble else "ensemble: none (--ensemble 0)")
    recs = assessment.load_records(args.records, args.csv_units)
    lvs = assessment.levels(recs, args)
    codes = code_checks(args, [lv.record.pga / intensity.G for lv in lvs], wall=study.wall, building=study.building)
    code_view = assessment_codes_building if args.building else assessment_codes  # one wall, or per storey
    if codes is not None:
        study.head.extend(code_view.head_lines(codes))
    for message in dict.fromkeys(intensity.pga_value_warning(lv.name, lv.record.pga / intensity.G) for lv in lvs):
        if message:
            cc.warn(message, args)  # --strict: refused before any run
    out = OutputFolder(cc.output_dir(args.out), "rockingwall assess")
    out.check(output_names(recs, codes))  # before the runs: no output replaces an input
    if study.slow_note:
        cc.note(study.slow_note(len(lvs), ensemble))
    cases, outcomes = study.run(lvs, ensemble)
    if codes is not None:
        cases = code_view.add_to_cases(cases, codes)
    # the names (the thresholds are each storey's wall's own): the first wall's
    states = next(st for st in study.states if st is not None) if args.building else study.states
    frag = assessment.fragilities(cases, states, study.column, outcomes)
    im_name = f"Sa({args.sa_period:g} s, 5 %) [g]" if args.sa else "PGA [g]"
    with out:  # the folder holds this run's files only, swapped in when all are written
        write_files(out, cases, frag, recs, [] if args.building else states, im_name, study)
        if codes is not None:
            out.write("codes.json", lambda tmp: strict_json.write(code_view.to_json(codes), tmp))
    print(f"wrote {out.path}/cases.csv, fragility.csv, fragility.png, {MANIFEST} and {len(recs)} IDA plots",
          file=sys.stderr)
    print(assessment_report.report(study.head, states, cases, frag, im_name, args.table,
                                   args.sa_period, study.column, study.scene_text))
    return 0  # the report last: a closed pipe cannot lose the files


def wall_study(args):
    wall = cc.wall_from_args(args)
    has_spring = int(wall.params["support"]) == SUPPORTS["flexibleTop"]
    if args.kd_values and not has_spring:
        raise ValueError("--kd-values: the wall's support has no top spring; K_d is used with --support "
                         "flexibleTop only")
    kds = sorted({units.parse(k, "N/m2", "K_d") for k in args.kd_values}) if args.kd_values else [wall.params["Kd"]]
    # each K_d checked (range, plausibility) before any run
    walls = {kd: cc.plausible(lambda kd=kd: wall.replace(Kd=kd), args) for kd in kds} if has_spring else {None: wall}
    diaphragm, tie = cc.diaphragm_from_args(args, wall)
    states = limits.parse_all(args.limit, wall)
    if diaphragm is not None:
        scene = scenes.diaphragm(diaphragm, tie).text().replace(units.format_kd(diaphragm.stiffness), "K_d (each above)")
    elif has_spring:
        scene = scenes.paper(dict(wall.params, Kd=kds[0])).text().replace(f"K_d = {units.format_kd(kds[0])}",
                                                                           "K_d (each above)")
    else:
        scene = scenes.paper(wall.params).text()
    head = [f"wall: {wall.describe(with_kd=False)}"]
    if has_spring:
        head.append(("diaphragm stiffness K_d: " if diaphragm else "K_d: ") + ", ".join(map(units.format_kd, kds)))
    head += [f"Delta_u = {wall.delta_u * 1e3:.1f} mm; limit states: " + "; ".join(s.describe() for s in states),
             scene]
    if args.engine == "exact" and diaphragm is None and not engine.covers(wall.params):
        head.append(f"solved by {PARAPET_ON_CVODE}")

    def run(lvs, ensemble):
        return assessment.run_cases(walls, lvs, args, states, ensemble, diaphragm, tie)
    hysteretic = diaphragm is not None and diaphragm.law != "linear"
    varied = tuple(f for f in SPREAD_FIELDS  # a massless or absent spring has no diaphragm to perturb
                   if (diaphragm is not None or f not in DIAPHRAGM_FIELDS) and (has_spring or f != "Kd")
                   and (hysteretic or f not in HYSTERETIC_FIELDS))
    return Study(run, states, head, scene, wall.describe(with_kd=False), assessment.KD_COLUMN, wall,
                 spread_fields=varied, slow_note=cc.diaphragm_slow_note(wall, diaphragm, tie, len(kds), states))


def building_study(args):
    from ..building import building_file, monolithic
    if cc.wall_given(args) or cc.diaphragm_given(args) or args.kd_values:
        raise ValueError("--building FILE describes the walls and diaphragms: give no wall, diaphragm or --kd-values "
                         "options")
    if args.engine != "exact":
        raise ValueError("--building runs on the scene solver: --engine does not apply")
    building = cc.plausible(lambda: building_file.read(args.building), args)
    states = assessment_building.storey_states(building, args.limit)
    scene = scenes.building(building).text()
    head = [building.describe(), "limit states: " + " | ".join(
        f"storey {i + 1}: " + "; ".join(s.describe() for s in st) for i, st in enumerate(states) if st), scene]

    def run(lvs, ensemble):
        return assessment_building.run_cases(building, lvs, states, ensemble)
    hysteretic = building.diaphragm_law != "linear"
    varied = tuple(f for f in SPREAD_FIELDS if hysteretic or f not in HYSTERETIC_FIELDS)

    def slow_note(cases, ensemble):
        runs = tuple(cases * n for n in assessment_building.case_runs(states, ensemble))
        return cc.slow_scene_note(monolithic.building_spec(building), runs,
                                  f"a building with {building.diaphragm_law} diaphragms")
    return Study(run, states, head, scene, building.name, assessment_building.STOREY_COLUMN, building=building,
                 spread_fields=varied, slow_note=slow_note)


def write_files(out, cases, frag, recs, states, im_name, study):
    csv = cases.replace([float("inf"), float("-inf")], float("nan"))  # a collapsed percentile: empty, not inf
    out.write("cases.csv", lambda tmp: csv.to_csv(tmp, index=False, float_format="%.6g"))
    out.write("fragility.csv", lambda tmp: frag.to_csv(tmp, index=False, float_format="%.6g"))
    from .. import assessment_plots  # matplotlib: imported when the plots are drawn
    scene = study.scene_text.splitlines()[0].replace("(each above)", "(per legend)")  # each plot names it
    for rec in tqdm(recs, desc="plots", unit="plot", file=sys.stderr, delay=2):
        d = cases[cases.record == rec.name]
        out.write(f"{cc.file_stem(rec.name)}.png", lambda tmp, d=d, rec=rec: assessment_plots.ida(
            d, f"{rec.name}: {study.title}\n{scene}", states, im_name, tmp, study.column))
    out.write("fragility.png", lambda tmp: assessment_plots.fragility(frag, im_name, tmp, study.column,
                                                                      f"{study.title}\n{scene}"))
