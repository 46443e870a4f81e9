"""The paper's Tables 5.1, 5.2, 5.4 and Figures 5.2-5.4 reproduced with the reference solver (rwref),
and the calibration scan of hingeSat (the logic of `rockingwall paper`, whose help says what is
written)."""
import csv
import glob
import os
import pathlib
import sys

import numpy as np

from . import outputs

try:  # the paper's tables are reproduced with the independent reference solver (a separate package)
    from rwref import Params, simulate, inputs, table_5_1, TABLE_5_1_PAPER, WALLS
except ImportError as exc:
    raise ImportError("rockingwall paper runs the reference solver: install it (pip install ./reference)") from exc

HEADER = ["table", "wall", "input", "model", "Kd_kN_per_m", "quantity", "ours", "paper"]
G_AMPL = {1: 0.040, 2: 0.040, 3: 0.050}
KD_5_2 = [1000, 100, 50, 10]
# Table 5.2 as printed; wall 2 Kd=1000 s1 is printed "0,613", read as 0.061 (a typo: docs/model.md)
PAPER_5_2 = {
    1: {"1DOF": 0.064, 1000: (0.066, 0.002), 100: (0.069, 0.021), 50: (0.073, 0.040), 10: (0.053, 0.085)},
    2: {"1DOF": 0.040, 1000: (0.061, 0.003), 100: (0.093, 0.036), 50: (0.058, 0.047), 10: (0.033, 0.073)},
    3: {"1DOF": 0.033, 1000: (0.068, 0.008), 100: (0.056, 0.056), 50: (0.034, 0.063), 10: (0.030, 0.053)},
}
KD_5_4 = [500, 50, 5]
PAPER_5_4 = {  # id: (percent PGA, 1DOF s1, {Kd: (s1, s2)})
    "elce": (50, 0.043, {500: (0.043, 0.004), 50: (0.137, 0.019), 5: (0.050, 0.109)}),
    "tolm": (100, 0.094, {500: (0.094, 0.004), 50: (0.114, 0.036), 5: (0.048, 0.095)}),
    "stur": (80, 0.053, {500: (0.048, 0.005), 50: (0.035, 0.023), 5: (0.082, 0.074)}),
    "loma": (50, 0.031, {500: (0.034, 0.004), 50: (0.039, 0.026), 5: (0.056, 0.078)}),
    "sylm": (35, 0.045, {500: (0.047, 0.005), 50: (0.057, 0.028), 5: (0.077, 0.082)}),
    "kjmh": (20, 0.063, {500: (0.068, 0.004), 50: (0.046, 0.035), 5: (0.060, 0.114)}),
}


LAWS_2DOF = ("dohertyHinge", "semiRigidHinge")  # the default first; the figures use it


def one_dof(wall, **kw):
    return Params(support="simplySupported", hinge_law="dohertyHinge", **WALLS[wall], **kw)


def two_dof(wall, Kd_kN, law=LAWS_2DOF[0], **kw):
    return Params(support="flexibleTop", hinge_law=law, Kd=Kd_kN * 1e3, **WALLS[wall], **kw)


def fmt(v):
    return "" if v is None else (v if isinstance(v, str) else f"{v:.4f}")


def peaks(res):
    if res.collapsed:
        return "collapse", "collapse"
    return res.peak_s1, res.peak_s2


def write_csv(path, rows):
    def write(tmp):
        with open(tmp, "w", newline="") as fh:
            w = csv.writer(fh)
            w.writerow(HEADER)
            for r in rows:
                w.writerow([fmt(x) if i >= 6 else x for i, x in enumerate(r)])
    outputs.write_atomic(path, write, "--out")


def print_table(title, rows):
    print(f"\n{title}")
    model = max([len("model"), *(len(str(r[3])) for r in rows)])  # '2DOF semiRigidHinge' whole, K_d after it
    print(f"{'wall':>4} {'input':>14} {'model':>{model}} {'Kd':>6} {'qty':>14} {'ours':>9} {'paper':>7}  diff")
    for r in rows:
        o, p = r[6], r[7]
        d = f"{(o - p) / p * 100:+6.1f} %" if isinstance(o, float) and isinstance(p, float) and p else ""
        print(f"{r[1]:>4} {r[2]:>14} {r[3]:>{model}} {str(r[4]):>6} {r[5]:>14} {fmt(o) or 'missing':>9} {fmt(p):>7}  {d}")


