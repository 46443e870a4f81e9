/* Cubic Hermite bounds of the indicators over a substep, inline.
 * The quick test of all of them at once, sign and range checks of one, a root's first guess. */
#ifndef RW_ENGINE_HERMITE_H
#define RW_ENGINE_HERMITE_H

#include <float.h>
#include <math.h>

#include "rw_engine_internal.h"

/* The common case of hermite_keeps_sign, with no square root: the interpolant is a convex
 * combination of za, zb plus at most 4/27 of |ma| + |mb|, so ends of one sign that far from zero
 * (with hermite_keeps_sign's margin, 5 % of |ma| + |mb| + |zb - za|) keep it. No branch. */
static inline int far_from_zero(double za, double da, double zb, double db, double L)
{
    const double aa = fabs(za), ab = fabs(zb);
    const double need = (4.0 / 27.0 + 0.05) * fabs(L) * (fabs(da) + fabs(db)) + 0.05 * fabs(zb - za);
    return (za * zb > 0.0) & (rw_min2(aa, ab) >= need);
}

/* The values of the cubic Hermite interpolant of (za, zb) with end slopes ma = L za', mb = L zb' on
 * u in [0, 1] at its interior extrema (the roots in (0, 1) of its derivative A u^2 + B u + C) into z:
 * their number, 0 to 2. */
static inline int hermite_interior_extrema(double za, double ma, double zb, double mb, double z[2])
{
    /* z(u) = h00 za + h10 ma + h01 zb + h11 mb */
    const double A = 6.0 * za + 3.0 * ma - 6.0 * zb + 3.0 * mb;
    const double B = -6.0 * za - 4.0 * ma + 6.0 * zb - 2.0 * mb;
    const double C = ma;
    double roots[2];
    int n = 0, found = 0, i;
    if (fabs(A) > 1e-300) {
        const double disc = B * B - 4.0 * A * C;
        if (disc >= 0.0) {
            const double r = sqrt(disc), inv = 0.5 / A;
            roots[n++] = (-B + r) * inv;
            roots[n++] = (-B - r) * inv;
        }
    } else if (fabs(B) > 1e-300) {
        roots[n++] = -C / B;
    }
    for (i = 0; i < n; i++) {
        const double u = roots[i], u2 = u * u, u3 = u2 * u;
        if (u > 0.0 && u < 1.0)
            z[found++] = (2 * u3 - 3 * u2 + 1) * za + (u3 - 2 * u2 + u) * ma + (-2 * u3 + 3 * u2) * zb + (u3 - u2) * mb;
    }
    return found;
}

/* Does the cubic Hermite interpolant of (z, dz) on [0, L] stay clear of zero inside, with a
 * margin larger than its error? The end values are exact; within a substep every significant mode
 * turns by at most 1 rad, where the interpolation error is below 0.3 % of the swing, and the
 * margin is 5 % of it. An interior extremum toward zero is what a dip needs. */
static inline int hermite_keeps_sign(double za, double da, double zb, double db, double L)
{
    const double ma = L * da, mb = L * db;
    const double margin = 0.05 * (fabs(ma) + fabs(mb) + fabs(zb - za));
    const int sign = za + zb > 0.0;
    double z[2];
    int n, i;
    if (far_from_zero(za, da, zb, db, L)) return 1;
    n = hermite_interior_extrema(za, ma, zb, mb, z);
    for (i = 0; i < n; i++)
        if (sign ? z[i] < margin : z[i] > -margin) return 0;
    return 1;
}

/* The root in (0, 1) of the cubic Hermite interpolant of (z, dz) on [0, L] whose end values have
 * opposite signs: the first guess of the root refinement (within a substep every significant mode
 * turns by at most 1 rad, so the interpolant is within a fraction of a percent of the motion).
 * Newton steps on the cubic from the chord's root, kept inside the bracket of the root (else a
 * bisection), until a step is below 1e-3 of the substep: the refinement's Halley step converges from
 * there, so more digits here would be spent twice. The chord misleads where an indicator starts just
 * off zero after an event and turns back: its root is next to 0, so such a root is sought from the
 * end's Newton step instead. */
