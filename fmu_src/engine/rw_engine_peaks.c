/* The peaks of |s1| and |s2| along a span, and the optional output grid.
 * Turning points are located exactly, under a fast mode's band too. */
#include "rw_engine_hermite.h"
#include "rw_engine_span.h"

#include <float.h>
#include <math.h>
#include <string.h>

/* s1 or s2 (rw_s1, rw_s2: linear in the rotations; their coefficients are taken from them in
 * rw_engine_init, so that a peak costs no call) */
static double s_of(const rw_engine *e, int which, const double x[RW_NX])
{
    return e->s_coef[which][0] * x[0] + e->s_coef[which][1] * x[1];
}

static double rate_of_s(const rw_span_ctx *sc, int which, double s)
{
    double x[RW_NX], v[RW_NX] = {0, 0, 0, 0};
    span_eval(&sc->sp, s, NULL, x, NULL);
    v[0] = x[2];
    v[1] = x[3];
    return s_of(sc->e, which, v);
}

void rwe_track_peak(rw_engine *e, int which, double value)
{
    double *peak = which == 0 ? &e->peak_s1 : &e->peak_s2;
    if (fabs(value) > *peak) *peak = fabs(value);
}

/* peaks over [a, b] of the span: the ends and an interior turning point of s1, s2 */
void rwe_peaks_on(const rw_span_ctx *sc, const double xa[RW_NX], double sa, const double xb[RW_NX], double sb)
{
    rw_engine *e = sc->e;
    int w;
    for (w = 0; w < 2; w++) {
        const double c0 = e->s_coef[w][0], c1 = e->s_coef[w][1];
        const double ra = c0 * xa[2] + c1 * xa[3], rb = c0 * xb[2] + c1 * xb[3];
        const double vb = c0 * xb[0] + c1 * xb[1];
        double *peak = w == 0 ? &e->peak_s1 : &e->peak_s2;
        double lo, hi;
        if (fabs(vb) > *peak) *peak = fabs(vb);
        if ((ra > 0.0) == (rb > 0.0) || !(sb > sa)) continue;
        /* the turning point matters only if it can pass the peak so far */
        hermite_range_bound(c0 * xa[0] + c1 * xa[1], ra, vb, rb, sb - sa, &lo, &hi);
        if (rw_max2(-lo, hi) >= *peak) {
            /* a turning point: its value is quadratic in the location error, 1e-9 of the substep is enough */
            const rw_bracket br = {sa, ra, sb, rb};
            const double s = rwe_find_switch(rate_of_s, sc, w, &br, 1e-9, NAN);
            double x[RW_NX];
            span_eval(&sc->sp, s, NULL, x, NULL);
            rwe_track_peak(e, w, s_of(e, w, x));
        }
    }
}

void rwe_record_output(rw_engine *e, const double x[RW_NX])
{
    size_t i = e->i_out;
    if (e->x_out) memcpy(e->x_out + RW_NX * i, x, sizeof(double) * RW_NX);
    if (e->s1_out) e->s1_out[i] = rw_s1(&e->P, x);
    if (e->s2_out) e->s2_out[i] = rw_s2(&e->P, x);
    e->i_out++;
}

/* grid times in (t0 + sa, t0 + sb] */
void rwe_outputs_on(const rw_span_ctx *sc, double sb)
{
    rw_engine *e = sc->e;
    const rw_span *sp = &sc->sp;
    while (e->i_out < e->n_out && e->t_out[e->i_out] <= sp->t0 + sb) {
        double x[RW_NX];
        span_eval(sp, e->t_out[e->i_out] - sp->t0, NULL, x, NULL);
        rwe_record_output(e, x);
    }
}

/* Can |s| (which: 0 for s1, 1 for s2) of the full motion pass its peak so far over [0, L], given the
 * slow part's states xa, xb at the ends? The slow part's range is its cubic Hermite interpolant's,
 * and the band adds its exact reach |s(dq_fast)| (s is linear in q). 1 with the reach and the slow
 * part's largest |s| (*reach, *slow_max), or 0. */
