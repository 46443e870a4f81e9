/* Polynomials on [0, 1] for the exact scene engine: evaluation, the first sign change (an event
 * indicator's root) and the largest magnitude (a peak), both by subdivision with range bounds of
 * the polynomial re-expanded on each piece, so that no root or peak between samples is missed. */
#include "rw_scene_exact_internal.h"

#include <float.h>
#include <math.h>
#include <string.h>

#define SX_MIN_WIDTH 1e-15 /* the narrowest piece the subdivision examines (in u) */

double sx_poly_eval(const double *p, int deg, double u)
{
    double v = p[deg];
    int k;
    for (k = deg - 1; k >= 0; k--) v = v * u + p[k];
    return v;
}

double sx_poly_deriv(const double *p, int deg, double u)
{
    double v = deg * p[deg];
    int k;
    for (k = deg - 1; k >= 1; k--) v = v * u + k * p[k];
    return deg >= 1 ? v : 0.0;
}

/* q(v) = p(a + v w), v in [0, 1] */
static void restrict_to(const double *p, int deg, double a, double w, double *q)
{
    double s = 1.0;
    int i, k;
    memcpy(q, p, sizeof(double) * (size_t)(deg + 1));
    if (a != 0.0)
        for (i = 0; i < deg; i++)
            for (k = deg - 1; k >= i; k--) q[k] += a * q[k + 1];
    if (w != 1.0)
        for (k = 1; k <= deg; k++) {
            s *= w;
            q[k] *= s;
        }
}

/* bounds of q over [0, 1] and of q' over [0, 1] */
static void ranges(const double *q, int deg, double *lo, double *hi, double *dlo, double *dhi)
{
    int k;
    *lo = *hi = q[0];
    *dlo = *dhi = deg >= 1 ? q[1] : 0.0;
    for (k = 1; k <= deg; k++) {
        if (q[k] < 0.0) *lo += q[k];
        else *hi += q[k];
        if (k >= 2) {
            if (q[k] < 0.0) *dlo += k * q[k];
            else *dhi += k * q[k];
        }
    }
}

/* the crossing inside [lo, hi] with p(lo) > 0 >= p(hi): safeguarded Newton, returning the end
 * past the crossing (p <= 0 there), as a root finder that reports a sign change does */
static double refine(const double *p, int deg, double lo, double hi)
{
    int it;
    for (it = 0; it < 200 && hi - lo > 2.0 * DBL_EPSILON * hi; it++) {
        const double plo = sx_poly_eval(p, deg, lo), phi = sx_poly_eval(p, deg, hi);
        double u = hi - phi * (hi - lo) / (phi - plo), pu, du;
        if (!(u > lo && u < hi)) u = 0.5 * (lo + hi);
        pu = sx_poly_eval(p, deg, u);
        du = sx_poly_deriv(p, deg, u);
        if (pu > 0.0) lo = u;
        else hi = u;
        if (du != 0.0) { /* a Newton step aimed just past the root keeps the bracket tight from both sides */
            const double step = pu / du, v = u - step - copysign(0.25 * DBL_EPSILON * fabs(u), step);
            if (v > lo && v < hi) {
                if (sx_poly_eval(p, deg, v) > 0.0) lo = v;
                else hi = v;
            }
        }
        if (it > 60) { /* slow convergence: bisect */
            const double m = 0.5 * (lo + hi);
            if (sx_poly_eval(p, deg, m) > 0.0) lo = m;
            else hi = m;
        }
    }
    return hi;
}

static double first_root(const double *p, int deg, double err, double a, double b)
{
    double q[SX_MAX_DEG * 2 + 2], lo, hi, dlo, dhi;
    const double pa = sx_poly_eval(p, deg, a);
    if (pa <= 0.0) return a;
    restrict_to(p, deg, a, b - a, q);
    ranges(q, deg, &lo, &hi, &dlo, &dhi);
    (void)err; /* the polynomial's own sign changes: the function's are within err of them */
    if (lo > 0.0) return 2.0;
    if (dlo > 0.0 || dhi < 0.0) { /* monotone: one crossing at most */
        if (sx_poly_eval(p, deg, b) > 0.0) return 2.0;
        return refine(p, deg, a, b);
    }
    if (b - a < SX_MIN_WIDTH) return sx_poly_eval(p, deg, b) <= 0.0 ? b : 2.0;
    {
        const double m = 0.5 * (a + b), r = first_root(p, deg, err, a, m);
        return r <= 1.0 ? r : first_root(p, deg, err, m, b);
    }
}

double sx_poly_abs_sum(const double *p, int deg)
{
    double s = 0.0;
    int k;
    for (k = 0; k <= deg; k++) s += fabs(p[k]);
    return s;
}

