"""Parametric sweep of the wall model on Dask: the exact engine in each worker's process (default),
or the RockingWall FMU through fmi2sim (--engine fmi2sim).

The grid is walls x models x hinge laws x K_d x records x intensities, from a TOML file's [grid]
table (--config) and/or the flags below (flags win). Intensities are scale factors on the records
as given (--scales) or target PGAs (--pga, in g: each record is scaled to each). Records are the
FEMA P695 far-field set (--suite fema, 44 components, converted once to AT2 files under
~/.cache/rockingwall/) or a folder of PEER .AT2 files (--suite DIR; ESM, GeoNet, K-NET and COSMOS
files in it are taken too, their first component, docs/records.md).

Runs go to a LocalCluster on this machine (--workers) or to a running Dask scheduler
(--scheduler ADDRESS; its workers need the rockingwall package installed: the records travel
with the tasks; with --engine fmi2sim they must also see fmi2sim, the FMU and the records at the same paths).
Each finished run is appended to one CSV (--out); run the same command again to resume: runs
already in the file, computed from the same inputs (record content, FMU, fmi2sim, settings), are
not repeated; killed or timed-out runs are. A run that fails (e.g. a damaged record) becomes a row
with status 'error' and fmi2sim's message, and the sweep goes on. One sweep at a time per results
file (FILE.lock). Exit status: 0 when every run is finished (even with 'error' rows), 1 when some
runs were killed or timed out (run the command again), the file had damaged lines (set aside
into FILE.set-aside-<time>, named line by line) or the Dask cluster could not be started (nothing
ran: run the command again), 2 for a refused command or file.

Example (the measured sweep of the README):
  rockingwall sweep --config examples/fema_ida.toml --out results/sweep_fema.csv
"""
import argparse
import os
import pathlib
import subprocess
import sys
import time

from .. import outputs, paths
from ..sweep import grid, store
from ..sweep.execute import ClusterError, Terminated, check_options, describe as describe_outcome, execute
from ..sweep.lock import Busy
from .common import plausible

def kd_in_kN(text):
    """K_d in kN/m per m from '30' (taken as kN/m per m) or a value with its unit ('3e4 N/m/m')."""
    from ..units import parse
    try:
        return float(text)
    except ValueError:
        return parse(text, "N/m2", "K_d") / 1e3