int rwe_peak_possible(const rw_span_ctx *sc, int which, const double xa[RW_NX], const double xb[RW_NX], double L,
                      double *reach, double *slow_max)
{
    const rw_engine *e = sc->e;
    const double amp[RW_NX] = {sc->r.dq_fast[0], sc->r.dq_fast[1], 0, 0};
    const double va[RW_NX] = {xa[2], xa[3], 0, 0}, vb[RW_NX] = {xb[2], xb[3], 0, 0};
    const double peak = which == 0 ? e->peak_s1 : e->peak_s2;
    const double sa = s_of(e, which, xa), ra = s_of(e, which, va), sb = s_of(e, which, xb), rb = s_of(e, which, vb);
    double lo, hi;
    *reach = fabs(s_of(e, which, amp));
    hermite_range_bound(sa, ra, sb, rb, L, &lo, &hi);
    if (rw_max2(-lo, hi) + *reach < peak) return 0;
    hermite_range(sa, ra, sb, rb, L, &lo, &hi);
    *slow_max = rw_max2(-lo, hi);
    return *slow_max + *reach >= peak;
}

/* |s1|, |s2| at the state x as a share of their peaks so far, the larger */
static double peak_share(const rw_engine *e, const double x[RW_NX])
{
    return rw_max2(fabs(s_of(e, 0, x)) / rw_max2(e->peak_s1, DBL_MIN),
                   fabs(s_of(e, 1, x)) / rw_max2(e->peak_s2, DBL_MIN));
}

/* The peaks over [u, v] of the span's full motion where the band matters for them
 * (RW_PEAKS_SUSPECT, rw_engine_band.c) and no indicator changes sign: where the slow part plus the
 * band can pass a peak so far (rwe_peak_possible), [u, v] is halved until a half turns the fast
 * mode by at most 8 rad, and such a piece takes rwe_peaks_on on the full motion at the fast rate.
 * Only the neighbourhood of a new peak is resolved, and without the indicators. xu, xv: the slow
 * part's states at u and v. */
void rwe_peaks_under_band(const rw_span_ctx *sc, double u, const double xu[RW_NX], double v, const double xv[RW_NX],
                          int depth)
{
    const rw_span *sp = &sc->sp;
    double reach, slow_max, len = v - u, xa[RW_NX], xb[RW_NX];
    int n, j;
    if (!rwe_peak_possible(sc, 0, xu, xv, len, &reach, &slow_max) &&
        !rwe_peak_possible(sc, 1, xu, xv, len, &reach, &slow_max))
        return;
    n = rwe_substeps_for(sc->r.fast_rate, &len);
    if (n > 8 && depth < 40) {
        const double mid = u + 0.5 * (v - u);
        double xm[RW_NX];
        span_eval_part(sp, mid, NULL, sc->r.fast, xm, NULL);
        /* the half that reaches higher first: the peak it sets mostly rules the other half out (a
         * growing motion is then searched in log2 of its fast periods, not in all of them) */
        if (peak_share(sc->e, xv) > peak_share(sc->e, xu)) {
            rwe_peaks_under_band(sc, mid, xm, v, xv, depth + 1);
            rwe_peaks_under_band(sc, u, xu, mid, xm, depth + 1);
        } else {
            rwe_peaks_under_band(sc, u, xu, mid, xm, depth + 1);
            rwe_peaks_under_band(sc, mid, xm, v, xv, depth + 1);
        }
        return;
    }
    span_eval(sp, u, NULL, xa, NULL);
    for (j = 1; j <= n; j++) {
        const double sa = u + (v - u) * (j - 1) / n, sb = j == n ? v : u + (v - u) * j / n;
        span_eval(sp, sb, NULL, xb, NULL);
        rwe_peaks_on(sc, xa, sa, xb, sb);
        memcpy(xa, xb, sizeof xa);
    }
}
