"""Ground-motion and top-displacement inputs.

Every input is a callable ``f(t) -> float``.  Accelerations are in m/s^2, positive toward +x
(docs/model.md "Sign convention").  Sampled records are `Signal` objects: linear interpolation
between samples and the end values HELD outside the sampled range (before the first and after the
last sample), the same convention as a zero-order-hold-free FMU input that keeps its last value.
"""
import math

import numpy as np

G_STD = 9.81


class Signal:
    """A sampled signal: arrays ``t`` (strictly increasing) and ``a``; linear interpolation,
    ends held outside [t[0], t[-1]]."""

    def __init__(self, t, a, name="signal"):
        t = np.asarray(t, dtype=float)
        a = np.asarray(a, dtype=float)
        if t.ndim != 1 or a.shape != t.shape or t.size < 1:
            raise ValueError(f"{name}: t and a must be 1-D arrays of the same non-zero length")
        if not (np.all(np.isfinite(t)) and np.all(np.isfinite(a))):
            raise ValueError(f"{name}: non-finite values")
        if t.size > 1 and np.any(np.diff(t) <= 0):
            raise ValueError(f"{name}: time must be strictly increasing")
        self.t, self.a, self.name = t, a, name

    def __call__(self, t):
        return float(np.interp(t, self.t, self.a))

    @property
    def dt(self):
        return float(np.median(np.diff(self.t))) if self.t.size > 1 else math.inf

    @property
    def duration(self):
        return float(self.t[-1])

    def knots(self, t0, t1):
        """Sample times strictly inside (t0, t1): the input is linear between them."""
        return self.t[(self.t > t0) & (self.t < t1)]

    def scaled(self, k):
        return Signal(self.t, self.a * k, self.name)


class GaussianPulse:
    """Ground acceleration of the Gaussian displacement impulse of paper Section 5.3:
    u_g = D exp(-(t - t0)^2 / (2 sigma^2)), sigma = T/8, t0 = T/2 (docs/model.md), a_g = u_g''."""

    def __init__(self, D, T, t0=None):
        if not T > 0:
            raise ValueError("gaussian: T must be > 0")
        self.D, self.T = float(D), float(T)
        self.t0 = self.T / 2 if t0 is None else float(t0)
        self.sigma = self.T / 8

    def displacement(self, t):
        return self.D * math.exp(-(t - self.t0) ** 2 / (2 * self.sigma**2))

    def __call__(self, t):
        z = t - self.t0
        s2 = self.sigma**2
        return self.D * math.exp(-z * z / (2 * s2)) * (z * z / (s2 * s2) - 1 / s2)


def sampled(fn, t_end, dt, name="sampled signal"):
    """fn (e.g. gaussian(...)) sampled every dt on [0, t_end]: the tabulated, linearly
    interpolated form that FMU hosts take, so the FMU and this solver see the same input."""
    t = np.arange(0.0, t_end + dt / 2, dt)
    return Signal(t, np.array([fn(x) for x in t]), name)


def gaussian(D, T, t0=None):
    return GaussianPulse(D, T, t0)


class Constant:
    def __init__(self, a):
        self.a = float(a)

    def __call__(self, t):
        return self.a


def constant(a):
    return Constant(a)


class Ramp:
    """0 before t_start, linear to a_end at t_start + t_ramp, a_end afterwards."""

    def __init__(self, a_end, t_ramp, t_start=0.0):
        if not t_ramp > 0:
            raise ValueError("ramp: t_ramp must be > 0")
        self.a_end, self.t_ramp, self.t_start = float(a_end), float(t_ramp), float(t_start)

    def __call__(self, t):
        return self.a_end * min(1.0, max(0.0, (t - self.t_start) / self.t_ramp))


def ramp(a_end, t_ramp, t_start=0.0):
    return Ramp(a_end, t_ramp, t_start)


def zero(t):
    return 0.0


def as_function(x):
    """None -> zero, number -> constant, callable (incl. Signal) -> itself."""
    if x is None:
        return zero
    if callable(x):
        return x
    if isinstance(x, (int, float, np.floating, np.integer)):
        return Constant(x)
    raise TypeError(f"input must be a callable t -> value, an inputs.Signal, a number or None; got {type(x)}")


def el_centro(scale=1.0, g=G_STD):
    """El Centro 1940 as shipped by quakeio (quakeio.elcentro.accel, dt = 0.02 s, in g),
    times `scale` ("times the record as given", docs/model.md), in m/s^2."""
    import quakeio.elcentro as ec

    acc = ec.accel
    data = np.asarray(acc.data, dtype=float)
    dt = float(acc.time_step)
    t = np.arange(data.size) * dt
    return Signal(t, data * g * scale, name=f"El Centro 1940 x{scale}")