def parse_args(argv=None):
    p = argparse.ArgumentParser(prog="rockingwall sweep", description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--config", help="TOML file with a [grid] table (keys: " + ", ".join(grid.DEFAULTS) + ")")
    p.add_argument("--walls", nargs="+", help="walls: presets paper1, paper2, paper3 (or 1, 2, 3), or the names of "
                                              "[walls.NAME] tables (b, h, W, psi) of the --config file")
    p.add_argument("--models", nargs="+", help=", ".join(grid.MODELS))
    p.add_argument("--hinge-laws", dest="hinge_laws", nargs="+", help=", ".join(grid.HINGE_LAWS))
    p.add_argument("--kd", dest="kd_kN", type=kd_in_kN, nargs="+",
                   help="diaphragm stiffnesses K_d: with a unit (30kN/m/m, 3e4N/m/m) or a bare number in kN/m per m "
                        "(the unit of the results' kd_kN column)")
    p.add_argument("--scales", type=float, nargs="+", help="scale factors on the records as given")
    p.add_argument("--pga", dest="pga_g", type=float, nargs="+", help="target PGAs [g] (replaces --scales)")
    p.add_argument("--building", help="a building file (TOML, docs/your-building.md): its storeys' walls under the "
                   "suite and intensities, solved as one building (replaces walls, models, hinge laws and K_d)")
    p.add_argument("--suite", help="'fema' (FEMA P695 far-field) or a folder of .AT2 (or ESM, GeoNet, K-NET, COSMOS) files")
    p.add_argument("--records", nargs="+", help="only these records of the suite (by name)")
    p.add_argument("--er", type=float, help="coefficient of restitution (default 0.86)")
    p.add_argument("--tail", type=float, help="seconds simulated after the record ends (default 5)")
    p.add_argument("--rtol", type=float, help="fmi2sim --rtol (default 1e-6)")
    p.add_argument("--out", default="results/sweep.csv", help="results CSV (appended, resumable)")
    p.add_argument("--engine", default="exact", choices=["exact", "fmi2sim"],
                   help="exact: the event-driven engine in each worker's process (default); fmi2sim: CVODE, a "
                        "subprocess per run (then every worker must see fmi2sim, the FMU and the records)")
    p.add_argument("--fmi2sim", help="with --engine fmi2sim (default: the installed one)")
    p.add_argument("--fmu", help="with --engine fmi2sim (default: the installed RockingWall.fmu)")
    p.add_argument("--scheduler", help="address of a running Dask scheduler, or 'synchronous' (no Dask)")
    p.add_argument("--workers", type=int, default=os.cpu_count() or 1, help="LocalCluster workers (default: cores)")
    p.add_argument("--batch", type=int, help="runs per Dask task (default: 64 with the exact engine, whose runs take "
                                            "milliseconds, so that Dask's per-task cost does not dominate; 4 with fmi2sim)")
    p.add_argument("--timeout", type=float, help="seconds a run may take before it is killed (default 600); "
                                                  "timed-out runs are retried on resume")
    p.add_argument("--dry-run", action="store_true", help="print the plan and its size, run nothing")
    p.add_argument("--scan-workers", type=int, nargs="+", metavar="N",
                   help="time the whole plan once per worker count, each into a fresh file OUT.wN.csv, "
                        "and print the speed-up")
    p.add_argument("--no-progress", action="store_true")
    return p.parse_args(argv)


def check_artefacts(args):
    if args.engine == "exact":
        paths.engine_library()
        return
    args.fmi2sim = args.fmi2sim or str(paths.fmi2sim())
    args.fmu = args.fmu or str(paths.wall_fmu())
    for path in (args.fmi2sim, args.fmu):
        if not pathlib.Path(path).is_file():
            raise FileNotFoundError(f"{path} is missing: build first (cmake -S . -B build && cmake --build build), "
                                    "or pass --fmi2sim/--fmu or RW_BUILD_DIR")


def protect_inputs(args, specs):
    """The files the sweep reads, which its results file may not be (nor a link to one)."""
    outputs.protect(args.config, "the --config file")
    outputs.protect(args.fmu, "the FMU")
    outputs.protect(args.fmi2sim, "fmi2sim")
    for s in specs:
        outputs.protect(s.record_path, "a record of the suite")


def check_command(args):
    """Refuse absurd execution options and an --out that cannot be a results file, before the
    (possibly long) planning."""
    if args.batch is None:
        args.batch = 64 if args.engine == "exact" else 4
    check_options(args.workers, args.batch, args.timeout)
    for n in args.scan_workers or []:
        check_options(n, args.batch, args.timeout)
    store.check_target(args.out)


def report(label, outcome):
    for line in describe_outcome(outcome, label):
        print(line, file=sys.stderr)
    if outcome.ran == 0:
        print(f"{label}: nothing to do: all {outcome.planned} runs are done")
        return
    print(f"{label}: {outcome.ran} runs ({outcome.errors} errors, {outcome.unfinished} killed or timed out, "
          f"{outcome.skipped} already done) in {outcome.seconds:.1f} s = {outcome.runs_per_s:.2f} runs/s "
          f"(+ {outcome.startup_s:.1f} s to start Dask)")


def exit_status(outcome):
    """1 when the results are not complete and clean: runs killed or timed out (run the command
    again), or damaged lines found in the file (set aside, and their runs computed again)."""
    return 1 if outcome.unfinished or (outcome.resume is not None and outcome.resume.bad) else 0


def main(argv=None):
    """The command line; refused commands and files end with a message (file, line, problem)
    and exit status 2, never a traceback."""
    args = parse_args(argv)
    try:
        return run(args)
    except (ValueError, OSError, ImportError, Busy) as exc:  # ResultsError, RecordError are ValueErrors
        print(f"rockingwall sweep: error: {exc}", file=sys.stderr)
        return 2
    except ClusterError as exc:  # nothing ran: not a refused command, run it again
        print(f"rockingwall sweep: error: {exc}", file=sys.stderr)
        return 1
    except (KeyboardInterrupt, Terminated) as exc:
        print(f"rockingwall sweep: interrupted ({type(exc).__name__} {exc}): the rows written so far are kept; "
              "run the same command again to resume", file=sys.stderr)
        return 130


def run(args):
    check_command(args)
    flags = {k: v for k, v in vars(args).items() if k in grid.DEFAULTS}
    cfg, suite, specs = plausible(lambda: grid.plan(args.config, flags), args)  # a building file's unit slips
    print(grid.describe(cfg, suite, specs))
    if args.dry_run:
        return 0
    check_artefacts(args)
    protect_inputs(args, specs)
    outputs.check_target(args.out, "--out")
    print("load:", subprocess.run(["uptime"], capture_output=True, text=True).stdout.strip())
    common = dict(fmi2sim=args.fmi2sim, fmu=args.fmu, rtol=cfg["rtol"], scheduler=args.scheduler,
                  batch=args.batch, progress=not args.no_progress, timeout=args.timeout, engine=args.engine)
    if not args.scan_workers:
        t0 = time.perf_counter()
        outcome = execute(specs, args.out, workers=args.workers, **common)
        report(f"{args.out}", outcome)
        print(f"total wall-clock time {time.perf_counter() - t0:.1f} s")
        return exit_status(outcome)
    base = pathlib.Path(args.out)
    times = {}
    for n in args.scan_workers:
        out = base.with_name(f"{base.stem}.w{n}{base.suffix}")
        outputs.check_target(out, "--scan-workers output")
        if out.exists():
            out.unlink()  # a timing needs every run computed, none resumed
        outcome = execute(specs, out, workers=n, **common)
        report(f"{n} worker(s) -> {out}", outcome)
        times[n] = outcome.seconds
    first = args.scan_workers[0]
    for n in args.scan_workers[1:]:
        print(f"speed-up {first} -> {n} workers: {times[first] / times[n]:.2f}x")
    return 0

