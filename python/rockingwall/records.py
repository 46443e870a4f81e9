"""Ground-motion records: the one reader of PEER NGA `.AT2` files and of two-column CSV files,
El Centro 1940 (from the quakeio package) and the paper's Gaussian displacement impulse.

A Record holds accelerations in m/s^2 at sample times in s, linear between samples, the end
values held (the convention of the FMU's inputs and of the engine)."""
import dataclasses
import hashlib
import math
import os
import pathlib
import re

import numpy as np

G_STD = 9.81
_FLOAT = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[EeDd][-+]?\d+)?"


class RecordError(ValueError):
    """A record that cannot be read, with the file, line and problem in the message."""


@dataclasses.dataclass(frozen=True, eq=False)
class Record:
    name: str
    t: np.ndarray    # s, strictly increasing
    ag: np.ndarray   # m/s^2
    source: str = ""

    @property
    def pga(self):
        """Peak ground acceleration [m/s^2]."""
        return float(np.max(np.abs(self.ag))) if self.ag.size else 0.0

    @property
    def duration(self):
        return float(self.t[-1] - self.t[0])

    @property
    def sha256(self):
        """Hash of the samples: results are tied to the numbers, not to the name."""
        h = hashlib.sha256(np.ascontiguousarray(self.t).tobytes())
        h.update(np.ascontiguousarray(self.ag).tobytes())
        return h.hexdigest()[:16]

    def scaled(self, factor):
        """The record times `factor` ("times the record as given")."""
        return dataclasses.replace(self, ag=self.ag * float(factor), name=f"{self.name} x{factor:g}")

    def to_pga(self, pga_g, g=G_STD):
        """The record scaled so that its PGA is pga_g [g]."""
        if not self.pga > 0:
            raise RecordError(f"{self.name}: a record of zeros cannot be scaled to a PGA")
        return dataclasses.replace(self.scaled(pga_g * g / self.pga), name=f"{self.name} at {pga_g:g} g")


def _number(token, path, lineno):
    try:
        v = float(token.replace("D", "E").replace("d", "e"))
    except ValueError:
        raise RecordError(f"{path}:{lineno}: cannot read {token!r} as a number") from None
    if not math.isfinite(v):
        raise RecordError(f"{path}:{lineno}: non-finite value {token!r}")
    return v


def at2_header(line, path="AT2", lineno=4):
    """NPTS and DT from an AT2 file's 4th header line, in both NGA layouts:
    'NPTS=  2688, DT=  .0100 SEC' and the old '2688  .0100  NPTS, DT'."""
    m_n = re.search(r"NPTS\s*=\s*(\d+)", line, re.I)
    m_dt = re.search(r"DT\s*=\s*(" + _FLOAT + ")", line, re.I)
    if m_n and m_dt:
        npts, dt = int(m_n.group(1)), _number(m_dt.group(1), path, lineno)
    else:
        tokens = re.split(r"[,\s]+", line.strip())
        try:
            npts, dt = int(tokens[0]), _number(tokens[1], path, lineno)
        except (ValueError, IndexError):
            raise RecordError(f"{path}:{lineno}: expected 'NPTS= N, DT= dt SEC', found {line.strip()[:200]!r}") from None
    if npts <= 0 or not dt > 0:
        raise RecordError(f"{path}:{lineno}: need NPTS > 0 and DT > 0, got NPTS={npts}, DT={dt}")
    return npts, dt


def read_at2(path, g=G_STD):
    """A PEER NGA .AT2 file: 4 header lines (the 3rd says the values are in g, the 4th gives NPTS
    and DT), then the values in g. Time starts at 0. Returns a Record in m/s^2."""
    path = os.fspath(path)
    try:
        with open(path, encoding="latin-1") as fh:
            lines = fh.read().splitlines()
    except OSError as exc:
        raise RecordError(f"{path}: {exc.strerror or exc}") from None
    if len(lines) < 4:
        raise RecordError(f"{path}:{len(lines) + 1}: file ends inside the 4-line AT2 header")
    if not re.search(r"\bG\b", lines[2].upper()):
        raise RecordError(f"{path}:3: expected the units line to say the values are in G, got {lines[2].strip()!r}")
    npts, dt = at2_header(lines[3], path)
    values = [_number(tok, path, lineno) for lineno, line in enumerate(lines[4:], 5)
              for tok in line.replace(",", " ").split()]
    if len(values) != npts:
        raise RecordError(f"{path}:{len(lines)}: the header (line 4) announces NPTS={npts} "
                          f"but the file has {len(values)} values")
    return Record(pathlib.Path(path).stem, np.arange(npts) * dt, np.array(values) * g, source=path)


