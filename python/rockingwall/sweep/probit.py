"""Lognormal fragility fits of many count tables at once: P = Phi(a + c x) at x = ln(IM), each
row of (runs, exceedances) per level fitted by maximum likelihood, which is a probit regression.

Its log-likelihood is concave in (a, c) and strictly so unless the outcomes separate, so the
maximum, where it exists, is unique: Newton's method with step halving reaches it to rounding.
Where it does not exist the row says why (status):
    INTERIOR   the maximum exists with c > C_FLAT: theta = exp(-a/c), beta = 1/c;
    SEPARATED  every run below some level stays short and every run above it reaches the limit
               state (equal at one level at most): the likelihood grows as beta -> 0, theta is
               anywhere in the gap (its log-midpoint is returned). Where one level is mixed, the
               median is on the side of it where half the runs would be: above it, up to the next
               level run, where fewer than half reach the limit state there; below it, down to the
               level run before, where more do (at it where half do), and an open side (no level
               run there) leaves it unbounded that way (the gap returned); theta is the mixed
               level, where the likelihood's supremum puts the step;
    FLAT       the share reaching it does not rise with the intensity: the supremum over c > 0
               is at c -> 0, beta -> inf, theta -> 0 or inf;
    NONE, ALL  no run or every run reaches it; ONE_LEVEL  every run at one level."""
import dataclasses

import numpy as np
from scipy import special

INTERIOR, SEPARATED, FLAT, NONE, ALL, ONE_LEVEL = range(6)
C_FLAT = 1e-8   # c = 1/beta at or below this (beta >= 1e8, a flat share to rounding) counts as FLAT
_LOG_SQRT_2PI = 0.5 * np.log(2 * np.pi)


@dataclasses.dataclass(frozen=True)
class Fits:
    """Per row: status, theta, beta (NaN where there is no estimate) and the gap's ends in ln(IM)
    for SEPARATED rows (NaN elsewhere)."""
    status: np.ndarray
    theta: np.ndarray
    beta: np.ndarray
    gap: np.ndarray


def classify(x, n, z):
    """(status per row, gap (rows x 2) in x). n, z: rows x levels."""
    short = (n - z) > 0
    reach = z > 0
    inf = np.inf
    max_short = np.where(short, x, -inf).max(axis=1)
    min_short = np.where(short, x, inf).min(axis=1)
    max_reach = np.where(reach, x, -inf).max(axis=1)
    min_reach = np.where(reach, x, inf).min(axis=1)
    status = np.full(n.shape[0], INTERIOR)
    status[max_reach <= min_short] = FLAT  # reaching only at levels below (or at) the shortfalls
    status[max_short <= min_reach] = SEPARATED
    status[(n > 0).sum(axis=1) < 2] = ONE_LEVEL
    status[~reach.any(axis=1)] = NONE
    status[~short.any(axis=1)] = ALL
    return status, np.column_stack([max_short, min_reach])


def median_bounds(x, n, z, level):
    """(rows x 2) where the median lies, in x, for rows separated at one mixed level (x = level):
    toward the next level run on the side where half the runs would reach the limit state
    (-inf or inf where no level was run on that side), the level itself where half do."""
    at = x[None, :] == level[:, None]
    share = (z * at).sum(axis=1) / (n * at).sum(axis=1)
    run = n > 0
    above = np.where(run & (x > level[:, None]), x, np.inf).min(axis=1)
    below = np.where(run & (x < level[:, None]), x, -np.inf).max(axis=1)
    lo = np.where(share > 0.5, below, level)
    hi = np.where(share < 0.5, above, level)
    return np.column_stack([lo, hi])


def log_likelihood(a, c, x, n, z):
    eta = a[:, None] + c[:, None] * x
    return np.sum(z * special.log_ndtr(eta) + (n - z) * special.log_ndtr(-eta), axis=1)