def table_5_1_rows():
    ours = table_5_1()
    rows = []
    for wall in (1, 2, 3):
        for q in ("R_el", "Delta_u", "F0_over_W", "Delta_u_over_b"):
            rows.append(["5.1", wall, "-", "-", "", q, ours[wall][q], TABLE_5_1_PAPER[wall][q]])
    return rows


def run_5_2(walls, bar, hinge_sat=2.0, keep=None, laws=LAWS_2DOF):
    rows = []
    for wall in walls:
        ag = inputs.gaussian(G_AMPL[wall], 1.0)
        inp = f"gauss D={G_AMPL[wall]:.3f} T=1"
        r = simulate(one_dof(wall), ag, 10.0)
        bar.update(1)
        rows.append(["5.2", wall, inp, "1DOF", "", "s1", peaks(r)[0], PAPER_5_2[wall]["1DOF"]])
        if keep is not None:
            keep[(wall, "1DOF")] = r
        for Kd in KD_5_2:
            for law in laws:
                r = simulate(two_dof(wall, Kd, law, hinge_sat=hinge_sat), ag, 10.0)
                bar.update(1)
                s1, s2 = peaks(r)
                rows.append(["5.2", wall, inp, f"2DOF {law}", Kd, "s1", s1, PAPER_5_2[wall][Kd][0]])
                rows.append(["5.2", wall, inp, f"2DOF {law}", Kd, "s2", s2, PAPER_5_2[wall][Kd][1]])
                if keep is not None and law == LAWS_2DOF[0]:
                    keep[(wall, Kd)] = r
    return rows


def _at2_signal(path, scale):
    """An AT2 record (the package's one reader) as the reference solver's input signal."""
    from .records import read_at2
    rec = read_at2(path)
    outputs.protect(path, "a record of --records")
    return inputs.Signal(rec.t, rec.ag * scale, name=rec.name)


def find_record(rid, records_dir):
    if rid == "elce":
        return "quakeio"
    if not records_dir:
        return None
    for f in sorted(glob.glob(os.path.join(records_dir, "*"))):
        base = os.path.basename(f).lower()
        if base.startswith(rid) and base.endswith(".at2"):
            return f
    return None


def run_5_4(ids, records_dir, bar, keep=None):
    rows, missing = [], []
    for rid in ids:
        pct, p1, p2 = PAPER_5_4[rid]
        src = find_record(rid, records_dir)
        inp = f"{rid} {pct}%"
        if src is None:
            missing.append(rid)
            rows.append(["5.4", 1, inp, "1DOF", "", "s1", None, p1])
            for Kd in KD_5_4:
                for law in LAWS_2DOF:
                    rows.append(["5.4", 1, inp, f"2DOF {law}", Kd, "s1", None, p2[Kd][0]])
                    rows.append(["5.4", 1, inp, f"2DOF {law}", Kd, "s2", None, p2[Kd][1]])
            bar.update(1 + len(KD_5_4) * len(LAWS_2DOF))
            continue
        ag = inputs.el_centro(pct / 100) if src == "quakeio" else _at2_signal(src, pct / 100)
        t_end = ag.duration
        r = simulate(one_dof(1), ag, t_end)
        bar.update(1)
        rows.append(["5.4", 1, inp, "1DOF", "", "s1", peaks(r)[0], p1])
        if keep is not None:
            keep[(rid, "1DOF")] = r
        for Kd in KD_5_4:
            for law in LAWS_2DOF:
                r = simulate(two_dof(1, Kd, law), ag, t_end)
                bar.update(1)
                s1, s2 = peaks(r)
                rows.append(["5.4", 1, inp, f"2DOF {law}", Kd, "s1", s1, p2[Kd][0]])
                rows.append(["5.4", 1, inp, f"2DOF {law}", Kd, "s2", s2, p2[Kd][1]])
                if keep is not None and law == LAWS_2DOF[0]:
                    keep[(rid, Kd)] = r
    return rows, missing