def read_csv(path, units="g", g=G_STD):
    """Two columns, time [s] and acceleration (comma, semicolon, tab or blank separated); '#'
    lines and one header line are skipped. units: 'g' or 'm/s2'."""
    if units not in ("g", "m/s2"):
        raise ValueError(f"units must be 'g' or 'm/s2', got {units!r}")
    path = os.fspath(path)
    times, accs = [], []
    try:
        fh = open(path, encoding="utf-8-sig")
    except OSError as exc:
        raise RecordError(f"{path}: {exc.strerror or exc}") from None
    with fh:
        for lineno, line in enumerate(fh, 1):
            tokens = [x for x in re.split(r"[,;\s]+", line.strip()) if x]
            if not tokens or tokens[0].startswith("#"):
                continue
            if not times and not re.fullmatch(_FLOAT, tokens[0]):
                continue  # the header line
            if len(tokens) != 2:
                raise RecordError(f"{path}:{lineno}: expected 2 columns (time, acceleration), found {len(tokens)}")
            t, a = _number(tokens[0], path, lineno), _number(tokens[1], path, lineno)
            if times and t <= times[-1]:
                raise RecordError(f"{path}:{lineno}: time {t} is not after the previous one ({times[-1]})")
            times.append(t)
            accs.append(a)
    if len(times) < 2:
        raise RecordError(f"{path}: need at least 2 rows of numbers, found {len(times)}")
    factor = g if units == "g" else 1.0
    return Record(pathlib.Path(path).stem, np.array(times), np.array(accs) * factor, source=path)


def el_centro(g=G_STD):
    """El Centro 1940 (Imperial Valley, 180 component) as shipped by quakeio, dt = 0.02 s."""
    import quakeio.elcentro as ec
    data = np.asarray(ec.accel.data, dtype=float)
    return Record("El Centro 1940", np.arange(data.size) * float(ec.accel.time_step), data * g, source="quakeio")


def gaussian(D=0.04, T=1.0, dt=1e-3, t_end=None):
    """The paper's Gaussian displacement impulse u_g = D exp(-(t - T/2)^2 / (2 (T/8)^2)),
    sampled every dt up to t_end (default 10 T): ground acceleration u_g'' [m/s^2]."""
    t_end = 10 * T if t_end is None else t_end
    t = np.arange(0.0, t_end + dt / 2, dt)
    s2 = (T / 8) ** 2
    z = t - T / 2
    return Record(f"Gaussian D={D:g} m T={T:g} s", t, D * np.exp(-z * z / (2 * s2)) * (z * z / (s2 * s2) - 1 / s2),
                  source="gaussian")


def load(spec, units="g"):
    """A record from what a user types: 'elcentro', 'gaussian' or 'gaussian:D,T' (m, s), or a path
    to an .AT2 or a .csv file (CSV in `units`), or to an ESM, GeoNet, K-NET or COSMOS file
    ('FILE:COMPONENT' picks a component; rockingwall.record_formats)."""
    text = os.fspath(spec)
    if text.lower() in ("elcentro", "el-centro", "el_centro"):
        return el_centro()
    if text.lower().startswith("gaussian"):
        _, _, args = text.partition(":")
        values = [float(v) for v in args.split(",") if v.strip()] if args else []
        return gaussian(*values)
    from . import record_formats  # imported here: record_formats imports this module
    found = record_formats.read_record(text)  # an ESM, GeoNet, K-NET or COSMOS file, whatever its name
    if found is not None:
        return found
    suffix = pathlib.Path(text).suffix.lower()
    if suffix == ".at2":
        return read_at2(text)
    if suffix in (".csv", ".txt", ".dat"):
        return read_csv(text, units=units)
    return record_formats.read_by_content(text, units)  # else the error that lists the formats read
