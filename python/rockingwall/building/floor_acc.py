"""The peak acceleration of the floor a wall stands on as an engineer reads it: low-pass filtered
at CUTOFF_HZ, from the floor's acceleration sampled densely enough that nothing aliases.

The raw peak grows with the tie's stiffness: an impact changes the wall's velocities at once, and
through a stiff tie the floor rings at the tie's own frequency (hundreds of Hz at 1e8-1e10 N/m
per m; in the rigid-tie limit an acceleration impulse). That ringing carries little energy and
depends on an idealised connection; the floor's motion that walls, parts and contents feel lies
well below 25 Hz, the cut-off strong-motion processing and floor spectra use. Filtered there, the
peak stops depending on the tie (docs/your-building.md, "Floor acceleration"). The sampling and the
filter serve the tie's force too (tie_force.py), whose raw peak rings the same way."""
import dataclasses

import numpy as np
from scipy import signal

from .. import scene_engine
from .trusted_run import check_energy

# The low-pass cut-off [Hz]: above the floors' and walls' structural modes and the band of
# acceleration-sensitive parts and contents, below a tie's ringing.
CUTOFF_HZ = 25.0
# A Butterworth filter of this order, run forward and backward (zero phase, so the peak is not
# delayed or skewed; the gain is squared: -6 dB at the cut-off, flat to 1e-6 below 4 Hz).
ORDER = 4
PAD_PERIODS = 4.0
# The sampling [s]: the Nyquist frequency at or above the scene's fastest linear mode (bounded
# from above by fastest_hz), so that nothing folds at all, at most DT_MAX and at least DT_MIN
# (a finer one would need more memory than a dense history is worth: 26 MB for 80 s of 5 storeys),
# DT_MAX halved as often as needed: a grid on the records' samples (0.005, 0.01 s), which the
# engine steps through at the cost of one on the record alone.
DT_MAX = 1e-3
DT_MIN = DT_MAX / 8
# A second check, and a refinement by halving (at most REFINEMENTS times): the filtered peaks from
# every sample and from every other sample agree within ALIAS_SHARE.
REFINEMENTS = 2
ALIAS_SHARE = 0.005


def lowpass(a, dt, cutoff_hz=CUTOFF_HZ):
    """The samples a (along axis 0, interval dt [s]) low-pass filtered at cutoff_hz, zero phase."""
    sos = signal.butter(ORDER, cutoff_hz, fs=1.0 / dt, output="sos")
    # the ends extended by PAD_PERIODS periods of the cut-off, so that the filter's start-up
    # transient dies outside the run: before it by zeros (the scene starts from rest, and the
    # floor with it), after it by the run mirrored (a run cut off mid-ringing ends on its local
    # mean; scipy's default, an odd extension, would keep the last sample and its ringing)
    a = np.asarray(a, dtype=float)
    pad = min(len(a) - 1, int(round(PAD_PERIODS / (cutoff_hz * dt))))
    padded = np.concatenate([np.zeros((pad,) + a.shape[1:]), a, a[-2:-pad - 2:-1]])
    return signal.sosfiltfilt(sos, padded, axis=0, padlen=0)[pad:pad + len(a)]


def filtered_peak(a, dt, cutoff_hz=CUTOFF_HZ):
    """The largest |a| after the low-pass, per column."""
    return np.max(np.abs(lowpass(a, dt, cutoff_hz)), axis=0)


def _alias_share(a, dt):
    """Every sample filtered, their filtered peaks, and how far the filtered peaks of every other
    sample are from those (relative to the filtered peak, or to 1e-3 of the raw one where the filter
    leaves less)."""
    filtered = lowpass(a, dt)
    full = np.max(np.abs(filtered), axis=0)
    half = filtered_peak(a[::2], 2.0 * dt)
    scale = np.maximum(full, 1e-3 * np.max(np.abs(a), axis=0)) + 1e-300
    return filtered, full, float(np.max(np.abs(full - half) / scale))