def newton(x, n, z, iterations=100):
    """The unconstrained maximum (a, c) of every row (rows whose outcomes do not separate)."""
    total = n.sum(axis=1)
    xm = (n * x).sum(axis=1) / total
    c = np.full(n.shape[0], 2.5)  # beta 0.4 to start
    a = special.ndtri(np.clip(z.sum(axis=1) / total, 1e-3, 1 - 1e-3)) - c * xm
    ll = log_likelihood(a, c, x, n, z)
    active = np.ones(n.shape[0], bool)
    for _ in range(iterations):
        if not active.any():
            break
        da, dc = _newton_step(a[active], c[active], x, n[active], z[active])
        t = np.ones(da.size)
        ll_old = ll[active]
        for _ in range(60):  # halve the step until the likelihood does not fall (it is concave)
            ll_new = log_likelihood(a[active] + t * da, c[active] + t * dc, x, n[active], z[active])
            worse = ~(ll_new >= ll_old - 1e-13 * np.abs(ll_old))
            if not worse.any():
                break
            t[worse] *= 0.5
        idx = np.flatnonzero(active)
        a[idx] += t * da
        c[idx] += t * dc
        ll[idx] = ll_new
        small = (np.abs(t * da) <= 1e-13 * (1 + np.abs(a[idx]))) & (np.abs(t * dc) <= 1e-13 * (1 + np.abs(c[idx])))
        active[idx[small]] = False
    return a, c


def _newton_step(a, c, x, n, z):
    eta = a[:, None] + c[:, None] * x
    log_phi = -0.5 * eta**2 - _LOG_SQRT_2PI
    lam_hi = np.exp(log_phi - special.log_ndtr(eta))    # phi/Phi(eta): the pull of the runs that reach
    lam_lo = np.exp(log_phi - special.log_ndtr(-eta))   # phi/Phi(-eta): of those that stay short
    d = z * lam_hi - (n - z) * lam_lo
    w = z * lam_hi * (eta + lam_hi) + (n - z) * lam_lo * (lam_lo - eta)  # minus the second derivative
    g0, g1 = d.sum(axis=1), (d * x).sum(axis=1)
    h00, h01, h11 = w.sum(axis=1), (w * x).sum(axis=1), (w * x * x).sum(axis=1)
    det = h00 * h11 - h01**2
    return (h11 * g0 - h01 * g1) / det, (h00 * g1 - h01 * g0) / det


def fit(x, n, z):
    """Fits every row of n, z (rows x levels, floats: runs and exceedances at the levels x =
    ln(IM)). Returns Fits."""
    x = np.asarray(x, dtype=float)
    n = np.atleast_2d(np.asarray(n, dtype=float))
    z = np.atleast_2d(np.asarray(z, dtype=float))
    status, gap = classify(x, n, z)
    theta = np.full(status.size, np.nan)
    beta = np.full(status.size, np.nan)
    rows = status == INTERIOR
    if rows.any():
        a, c = newton(x, n[rows], z[rows])
        flat = c <= C_FLAT
        idx = np.flatnonzero(rows)
        status[idx[flat]] = FLAT
        ok = idx[~flat]
        theta[ok], beta[ok] = np.exp(-a[~flat] / c[~flat]), 1.0 / c[~flat]
    sep = status == SEPARATED
    theta[sep], beta[sep] = np.exp(gap[sep].mean(axis=1)), 0.0
    mixed = sep & (gap[:, 0] == gap[:, 1])  # theta at the mixed level, the gap where the median may be
    gap[mixed] = median_bounds(x, n[mixed], z[mixed], gap[mixed, 0])
    flat = status == FLAT
    if flat.any():  # beta -> inf; theta -> inf if fewer than half reach the limit state, 0 if more
        share = z[flat].sum(axis=1) / n[flat].sum(axis=1)
        middle = np.exp((n[flat] * x).sum(axis=1) / n[flat].sum(axis=1))
        theta[flat] = np.where(share < 0.5, np.inf, np.where(share > 0.5, 0.0, middle))
        beta[flat] = np.inf
    gap[~sep] = np.nan
    return Fits(status, theta, beta, gap)
