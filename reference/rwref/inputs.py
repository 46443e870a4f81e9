"""Ground-motion and top-displacement inputs.

Every input is a callable ``f(t) -> float``.  Accelerations are in m/s^2, positive toward +x
(docs/model.md "Sign convention").  Sampled records are `Signal` objects: linear interpolation
between samples and the end values HELD outside the sampled range (before the first and after the
last sample), the same convention as a zero-order-hold-free FMU input that keeps its last value.
"""
import math
import os
import re

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


_FLOAT = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[EeDd][-+]?\d+)?"


def _float(tok, path, lineno):
    try:
        v = float(tok.replace("D", "E").replace("d", "e"))
    except ValueError:
        raise ValueError(f"{path}:{lineno}: cannot read {tok!r} as a number") from None
    if not math.isfinite(v):
        raise ValueError(f"{path}:{lineno}: non-finite value {tok!r}")
    return v


def read_csv(path, units="g", scale=1.0, g=G_STD):
    """Two columns ``time, accel`` (comma, semicolon, tab or blank separated).  Blank lines and
    lines starting with '#' are skipped; one non-numeric header line is allowed as the first
    data line.  units: "g" or "m/s2".  Returns a Signal in m/s^2 times `scale`."""
    if units not in ("g", "m/s2"):
        raise ValueError(f"read_csv: units must be 'g' or 'm/s2', got {units!r}")
    path = os.fspath(path)
    ts, acc = [], []
    seen_data = False
    with open(path, encoding="utf-8-sig") as fh:
        for lineno, line in enumerate(fh, 1):
            s = line.strip()
            if not s or s.startswith("#"):
                continue
            toks = [x for x in re.split(r"[,;\s]+", s) if x]
            if not seen_data and not re.fullmatch(_FLOAT, toks[0]):
                seen_data = True  # header line
                continue
            seen_data = True
            if len(toks) != 2:
                raise ValueError(f"{path}:{lineno}: expected 2 columns (time, accel), found {len(toks)}")
            t, a = _float(toks[0], path, lineno), _float(toks[1], path, lineno)
            if ts and t <= ts[-1]:
                raise ValueError(f"{path}:{lineno}: time {t} is not strictly increasing (previous {ts[-1]})")
            ts.append(t)
            acc.append(a)
    if len(ts) < 2:
        raise ValueError(f"{path}: need at least 2 data lines, found {len(ts)}")
    k = (g if units == "g" else 1.0) * scale
    return Signal(np.array(ts), np.array(acc) * k, name=os.path.basename(path))


def read_at2(path, scale=1.0, g=G_STD):
    """PEER NGA .AT2: 4 header lines (line 3 states units of g, line 4 gives NPTS and DT, either
    "NPTS=  n, DT=  dt SEC" or the old "n  dt  NPTS, DT"), then the values in g.  Time starts at 0.
    Returns a Signal in m/s^2 times `scale`."""
    path = os.fspath(path)
    with open(path, encoding="latin-1") as fh:
        lines = fh.read().splitlines()
    if len(lines) < 4:
        raise ValueError(f"{path}:{len(lines) + 1}: file ends inside the 4-line AT2 header")
    if not re.search(r"\bG\b", lines[2].upper()):
        raise ValueError(f"{path}:3: expected the units line to say the values are in G, got {lines[2].strip()!r}")
    hdr = lines[3]
    m_n = re.search(r"NPTS\s*=\s*(\d+)", hdr, re.I)
    m_dt = re.search(r"DT\s*=\s*(" + _FLOAT + ")", hdr, re.I)
    if m_n and m_dt:
        npts, dt = int(m_n.group(1)), _float(m_dt.group(1), path, 4)
    else:
        toks = re.split(r"[,\s]+", hdr.strip())
        try:
            npts, dt = int(toks[0]), _float(toks[1], path, 4)
        except (ValueError, IndexError):
            raise ValueError(f"{path}:4: cannot find NPTS and DT in the header line {hdr.strip()!r}") from None
    if npts <= 0 or not dt > 0:
        raise ValueError(f"{path}:4: need NPTS > 0 and DT > 0, got NPTS={npts}, DT={dt}")
    vals = []
    for lineno, line in enumerate(lines[4:], 5):
        for tok in line.replace(",", " ").split():
            vals.append(_float(tok, path, lineno))
    if len(vals) != npts:
        raise ValueError(f"{path}:{len(lines)}: header (line 4) announces NPTS={npts} but the file has {len(vals)} values")
    t = np.arange(npts) * dt
    return Signal(t, np.array(vals) * g * scale, name=os.path.basename(path))
