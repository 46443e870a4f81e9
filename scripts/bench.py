"""Speed against accuracy: a work-precision diagram of every way this project can run the wall.

Contenders, all on the same scenes and the same sampled input:
  the exact event-driven engine (in-process, no tolerance: one point), fmi2sim (CVODE BDF and Adams,
  ARKODE ERK, rtol 1e-3 .. 1e-10), fmpy driving the same FMU (CVode at several rtol, forward Euler
  at several steps), and the Python reference solver (RK45, DOP853, Radau).
Error of a run = max(relative error of peak s1, of peak s2, RMS error of s1(t) / peak s1), all on the
common 0.01 s output grid, against a converged run (fmi2sim BDF at rtol 1e-12).
Cost = CPU time of the process doing the work (child rusage for fmi2sim), in Python of the thread
(time.thread_time: NumPy's BLAS threads, spinning after a matrix product, left out).

Prints the table, the speed ratios at equal accuracy measured side by side in this one run,
the model ladder (what each simpler model costs and how far its peaks are), and writes
results/bench_*.csv and results/work_precision.png.

    .venv/bin/python scripts/bench.py [--quick] [--summary-only]
"""
import argparse
import csv
import os
import pathlib
import resource
import subprocess
import sys
import tempfile
import time

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from tqdm import tqdm

REPO = pathlib.Path(__file__).resolve().parents[1]
from rockingwall import engine as rw_engine  # noqa: E402
from rockingwall import fmi2sim  # noqa: E402
from rockingwall import fmu as rw_fmu  # noqa: E402
from rwref import Params, simulate, inputs  # noqa: E402
from fmpy import extract  # noqa: E402

FMU = REPO / "build" / "RockingWall.fmu"
FMI2SIM = REPO / "build" / "fmi2sim"
WALL_1 = dict(h=2.5, b=0.15, W=6622.0, psi=0.0, er=0.86)
DT_OUT = 0.01


def scenes(quick):
    gauss = inputs.sampled(inputs.gaussian(0.04, 1.0), 8.0, 0.002, "Gaussian D=0.04 m T=1 s")
    elce = inputs.el_centro(0.5)
    if quick:
        elce = inputs.Signal(elce.t[elce.t <= 15.0], elce.a[elce.t <= 15.0], "El Centro x0.5 (15 s)")
    out = []
    for signal, label in ((elce, "El Centro 50%"), (gauss, "Gaussian")):
        for kd in (5e4, 5e7):
            out.append((f"{label}, Kd={kd / 1e3:g} kN/m", signal, kd))
    return out


class Fmi2sim:
    """Runs build/fmi2sim on an input CSV; CPU time from the child's rusage."""

    def __init__(self, workdir, fmu_dir):
        self.workdir = pathlib.Path(workdir)
        self.fmu_dir = fmu_dir

    def run(self, signal, params, solver="bdf", rtol=1e-6, t_end=None):
        inp = self.workdir / "input.csv"
        if not inp.exists() or getattr(self, "_signal", None) is not signal:
            np.savetxt(inp, np.column_stack([signal.t, signal.a]), delimiter=",", header="time,ag", comments="")
            self._signal = signal
        out = self.workdir / "out.csv"
        cmd = fmi2sim.command(self.fmu_dir, input_csv=inp, output=out, solver=solver, rtol=float(rtol),
                              stop_time=float(t_end or signal.t[-1]), output_interval=DT_OUT,
                              sets=rw_fmu.start_values(**params).items(), executable=FMI2SIM)
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        proc = subprocess.run(cmd, capture_output=True, text=True)
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        if proc.returncode != 0:
            raise RuntimeError(f"fmi2sim failed: {proc.stderr.strip()}")
        cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
        data = np.genfromtxt(out, delimiter=",", names=True)
        return data["time"], data["s1"], data["s2"], cpu


def fmpy_run(fmu_dir, signal, params, solver, rtol=None, step=None):
    start = time.thread_time()
    run = rw_fmu.simulate(fmu_dir, float(signal.t[-1]), signal.t, signal.a, rtol=rtol or 1e-6,
                          output_interval=DT_OUT if step is None else max(step, DT_OUT),
                          solver=solver, step_size=step, **params)
    return run.t, run.s1, run.s2, time.thread_time() - start


def engine_run(signal, params):
    """The exact engine in this process, on the output grid."""
    start = time.thread_time()
    grid = np.arange(0.0, signal.t[-1] + DT_OUT / 2, DT_OUT)
    r = rw_engine.run(signal.t, signal.a, t_end=float(signal.t[-1]), t_out=grid, **rw_fmu.start_values(**params))
    return grid, r.s1, r.s2, time.thread_time() - start