def fastest_hz(spec):
    """An upper bound [Hz] of the scene's fastest linear mode: Gershgorin's bound on M^-1 K with each
    mass taken alone, twice the stiffness tied to it over it; a wall's top as a twelfth of its mass
    (a rigid body rocking about its base moves a third of it at the top; a mid-height hinge less)."""
    w2 = 0.0
    floors = list(spec.storeys)
    for i, s in enumerate(floors):
        tie = s.wall["Kd"] if s.wall else 0.0
        if s.wall:
            w2 = max(w2, 2.0 * tie / (s.wall["W"] / 9.81 / 12.0))
        if s.md > 0:
            w2 = max(w2, 2.0 * (tie + s.kd) / s.md)
        if not spec.rigid_in_plane and s.m > 0:
            above = floors[i + 1] if i + 1 < len(floors) else None
            attached = s.k + s.kd + (above.k + (above.wall["Kd"] if above.wall else 0.0) if above else 0.0)
            w2 = max(w2, 2.0 * attached / s.m)
    return np.sqrt(w2) / (2.0 * np.pi)


def sample_dt(spec):
    """(the sampling interval [s], whether its Nyquist frequency reaches fastest_hz)."""
    needed = 0.5 / max(fastest_hz(spec), 1e-9)
    dt = DT_MAX / 2.0 ** max(0, int(np.ceil(np.log2(DT_MAX / needed) - 1e-12)))
    return max(dt, DT_MIN), dt >= DT_MIN


@dataclasses.dataclass(frozen=True)
class Sampled:
    """One history of every storey sampled densely and low-pass filtered: the filtered peaks, the raw
    peaks on the same samples, the sampling interval [s] from `start` [s], whether the sampling
    resolved them (its Nyquist frequency above the scene's fastest mode and every other sample
    giving the same filtered peaks within ALIAS_SHARE), and the filtered samples (rows: times)."""
    filtered_peak: np.ndarray
    raw_peak: np.ndarray
    dt: float
    resolved: bool
    filtered: np.ndarray
    start: float

    def at(self, t):
        """The filtered history at the times t [s] (rows), linear between samples; NaN after the
        run stopped (the samples end there)."""
        times = self.start + self.dt * np.arange(len(self.filtered))
        columns = [np.interp(t, times, col, right=np.nan) for col in np.atleast_2d(self.filtered.T)]
        return np.column_stack(columns)


def _sampled_histories(spec, record, t_end, rtol, engine, dt, histories, what):
    """{name: samples} of the scene's histories (names of scene_engine.HISTORIES) every dt [s] up to
    where the run stopped, from one run whose energy is checked (`what` names it in the error)."""
    start = float(record.t[0])
    end = float(record.t[-1]) if t_end is None else float(t_end)
    grid = start + dt * np.arange(int(np.floor((end - start) / dt)) + 1)
    r = scene_engine.run(spec, record.t, record.ag, t_end=end, rtol=rtol, t_out=grid, engine=engine,
                         histories=tuple(histories))
    check_energy(r, f"{record.name} sampled every {dt:g} s ({what})")
    rows = {name: getattr(r, name) for name in histories}
    first = rows[histories[0]]
    reached = np.flatnonzero(np.all(np.isfinite(first), axis=1))   # rows after the run stopped are NaN
    return {name: (h[: reached[-1] + 1] if reached.size else np.zeros((1, h.shape[1]))) for name, h in rows.items()}


def sample_histories(spec, record, histories, what, t_end=None, rtol=1e-8, engine=None):
    """{name: Sampled} of each storey's `histories` (names of scene_engine.HISTORIES), all from one
    run, sampled and filtered: the sampling refined until every other sample gives the same
    filtered peaks, for each of them."""
    dt, fine_enough = sample_dt(spec)
    start = float(record.t[0])
    for refinement in range(REFINEMENTS + 1):
        samples = _sampled_histories(spec, record, t_end, rtol, engine, dt, histories, what)
        checked = {name: _alias_share(s, dt) for name, s in samples.items()}  # any length: a few samples too
        if all(share <= ALIAS_SHARE for _, _, share in checked.values()) or dt / 2 < DT_MIN * (1 - 1e-12):
            break
        dt /= 2
    return {name: Sampled(peak, np.max(np.abs(samples[name]), axis=0), dt, fine_enough and share <= ALIAS_SHARE,
                          filtered, start) for name, (filtered, peak, share) in checked.items()}


def sample_history(spec, record, history, what, t_end=None, rtol=1e-8, engine=None):
    """Each storey's `history` sampled and filtered, on a run of its own (a Sampled)."""
    return sample_histories(spec, record, (history,), what, t_end, rtol, engine)[history]


def sample(spec, record, t_end=None, rtol=1e-8, engine=None):
    """Each storey's floor acceleration [m/s2], sampled and filtered (a Sampled)."""
    return sample_history(spec, record, "base_acc", "the floors' accelerations", t_end, rtol, engine)
