"""Fragility: P(reached | IM = x) = Phi(ln(x / theta) / beta), fitted by maximum likelihood to the
counts of runs that reach a limit state at each intensity level (binomial likelihood, as in Baker
2015, "Efficient analytical fragility function fitting using dynamic structural analysis data"),
with bootstrap intervals over the records.

The likelihood is that of a probit regression, Phi(a + c ln x) with c = 1/beta and a = -c ln
theta, which is concave in (a, c): its maximum, where it exists, is unique and Newton's method
finds it to rounding. The bootstrap's resamples are fitted together, as arrays (probit.py)."""
import dataclasses

import numpy as np
from scipy import special

from . import probit


@dataclasses.dataclass(frozen=True)
class Fragility:
    theta: float   # median: the IM at which half the runs reach the limit state
    beta: float    # lognormal standard deviation; 0 where the data do not overlap (a step)
    n_runs: int
    gap: tuple = None   # where the data do not overlap, (lo, hi) of IM: the median may be anywhere inside
    mixed: "MixedLevel" = None   # the one level of such a fit where some runs reach the limit state

    def __call__(self, im):
        x = np.log(np.asarray(im, dtype=float) / self.theta)
        if self.beta == 0:
            return np.where(x < 0, 0.0, np.where(x > 0, 1.0, 0.5))
        return special.ndtr(x / self.beta)


@dataclasses.dataclass(frozen=True)
class MixedLevel:
    """The level of a fit whose data do not overlap at which some runs reach the limit state and
    some do not, with the levels run next to it (None: none on that side)."""
    level: float
    reached: float
    runs: float
    lower: float = None
    higher: float = None

    @classmethod
    def of(cls, levels, n, z):
        """The mixed level of the counts (levels, n, z per level), or None where no level is mixed."""
        mixed = np.flatnonzero((z > 0) & (n - z > 0) & (n > 0))
        if mixed.size != 1:
            return None
        j, run = int(mixed[0]), np.flatnonzero(n > 0)
        lower, higher = run[run < j], run[run > j]
        return cls(float(levels[j]), float(z[j]), float(n[j]), float(levels[lower[-1]]) if lower.size else None,
                   float(levels[higher[0]]) if higher.size else None)


def counts(im, collapsed):
    """Per distinct IM level: (level, runs, collapses)."""
    im = np.asarray(im, dtype=float)
    collapsed = np.asarray(collapsed, dtype=bool)
    levels = np.unique(im)
    n = np.array([np.sum(im == x) for x in levels])
    z = np.array([np.sum(collapsed[im == x]) for x in levels])
    return levels, n, z


def no_estimate_message(status, what):
    """Why a fit has no estimate, in words naming the limit state `what` ('collapse', '0.6 Delta_u')."""
    if status == probit.NONE:
        return f"no run reaches {what}: the fragility has no finite estimate (its median is above every intensity run)"
    if status == probit.ALL:
        return f"every run reaches {what}: the fragility has no finite estimate (its median is below every intensity run)"
    if status == probit.FLAT:
        return (f"the share of runs reaching {what} does not rise with the intensity: the fragility has no finite "
                "estimate (beta unbounded)")
    return f"the runs are all at one intensity: the fragility of {what} has no estimate (beta not identified)"


def gap_median(gap, digits=2):
    """Where the median of a fit whose data do not overlap lies, in words: 'at x' where the gap is
    one level (whose runs are mixed, half reaching the limit state), 'above x' or 'below x' where no
    level was run on that side, else 'anywhere in [lo, hi]'."""
    lo, hi = (f"{end:.{digits}g}" for end in gap)
    if gap[0] == gap[1]:
        return f"at {lo}"
    if np.isinf(gap[1]):
        return f"above {lo}"
    return f"below {hi}" if gap[0] == 0 else f"anywhere in [{lo}, {hi}]"


def clipped(gap, top):
    """The gap with an open upper end (no level run above it) drawn up to `top`."""
    return gap[0], min(gap[1], max(top, gap[0]))