def reference_run(signal, params, method, rtol):
    start = time.thread_time()
    grid = np.arange(0.0, signal.t[-1] + DT_OUT / 2, DT_OUT)
    res = simulate(Params(**params), signal, float(signal.t[-1]), method=method, rtol=rtol,
                   atol=rtol * 1e-3, t_out=grid)
    return res.t, res.s1, res.s2, time.thread_time() - start


def on_grid(run, grid):
    """s1, s2 of a run on the common output grid (event instants appear twice in a run)."""
    return rw_fmu.on_grid(run[0], run[1], grid), rw_fmu.on_grid(run[0], run[2], grid)


def error(run, ref, grid):
    """max(rel. error of peak s1, of peak s2, RMS(s1 - s1_ref)/peak s1), all on the common grid so
    that every contender's peaks are sampled alike. A peak s2 below 1 % of peak s1 (stiff spring:
    the top hardly moves) is compared relative to peak s1 instead of to itself."""
    s1, s2 = on_grid(run, grid)
    r1, r2 = on_grid(ref, grid)
    p1, p2 = np.max(np.abs(r1)), np.max(np.abs(r2))
    e_peak1 = abs(np.max(np.abs(s1)) - p1) / p1
    e_peak2 = abs(np.max(np.abs(s2)) - p2) / max(p2, 0.01 * p1)
    e_rms = np.sqrt(np.mean((s1 - r1) ** 2)) / p1
    return max(e_peak1, e_peak2, e_rms)


class Tee:
    """Print as usual and keep a copy in a file (docs/performance.md quotes it: scripts/update_docs.py)."""

    def __init__(self, path):
        self.path, self.lines, self.stdout = path, [], None

    def __enter__(self):
        self.stdout, sys.stdout = sys.stdout, self
        return self

    def write(self, text):
        self.lines.append(text)
        return self.stdout.write(text)

    def flush(self):
        self.stdout.flush()

    def __exit__(self, *exc):
        sys.stdout = self.stdout
        self.path.write_text("".join(self.lines).lstrip("\n"))


def cost_at(points, target):
    """CPU time a contender needs to reach error <= target: the cheapest run that does."""
    ok = [cpu for err, cpu in points if err <= target]
    return min(ok) if ok else None


LADDER = [  # (label, model, hinge law, K_d in N/m per m or None)
    ("parapet (rigid block)", "parapet", "rigid", None),
    ("simply supported, rigid", "simplySupported", "rigid", None),
    ("simply supported, trilinear", "simplySupported", "semiRigidHinge", None),
    ("2DOF rigid, Kd=50 kN/m", "flexibleTop", "rigid", 5e4),
    ("2DOF semiRigidPaper, Kd=50 kN/m", "flexibleTop", "semiRigidPaper", 5e4),
    ("2DOF semiRigidHinge, Kd=50 kN/m", "flexibleTop", "semiRigidHinge", 5e4),
    ("2DOF semiRigidHinge, Kd=50000 kN/m", "flexibleTop", "semiRigidHinge", 5e7),
    ("2DOF dohertyHinge, Kd=50 kN/m", "flexibleTop", "dohertyHinge", 5e4),
    ("2DOF dohertyHinge, Kd=50000 kN/m", "flexibleTop", "dohertyHinge", 5e7),
]
KD_SWEEP = np.logspace(3, 9, 13)  # N/m per m: 1 kN/m .. 1e6 kN/m


