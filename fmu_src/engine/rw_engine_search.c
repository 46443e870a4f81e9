/* The earliest event in a substep: sign changes and dips of the indicators, roots refined.
 * The roots are refined on the exact motion, the earliest guess first. */
#include "rw_engine_hermite.h"
#include "rw_engine_span.h"

#include <float.h>
#include <math.h>
#include <string.h>

static double indicator_at(const rw_span_ctx *sc, int k, double s)
{
    double x[RW_NX], z[RW_NZ];
    rw_input in = span_input(&sc->sp, s);
    span_eval(&sc->sp, s, NULL, x, NULL);
    rwe_region_indicators(sc, &in, x, NULL, 1u << k, z, NULL);
    return z[k];
}

/* rate of indicator k at s (for the extremum of a possible double crossing) */
static double indicator_rate(const rw_span_ctx *sc, int k, double s)
{
    rw_point pt;
    eval_point(sc, s, NULL, &pt);
    return pt.dz[k];
}

/* Safeguarded regula falsi (Illinois; a bisection when three steps have not halved the bracket)
 * for the first s in (lo, hi] where the boolean (value > 0) differs from its value at lo, starting
 * from the guess (NaN: none). Returns hi at convergence (to a few ulps of the absolute time), the
 * first point known to be past the root. */
double rwe_find_switch(rw_scalar_fn f, const rw_span_ctx *sc, int k, const rw_bracket *br, double rel_tol,
                       double guess)
{
    double lo = br->lo, flo = br->flo, hi = br->hi, fhi = br->fhi;
    const int blo = flo > 0.0;
    const double tol_interval = rel_tol * (hi - lo);
    double width_before = hi - lo;
    int it, last = 0;
    for (it = 0; it < 400; it++) {
        const double tol = rw_max2(4.0 * DBL_EPSILON * (fabs(sc->sp.t0) + fabs(hi)) + 1e-300, tol_interval);
        double s, fs;
        int bisect = 0;
        if (hi - lo <= tol) break;
        if (it % 3 == 0) { /* the safeguard: every three steps the bracket must have halved */
            bisect = it > 0 && hi - lo > 0.5 * width_before;
            width_before = hi - lo;
        }
        if (it == 0 && guess > lo && guess < hi) s = guess;
        else s = (bisect || fhi == flo) ? 0.5 * (lo + hi) : (lo * fhi - hi * flo) / (fhi - flo);
        if (!(s > lo && s < hi)) s = 0.5 * (lo + hi);
        if (!(s > lo && s < hi)) break; /* adjacent doubles */
        fs = f(sc, k, s);
        if ((fs > 0.0) != blo) {
            hi = s;
            fhi = fs;
            if (last == -1) flo *= 0.5;
            last = -1;
        } else {
            lo = s;
            flo = fs;
            if (last == 1) fhi *= 0.5;
            last = 1;
        }
    }
    return hi;
}

/* Indicator k and its rate at s and, for a line of the rotations, its second rate (*curv; NaN for
 * the others). A line's value comes from the same state and the same evaluation as
 * rwe_region_indicators', so its sign at the root is the one every other test sees. */
static double indicator_rates_at(const rw_span_ctx *sc, int k, double s, double x[RW_NX], double *rate, double *curv)
{
    double xd[RW_NX], z[RW_NZ], dz[RW_NZ];
    rw_input in;
    span_eval(&sc->sp, s, NULL, x, xd);
    if ((sc->e->line_mask >> k) & 1u) {
        const rw_indicator_line *L = &sc->e->lines[k];
        const double w = L->a[0] * x[0] + L->a[1] * x[1];
        const double slope = L->s * ((w > 0.0) - (w < 0.0)) + L->t;
        *curv = slope * (L->a[0] * xd[2] + L->a[1] * xd[3]);
        return rw_line_value(L, x, xd, rate);
    }
    in = span_input(&sc->sp, s);
    rwe_region_indicators(sc, &in, x, xd, 1u << k, z, dz);
    *rate = dz[k];
    *curv = NAN;
    return z[k];
}

