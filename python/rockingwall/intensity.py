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


PGA_PLAUSIBLE = (1e-4, 3.0)  # g: a record scaled outside this is most often in the wrong unit


def pga_warning(record):
    """A message when the record's PGA (as scaled) is outside PGA_PLAUSIBLE, naming the likely
    unit slip; None when it is plausible."""
    return pga_value_warning(record.name, pga(record))


def pga_value_warning(name, value):
    """pga_warning for a record `name` whose PGA as run is `value` [g]."""
    low, high = PGA_PLAUSIBLE
    if value > high:
        return (f"{name}: PGA {value:.3g} g is above {high:g} g: is the record in cm/s^2 or m/s^2 and read "
                f"as g (a CSV file: --csv-units cm/s2 or m/s2)? {value:.3g} g is {value * G:.3g} m/s^2")
    if value < low:
        return (f"{name}: PGA {value:.3g} g is below {low:g} g: is the record in g and read as m/s^2 or "
                "cm/s^2 (a CSV file: --csv-units g), or the scale factor too small?")
    return None