def gap_message(gap, what, mixed=None):
    """What a fit whose data do not overlap (Fragility.gap, .mixed) can say, in words naming `what`."""
    if mixed is None:
        seen = f"no run at or below {gap[0]:.2g} reaches {what} and every run at or above {gap[1]:.2g} does"
    else:
        below = "no run below it does" if mixed.lower is not None else "no intensity below it was run"
        above = "every run above it does" if mixed.higher is not None else "no intensity above it was run"
        half = ("fewer than half" if 2 * mixed.reached < mixed.runs else
                "more than half" if 2 * mixed.reached > mixed.runs else "half")
        seen = f"at {mixed.level:.2g}, {mixed.reached:g} of {mixed.runs:g} runs reach {what} ({half}); {below}; {above}"
    return f"{seen}: the data do not overlap, so beta is not identified (0) and the median is {gap_median(gap)}"


def fit(im, exceeded, what="collapse"):
    """The MLE of (theta, beta). ValueError where there is none: no run or every run reaches the
    limit state, the share reaching it does not rise with the intensity, or one intensity only.
    Where no run overlaps (every run below some intensity stays short, every run above reaches it)
    beta is 0 and theta anywhere in the gap: theta is then the gap's geometric mean, or the level
    whose runs are mixed where there is one (the gap then says which side of it the median is on:
    probit.fit)."""
    levels, n, z = counts(im, exceeded)
    fits = probit.fit(np.log(levels), n[None, :], z[None, :])
    status = int(fits.status[0])
    if status not in (probit.INTERIOR, probit.SEPARATED):
        raise ValueError(no_estimate_message(status, what))
    gap = tuple(float(x) for x in np.exp(fits.gap[0])) if status == probit.SEPARATED else None
    return Fragility(float(fits.theta[0]), float(fits.beta[0]), int(n.sum()), gap,
                     MixedLevel.of(levels, n, z) if gap else None)


MIN_RECORDS = 10  # below this the dispersion beta is poorly constrained (FEMA P695 uses 22 pairs)


@dataclasses.dataclass(frozen=True)
class Estimate:
    """A fragility with its uncertainty: 90 % bootstrap intervals over the records (an end is
    inf, or 0 for theta, where the bootstrap cannot bound it; NaN where the data do not overlap,
    whose median is a gap, not an estimate with a spread), and warnings where the data cannot
    support the fit."""
    fit: Fragility | None
    theta_90: tuple = (np.nan, np.nan)
    beta_90: tuple = (np.nan, np.nan)
    n_records: int = 0
    warnings: tuple = ()


def tables(im, exceeded, records):
    """(record names, IM levels, runs per record and level, exceedances per record and level)."""
    im, exceeded, records = np.asarray(im, float), np.asarray(exceeded, bool), np.asarray(records)
    names, r = np.unique(records, return_inverse=True)
    levels, l = np.unique(im, return_inverse=True)
    n = np.zeros((names.size, levels.size))
    z = np.zeros((names.size, levels.size))
    np.add.at(n, (r, l), 1.0)
    np.add.at(z, (r, l), exceeded.astype(float))
    return names, levels, n, z


def bootstrap_weights(n_records, n_boot, seed):
    """(n_boot, n_records): how often each record is drawn in each resample (records drawn with
    replacement, as many as there are)."""
    rng = np.random.default_rng(seed)
    picks = rng.choice(n_records, size=(n_boot, n_records), replace=True)
    weights = np.zeros((n_boot, n_records))
    np.add.at(weights, (np.arange(n_boot)[:, None], picks), 1.0)
    return weights


def fit_with_uncertainty(im, exceeded, records, n_boot=200, seed=1, what="collapse"):
    """The MLE fit, and the 5-95 % range of theta and beta when the records are resampled with
    replacement (each record keeps all its runs at every intensity level: the records, not the
    runs, are the independent samples). A resample where no run or every run reaches the limit
    state has no estimate and is left out; one whose data do not overlap counts with beta 0, one
    whose share does not rise with the intensity with beta unbounded (inf)."""
    names, levels, n, z = tables(im, exceeded, records)
    return fit_tables(levels, n, z, n_boot, seed, what)


