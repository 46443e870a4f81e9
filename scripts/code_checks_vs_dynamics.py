"""Draws docs/img/code_checks_vs_dynamics.png and prints the table of docs/code-checks-vs-dynamics.md:
the assessor's ground-storey wall at a site whose design PGA is 0.2 g, the three codes' verdicts,
and the exact engine's peaks under four records scaled to 0.2 g as K_d goes from 5 to 1000 kN/m
per m, in the paper's scene and with a 200 kg/m diaphragm. Takes about a second.

    .venv/bin/python scripts/code_checks_vs_dynamics.py [--out docs/img/code_checks_vs_dynamics.png]"""
import argparse
import dataclasses
import pathlib
import sys
import types

from rockingwall import Wall, assessment_codes, records
from rockingwall import codes_vs_dynamics as cvd
from rockingwall.sweep import suites

REPO = pathlib.Path(__file__).resolve().parents[1]
PGA = 0.2                                            # g: the site's design PGA, every record scaled to it
KDS = [5e3, 10e3, 20e3, 50e3, 100e3, 200e3, 500e3, 1000e3]  # N/m per m
DIAPHRAGM_MASS = 200.0                               # kg/m of wall, with 5 % damping
FEMA = {"ff13a": "Loma Prieta 1989, Capitola 000", "ff07a": "Kobe 1995, Nishi-Akashi 000",
        "ff03a": "Duzce 1999, Bolu 000"}           # FEMA P695 far-field components
# The site: every code's ground acceleration is 0.2 g (C8: C(0) = Z = 0.2 on soil B; NTC: a_g S = 0.2 g
# on soil A); S_X1 = 0.2 g for ASCE 41. The wall stands on the ground in a one-storey building.
SITE = dict(nz_Z="0.2", nz_soil="B", ntc_ag="0.2g", ntc_soil="A", asce_SX1="0.2g")


def study_records():
    fema = {r.name: r for r in suites.fema_farfield(suites.fema_cache()) if r.name in FEMA}
    recs = [records.el_centro()] + [dataclasses.replace(records.read_at2(fema[name].path), name=label)
                                    for name, label in FEMA.items()]
    return [dataclasses.replace(r.to_pga(PGA), name=r.name) for r in recs]


def site_checks(wall):
    args = types.SimpleNamespace(**SITE)
    return assessment_codes.check(wall, assessment_codes.CODES, assessment_codes.option_values(args))


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", default=str(REPO / "docs" / "img" / "code_checks_vs_dynamics.png"))
    a = ap.parse_args(argv)
    wall = Wall.make(b=0.23, h=3.6, W=14904.0, psi=0.2, support="flexibleTop", warn=False)
    checks = site_checks(wall)
    recs = study_records()
    panels = [cvd.Panel("the paper's scene: K_d to a fixed point", cvd.dynamics(wall, recs, KDS)),
              cvd.Panel(f"with the diaphragm's mass ({DIAPHRAGM_MASS:g} kg/m, 5 % damping)",
                        cvd.dynamics(wall, recs, KDS, diaphragm_mass=DIAPHRAGM_MASS))]
    fig = cvd.plot(panels, checks, wall.delta_u, f"{wall.describe(with_kd=False)}; records scaled to PGA {PGA:g} g")
    fig.savefig(a.out, dpi=110)
    print(f"wrote {a.out}", file=sys.stderr)
    for line in assessment_codes.checks_lines(checks):
        print(line)
    for panel in panels:
        print(f"\n{panel.title}")
        print("| record | " + " | ".join(f"{kd / 1e3:g}" for kd in KDS) + " |")
        print("|---|" + "---|" * len(KDS))
        for name, d in panel.frame.groupby("record", sort=False):
            cells = ["collapse" if c else f"{r:.2f}" for r, c in zip(d.ratio, d.collapsed)]
            print(f"| {name} | " + " | ".join(cells) + " |")
        flagged = cvd.unconservative_kds(checks, panel.frame)
        for code, kds in flagged.items():
            where = ", ".join(f"{kd / 1e3:g}" for kd in kds) or "none"
            print(f"{assessment_codes.LABELS[code]} unconservative at K_d [kN/m per m]: {where}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