def model_ladder(sim, cases, out):
    """Cost (fmi2sim BDF, rtol 1e-6) and peaks of each model, and the K_d above which the simply
    supported wall gives the 2DOF peak s1 within 5 % (same record, wall 1)."""
    rows = []
    print("\nModel ladder (fmi2sim BDF, rtol 1e-6; CPU seconds; peaks in m)")
    for scene, signal in cases:
        print(f"  {scene}")
        for label, model, law, kd in LADDER:
            params = dict(WALL_1, support=model, hinge_law=law, **({"Kd": kd} if kd else {}))
            best = float("inf")
            for _ in range(3):  # best of 3: the runs are milliseconds long
                t, s1, s2, cpu = sim.run(signal, params, "bdf", 1e-6)
                best = min(best, cpu)
            rows.append((scene, label, best, np.max(np.abs(s1)), np.max(np.abs(s2)), t[-1] < signal.t[-1] - 1e-6))
            r = rows[-1]
            print(f"    {label:<38} cpu {r[2]:.4f}  s1 {r[3]:.4f}  s2 {r[4]:.4f}{'  collapsed' if r[5] else ''}")
    with open(out / "bench_model_ladder.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["scene", "model", "cpu_s", "peak_s1", "peak_s2", "collapsed"])
        w.writerows(rows)

    print("\nK_d above which the simply supported wall gives the 2DOF peak s1 within 5 %")
    sweep_rows = []
    for scene, signal in cases:
        for law_2dof, law_1dof in (("rigid", "rigid"), ("semiRigidHinge", "semiRigidHinge"),
                                   ("dohertyHinge", "dohertyHinge")):
            one = sim.run(signal, dict(WALL_1, support="simplySupported", hinge_law=law_1dof), "bdf", 1e-6)
            s1_1dof, cpu_1dof = np.max(np.abs(one[1])), one[3]
            if s1_1dof == 0.0:
                print(f"  {scene:<16} 2DOF {law_2dof:<15} vs 1DOF {law_1dof:<15}: the 1DOF does not rock here")
                continue
            within, cpus = [], []
            for kd in KD_SWEEP:
                two = sim.run(signal, dict(WALL_1, support="flexibleTop", hinge_law=law_2dof, Kd=kd), "bdf", 1e-6)
                err = abs(np.max(np.abs(two[1])) - s1_1dof) / s1_1dof
                within.append(err <= 0.05)
                cpus.append(two[3])
                sweep_rows.append((scene, law_2dof, kd, np.max(np.abs(two[1])), np.max(np.abs(two[2])), s1_1dof, err))
            # the smallest K_d from which every stiffer one in the sweep stays within 5 %
            k = len(within)
            while k > 0 and within[k - 1]:
                k -= 1
            if k == len(within):
                print(f"  {scene:<16} 2DOF {law_2dof:<15} vs 1DOF {law_1dof:<15}: at no K_d up to "
                      f"{KD_SWEEP[-1] / 1e3:g} kN/m (the two hinge laws differ, see docs/performance.md)")
                continue
            speed = np.mean(cpus[k:]) / cpu_1dof
            print(f"  {scene:<16} 2DOF {law_2dof:<15} vs 1DOF {law_1dof:<15}: from K_d = {KD_SWEEP[k] / 1e3:.3g} kN/m"
                  f" (the 2DOF costs {speed:.1f}x the 1DOF there)")
    with open(out / "bench_kd_sweep.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["scene", "hinge_law", "Kd_N_per_m_per_m", "peak_s1", "peak_s2", "peak_s1_1dof", "rel_diff"])
        w.writerows(sweep_rows)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--quick", action="store_true", help="fewer tolerances, 15 s of El Centro")
    parser.add_argument("--ladder-only", action="store_true", help="only the model ladder and the K_d sweep")
    parser.add_argument("--out", default=str(REPO / "results"))
    parser.add_argument("--summary-only", action="store_true",
                        help="rewrite the ratio table of bench_summary.txt from bench_work_precision.csv")
    args = parser.parse_args()
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    if args.summary_only:
        summary_from_csv(out)
        return

    fmu_dir = extract(str(FMU))
    work = tempfile.mkdtemp(prefix="rw_bench_")
    sim = Fmi2sim(work, fmu_dir)
    ladder_cases = [(label.split(",")[0], signal) for label, signal, kd in scenes(args.quick) if kd == 5e4]
    if args.ladder_only:
        with Tee(out / "bench_summary.txt"):
            model_ladder(sim, ladder_cases, out)
        return
    rtols_sim = [1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-10] if not args.quick else [1e-4, 1e-6, 1e-8]
    rtols_py = [1e-4, 1e-6, 1e-8] if not args.quick else [1e-4, 1e-6]
    contenders = [("exact engine", 0.0, engine_run)]
    for solver in ("bdf", "adams", "erk"):
        for rtol in rtols_sim:
            contenders.append((f"fmi2sim {solver.upper()}", rtol,
                               lambda s, p, solver=solver, rtol=rtol: sim.run(s, p, solver, rtol)))
    for rtol in rtols_py:
        contenders.append(("fmpy CVode", rtol, lambda s, p, rtol=rtol: fmpy_run(fmu_dir, s, p, "CVode", rtol=rtol)))
    for step in ([1e-3, 1e-4] if not args.quick else [1e-3]):
        contenders.append(("fmpy Euler", step, lambda s, p, step=step: fmpy_run(fmu_dir, s, p, "Euler", step=step)))
    for method in ("RK45", "DOP853", "Radau"):
        for rtol in rtols_py:
            contenders.append((f"reference {method}", rtol,
                               lambda s, p, method=method, rtol=rtol: reference_run(s, p, method, rtol)))

    rows = []
    cases = scenes(args.quick)
    with tqdm(total=len(cases) * (len(contenders) + 1), desc="bench") as bar:
        for label, signal, kd in cases:
            params = dict(WALL_1, support="flexibleTop", hinge_law="dohertyHinge", Kd=kd)
            grid = np.arange(0.0, signal.t[-1] + DT_OUT / 2, DT_OUT)
            converged = sim.run(signal, params, "bdf", 1e-12)
            bar.update()
            for name, setting, fn in contenders:
                if name.startswith("reference") and kd > 1e6 and name != "reference Radau" and setting < 1e-6:
                    bar.update()
                    continue  # explicit methods on the stiff spring at tight rtol take minutes: skipped, said below
                try:
                    run = fn(signal, params)
                    rows.append((label, name, setting, error(run, converged, grid), run[3]))
                except Exception as exc:  # a failing contender is a result too
                    rows.append((label, name, setting, float("nan"), float("nan")))
                    tqdm.write(f"{label}: {name} {setting:g} failed: {exc}")
                bar.update()

    with open(out / "bench_work_precision.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["scene", "contender", "setting", "error", "cpu_s"])
        w.writerows(rows)

    # The diagram: one panel per scene.
    fig, axes = plt.subplots(2, 2, figsize=(11, 8))
    for ax, (label, _, _) in zip(axes.flat, cases):
        for name in dict.fromkeys(r[1] for r in rows):
            pts = sorted((r[4], r[3]) for r in rows if r[0] == label and r[1] == name and np.isfinite(r[3]))
            if pts:
                ax.loglog([p[0] for p in pts], [max(p[1], 1e-12) for p in pts], "o-", ms=3, label=name)
        ax.set_title(label, fontsize=9)
        ax.set_xlabel("CPU time [s]")
        ax.set_ylabel("error")
        ax.grid(alpha=0.3, which="both")
    axes.flat[0].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(out / "work_precision.png", dpi=110)

    # Speed ratios at equal accuracy, from this one run.
    tee = Tee(out / "bench_summary.txt").__enter__()
    print_ratios(rows, [label for label, _, _ in cases])
    model_ladder(sim, ladder_cases, out)
    tee.__exit__(None, None, None)
    print(f"\nwrote {out}/bench_work_precision.csv, bench_model_ladder.csv, bench_kd_sweep.csv and work_precision.png")


def print_ratios(rows, labels):
    """CPU seconds each family needs to reach an error target, the ratios to fmi2sim (the cheapest
    of BDF, Adams and ERK), and the exact engine's one run when it reaches the target."""
    print("\nCPU seconds to reach an error target (cheapest run that does), and ratios to fmi2sim "
          "(BDF, Adams or ERK); the exact engine has no tolerance: its one run, if it reaches the target")
    print(f"{'scene':<34}{'target':>8}{'engine':>9}{'fmi2sim':>10}{'fmpy':>10}{'reference':>11}"
          f"{'sim/eng':>9}{'ref/sim':>9}{'fmpy/sim':>9}")
    for label in labels:
        for target in (1e-2, 1e-3, 1e-4):
            def best(prefix):
                pts = [(r[3], r[4]) for r in rows if r[0] == label and r[1].startswith(prefix)]
                return cost_at(pts, target)
            c_eng, c_sim, c_fmpy, c_ref = best("exact engine"), best("fmi2sim"), best("fmpy"), best("reference")
            fmt = lambda c: f"{c:.3f}" if c is not None else "-"
            ratio = lambda a, b: f"{a / b:.0f}x" if (a is not None and b) else "-"
            print(f"{label:<34}{target:>8g}{fmt(c_eng):>9}{fmt(c_sim):>10}{fmt(c_fmpy):>10}{fmt(c_ref):>11}"
                  f"{ratio(c_sim, c_eng):>9}{ratio(c_ref, c_sim):>9}{ratio(c_fmpy, c_sim):>9}")


def summary_from_csv(out):
    """--summary-only: the ratio table again from bench_work_precision.csv, the model ladder kept"""
    with open(out / "bench_work_precision.csv") as f:
        rows = [(r["scene"], r["contender"], float(r["setting"]), float(r["error"]), float(r["cpu_s"]))
                for r in csv.DictReader(f)]
    summary = out / "bench_summary.txt"
    ladder = summary.read_text()
    ladder = ladder[ladder.index("Model ladder"):] if "Model ladder" in ladder else ""
    with Tee(summary):
        print_ratios(rows, list(dict.fromkeys(r[0] for r in rows)))
        print("\n" + ladder, end="")


if __name__ == "__main__":
    main()