def fit_tables(levels, n, z, n_boot=200, seed=1, what="collapse"):
    """fit_with_uncertainty from count tables: n, z (records x levels) the runs and the runs that
    reach the limit state of each record at each level (several runs per record and level: the
    members of an ensemble, which a resample keeps together with their record)."""
    n_records = n.shape[0]
    notes = []
    if n_records < MIN_RECORDS:
        notes.append(f"only {n_records} record{'s' if n_records != 1 else ''} (fewer than {MIN_RECORDS}): the median and above all the "
                     "dispersion beta are poorly constrained; read the intervals, not the digits")
    weights = np.vstack([np.ones(n_records), bootstrap_weights(n_records, n_boot, seed)])
    fits = probit.fit(np.log(levels), weights @ n, weights @ z)
    status = int(fits.status[0])
    if status not in (probit.INTERIOR, probit.SEPARATED):
        return Estimate(None, n_records=n_records, warnings=tuple(notes + [no_estimate_message(status, what)]))
    gap = tuple(float(x) for x in np.exp(fits.gap[0])) if status == probit.SEPARATED else None
    mixed = MixedLevel.of(levels, n.sum(axis=0), z.sum(axis=0)) if gap else None
    best = Fragility(float(fits.theta[0]), float(fits.beta[0]), int(n.sum()), gap, mixed)
    if gap:  # no interval: the resamples' medians are the convention's points inside their gaps, not a spread
        return Estimate(best, n_records=n_records, warnings=tuple(notes + [gap_message(gap, what, mixed)]))
    boot = fits.status[1:]
    used = (boot != probit.NONE) & (boot != probit.ALL) & (boot != probit.ONE_LEVEL)
    if used.sum() < 0.8 * n_boot or (boot[used] != probit.INTERIOR).sum() >= 0.05 * n_boot:
        notes.append(f"{n_boot - int(used.sum())} of {n_boot} bootstrap resamples had no estimate (no run or every "
                     f"run past the limit), {int((boot == probit.SEPARATED).sum())} no overlap (beta 0), "
                     f"{int((boot == probit.FLAT).sum())} a share that does not rise with the intensity (beta "
                     "unbounded)")
    if not used.any():
        return Estimate(best, n_records=n_records, warnings=tuple(notes))
    return Estimate(best, percentiles(fits.theta[1:][used]), percentiles(fits.beta[1:][used]), n_records,
                    tuple(notes))


def percentiles(values, q=(5, 95)):
    """np.percentile's linear interpolation, where an infinite value at or beside the percentile
    gives inf (the bootstrap cannot bound that end) instead of nan."""
    v = np.sort(np.asarray(values, dtype=float))
    if np.isfinite(v).all():
        return tuple(float(x) for x in np.percentile(v, q))
    out = []
    for p in q:
        pos = p / 100 * (v.size - 1)
        lo, hi = int(np.floor(pos)), int(np.ceil(pos))
        if np.isinf(v[lo]) or np.isinf(v[hi]):
            out.append(np.inf)
        else:
            out.append(float(v[lo] + (v[hi] - v[lo]) * (pos - lo)))
    return tuple(out)


def resurrections(levels, collapsed):
    """Intensity levels at which a record that collapsed the wall at a lower level leaves it
    standing: IDA's 'resurrection', which a fragility fit hides."""
    order = np.argsort(levels)
    levels, collapsed = np.asarray(levels)[order], np.asarray(collapsed, bool)[order]
    first = np.flatnonzero(collapsed)
    if first.size == 0:
        return []
    return [float(x) for x, c in zip(levels[first[0] + 1:], collapsed[first[0] + 1:]) if not c]
