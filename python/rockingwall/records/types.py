"""A ground-motion record (accelerations in m/s^2 at sample times in s, linear between samples,
the end values held: the convention of the FMU's inputs and of the engine) and the error a
record file that cannot be read raises, with the file, line and problem."""
import dataclasses
import hashlib
import math
import os

import numpy as np

from .. import bounds

G_STD = 9.81
FLOAT = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[EeDd][-+]?\d+)?"


class RecordError(ValueError):
    """A record that cannot be read, with the file, line and problem in the message."""


@dataclasses.dataclass(frozen=True, eq=False)
class Record:
    name: str
    t: np.ndarray    # s, strictly increasing
    ag: np.ndarray   # m/s^2
    source: str = ""

    def __post_init__(self):
        """Every Record is one the model can run: finite, increasing times, finite accelerations of
        at most bounds.MAX_AG_G (a unit slip or a corrupt file is refused here, with its name)."""
        where = self.label
        t, ag = np.asarray(self.t), np.asarray(self.ag)
        if t.ndim != 1 or ag.shape != t.shape or t.size < 1:
            raise RecordError(f"{where}: times and accelerations must be two 1-D arrays of one length")
        if not np.isfinite(t).all() or (t.size > 1 and not (np.diff(t) > 0).all()):
            raise RecordError(f"{where}: the times must be finite and increasing")
        if not np.isfinite(ag).all():
            raise RecordError(f"{where}: an acceleration is not a finite number")
        try:
            bounds.peak_ag(float(np.max(np.abs(ag))), where)
        except ValueError as exc:
            raise RecordError(str(exc)) from None

    @property
    def label(self):
        """What messages call the record: its file when it has one, else its name."""
        return self.source if self.source and os.path.isfile(self.source) else self.name

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
        """The record times `factor` ("times the record as given"), a finite number > 0."""
        factor = bounds.positive(factor, f"{self.name}: scale factor")
        return dataclasses.replace(self, ag=self.ag * factor, name=f"{self.name} x{factor:g}")

    def to_pga(self, pga_g, g=G_STD):
        """The record scaled so that its PGA is pga_g [g] (finite, > 0, at most bounds.MAX_AG_G)."""
        pga_g = bounds.intensity_g(pga_g, f"{self.name}: target PGA")
        if not self.pga > 0:
            raise RecordError(f"{self.name}: a record of zeros cannot be scaled to a PGA")
        return dataclasses.replace(self.scaled(pga_g * g / self.pga), name=f"{self.name} at {pga_g:g} g")


def number(token, path, lineno):
    """A finite number from a token of a record file (Fortran D exponents too); RecordError naming
    the file and line otherwise."""
    try:
        v = float(token.replace("D", "E").replace("d", "e"))
    except ValueError:
        raise RecordError(f"{path}:{lineno}: cannot read {token!r} as a number") from None
    if not math.isfinite(v):
        raise RecordError(f"{path}:{lineno}: non-finite value {token!r}")
    return v


