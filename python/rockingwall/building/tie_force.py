"""The force of each storey's tie on its diaphragm, as an engineer reads it: low-pass filtered at
floor_acc.CUTOFF_HZ, from the scene's tie-force history sampled densely.

Its raw peak grows with the tie's stiffness, as the floor's acceleration does: an impact changes
the wall's velocities at once, the diaphragm's mass follows only through the tie, and the tie rings
at its own frequency with a force of about the velocity's jump times sqrt(k_tie m). The assessor's
upper wall under its roof and El Centro at 0.1 g: 4.0, 13.3 and 34.1 kN/m raw at ties of 1e7, 1e8
and 1e9 N/m per m, 1.36, 1.34 and 1.34 kN/m filtered (docs/your-building.md, "Tie force"). The
filtered force is the one the diaphragm's spring, dashpot and mass put on the connection; the raw
one depends on an idealised connection's stiffness, which the user seldom gives. A wall that
collapses leaves the scene and its tie with it: its force is then 0, and no demand is read from
a collapsed wall's."""
from . import floor_acc


def sample(spec, record, t_end=None, rtol=1e-8, engine=None):
    """Each storey's tie force [N/m], sampled and filtered (a floor_acc.Sampled)."""
    return floor_acc.sample_history(spec, record, "tie", "the ties' forces", t_end, rtol, engine)
