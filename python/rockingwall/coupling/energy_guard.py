"""The energy guard of a coupled run: the Jacobi master's monitor (rockingwall.coupling.jacobi)
that balances the scene's energy at every communication point and stops the run, with a
CouplingUnstable naming the likely cause and the remedy, once the residual passes the stop bound
(rules.ENERGY_STOP_SHARE of the peak input work so far): a run past its stability limit ends with
an error, never with a collapse or a peak that the scheme made.

The scene gives read_meta(slaves) (what the balance needs once: masses, damping coefficients)
and parts(point, fallen, meta) -> (input power, damping power, stored energy, losses at events),
all per metre of wall; the guard integrates the powers with the trapezoidal rule on the
communication grid, as the scenes' own bookkeeping does.

The check starts after SETTLE_STEPS macro steps (at least SETTLE_SECONDS): in the first steps of a
coarse but stable run the input work is still tiny and the one-step lag of the exchange a large
share of it (held inputs at 8 ms passed half of it at 0.06 s and fell to a few per cent later).
Nothing escapes by the wait: the energy an unstable exchange made stays in the residual (in a
fallen wall's frozen energy too), so the first check after the wait stops the run."""
import math

from . import rules
from .slaves import CouplingUnstable

SETTLE_STEPS = 50
SETTLE_SECONDS = 0.05


class EnergyGuard:
    """Monitor of jacobi.run; explain(t, residual, peak_input) -> the error message."""

    def __init__(self, read_meta, parts, explain, share=rules.ENERGY_STOP_SHARE):
        if not (math.isfinite(share) and share > 0):
            raise ValueError(f"energy stop share {share!r} must be a positive number")
        self.read_meta, self.parts, self.explain, self.share = read_meta, parts, explain, share
        self.meta = None
        self.previous = None
        self.t_start = None
        self.work_in = self.work_damping = self.peak_input = self.max_share = 0.0

    def start(self, slaves):
        self.meta = self.read_meta(slaves)
        self.previous = None
        self.work_in = self.work_damping = self.peak_input = self.max_share = 0.0

    def check(self, point, fallen):
        P_in, P_d, stored, losses = self.parts(point, fallen, self.meta)
        if self.previous is None:
            self.start_stored, self.start_losses, self.t_start = stored, losses, point.t
            self.step = None
        else:
            self.step = self.step or point.t - self.previous[0]
            t0, P_in0, P_d0 = self.previous
            dt = point.t - t0
            self.work_in += 0.5 * (P_in + P_in0) * dt
            self.work_damping += 0.5 * (P_d + P_d0) * dt
        self.previous = (point.t, P_in, P_d)
        residual = self.work_in - (stored - self.start_stored) - self.work_damping - (losses - self.start_losses)
        self.peak_input = max(self.peak_input, abs(self.work_in))
        settled = self.step is not None and point.t - self.t_start >= max(SETTLE_STEPS * self.step, SETTLE_SECONDS)
        if not math.isfinite(residual) or (settled and residual != 0.0 and abs(residual) > self.share * self.peak_input):
            raise CouplingUnstable(self.explain(point.t, residual, self.peak_input))
        if settled and self.peak_input > 0:
            self.max_share = max(self.max_share, abs(residual) / self.peak_input)