static inline double hermite_root(double za, double da, double zb, double db, double L)
{
    const double ma = L * da, mb = L * db;
    const int a_positive = za > 0.0;
    double u = za / (za - zb), lo = 0.0, hi = 1.0;
    int it;
    if (za * ma > 0.0) { /* moving away from zero at the start: the root is past a turn, nearer the end */
        const double from_end = 1.0 - zb / mb;
        u = from_end > 0.0 && from_end < 1.0 ? from_end : 0.5;
    }
    for (it = 0; it < 12; it++) {
        const double u2 = u * u, u3 = u2 * u;
        const double z = (2 * u3 - 3 * u2 + 1) * za + (u3 - 2 * u2 + u) * ma + (-2 * u3 + 3 * u2) * zb + (u3 - u2) * mb;
        const double dz = (6 * u2 - 6 * u) * za + (3 * u2 - 4 * u + 1) * ma + (-6 * u2 + 6 * u) * zb + (3 * u2 - 2 * u) * mb;
        double next;
        if ((z > 0.0) == a_positive) lo = u;
        else hi = u;
        next = u - z / dz;
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi); /* also NaN */
        if (fabs(next - u) < 1e-3) return next;
        u = next;
    }
    return u;
}

/* A range that holds hermite_range's (below) (wider, no extremum, no square root): the interpolant is a
 * convex combination of za, zb plus at most 4/27 of |ma| + |mb|. A substep quiet under it is quiet
 * under the exact range; only the others need that. */
static inline void hermite_range_bound(double za, double da, double zb, double db, double L, double *lo, double *hi)
{
    const double ma = L * da, mb = L * db;
    const double margin = 0.05 * (fabs(ma) + fabs(mb) + fabs(zb - za)), swing = 4.0 / 27.0 * (fabs(ma) + fabs(mb));
    *lo = rw_min2(za, zb) - swing - margin;
    *hi = rw_max2(za, zb) + swing + margin;
}

/* min and max over [0, 1] of the cubic Hermite interpolant of (z, dz) on [0, L], ends included */
static inline void hermite_range(double za, double da, double zb, double db, double L, double *lo, double *hi)
{
    const double ma = L * da, mb = L * db;
    const double margin = 0.05 * (fabs(ma) + fabs(mb) + fabs(zb - za));
    double z[2];
    const int n = hermite_interior_extrema(za, ma, zb, mb, z);
    int i;
    *lo = rw_min2(za, zb);
    *hi = rw_max2(za, zb);
    for (i = 0; i < n; i++) {
        *lo = rw_min2(*lo, z[i]);
        *hi = rw_max2(*hi, z[i]);
    }
    *lo -= margin;
    *hi += margin;
}

/* The indicators that the quick test does not clear over [a, b] (a bit each): those whose state at
 * b differs from the tracked one, or that are not farther from zero at both ends than the margin
 * of far_from_zero plus band[k] (band NULL: none; a fast mode's band, rw_engine_band.c). No
 * branch: most substeps end with none. */
static inline unsigned clearance_suspects(const rw_engine *e, const double za[RW_NZ], const double dza[RW_NZ],
                                          const double zb[RW_NZ], const double dzb[RW_NZ], const double *band,
                                          double L)
{
    double clear[RW_NZ];
    unsigned suspects = 0;
    int k;
    /* far_from_zero with both ends on the tracked side (z times its sign positive), as one pass of
     * array arithmetic that the compiler vectorizes: clear >= 0 when quiet */
    for (k = 0; k < RW_NZ; k++) {
        const double ta = za[k] * e->b_sign[k], tb = zb[k] * e->b_sign[k];
        const double nearest = ta < tb ? ta : tb;
        const double need = (4.0 / 27.0 + 0.05) * fabs(L) * (fabs(dza[k]) + fabs(dzb[k])) + 0.05 * fabs(zb[k] - za[k]);
        clear[k] = nearest - rw_max2(band ? need + band[k] : need, DBL_MIN); /* >= 0: nearest >= need and > 0 */
    }
    for (k = 0; k < RW_NZ; k++) suspects |= (unsigned)(clear[k] < 0.0) << k;
    return suspects;
}

static inline unsigned suspects_of(const rw_engine *e, const double za[RW_NZ], const double dza[RW_NZ],
                                   const double zb[RW_NZ], const double dzb[RW_NZ], double L)
{
    return clearance_suspects(e, za, dza, zb, dzb, NULL, L);
}

/* Indicator i into order[0..n), kept sorted by guess (a NaN guess sorts anywhere: the order only
 * saves work). Returns the new length, n + 1. */
static inline int insert_by_guess(int order[RW_NZ], int n, const double guess[RW_NZ], int i)
{
    int j;
    for (j = n; j > 0 && !(guess[order[j - 1]] <= guess[i]); j--) order[j] = order[j - 1];
    order[j] = i;
    return n + 1;
}

#endif
