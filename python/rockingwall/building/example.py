"""The worked example of docs/building-coupling.md: a two-storey building with flexible timber
diaphragms (Bouc-Wen with pinching) and the paper's wall 1 in each storey, tied stiffly to the
diaphragm above it, under El Centro 1940 and two FEMA P695 far-field records, each scaled to the
same PGA. Each wall's peaks against the paper's scene (the same wall on the ground, its spring
K_d equal to the diaphragm's stiffness, fixed at its far end), and the floor spectra that reach
each wall (5 %-damped Sa of the ground and of diaphragm 1's absolute acceleration).

    rockingwall couple-building --example [--out DIR]

writes DIR/building_coupling.png (DIR: results/; the document's figure is the one written with
--out docs/img) and prints the table of the document.
"""
import pathlib

import numpy as np

from .. import engine, intensity, outputs, records
from ..names import HINGE_LAWS, SUPPORTS, paper_wall
from . import scene as bs

PGA_G = 0.15
FEMA_NAMES = ("ff01a", "ff02a")
TIE_KD = 1e7          # N/m per m: the wall-to-diaphragm tie, stiff next to the diaphragm
H = 5e-4              # s, macro step
PERIODS = np.geomspace(0.05, 2.0, 40)
PNG = "building_coupling.png"


def example_records(cache_dir):
    from ..sweep import suites
    fema = {r.name: r for r in suites.fema_farfield(cache_dir)}
    out = [records.el_centro()] + [records.read_at2(fema[n].path) for n in FEMA_NAMES]
    return [r.to_pga(PGA_G) for r in out]


def paper_scene_peaks(record, kd):
    """The wall alone on the ground, K_d = kd fixed at its far end (the exact engine)."""
    r = engine.run(record.t, record.ag, **paper_wall(1), Kd=kd, support=SUPPORTS["flexibleTop"],
                   hingeLaw=HINGE_LAWS["dohertyHinge"])
    return r.peak_s1, r.peak_s2, r.collapsed


def building_scene():
    return bs.default_scene(2, wall=1, Kd=TIE_KD, diaphragm_law=2)


def run_one(record, kd):
    r = bs.run(building_scene(), record, float(record.t[-1]), H, order=2)
    floor1 = records.Record("diaphragm 1", r["time"], r["a_diaph_1"], source="building")
    spectra = {"ground": [intensity.sa(record, T) for T in PERIODS],
               "diaphragm 1": [intensity.sa(floor1, T) for T in PERIODS]}
    rows = []
    for storey in (1, 2):
        p1, p2, collapsed = paper_scene_peaks(record, kd)
        rows.append(dict(record=record.name, storey=storey, s1=r.peak(storey, "s1"), s2=r.peak(storey, "s2"),
                         paper_s1=p1, paper_s2=p2, paper_collapsed=collapsed,
                         collapsed_at=r["collapsed"].get(storey)))
    return rows, spectra


def plot(results, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 2, figsize=(11, 4.2))
    for (name, (rows, spectra)), colour in zip(results.items(), ("C0", "C1", "C2")):
        ax[0].semilogx(PERIODS, spectra["ground"], color=colour, ls="--", label=f"{name}: ground (wall 1)")
        ax[0].semilogx(PERIODS, spectra["diaphragm 1"], color=colour, label=f"{name}: diaphragm 1 (wall 2)")
    ax[0].set_xlabel("period [s]")
    ax[0].set_ylabel("Sa (5 %) [g]")
    ax[0].set_title("the motion reaching each wall's base")
    ax[0].legend(fontsize=7)
    labels, building, paper, fell = [], [], [], []
    for name, (rows, _) in results.items():
        for row in rows:
            labels.append(f"{name.split(' at ')[0].replace(' 1940', '')}\nstorey {row['storey']}")
            building.append(1e3 * row["s1"])
            paper.append(1e3 * row["paper_s1"])
            fell.append((row["collapsed_at"] is not None, row["paper_collapsed"]))
    x = np.arange(len(labels))
    ax[1].bar(x - 0.2, building, 0.4, label="in the building")
    ax[1].bar(x + 0.2, paper, 0.4, label="paper's scene (K_d = diaphragm's k, on the ground)")
    for xi, (b, p), (fb, fp) in zip(x, zip(building, paper), fell):
        for dx, value, f in ((-0.2, b, fb), (0.2, p, fp)):
            if f:
                ax[1].text(xi + dx, value, "collapse", ha="center", va="bottom", fontsize=6, rotation=90)
    ax[1].set_xticks(x, labels, fontsize=7)
    ax[1].set_ylabel("peak s1 [mm]")
    ax[1].set_ylim(0, 1.3e3 * max(max(r["s1"], r["paper_s1"]) for rows, _ in results.values() for r in rows))
    ax[1].set_title(f"wall 1, records at PGA {PGA_G:g} g")
    ax[1].legend(fontsize=7)
    fig.tight_layout()
    path.parent.mkdir(parents=True, exist_ok=True)
    outputs.write_atomic(path, lambda tmp: fig.savefig(tmp, dpi=110, format="png"))  # whole, never through a link
    plt.close(fig)


def main(cache_dir, out_dir="results"):
    kd = building_scene().building_real.get("kd_1", 7e5)
    results = {}
    for rec in example_records(cache_dir):
        results[rec.name] = run_one(rec, kd)
    plot(results, pathlib.Path(out_dir) / PNG)
    print("| record | storey | peak s1 [mm] | peak s2 [mm] | paper's scene s1 [mm] | s2 [mm] |")
    print("|---|---|---|---|---|---|")
    for name, (rows, _) in results.items():
        for r in rows:
            end = f" (collapsed at {r['collapsed_at']:.2f} s)" if r["collapsed_at"] is not None else ""
            pend = " (collapsed)" if r["paper_collapsed"] else ""
            print(f"| {name} | {r['storey']} | {1e3 * r['s1']:.1f}{end} | {1e3 * r['s2']:.1f} | "
                  f"{1e3 * r['paper_s1']:.1f}{pend} | {1e3 * r['paper_s2']:.1f} |")
    print(f"wrote {PNG}")
    return 0