def figures(out, keep52, keep54):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    # Fig. 5.2: 1DOF acceleration-displacement curve (static ag/g that balances F(D): ag = 2 g F / W)
    p = one_dof(1)
    from rwref.dynamics import SimplySupported, Mode
    D = np.linspace(0, p.Delta_u, 600)
    semi = SimplySupported(p, inputs.zero, inputs.zero)
    rig = SimplySupported(p.replace(hinge_law="rigid"), inputs.zero, inputs.zero)
    a_semi = [2 * abs(semi.force(d, Mode())) / p.W for d in D]
    a_rig = [2 * abs(rig.force(d, Mode(side_b=1.0))) / p.W for d in D]
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.plot(D * 1e3, a_rig, "b:", label="rigid")
    ax.plot(D * 1e3, a_semi, "r-", label="semi-rigid (trilinear)")
    for x, lab in ((p.Delta_1, r"$\Delta_1$"), (p.Delta_2, r"$\Delta_2$"), (p.Delta_u, r"$\Delta_u$")):
        ax.axvline(x * 1e3, color="0.7", lw=0.8)
        ax.text(x * 1e3, 0.01, lab)
    ax.set_xlabel("mid-height displacement D [mm]")
    ax.set_ylabel("acceleration capacity [g]")
    ax.set_title("Fig. 5.2 - wall 1, simply supported (1DOF)")
    ax.legend()
    fig.tight_layout()
    outputs.write_png(fig, out / "fig_5_2.png", "--out", 120)
    plt.close(fig)

    def hist(keys, title, fname):
        fig, axs = plt.subplots(len(keys), 1, figsize=(8, 1.9 * len(keys)), sharex=True)
        for ax, (key, lab) in zip(axs, keys):
            r = keep[key]
            ax.plot(r.t, r.s1 * 1e3, "b-", lw=0.9, label="s1")
            if lab != "1DOF":
                ax.plot(r.t, r.s2 * 1e3, "r-", lw=0.9, label="s2")
            ax.set_ylabel("[mm]")
            ax.set_title(lab + (" (collapse)" if r.collapsed else ""), fontsize=9)
            ax.grid(alpha=0.3)
            ax.legend(fontsize=7, loc="upper right")
        axs[-1].set_xlabel("t [s]")
        fig.suptitle(title, fontsize=10)
        fig.tight_layout()
        outputs.write_png(fig, out / fname, "--out")
        plt.close(fig)

    keep = keep52
    if (1, 10) in keep52:
        hist([((1, "1DOF"), "1DOF")] + [((1, K), f"2DOF Kd = {K} kN/m") for K in KD_5_2],
             "Fig. 5.3 - wall 1, Gaussian D = 40 mm, T = 1 s", "fig_5_3.png")
    keep = keep54
    if ("elce", 5) in keep54:
        hist([(("elce", "1DOF"), "1DOF")] + [(("elce", K), f"2DOF Kd = {K} kN/m") for K in KD_5_4],
             "Fig. 5.4 - wall 1, El Centro 1940 at 50 %", "fig_5_4.png")