/* The next iterate from s: Halley's step where the second rate is known (cubic convergence: from
 * the Hermite guess one step reaches rounding), else Newton's; NaN if neither is defined. */
static double root_step(double f, double df, double ddf)
{
    const double den = 2.0 * df * df - f * ddf;
    if (ddf == ddf && den > 0.0) return -2.0 * f * df / den; /* ddf == ddf: not NaN */
    return df != 0.0 ? -f / df : NAN;
}

/* The first s in the bracket's (lo, hi] where indicator k leaves the state `was` (the state at lo),
 * to a few ulps of the absolute time, from the guess (NaN: none): Halley or Newton steps on the
 * exact motion, kept inside the bracket (else a regula falsi step, and a bisection when three steps
 * have not halved it). Near the root the last step is taken a little past it, so that the bracket
 * closes. Returns hi, the first point known to be past the root, with the state there in x_hi if it
 * was evaluated here (*x_valid). */
double rwe_refine_root(const rw_span_ctx *sc, int k, int was, const rw_bracket *br, double guess,
                       double x_hi[RW_NX], int *x_valid)
{
    double lo = br->lo, flo = br->flo, hi = br->hi, fhi = br->fhi;
    double width_before = hi - lo, s = guess;
    int it, past;
    *x_valid = 0;
    for (it = 0; it < 200; it++) {
        const double tol = 4.0 * DBL_EPSILON * (fabs(sc->sp.t0) + fabs(hi)) + 1e-300;
        double fs, rate, curv, step, x[RW_NX];
        if (hi - lo <= tol) break;
        if (it % 3 == 0) { /* the safeguard: every three steps the bracket must have halved */
            if (it > 0 && hi - lo > 0.5 * width_before) s = 0.5 * (lo + hi);
            width_before = hi - lo;
        }
        if (!(s > lo && s < hi)) s = fhi != flo ? (lo * fhi - hi * flo) / (fhi - flo) : 0.5 * (lo + hi);
        if (!(s > lo && s < hi)) s = 0.5 * (lo + hi);
        if (!(s > lo && s < hi)) break; /* adjacent doubles */
        fs = indicator_rates_at(sc, k, s, x, &rate, &curv);
        past = (fs > 0.0) != was;
        if (past) {
            hi = s, fhi = fs;
            memcpy(x_hi, x, sizeof x);
            *x_valid = 1;
        } else {
            lo = s, flo = fs;
        }
        step = root_step(fs, rate, curv);
        if (past && fabs(step) < 0.5 * tol) break; /* s is past the root, and the root within tol of it */
        /* within rounding of the root the step's direction is noise: probe half the tolerance past
         * it, so that the bracket closes; else aim a quarter of it past the root, so that the next
         * point, when the step has converged, is the one returned */
        if (fabs(step) < 0.5 * tol) step = 0.5 * tol;
        else step += 0.25 * tol;
        s += step; /* NaN or outside the bracket: the fallback above */
    }
    return hi;
}

#define RW_DIP_DEPTH 3 /* a suspicious substep is split 4 ways, at most this many times */

/* Does indicator k, on the same side of zero (state `was`) at both ends of [a, b], dip through
 * zero in between? Only when it moves toward zero at an end and its Hermite interpolant does not
 * clear zero; then the piece is split (a breakpoint indicator |w| - c has a kink at w = 0, so one
 * piece can hold a dip and a turn), and at the finest level the extremum is located. On a dip,
 * *br brackets its first crossing. */
