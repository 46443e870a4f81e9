"""RockingWall coupled to a Diaphragm FMU through FMI 2.0 Co-Simulation.

The paper's top spring K_d is fixed to the ground at its far end; here its far end is a diaphragm
with mass, stiffness and damping (build/Diaphragm.fmu). Both FMUs are Co-Simulation slaves that
integrate themselves with CVODE; a master exchanges their values every macro step H:

    ground motion ag(t)  --> wall.ag,  diaphragm.ag          [m/s2, + toward +x]
    diaphragm.u          --> wall.u_top                      [m, relative to the ground]
    wall.F_top           --> diaphragm.F_top                 [N/m, force of the spring on the diaphragm]

Two independent masters run the same fixed-step Jacobi scheme (every slave steps from t to t+H
with the inputs set at t; after the step the outputs at t+H become the inputs of the next step):
fmpy (FMU2Slave) and libcosim (libcosimpy). The command line runs each master in a child process
(this script with --json), so an FMU that crashes or a libcosim abort ends in a message naming
the master and the signal, not a dead interpreter; every file the child unpacks goes into a
temporary folder removed afterwards. The ground motion is held over each step in both. For the
wall's answer rather than the coupling's, `rockingwall run --Kd k --diaphragm-mass m
--diaphragm-damping zeta --tie Kd` solves the same scene in one integration (the diaphragm's k, m
and zeta as its stiffness, mass and damping, couple's K_d as the tie; no macro step, no limit).

    rockingwall couple                                  # wall 1, El Centro x 0.5, fmpy master
    rockingwall couple --master both                    # fmpy and libcosim, and their difference
    rockingwall couple --macro-step 0.005 --t-end 20 --Kd 1e5 --m 2000 --k 7e5 --zeta 0.05
    rockingwall couple --monolithic                     # both FMUs as Model Exchange under one CVODE

The macro step defaults to the largest one the tie K_d allows (coupling.rules.max_macro_step:
H <= c sqrt(m_r/K_d), docs/coupling.md), at most 1 ms; a larger --macro-step (--step) is run with a
warning. A run whose energy residual exceeds --energy-share of the peak ground work (1 %) is
flagged: a warning on stderr, "energy_ok": false in the summary JSON, and exit status 3 with
--strict. A run whose residual passes half of the ground work (coupling.rules.ENERGY_STOP_SHARE)
has gone unstable: it ends with an error naming the likely cause and the remedy, exit status 1,
and nothing of it is written or printed as a result. --monolithic integrates both FMUs as Model Exchange under one CVODE (no macro step).

Writes into --out (default results/) couple.csv (time, s1, s2, u, F_top and the energy terms),
couple.png and couple.json (the summary: peaks, step, step limit, energy residual share and flags).
"""
import argparse
import math
import pathlib
import sys

import numpy as np

from .. import outputs, paths, records, scenes, strict_json
from ..building.description import Diaphragm
from ..coupling import isolation, output, rules
from ..coupling.slaves import CouplingError
from ..coupling.wall_diaphragm import (MACRO_STEP_DEFAULT_MAX, MACRO_STEP_MIN, RTOL_RANGE, T_END_RANGE,
                                       check_options, macro_step, parse_settings, unstable_message,
                                       wall_start_values)
from ..names import HINGE_LAWS as LAWS
from .common import folders_to_make, output_dir, remove_empty_folders, scale_factor

EXIT_FLAGGED = 3               # --strict: the run finished but a safety check failed


def _stiffness(text):
    """A stiffness per metre of wall in N/m per m, from a bare number or a value with its unit."""
    from ..units import parse
    return parse(text, "N/m2", "stiffness")


