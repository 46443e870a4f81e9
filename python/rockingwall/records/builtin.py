"""The records that need no file: El Centro 1940 (from the quakeio package) and the paper's
Gaussian displacement impulse."""
import numpy as np

from .. import bounds
from .types import G_STD, Record, RecordError

def el_centro(g=G_STD):
    """El Centro 1940 (Imperial Valley, 180 component) as shipped by quakeio, dt = 0.02 s."""
    import quakeio.elcentro as ec
    data = np.asarray(ec.accel.data, dtype=float)
    return Record("El Centro 1940", np.arange(data.size) * float(ec.accel.time_step), data * g, source="quakeio")


def gaussian(D=0.04, T=1.0, dt=1e-3, t_end=None):
    """The paper's Gaussian displacement impulse u_g = D exp(-(t - T/2)^2 / (2 (T/8)^2)),
    sampled every dt up to t_end (default 10 T): ground acceleration u_g'' [m/s^2]."""
    t_end = 10 * T if t_end is None else t_end
    for name, value in (("D", D), ("T", T), ("dt", dt), ("t_end", t_end)):
        if not (np.isfinite(value) and value > 0):
            raise RecordError(f"Gaussian impulse: {name} = {value!r} must be a finite number > 0")
    if t_end > bounds.MAX_RUN_S or t_end / dt > bounds.MAX_OUTPUT_ROWS * 10:
        raise RecordError(f"Gaussian impulse: {t_end:g} s every {dt:g} s is longer than {bounds.MAX_RUN_S:g} s, "
                          "the longest run this program makes, or has too many samples")
    t = np.arange(0.0, t_end + dt / 2, dt)
    s2 = (T / 8) ** 2
    z = t - T / 2
    return Record(f"Gaussian D={D:g} m T={T:g} s", t, D * np.exp(-z * z / (2 * s2)) * (z * z / (s2 * s2) - 1 / s2),
                  source="gaussian")


