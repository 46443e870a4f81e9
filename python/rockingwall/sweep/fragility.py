"""Collapse fragility: P(collapse | IM = x) = Phi(ln(x / theta) / beta), fitted by maximum
likelihood to the collapse counts at each intensity level (binomial likelihood, as in Baker 2015,
"Efficient analytical fragility function fitting using dynamic structural analysis data")."""
import dataclasses

import numpy as np
from scipy import optimize, stats


@dataclasses.dataclass(frozen=True)
class Fragility:
    theta: float   # median: the IM at which half the records collapse the wall
    beta: float    # lognormal standard deviation
    n_runs: int

    def __call__(self, im):
        return stats.norm.cdf(np.log(np.asarray(im, dtype=float) / self.theta) / self.beta)


def counts(im, collapsed):
    """Per distinct IM level: (level, runs, collapses)."""
    im = np.asarray(im, dtype=float)
    collapsed = np.asarray(collapsed, dtype=bool)
    levels = np.unique(im)
    n = np.array([np.sum(im == x) for x in levels])
    z = np.array([np.sum(collapsed[im == x]) for x in levels])
    return levels, n, z


def fit(im, collapsed):
    """MLE of (theta, beta). Needs at least one collapse and one survival, else no estimate."""
    levels, n, z = counts(im, collapsed)
    if z.sum() == 0 or z.sum() == n.sum():
        raise ValueError("all runs collapse or none does: the fragility has no finite estimate")

    def nll(p):
        # log-parameters keep theta, beta > 0; clipping keeps log() finite at p = 0 or 1
        prob = np.clip(stats.norm.cdf((np.log(levels) - p[0]) / np.exp(p[1])), 1e-12, 1 - 1e-12)
        return -np.sum(z * np.log(prob) + (n - z) * np.log1p(-prob))

    median_guess = np.log(levels[np.argmin(np.abs(z / n - 0.5))])
    res = optimize.minimize(nll, x0=[median_guess, np.log(0.4)], method="Nelder-Mead",
                            options=dict(xatol=1e-8, fatol=1e-10, maxiter=4000))
    if not res.success:
        raise RuntimeError(f"fragility fit did not converge: {res.message}")
    return Fragility(float(np.exp(res.x[0])), float(np.exp(res.x[1])), int(n.sum()))


MIN_RECORDS = 10  # below this the dispersion beta is poorly constrained (FEMA P695 uses 22 pairs)


@dataclasses.dataclass(frozen=True)
class Estimate:
    """A fragility with its uncertainty: 90 % bootstrap intervals over the records, and warnings
    where the data cannot support the fit."""
    fit: Fragility | None
    theta_90: tuple = (np.nan, np.nan)
    beta_90: tuple = (np.nan, np.nan)
    n_records: int = 0
    warnings: tuple = ()


def fit_with_uncertainty(im, exceeded, records, n_boot=200, seed=1):
    """The MLE fit, and the 5-95 % range of theta and beta when the records are resampled with
    replacement (each record keeps all its intensity levels: the records, not the runs, are the
    independent samples)."""
    im, exceeded, records = np.asarray(im, float), np.asarray(exceeded, bool), np.asarray(records)
    names = np.unique(records)
    notes = []
    if len(names) < MIN_RECORDS:
        notes.append(f"only {len(names)} records (fewer than {MIN_RECORDS}): the median and above all the "
                     "dispersion beta are poorly constrained; read the intervals, not the digits")
    try:
        best = fit(im, exceeded)
    except (ValueError, RuntimeError) as exc:
        return Estimate(None, n_records=len(names), warnings=tuple(notes + [str(exc)]))
    if exceeded.any() and (~exceeded).any() and im[~exceeded].max() < im[exceeded].min():
        notes.append("every run below an intensity survives and every run above it fails: the data do not "
                     "overlap, so beta is not identified (the fit's beta only reflects the spacing of the levels)")
    rng = np.random.default_rng(seed)
    by_record = {n: np.flatnonzero(records == n) for n in names}
    thetas, betas = [], []
    for _ in range(n_boot):
        pick = np.concatenate([by_record[n] for n in rng.choice(names, size=len(names), replace=True)])
        try:
            f = fit(im[pick], exceeded[pick])
        except (ValueError, RuntimeError):
            continue  # a resample with no exceedance (or only exceedances) has no estimate
        thetas.append(f.theta)
        betas.append(f.beta)
    if len(thetas) < 0.8 * n_boot:
        notes.append(f"{n_boot - len(thetas)} of {n_boot} bootstrap resamples had no finite estimate")
    if not thetas:
        return Estimate(best, n_records=len(names), warnings=tuple(notes))
    return Estimate(best, tuple(np.percentile(thetas, [5, 95])), tuple(np.percentile(betas, [5, 95])),
                    len(names), tuple(notes))


def resurrections(levels, collapsed):
    """Intensity levels at which a record that collapsed the wall at a lower level leaves it
    standing: IDA's 'resurrection', which a fragility fit hides."""
    order = np.argsort(levels)
    levels, collapsed = np.asarray(levels)[order], np.asarray(collapsed, bool)[order]
    first = np.flatnonzero(collapsed)
    if first.size == 0:
        return []
    return [float(x) for x, c in zip(levels[first[0] + 1:], collapsed[first[0] + 1:]) if not c]