def parse_args(argv):
    ap = argparse.ArgumentParser(prog="rockingwall couple", description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--wall-fmu", help="default: the installed RockingWall.fmu")
    ap.add_argument("--diaphragm-fmu", help="default: the installed Diaphragm.fmu")
    ap.add_argument("--record", default="elcentro", help="'elcentro' (quakeio) or a PEER .AT2 file")
    ap.add_argument("--scale", type=scale_factor, default=0.5, help="factor on the record (> 0, default 0.5)")
    ap.add_argument("--wall", type=int, default=1, choices=[1, 2, 3], help="the paper's wall")
    ap.add_argument("--Kd", type=_stiffness, default=1e5,
                    help="wall-to-diaphragm spring, N/m per m of wall, or with a unit (100kN/m/m)")
    ap.add_argument("--hinge-law", default="dohertyHinge", choices=list(LAWS))
    ap.add_argument("--m", type=float, default=2000.0, help="diaphragm mass, kg per m of wall")
    ap.add_argument("--k", type=_stiffness, default=7e5,
                    help="diaphragm stiffness, N/m per m of wall, or with a unit (700kN/m/m)")
    ap.add_argument("--zeta", type=float, default=0.05)
    ap.add_argument("--macro-step", "--step", dest="macro_step", type=float, default=None,
                    help=f"communication step H [s], in [{MACRO_STEP_MIN:g}, t_end]; default: the largest "
                         f"step the tie K_d allows (docs/coupling.md), at most {MACRO_STEP_DEFAULT_MAX:g} s; "
                         f"a larger one runs with a warning")
    ap.add_argument("--set", action="append", default=[], metavar="NAME=VALUE",
                    help="a Real parameter of RockingWall (b, h, W, psi, er, ...) replacing the --wall's, in SI or "
                         "with its unit (W=14.08kN/m, b=230mm); repeatable")
    ap.add_argument("--energy-share", type=float, default=rules.ENERGY_SHARE_MAX,
                    help="flag the run when max |energy residual| exceeds this share of max |ground work| "
                         f"(default {rules.ENERGY_SHARE_MAX:g})")
    ap.add_argument("--strict", action="store_true",
                    help=f"exit with status {EXIT_FLAGGED} when the run is flagged (energy residual too large, "
                         f"or a macro step above the tie's limit)")
    ap.add_argument("--monolithic", action="store_true",
                    help="both FMUs as Model Exchange under one CVODE (fmpy.sundials): no macro step "
                         f"(--macro-step is then the output interval, default {MACRO_STEP_DEFAULT_MAX:g} s)")
    ap.add_argument("--summary", default=None,
                    help="the summary JSON (default: beside the CSV, suffix .json)")
    ap.add_argument("--t-end", type=float, default=30.0, help=f"[s], in [{T_END_RANGE[0]:g}, {T_END_RANGE[1]:g}]")
    ap.add_argument("--rtol", type=float, default=1e-6, help=f"the slaves' tolerance, in [{RTOL_RANGE[0]:g}, {RTOL_RANGE[1]:g}]")
    ap.add_argument("--master", choices=["fmpy", "libcosim", "both", "monolithic"], default="fmpy",
                    help="fmpy or libcosim (Co-Simulation), both; monolithic is what --monolithic runs")
    ap.add_argument("--out", default="results",
                    help="a folder (created if missing) for couple.csv, couple.png and couple.json (default "
                         "results), or the time histories' CSV file (FILE.csv: the plot and summary beside it)")
    ap.add_argument("--plot", default=None, help="the plot (default: beside the CSV, suffix .png)")
    ap.add_argument("--json", help="run one master in this process and write its result arrays as JSON "
                                   "(how the command line runs each master in a child process)")
    a = ap.parse_args(argv)
    a.wall_fmu = a.wall_fmu or str(paths.wall_fmu())
    a.diaphragm_fmu = a.diaphragm_fmu or str(paths.diaphragm_fmu())
    return a


def report(master, r, a):
    end = (f", wall collapsed at t = {r['collapsed_at']:.3f} s" if r.get("collapsed_at") is not None
           else f", to t = {r['time'][-1]:g} s")
    step = "no macro step (one CVODE)" if master == "monolithic" else f"H = {a.macro_step:g} s"
    print(f"{master} master, {step}: peak s1 {np.abs(r['wall_s1']).max():.5f} m, "
          f"s2 {np.abs(r['wall_s2']).max():.5f} m, diaphragm u {np.abs(r['dia_u']).max():.5f} m{end}")


def resolve_macro_step(a):
    """(limit, warning): sets a.macro_step (the tie's limit by default); the warning, when a
    requested step exceeds the limit, is printed after the run: a failure's own error comes first."""
    wall_real, _ = wall_start_values(a.wall, a.Kd, a.hinge_law, overrides=parse_settings(a.set))
    a.macro_step, limit, warning = macro_step(wall_real, {"m": a.m, "k": a.k, "zeta": a.zeta}, a.macro_step,
                                              a.t_end, monolithic=a.monolithic)
    return limit, warning


def unstable_masters(results, a):
    """The error of the first master whose energy residual passed rules.ENERGY_STOP_SHARE of the
    ground work (the fmpy master stops itself there; libcosim's is checked after its run), or None."""
    wall = wall_start_values(a.wall, a.Kd, a.hinge_law, overrides=parse_settings(a.set))
    for master, r in results.items():
        residual, work = r.energy_residual(), r.ground_work()
        share, ok = rules.energy_check(residual, work, rules.ENERGY_STOP_SHARE)
        if not ok:
            k = int(np.argmax(np.abs(residual) > rules.ENERGY_STOP_SHARE * np.abs(work).max()))
            explain = unstable_message(wall, {"m": a.m, "k": a.k}, a.macro_step)
            return f"{master} master: " + explain(float(r["time"][k]), float(residual[k]), float(np.abs(work).max()))
    return None


def csv_file(a):
    """The time histories' CSV: --out itself where it names a .csv file, else couple.csv in the
    folder --out (as the other commands' --out DIR)."""
    out = pathlib.Path(a.out)
    return out if out.suffix.lower() == ".csv" else out / "couple.csv"


def plot_file(a):
    return pathlib.Path(a.plot or csv_file(a).with_suffix(".png"))


def summary_file(a):
    return pathlib.Path(a.summary or csv_file(a).with_suffix(".json"))


def check_files(a, made):
    """Before the run: the FMUs and the record are inputs the outputs never replace, the three
    outputs are three files, and their folders exist (created: a folder that cannot be made
    fails here, not after the run). The folders it makes go into `made`, deepest first, as they
    are made (so a failure at the second target still knows the first's), for a failed run to remove."""
    outputs.protect(a.wall_fmu, "the wall FMU")
    outputs.protect(a.diaphragm_fmu, "the diaphragm FMU")
    outputs.protect(records.split_spec(a.record)[0], "the record")
    targets = {"--out": csv_file(a), "--plot": plot_file(a), "--summary": summary_file(a)}
    outputs.check_targets(list(targets.values()), "output")
    for option, target in targets.items():
        new = folders_to_make(target.parent)
        output_dir(target.parent, option)
        made[:0] = new  # a later target's folders may sit inside an earlier one's: deepest first


def main(argv=None):
    a = parse_args(argv)
    step_warning, made = None, []  # made: the output folders made, removed again if the run fails
    try:
        if a.json:  # the child: one master here, its arrays to the parent
            check_options(a.t_end, a.macro_step, a.rtol)
            isolation.write_result(isolation.run_in_this_process(a), a.json)
            return 0
        if not (math.isfinite(a.energy_share) and a.energy_share > 0):
            raise ValueError(f"--energy-share {a.energy_share!r} must be a positive number")
        if a.monolithic and a.master != "fmpy":
            raise ValueError("--monolithic runs one CVODE over both FMUs: it takes no --master")
        check_options(a.t_end, a.macro_step if a.macro_step is not None else min(a.t_end, 1e-3), a.rtol)
        check_files(a, made)
        limit, step_warning = resolve_macro_step(a)
        check_options(a.t_end, a.macro_step, a.rtol)
        masters = ["monolithic"] if a.monolithic else ["fmpy", "libcosim"] if a.master == "both" else [a.master]
        results = {m: isolation.run_child(m, a) for m in masters}
    except (ValueError, OSError, CouplingError) as exc:
        remove_empty_folders(made)
        print(f"{isolation.ERROR}{exc}", file=sys.stderr)
        if step_warning:
            print(f"{isolation.PROG}: warning: {step_warning}", file=sys.stderr)
        return 2 if isinstance(exc, ValueError) and not isinstance(exc, CouplingError) else 1
    if step_warning:
        print(f"{isolation.PROG}: warning: {step_warning}", file=sys.stderr)
    unstable = unstable_masters(results, a)
    if unstable:
        remove_empty_folders(made)
        print(f"{isolation.ERROR}{unstable}", file=sys.stderr)
        return 1
    r = results[masters[0]]
    scene = scenes.diaphragm(Diaphragm(stiffness=a.k, mass=a.m, damping=a.zeta), a.Kd)
    print(scene.text())
    output.save_csv(r, csv_file(a))
    record = records.load(a.record).scaled(a.scale).name  # the children ran it: here only its name
    title = (f"{record}, wall {a.wall}, " + ("monolithic (one CVODE)" if a.monolithic else
                                             f"co-simulation, H = {a.macro_step:g} s") + f"\nscene: {scene.title}")
    output.plot(r, plot_file(a), title, results.get("libcosim") if len(masters) == 2 else None)
    for m in masters:
        report(m, results[m], a)
    info = dict(output.summary(r, masters[0], a.macro_step, a.energy_share, limit, step_warning), scene=scene.to_dict())
    summary_path = summary_file(a)
    outputs.write_atomic(summary_path, lambda tmp: strict_json.write(info, tmp), "--summary")
    print(f"energy: max |residual| {info['energy_residual_max']:.4g} J/m against "
          f"max |ground work| {info['ground_work_max']:.4g} J/m")
    if not info["energy_ok"]:
        share = info["energy_residual_share"]
        print(f"{isolation.PROG}: warning: ENERGY CHECK FAILED: the energy residual is "
              f"{'unbounded' if share is None else f'{100 * share:.3g} %'} of the ground work, above "
              f"{100 * a.energy_share:g} %: the coupled result is not to be trusted (a smaller --macro-step, "
              f"or --monolithic)", file=sys.stderr)
    if len(masters) == 2:
        other = results["libcosim"]
        n = min(len(r["time"]), len(other["time"]))
        print(f"max |s1 fmpy - s1 libcosim| = {np.abs(r['wall_s1'][:n] - other['wall_s1'][:n]).max():.3g} m")
    print(f"wrote {csv_file(a)}, {plot_file(a)} and {summary_path}" + ("  [FLAGGED: see the warnings]" if info["flagged"] else ""))
    return EXIT_FLAGGED if (a.strict and info["flagged"]) else 0