static int dip(const rw_span_ctx *sc, int k, int was, const rw_point *a, const rw_point *b, int depth, rw_bracket *br)
{
    const int approach = was ? a->dz[k] < 0.0 : a->dz[k] > 0.0;
    const int leave = was ? b->dz[k] > 0.0 : b->dz[k] < 0.0;
    rw_point p[2];
    int i;
    if (!approach && !leave) return 0;
    if (hermite_keeps_sign(a->z[k], a->dz[k], b->z[k], b->dz[k], b->s - a->s)) return 0;
    if (depth == RW_DIP_DEPTH) {
        double s_ext, z_ext;
        if (!approach || !leave) return 0;
        {
            const rw_bracket rates = {a->s, a->dz[k], b->s, b->dz[k]};
            s_ext = rwe_find_switch(indicator_rate, sc, k, &rates, 1e-9, NAN);
        }
        z_ext = indicator_at(sc, k, s_ext);
        if ((z_ext > 0.0) == was) return 0;
        br->lo = a->s, br->flo = a->z[k], br->hi = s_ext, br->fhi = z_ext;
        return 1;
    }
    p[0] = *a;
    for (i = 1; i <= 4; i++) {
        rw_point *q = &p[i & 1];
        const rw_point *prev = &p[(i - 1) & 1];
        if (i == 4) *q = *b;
        else eval_point(sc, a->s + 0.25 * i * (b->s - a->s), NULL, q);
        if ((q->z[k] > 0.0) != was) {
            br->lo = prev->s, br->flo = prev->z[k], br->hi = q->s, br->fhi = q->z[k];
            return 1;
        }
        if (dip(sc, k, was, prev, q, depth + 1, br)) return 1;
    }
    return 0;
}

/* Can indicator k have left the state `was` in (a->s, s_best], given the state x_best at s_best
 * (position and rates)? 1 unless it is a line still in that state at s_best whose cubic Hermite
 * interpolant over [a->s, s_best] keeps clear of zero (then it has no earlier root). */
static int crossed_before(const rw_engine *e, int k, int was, const rw_point *a, double s_best,
                          const double x_best[RW_NX])
{
    double z, dz;
    if (!((e->line_mask >> k) & 1u) || (a->z[k] > 0.0) != was) return 1;
    z = rw_line_value(&e->lines[k], x_best, x_best + 2, &dz);
    if ((z > 0.0) != was) return 1;
    return !hermite_keeps_sign(a->z[k], a->dz[k], z, dz, s_best - a->s);
}

/* Earliest s in (a->s, b->s] where an indicator of `suspects` (suspects_of) changes its state
 * e->b[k], including a dip through zero and back inside the substep. Returns 1 with *ev, or 0
 * (*ev unchanged). */
int rwe_first_event(const rw_span_ctx *sc, const rw_point *a, const rw_point *b, unsigned suspects, rw_root *ev)
{
    const rw_engine *e = sc->e;
    int order[RW_NZ], n = 0, i, found = 0, x_known = 0;
    double guess[RW_NZ], best = b->s;
    /* the indicators that change sign first, the earliest guess first, then the possible dips: a
     * line found later is mostly settled by its value at the first root (crossed_before), without
     * a refinement of its own */
    for (i = 0; suspects >> i; i++) {
        if (!((suspects >> i) & 1u)) continue;
        guess[i] = INFINITY;
        if ((b->z[i] > 0.0) != e->b[i]) {
            guess[i] = NAN;
            if ((a->z[i] > 0.0) == e->b[i])
                guess[i] = a->s + (b->s - a->s) * hermite_root(a->z[i], a->dz[i], b->z[i], b->dz[i], b->s - a->s);
        }
        n = insert_by_guess(order, n, guess, i);
    }
    for (i = 0; i < n; i++) {
        const int k = order[i], was = e->b[k];
        rw_bracket br = {a->s, a->z[k], b->s, b->z[k]};
        double s, x_root[RW_NX];
        int x_valid;
        if (found && x_known && !crossed_before(e, k, was, a, best, ev->x)) continue;
        if (guess[k] == INFINITY && !dip(sc, k, was, a, b, 0, &br)) continue;
        if ((br.flo > 0.0) != was) br.flo = was ? DBL_MIN : 0.0; /* the state at lo is the tracked one */
        if (found && br.lo >= best) continue;
        s = rwe_refine_root(sc, k, was, &br, guess[k] == INFINITY ? NAN : guess[k], x_root, &x_valid);
        if (!found || s < best) {
            best = s;
            ev->k = k;
            x_known = x_valid;
            if (x_valid) memcpy(ev->x, x_root, sizeof x_root);
        }
        found = 1;
    }
    if (!found) return 0;
    ev->s = best;
    if (!x_known) span_eval(&sc->sp, best, NULL, ev->x, NULL);
    return 1;
}