double sx_poly_first_root(const double *p, int deg, double err)
{
    if (p[0] > sx_poly_abs_sum(p + 1, deg - 1)) return 2.0; /* clear of zero over [0, 1]: most lines, most pieces */
    return first_root(p, deg, err, 0.0, 1.0);
}

/* the extremum of p inside [a, b] where p' changes sign once (p'' of one sign) */
static double extremum(const double *p, int deg, double a, double b)
{
    double dp[SX_MAX_DEG * 2 + 2], lo = a, hi = b;
    int k, it;
    for (k = 1; k <= deg; k++) dp[k - 1] = k * p[k];
    if (sx_poly_eval(dp, deg - 1, a) * sx_poly_eval(dp, deg - 1, b) > 0.0) return a;
    for (it = 0; it < 200 && hi - lo > 2.0 * DBL_EPSILON * hi; it++) {
        const double m = 0.5 * (lo + hi);
        if ((sx_poly_eval(dp, deg - 1, m) > 0.0) == (sx_poly_eval(dp, deg - 1, lo) > 0.0)) lo = m;
        else hi = m;
    }
    return 0.5 * (lo + hi);
}

static double max_abs(const double *p, int deg, double err, double a, double b, double best)
{
    double q[SX_MAX_DEG * 2 + 2], lo, hi, dlo, dhi;
    restrict_to(p, deg, a, b - a, q);
    ranges(q, deg, &lo, &hi, &dlo, &dhi);
    if (fmax(fabs(lo), fabs(hi)) + err <= best) return best;
    best = fmax(best, fmax(fabs(q[0]), fabs(sx_poly_eval(q, deg, 1.0))));
    if (dlo > 0.0 || dhi < 0.0) return best; /* monotone: the ends hold the extremes */
    if (deg >= 2) {
        double ddlo = 0.0, ddhi = 0.0;
        int k;
        for (k = 2; k <= deg; k++) { /* q'' over [0, 1] */
            const double c = k * (k - 1) * q[k];
            if (k == 2) ddlo = ddhi = c;
            else if (c < 0.0) ddlo += c;
            else ddhi += c;
        }
        if (ddlo > 0.0 || ddhi < 0.0) /* q' monotone: one extremum */
            return fmax(best, fabs(sx_poly_eval(p, deg, extremum(p, deg, a, b))));
    }
    if (b - a < SX_MIN_WIDTH) return fmax(best, fabs(sx_poly_eval(p, deg, 0.5 * (a + b))));
    best = max_abs(p, deg, err, a, 0.5 * (a + b), best);
    return max_abs(p, deg, err, 0.5 * (a + b), b, best);
}

double sx_poly_max_abs(const double *p, int deg, double err, double b, double best)
{
    if (!(b > 0.0)) return fmax(best, fabs(p[0]));
    if (b <= 1.0 && err + sx_poly_abs_sum(p, deg) <= best) return best; /* under the peak over [0, 1]: most pieces */
    return max_abs(p, deg, err, 0.0, b, best);
}

double sx_poly_integral(const double *p, int deg, double b)
{
    double v = 0.0;
    int k;
    for (k = deg; k >= 0; k--) v = v * b + p[k] / (k + 1);
    return v * b;
}

void sx_poly_product(const double *p, const double *q, int deg, double *pq)
{
    int j, k;
    for (k = 0; k <= 2 * deg; k++) pq[k] = 0.0;
    for (j = 0; j <= deg; j++)
        for (k = 0; k <= deg; k++) pq[j + k] += p[j] * q[k];
}

void sx_poly_square(const double *p, int deg, double *sq)
{
    int j, k;
    for (k = 0; k <= 2 * deg; k++) sq[k] = 0.0;
    for (j = 0; j <= deg; j++) { /* each cross product once, doubled: half the products' multiplications */
        sq[2 * j] += p[j] * p[j];
        for (k = j + 1; k <= deg; k++) sq[j + k] += 2.0 * p[j] * p[k];
    }
}

double sx_lopoly_at(const sx_lopoly *p, double u)
{
    const double v = 1.0 - u;
    if (!p->bern) return sx_poly_eval(p->coef, p->deg, u);
    return v * v * v * p->coef[0] + 3.0 * u * v * (v * p->coef[1] + u * p->coef[2]) + u * u * u * p->coef[3];
}

double sx_poly_square_integral(const double *p, int deg, double u)
{
    double sq[SX_MAX_DEG * 2 + 2];
    sx_poly_square(p, deg, sq);
    return sx_poly_integral(sq, 2 * deg, u);
}
