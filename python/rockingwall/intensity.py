"""Intensity measures of a record: PGA, and Sa(T), the 5 %-damped pseudo-spectral acceleration
of a linear oscillator of period T (e.g. the diaphragm's or the wall's), which often explains
out-of-plane demand better than PGA."""
import numpy as np
from scipy import signal

from .records import G_STD as G


def pga(record):
    """[g]"""
    return record.pga / G


def sa(record, period, damping=0.05):
    """Pseudo-spectral acceleration [g] at `period` [s]: omega^2 max|u| of u'' + 2 zeta omega u'
    + omega^2 u = -ag, with ag linear between samples (first-order hold, as the model sees it)."""
    if not period > 0:
        raise ValueError(f"Sa period {period!r} s: must be > 0")
    omega = 2 * np.pi / period
    system = signal.lti([[0.0, 1.0], [-omega**2, -2 * damping * omega]], [[0.0], [-1.0]], [[1.0, 0.0]], [[0.0]])
    # resample finely enough for the oscillator (20 points per period), never coarser than the record
    dt = min(float(np.min(np.diff(record.t))), period / 20)
    t = np.arange(record.t[0], record.t[-1] + 3 * period, dt)
    ag = np.interp(t, record.t, record.ag, right=0.0)
    _, u, _ = signal.lsim(system, ag, t, interp=True)
    return omega**2 * float(np.max(np.abs(u))) / G