def calibrate(out, bar_factory):
    target = PAPER_5_2[1][1000][0]
    ag = inputs.gaussian(G_AMPL[1], 1.0)
    scan = []
    for hs in (1.0, 1.5, 2.0, 2.25, 2.5, 2.75, 3.0, 3.5, 4.0):
        r = simulate(two_dof(1, 1000, "semiRigidHinge", hinge_sat=hs), ag, 10.0)
        scan.append((hs, r.peak_s1))
    print("\nCalibration scan: wall 1, Kd = 1000 kN/m, s1 (paper 0.066)")
    for hs, s1 in scan:
        print(f"  hingeSat = {hs:5.2f}: s1 = {s1:.4f}")
    best = None
    for (h0, s0), (h1, s1) in zip(scan[:-1], scan[1:]):
        if (s0 - target) * (s1 - target) <= 0:
            from scipy.optimize import brentq
            f = lambda hs: simulate(two_dof(1, 1000, "semiRigidHinge", hinge_sat=hs), ag, 10.0).peak_s1 - target
            best = brentq(f, h0, h1, xtol=1e-3)
            break
    rows = []
    if best is None:
        print("  no hingeSat in the scan matches 0.066")
    else:
        print(f"  hingeSat = {best:.3f} matches s1 = 0.066; Table 5.2 at that value vs default (2.0):")
        with bar_factory(15) as bar:
            cal = run_5_2((1, 2, 3), bar, hinge_sat=best, laws=("semiRigidHinge",))
        with bar_factory(15) as bar:
            dfl = run_5_2((1, 2, 3), bar, hinge_sat=2.0, laws=("semiRigidHinge",))
        err = {"cal": [], "dfl": []}
        print(f"{'wall':>4} {'Kd':>6} {'qty':>4} {'hs=2':>8} {'hs=%.2f' % best:>8} {'paper':>7}")
        for a, b in zip(dfl, cal):
            if not a[3].startswith("2DOF"):
                continue
            print(f"{a[1]:>4} {a[4]:>6} {a[5]:>4} {fmt(a[6]):>8} {fmt(b[6]):>8} {fmt(a[7]):>7}")
            rows.append([a[1], a[4], a[5], a[6], b[6], a[7]])
            if isinstance(a[6], float) and isinstance(b[6], float):
                err["dfl"].append(abs(a[6] - a[7]))
                err["cal"].append(abs(b[6] - b[7]))
        print(f"  mean |ours - paper| over the 2DOF cells: hingeSat=2: {np.mean(err['dfl']):.4f} m, "
              f"hingeSat={best:.3f}: {np.mean(err['cal']):.4f} m")

    def write(tmp):
        with open(tmp, "w", newline="") as fh:
            w = csv.writer(fh)
            w.writerow(["hinge_sat", "wall1_Kd1000_s1"])
            for hs, s1 in scan:
                w.writerow([hs, f"{s1:.5f}"])
            if best is not None:
                w.writerow([])
                w.writerow(["wall", "Kd_kN_per_m", "quantity", "ours_hs2", f"ours_hs{best:.3f}", "paper"])
                for r in rows:
                    w.writerow([r[0], r[1], r[2], fmt(r[3]), fmt(r[4]), fmt(r[5])])
    outputs.write_atomic(out / "calibration.csv", write, "--out")


def reproduce(out, records_dir=None, quick=False, calibrate_hinge_sat=False):
    """Tables 5.1, 5.2, 5.4 (CSV and printed comparisons), the figures unless quick, and the
    calibration scan with calibrate_hinge_sat, into the folder `out` (created if missing)."""
    from tqdm import tqdm
    out = pathlib.Path(out)
    out.mkdir(parents=True, exist_ok=True)
    bar_factory = lambda n: tqdm(total=n, desc="simulations", unit="run", file=sys.stderr)

    walls = (1,) if quick else (1, 2, 3)
    ids = ("elce",) if quick else tuple(PAPER_5_4)
    rows51 = table_5_1_rows()
    keep52, keep54 = {}, {}
    n2 = len(LAWS_2DOF)
    with bar_factory((1 + 4 * n2) * len(walls) + (1 + 3 * n2) * len(ids)) as bar:
        rows52 = run_5_2(walls, bar, keep=keep52)
        rows54, missing = run_5_4(ids, records_dir, bar, keep=keep54)
    write_csv(out / "table_5_1.csv", rows51)
    write_csv(out / "table_5_2.csv", rows52)
    write_csv(out / "table_5_4.csv", rows54)
    print_table("Table 5.1 (kN/m, m)", rows51)
    print_table("Table 5.2 - Gaussian impulse, T = 1 s (m); paper's wall-2 Kd=1000 s1 '0,613' read as 0.061", rows52)
    print_table("Table 5.4 - recorded accelerograms, wall 1 (m)", rows54)
    if missing:
        print(f"\nmissing records (no .AT2 in --records): {', '.join(missing)}")
    if not quick:
        figures(out, keep52, keep54)
        print(f"\nwrote {out}/table_5_1.csv, table_5_2.csv, table_5_4.csv, fig_5_2.png, fig_5_3.png, fig_5_4.png")
    if calibrate_hinge_sat:
        calibrate(out, bar_factory)
