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
