"""An animated GIF of the two-body wall rocking under a record, restrained at the top by the
diaphragm spring K_d, drawn from a run of the exact engine, with the ground acceleration below. The wall is
drawn to scale but its rotations are exaggerated (--exaggerate, stated in the title): tens of
millimetres on a 2.5 m wall are invisible otherwise.

The bodies are placed from s1, s2 (q1 = 2 s1/h, q2 = 2 s2/h - q1): the lower body turns by q1 about
the base corner it rocks on (side sign(q1)), the upper body by q2 about the mid-height corner on
which the joint closes (side -sign(q2 - q1)), as in docs/model.md. The diaphragm is drawn fixed
(u_top = 0, as in the run), the ground moves with the record.

  rockingwall animate --wall paper1 --Kd 50kN/m/m --pga 0.2 RECORD.AT2 --out docs/img/rocking_wall.gif
"""
import pathlib

from .. import animation, outputs
from . import common as cc


def main(argv=None):
    p = cc.Parser(prog="rockingwall animate", description=__doc__)
    cc.add_wall_arguments(p)
    cc.add_record_arguments(p)
    p.add_argument("--t-end", type=float, default=20.0, help="seconds of the record shown")
    p.add_argument("--speed", type=float, default=1.0, help="simulated seconds per second of GIF")
    p.add_argument("--fps", type=int, default=12)
    p.add_argument("--exaggerate", type=float, default=5.0, help="factor on the drawn rotations")
    p.add_argument("--out", default="results/rocking_wall.gif")
    args = p.parse_args(argv)
    wall = cc.wall_from_args(args)
    if not (1 <= args.fps <= 100 and 0 < args.speed <= 100 and 0 < args.t_end < float("inf")):
        raise ValueError(f"--fps {args.fps} (1..100), --speed {args.speed:g} (0..100] and --t-end {args.t_end:g} "
                         "(> 0): out of range")
    rec = cc.record_from_args(args.record, args)
    out = pathlib.Path(args.out)
    cc.output_dir(out.parent)
    outputs.check_target(out, "--out")  # before the run: the GIF never replaces the record
    n_frames, s1, s2 = animation.animate(wall, rec, out, args.t_end, args.speed, args.fps, args.exaggerate)
    print(f"wrote {out} ({out.stat().st_size / 1e6:.2f} MB, {n_frames} frames); peaks in the clip: "
          f"s1 {1000 * s1:.1f} mm, s2 {1000 * s2:.1f} mm")
    return 0
