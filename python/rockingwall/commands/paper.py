"""Reproduce the paper's Tables 5.1, 5.2, 5.4 and Figures 5.2-5.4 with the reference solver (rwref).

    rockingwall paper --out results/ [--records DIR] [--quick] [--calibrate]

Writes results/table_5_1.csv, table_5_2.csv, table_5_4.csv (columns
table,wall,input,model,Kd_kN_per_m,quantity,ours,paper; paper's units m, kN/m) and fig_5_2.png,
fig_5_3.png, fig_5_4.png, and prints the comparisons.  The 2DOF runs use both 2DOF semi-rigid
laws that come from a potential, dohertyHinge (the default) and semiRigidHinge (hingeSat = 2),
one row each ("model" column "2DOF <law>"); the 1DOF is Doherty's trilinear simply supported wall.
Table 5.4: El Centro 1940 from quakeio; the other records are read as PEER NGA .AT2 files from
--records DIR (file names starting with the paper's id: tolm*, stur*, loma*, sylm*, kjmh*); a missing
record gives rows with an empty "ours" and is reported as missing.
--calibrate: scan hingeSat on the cell (wall 1, Kd = 1000 kN/m, s1) and report every other cell of
Table 5.2 at the value that matches it (results/calibration.csv).
--quick: Table 5.2 wall 1 and El Centro only, no figures.
"""
import argparse

from .. import paper_tables


def main(argv=None):
    ap = argparse.ArgumentParser(prog="rockingwall paper", description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", default="results", help="output directory")
    ap.add_argument("--records", help="directory of PEER .AT2 records for Table 5.4")
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--calibrate", action="store_true")
    a = ap.parse_args(argv)
    paper_tables.reproduce(a.out, a.records, a.quick, a.calibrate)
    return 0
