"""The main job: wall 1 of the paper under El Centro 1940 at 50 %, simulated through the
exact engine (or --engine fmi2sim / fmpy: the FMU) as the simply supported wall and with a flexible diaphragm
(K_d = 500, 50, 5 kN/m per metre of wall, the cases of the paper's Table 5.4 / Fig. 5.4), with
the default hinge law (dohertyHinge).

Prints the peak mid-height and top displacements beside the paper's (naming the cases far from
them), writes the time histories to a CSV and draws them (results/main_elcentro.csv,
results/main_elcentro.png)."""
import pathlib

from .. import main_job
from ..api import ENGINES
from . import common as cc


def main(argv=None):
    parser = cc.Parser(prog="rockingwall demo", description=__doc__)
    parser.add_argument("--scale", type=cc.scale_factor, default=0.5, help="factor on the record as given (default 0.5)")
    parser.add_argument("--engine", default="exact", choices=ENGINES)
    parser.add_argument("--out", default="results", help="folder for the CSV and the plot (created if missing)")
    args = parser.parse_args(argv)

    out = cc.output_dir(args.out)
    runs = main_job.run(args.scale, args.engine)
    lines = main_job.table(runs, args.scale)
    print("\n" + "\n".join(lines))
    cc.write_atomic(out / "main_job.txt", lambda tmp: pathlib.Path(tmp).write_text("\n".join(lines) + "\n"))

    csv_path = out / "main_elcentro.csv"
    table = main_job.histories(runs)
    cc.write_atomic(csv_path, lambda tmp: table.to_csv(tmp, index=False, float_format="%.6g"))

    png_path = out / "main_elcentro.png"
    fig = main_job.figure(runs, args.scale, args.engine)
    cc.write_atomic(png_path, lambda tmp: fig.savefig(tmp, dpi=110, format="png"))
    print(f"\nwrote {csv_path} and {png_path}")
    return 0
