"""The force of the tie on the diaphragm of a wall under a diaphragm with mass, as an engineer reads
it: low-pass filtered at floor_acc.CUTOFF_HZ, from the tie's stretch sampled densely, while the wall
stands.

Its raw peak grows with the tie's stiffness, as the floor's acceleration does: an impact changes
the wall's velocities at once, the diaphragm's mass follows only through the tie, and the tie rings
at its own frequency with a force of about the velocity's jump times sqrt(k_tie m). The assessor's
upper wall under El Centro at 0.1 g: 4.0, 13.3 and 34.1 kN/m raw at ties of 1e7, 1e8 and 1e9 N/m
per m, 1.36, 1.34 and 1.34 kN/m filtered (docs/your-building.md, "Tie force"). The filtered force is
the one the diaphragm's spring, dashpot and mass put on the connection; the raw one depends on an
idealised connection's stiffness, which the user seldom gives."""
import numpy as np

from . import floor_acc


def _stretch_while_standing(tie):
    def series(r, grid, reached):
        keep = reached if not r.collapsed[0] else int(np.searchsorted(grid[:reached], r.t_collapse[0]))
        # after a collapse the wall's histories hold its last state and the tie holds nothing
        return tie * (r.s2[:keep, :1] - r.diaphragm[:keep, :1]) if keep else np.zeros((1, 1))
    return series


def peaks(spec, record, tie, t_end=None, rtol=1e-8, engine=None):
    """(the filtered peak [N/m] of the tie's force on the first storey's diaphragm while its wall
    stands, its raw peak on the same samples [N/m], the sampling interval [s], whether the sampling
    resolved it: floor_acc.sampled_peaks')."""
    filtered, raw, dt, resolved = floor_acc.sampled_peaks(spec, record, _stretch_while_standing(tie),
                                                          ("s2", "diaphragm"), "the tie's force", t_end, rtol,
                                                          engine)
    return float(filtered[0]), float(raw[0]), dt, resolved
