/* RockingWall exact event-driven engine: see rw_engine.h.
 *
 * Layout: Stumpff functions (the exact scalar solution) -> spans (a region of
 * rw_engine_regions.c with a linear input from a start state) -> event search on a span (a quiet
 * test, Hermite extremum checks, Newton root refinement) -> the stepper over one input segment.
 * The batch runs over a record are in rw_engine_batch.c.
 */
#include "rw_engine_internal.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define RW_MAX_EVENT_ROUNDS 100 /* event-iteration rounds at one event, as cs_cvode.c allows 1000 */
#define RW_PHASE_PER_SUBSTEP 1.0 /* rad of the fastest significant mode per bracketing substep */
#define RW_MAX_SUBSTEPS 2000000L
#define RW_SELECT_DT 1e-9 /* s: look-ahead of the direction that picks the region on a breakpoint */
#define RW_AFFINE_Q_CLEARANCE 1e-6 /* scale-free collapse indicator: below this, the law itself decides */

/* ---- Stumpff functions ----------------------------------------------------------------------
 * c_k(z) = sum_j (-z)^j/(2j+k)!: c0 = cos(sqrt z), c1 = sin(sqrt z)/sqrt z, c2 = (1-c0)/z,
 * c3 = (1-c1)/z (cosh/sinh for z < 0, polynomial at z = 0). With z = lam s^2 the solution of
 * eta'' + lam eta = f0 + f1 s is eta0 c0 + v0 s c1 + f0 s^2 c2 + f1 s^3 c3 for every sign of lam,
 * with no cancellation near lam = 0 (series there). */
/* 1/n! for the series of the Stumpff functions */
static const double INV_FACT[24] = {
    1.0, 1.0, 1.0 / 2, 1.0 / 6, 1.0 / 24, 1.0 / 120, 1.0 / 720, 1.0 / 5040, 1.0 / 40320, 1.0 / 362880,
    1.0 / 3628800, 1.0 / 39916800, 1.0 / 479001600, 1.0 / 6227020800.0, 1.0 / 87178291200.0,
    1.0 / 1307674368000.0, 1.0 / 20922789888000.0, 1.0 / 355687428096000.0, 1.0 / 6402373705728000.0,
    1.0 / 121645100408832000.0, 1.0 / 2432902008176640000.0, 1.0 / 51090942171709440000.0,
    1.0 / 1124000727777607680000.0, 1.0 / 25852016738884976640000.0};

static void stumpff(double z, double c[4])
{
    if (z == 0.0) {
        c[0] = c[1] = 1.0;
        c[2] = 0.5;
        c[3] = 1.0 / 6.0;
        return;
    }
    if (fabs(z) < 1.0) {
        /* c_k = sum_j (-z)^j/(2j+k)! over j = 0..9 leaves < 1/(2*10+k)! < 4e-19; only c2 and c3 are
         * summed, c0 = 1 - z c2 and c1 = 1 - z c3 lose nothing for |z| < 1 (c0, c1 > 0.5). Each sum
         * is split into its even and odd terms, E(y) - z O(y) with y = z^2, so that four short
         * Horner chains run side by side instead of two long ones (the sum is latency-bound). */
        const double y = z * z;
        double e2 = INV_FACT[4 * 4 + 2], o2 = INV_FACT[4 * 4 + 4], e3 = INV_FACT[4 * 4 + 3], o3 = INV_FACT[4 * 4 + 5];
        int i;
        for (i = 3; i >= 0; i--) { /* the terms j = 2i (even: 1/(4i+k)!) and j = 2i + 1 (odd: 1/(4i+2+k)!) */
            e2 = INV_FACT[4 * i + 2] + y * e2;
            o2 = INV_FACT[4 * i + 4] + y * o2;
            e3 = INV_FACT[4 * i + 3] + y * e3;
            o3 = INV_FACT[4 * i + 5] + y * o3;
        }
        c[2] = e2 - z * o2;
        c[3] = e3 - z * o3;
        c[0] = 1.0 - z * c[2];
        c[1] = 1.0 - z * c[3];
        return;
    }
    if (z > 0.0) {
        const double r = sqrt(z);
        c[0] = cos(r);
        c[1] = sin(r) / r;
    } else {
        const double r = sqrt(-z);
        c[0] = cosh(r);
        c[1] = sinh(r) / r;
    }
    c[2] = (1.0 - c[0]) / z;
    c[3] = (1.0 - c[1]) / z;
}

/* ---- spans: a region with a linear input, from a start state ------------------------------- */
typedef struct {
    const rw_cache_entry *R;
    double t0;
    double eta[2], v[2]; /* modal state at t0 */
    double f0[2], f1[2]; /* modal forcing at t0 and its rate */
    double ag0, ag1, u0, u1; /* the input at t0 and its rate */
    double x0[RW_NX];        /* the start state itself: the motion is x0 + P (eta(s) - eta(0)) */
    rw_affine_Q aq;          /* the region's hinge moments, if affine in q */
} rw_span;

static void span_start(rw_span *sp, const rw_cache_entry *R, const double g0[2], double t0, const double x[RW_NX],
                       const rw_linear_input *in, double t_in)
{
    const rw_modes2 *E = &R->E;
    int i;
    /* sp->aq is the region's: set by the caller once per region */
    sp->R = R;
    sp->t0 = t0;
    sp->ag0 = in->ag + in->ag_slope * (t0 - t_in);
    sp->u0 = in->u_top + in->u_slope * (t0 - t_in);
    sp->ag1 = in->ag_slope;
    sp->u1 = in->u_slope;
    memcpy(sp->x0, x, sizeof sp->x0);
    for (i = 0; i < 2; i++) {
        sp->eta[i] = E->Pi[i][0] * x[0] + E->Pi[i][1] * x[1];
        sp->v[i] = E->Pi[i][0] * x[2] + E->Pi[i][1] * x[3];
        sp->f0[i] = g0[i] + E->ga[i] * sp->ag0 + E->gu[i] * sp->u0;
        sp->f1[i] = E->ga[i] * sp->ag1 + E->gu[i] * sp->u1;
    }
}

/* Modal motion at s with the Stumpff coefficients C of each mode at lam s^2 (NULL: computed), as
 * changes from the start, deta = eta(s) - eta(0), dv = v(s) - v(0) (with c0 = 1 - z c2, free of
 * cancellation), and the modal accelerations a. Written as changes, the state at s = 0 is the start
 * state itself, not its image through P Pi: an indicator that set an event's state keeps its sign
 * where the next span begins. fast[i] (fast may be NULL) leaves out the free oscillation of mode i:
 * its exact particular solution (f0 + f1 s)/lam alone, the slow part of a stiff mode. */
static inline void mode_motion(const rw_span *sp, int i, double s, const double C[2][4], int slow_part, double *deta,
                               double *dv, double *a)
{
    double c[4];
    const double lam = sp->R->E.lam[i], eta0 = sp->eta[i], v0 = sp->v[i];
    const double f0 = sp->f0[i], f1 = sp->f1[i];
    if (slow_part) {
        *deta = (f0 + f1 * s) / lam - eta0;
        *dv = f1 / lam - v0;
        *a = 0.0;
        return;
    }
    if (C) memcpy(c, C[i], sizeof c);
    else stumpff(lam * s * s, c);
    *deta = s * (v0 * c[1] + s * ((f0 - lam * eta0) * c[2] + s * f1 * c[3]));
    *dv = s * ((f0 - lam * eta0) * c[1] + s * (f1 - lam * v0) * c[2]);
    *a = -lam * (eta0 + *deta) + f0 + f1 * s;
}

static inline void span_modal(const rw_span *sp, double s, const double C[2][4], const int *fast, double deta[2],
                              double dv[2], double a[2])
{
    int i;
    for (i = 0; i < 2; i++) mode_motion(sp, i, s, C, fast && fast[i], &deta[i], &dv[i], &a[i]);
}

static void to_physical(const rw_span *sp, const double deta[2], const double dv[2], double x[RW_NX])
{
    const rw_modes2 *E = &sp->R->E;
    x[0] = sp->x0[0] + (E->P[0][0] * deta[0] + E->P[0][1] * deta[1]);
    x[1] = sp->x0[1] + (E->P[1][0] * deta[0] + E->P[1][1] * deta[1]);
    x[2] = sp->x0[2] + (E->P[0][0] * dv[0] + E->P[0][1] * dv[1]);
    x[3] = sp->x0[3] + (E->P[1][0] * dv[0] + E->P[1][1] * dv[1]);
}

/* the state x and, if xd is not NULL, its time derivative from the modal motion */
static inline void modal_to_state(const rw_span *sp, const double deta[2], const double dv[2], const double a[2],
                                  double x[RW_NX], double *xd)
{
    to_physical(sp, deta, dv, x);
    if (xd) {
        xd[0] = x[2];
        xd[1] = x[3];
        xd[2] = sp->R->E.P[0][0] * a[0] + sp->R->E.P[0][1] * a[1];
        xd[3] = sp->R->E.P[1][0] * a[0] + sp->R->E.P[1][1] * a[1];
    }
}

/* State x and its time derivative xd at t0 + s (span_eval_part: without the fast modes' free
 * oscillation). */
static void span_eval_part(const rw_span *sp, double s, const double C[2][4], const int *fast, double x[RW_NX],
                           double xd[RW_NX])
{
    double deta[2], dv[2], a[2];
    span_modal(sp, s, C, fast, deta, dv, a);
    modal_to_state(sp, deta, dv, a, x, xd);
}

static void span_eval(const rw_span *sp, double s, const double C[2][4], double x[RW_NX], double xd[RW_NX])
{
    span_eval_part(sp, s, C, NULL, x, xd);
}

/* span_eval_part with the fast modes left out (x_slow, xd_slow) and the full state x_full at once:
 * the other modes' terms are the same in both */
static void span_eval_slow_and_full(const rw_span *sp, double s, const double C[2][4], const int fast[2],
                                    double x_slow[RW_NX], double xd_slow[RW_NX], double x_full[RW_NX])
{
    double deta[2], dv[2], a[2];
    int i;
    span_modal(sp, s, C, fast, deta, dv, a);
    modal_to_state(sp, deta, dv, a, x_slow, xd_slow);
    for (i = 0; i < 2; i++)
        if (fast[i]) mode_motion(sp, i, s, C, 0, &deta[i], &dv[i], &a[i]);
    to_physical(sp, deta, dv, x_full);
}

static rw_input span_input(const rw_span *sp, double s)
{
    rw_input in;
    in.ag = sp->ag0 + sp->ag1 * s;
    in.u_top = sp->u0 + sp->u1 * s;
    return in;
}

/* The modes of a span, for bracketing: unstable modes always count; an oscillating mode counts
 * when its free oscillation about the quasi-static solution is larger than 1e-12 of the toppling
 * rotation (a stiff spring's mode driven quasi-statically is not), and it is `fast` when it turns
 * more than 4 times faster than every other counted rate (including the wall's rocking rate, see
 * substeps_for): its free oscillation is then a band around the slow motion (rw_engine.c "fast
 * modes") instead of setting the substeps. At most one mode is fast (each would have to turn 4
 * times faster than the other), so the band is dq_fast times a factor in [-1, 1]: the mode's
 * shape times its amplitude, with signs. */
typedef struct {
    int fast[2], any_fast;
    double slow_rate, fast_rate;
    double dq_fast[2]; /* the fast mode's free oscillation at its extreme, in (q1, q2) */
} rw_rates;

/* the squared amplitude of mode i's free oscillation about its quasi-static solution */
static double mode_amplitude2(const rw_span *sp, int i)
{
    const double il = sp->R->inv_lam[i];
    const double a = sp->eta[i] - sp->f0[i] * il, b = sp->v[i] - sp->f1[i] * il;
    return a * a + b * b * il;
}

static void span_rates(const rw_engine *e, const rw_span *sp, double floor_rate, rw_rates *r)
{
    const rw_cache_entry *R = sp->R;
    const double small = 1e-12 * e->D.q_topple;
    double w[2] = {0.0, 0.0}, amp2[2];
    int i;
    memset(r, 0, sizeof *r);
    for (i = 0; i < 2; i++) {
        amp2[i] = mode_amplitude2(sp, i);
        if (R->E.lam[i] <= 0.0 || amp2[i] * R->col[i] * R->col[i] > small * small) w[i] = R->w[i];
    }
    r->slow_rate = floor_rate;
    for (i = 0; i < 2; i++) {
        const double other = rw_max2(floor_rate, w[1 - i]);
        if (R->E.lam[i] > 0.0 && w[i] > 4.0 * other) {
            const double amp = sqrt(amp2[i]); /* rotations of a standing wall: no overflow */
            r->fast[i] = r->any_fast = 1;
            r->fast_rate = rw_max2(r->fast_rate, w[i]);
            r->dq_fast[0] = amp * R->E.P[0][i];
            r->dq_fast[1] = amp * R->E.P[1][i];
        } else {
            r->slow_rate = rw_max2(r->slow_rate, w[i]);
        }
    }
}

/* ---- indicators along a span ---------------------------------------------------------------- */
typedef rw_engine_point rw_point; /* rw_engine.h */

/* The indicators of the closed rigid hinges among `mask` at the state x (rates along xd, if not
 * NULL, with the input at the rate in_rate) from the region's affine form of their moments
 * (rw_closed_force_form): 1 - |f|/cap + eps_f, as rw_event_indicators computes it. Returns those
 * within RW_AFFINE_Q_CLEARANCE of zero, which the physics itself takes (the signs decided near a
 * root must come from one function, as for the collapse form). */
static unsigned closed_hinge_values(const rw_engine *e, const rw_input *in, const rw_input *in_rate,
                                    const double x[RW_NX], const double *xd, unsigned mask, double *z, double *dz)
{
    const rw_closed_form *F = &e->closed_form;
    unsigned near_zero = 0;
    int j;
    for (j = 0; j < 2; j++) {
        const int k = j == 0 ? RW_Z_BASE : RW_Z_MID;
        double f;
        if (!((mask >> k) & 1u)) continue;
        f = F->c[j] + F->G[j][0] * x[0] + F->G[j][1] * x[1] + F->g_ag[j] * in->ag + F->g_u[j] * in->u_top;
        z[k] = 1.0 - fabs(f) * F->inv_cap[j] + RW_EPS_F;
        if (fabs(z[k]) < RW_AFFINE_Q_CLEARANCE) near_zero |= 1u << k;
        else if (xd) {
            const double df =
                F->G[j][0] * xd[0] + F->G[j][1] * xd[1] + F->g_ag[j] * in_rate->ag + F->g_u[j] * in_rate->u_top;
            dz[k] = -((f > 0.0) - (f < 0.0)) * df * F->inv_cap[j];
        }
    }
    return near_zero;
}

/* Does the region's collapse form hold at x? Always for a law of q alone (the other laws with a
 * form, rw_engine_regions.c); for the rigid law while each open hinge's rotation is on its side (or
 * zero), as the law's collapse test takes the sides from the rotations: in the moment before an
 * impact or a switch, where a rotation has just passed zero, the law's G keeps |rotation| terms
 * that the region's constant moments turn negative. */
static int collapse_form_holds(const rw_engine *e, const rw_regime *m, const double x[RW_NX])
{
    return !e->rigid || (m->side_b * x[0] >= 0.0 && m->side_m * (x[1] - x[0]) >= 0.0);
}

/* The model's indicators of `mask` at the state x of the span's motion and, if xd is not NULL,
 * their rates dz along it (x moving at xd, the input at the span's rate). The indicators that are
 * lines of the rotations (rw_indicator_lines, taken once per region) are evaluated here; the
 * others (collapse, toppling, closed hinges) by the shared physics, with the region's affine
 * hinge moments where the law has them (rw_hinge_law.q_only). */
static void region_indicators(const rw_engine *e, const rw_regime *m, const rw_span *sp, const rw_input *in,
                              const double x[RW_NX], const double xd[RW_NX], unsigned mask, double *restrict z,
                              double *restrict dz)
{
    const unsigned collapse = 1u << RW_Z_COLLAPSE, topple = 1u << RW_Z_TOPPLE;
    unsigned rest = mask & ~e->line_mask;
    int k;
    if (xd && mask == RW_Z_ALL) { /* every line, without a test per line (the others are overwritten below) */
        const rw_line_arrays *A = &e->line_arrays;
        for (k = 0; k < RW_NZ; k++) { /* rw_line_value's arithmetic on arrays, which the compiler vectorizes */
            const double w = A->a0[k] * x[0] + A->a1[k] * x[1], wd = A->a0[k] * xd[0] + A->a1[k] * xd[1];
            const double sign = (double)(w > 0.0) - (double)(w < 0.0);
            dz[k] = (A->s[k] * sign + A->t[k]) * wd;
            z[k] = A->c[k] + A->s[k] * fabs(w) + A->t[k] * w;
        }
    } else {
        for (k = 0; k < RW_NZ; k++)
            if ((mask & e->line_mask) >> k & 1u) z[k] = rw_line_value(&e->lines[k], x, xd, xd ? &dz[k] : NULL);
    }
    if ((rest & topple) && e->P.support == RW_FLEXIBLE_TOP) {
        z[RW_Z_TOPPLE] = rw_topple_value(&e->D, x, xd, xd ? &dz[RW_Z_TOPPLE] : NULL);
        rest &= ~topple;
    }
    if (rest & e->closed_mask) {
        const rw_input rate = {sp->ag1, sp->u1};
        rest = (rest & ~e->closed_mask) | closed_hinge_values(e, in, &rate, x, xd, rest & e->closed_mask, z, dz);
    }
    if ((rest & collapse) && sp->aq.valid && collapse_form_holds(e, m, x)) {
        if (e->collapse_radius == 0.0) {
            /* a region that cannot collapse (collapse_form_of_region): its indicator, positive
             * everywhere in it, as its clipped value, at no cost */
            z[RW_Z_COLLAPSE] = RW_COLLAPSE_ZMAX;
            if (xd) dz[RW_Z_COLLAPSE] = 0.0;
        } else {
            z[RW_Z_COLLAPSE] = rw_collapse_form_value(&e->collapse_form, x, xd, xd ? &dz[RW_Z_COLLAPSE] : NULL);
            /* Near its root the collapse indicator is taken from the law itself: the region's form
             * differs from it by rounding, and every sign decided near zero (the root, the tracked
             * state set after an event, the collapse test) must come from one function, or an event
             * repeats at one instant. Away from zero both have the same sign. */
            if (fabs(z[RW_Z_COLLAPSE]) < RW_AFFINE_Q_CLEARANCE)
                rw_event_indicators_some(&e->P, &e->D, m, in, x, NULL, collapse, z);
        }
        rest &= ~collapse;
    }
    if (!rest) return;
    if (xd) {
        const rw_input rate = {sp->ag1, sp->u1};
        rw_event_indicator_rates(&e->P, &e->D, m, in, &rate, x, xd, NULL, NULL, rest, z, dz);
    } else {
        rw_event_indicators_some(&e->P, &e->D, m, in, x, NULL, rest, z);
    }
}

static inline void eval_point(const rw_engine *e, const rw_regime *m, const rw_span *sp, double s,
                              const double C[2][4], rw_point *pt)
{
    double xd[RW_NX];
    rw_input in = span_input(sp, s);
    pt->s = s;
    span_eval(sp, s, C, pt->x, xd);
    region_indicators(e, m, sp, &in, pt->x, xd, RW_Z_ALL, pt->z, pt->dz);
}

static double indicator_at(const rw_engine *e, const rw_regime *m, const rw_span *sp, int k, double s)
{
    double x[RW_NX], z[RW_NZ];
    rw_input in = span_input(sp, s);
    span_eval(sp, s, NULL, x, NULL);
    region_indicators(e, m, sp, &in, x, NULL, 1u << k, z, NULL);
    return z[k];
}

/* rate of indicator k at s (for the extremum of a possible double crossing) */
static double indicator_rate(const rw_engine *e, const rw_regime *m, const rw_span *sp, int k, double s)
{
    rw_point pt;
    eval_point(e, m, sp, s, NULL, &pt);
    return pt.dz[k];
}

/* Safeguarded regula falsi (Illinois; a bisection when three steps have not halved the bracket)
 * for the first s in (lo, hi] where the boolean (value > 0) differs from its value at lo, starting
 * from the guess (NaN: none). Returns hi at convergence (to a few ulps of the absolute time), the
 * first point known to be past the root. */
typedef double (*rw_scalar_fn)(const rw_engine *e, const rw_regime *m, const rw_span *sp, int k, double s);

static double find_switch(rw_scalar_fn f, const rw_engine *e, const rw_regime *m, const rw_span *sp, int k, double lo,
                          double flo, double hi, double fhi, double rel_tol, double guess)
{
    const int blo = flo > 0.0;
    const double tol_interval = rel_tol * (hi - lo);
    double width_before = hi - lo;
    int it, last = 0;
    for (it = 0; it < 400; it++) {
        const double tol = rw_max2(4.0 * DBL_EPSILON * (fabs(sp->t0) + fabs(hi)) + 1e-300, tol_interval);
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
        fs = f(e, m, sp, k, s);
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
 * region_indicators', so its sign at the root is the one every other test sees. */
static double indicator_rates_at(const rw_engine *e, const rw_regime *m, const rw_span *sp, int k, double s,
                                 double x[RW_NX], double *rate, double *curv)
{
    double xd[RW_NX], z[RW_NZ], dz[RW_NZ];
    rw_input in;
    span_eval(sp, s, NULL, x, xd);
    if ((e->line_mask >> k) & 1u) {
        const rw_indicator_line *L = &e->lines[k];
        const double w = L->a[0] * x[0] + L->a[1] * x[1];
        const double slope = L->s * ((w > 0.0) - (w < 0.0)) + L->t;
        *curv = slope * (L->a[0] * xd[2] + L->a[1] * xd[3]);
        return rw_line_value(L, x, xd, rate);
    }
    in = span_input(sp, s);
    region_indicators(e, m, sp, &in, x, xd, 1u << k, z, dz);
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

/* The first s in (lo, hi] where indicator k leaves the state `was` (the state at lo), to a few ulps
 * of the absolute time, from the guess (NaN: none): Halley or Newton steps on the exact motion,
 * kept inside the bracket (else a regula falsi step, and a bisection when three steps have not
 * halved it). Near the root the last step is taken a little past it, so that the bracket closes.
 * Returns hi, the first point known to be past the root, with the state there in x_hi if it was
 * evaluated here (*x_valid). */
static double refine_root(const rw_engine *e, const rw_regime *m, const rw_span *sp, int k, int was, double lo,
                          double flo, double hi, double fhi, double guess, double x_hi[RW_NX], int *x_valid)
{
    double width_before = hi - lo, s = guess;
    int it, past;
    *x_valid = 0;
    for (it = 0; it < 200; it++) {
        const double tol = 4.0 * DBL_EPSILON * (fabs(sp->t0) + fabs(hi)) + 1e-300;
        double fs, rate, curv, step, x[RW_NX];
        if (hi - lo <= tol) break;
        if (it % 3 == 0) { /* the safeguard: every three steps the bracket must have halved */
            if (it > 0 && hi - lo > 0.5 * width_before) s = 0.5 * (lo + hi);
            width_before = hi - lo;
        }
        if (!(s > lo && s < hi)) s = fhi != flo ? (lo * fhi - hi * flo) / (fhi - flo) : 0.5 * (lo + hi);
        if (!(s > lo && s < hi)) s = 0.5 * (lo + hi);
        if (!(s > lo && s < hi)) break; /* adjacent doubles */
        fs = indicator_rates_at(e, m, sp, k, s, x, &rate, &curv);
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

/* The common case of hermite_keeps_sign, with no square root: the interpolant is a convex
 * combination of za, zb plus at most 4/27 of |ma| + |mb|, so ends of one sign that far from zero
 * (with hermite_keeps_sign's margin, 5 % of |ma| + |mb| + |zb - za|) keep it. No branch. */
static int far_from_zero(double za, double da, double zb, double db, double L)
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
static int hermite_keeps_sign(double za, double da, double zb, double db, double L)
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
static double hermite_root(double za, double da, double zb, double db, double L)
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

#define RW_DIP_DEPTH 3 /* a suspicious substep is split 4 ways, at most this many times */

/* Does indicator k, on the same side of zero (state `was`) at both ends of [a, b], dip through
 * zero in between? Only when it moves toward zero at an end and its Hermite interpolant does not
 * clear zero; then the piece is split (a breakpoint indicator |w| - c has a kink at w = 0, so one
 * piece can hold a dip and a turn), and at the finest level the extremum is located. On a dip,
 * *lo, *hi bracket its first crossing. */
static int dip(const rw_engine *e, const rw_regime *m, const rw_span *sp, int k, int was, const rw_point *a,
               const rw_point *b, int depth, double *lo, double *flo, double *hi, double *fhi)
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
        s_ext = find_switch(indicator_rate, e, m, sp, k, a->s, a->dz[k], b->s, b->dz[k], 1e-9, NAN);
        z_ext = indicator_at(e, m, sp, k, s_ext);
        if ((z_ext > 0.0) == was) return 0;
        *lo = a->s, *flo = a->z[k], *hi = s_ext, *fhi = z_ext;
        return 1;
    }
    p[0] = *a;
    for (i = 1; i <= 4; i++) {
        rw_point *q = &p[i & 1];
        const rw_point *prev = &p[(i - 1) & 1];
        if (i == 4) *q = *b;
        else eval_point(e, m, sp, a->s + 0.25 * i * (b->s - a->s), NULL, q);
        if ((q->z[k] > 0.0) != was) {
            *lo = prev->s, *flo = prev->z[k], *hi = q->s, *fhi = q->z[k];
            return 1;
        }
        if (dip(e, m, sp, k, was, prev, q, depth + 1, lo, flo, hi, fhi)) return 1;
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

/* The indicators that the quick test does not clear over [a, b] (a bit each): those whose state at
 * b differs from the tracked one, or that are not farther from zero at both ends than the margin
 * of far_from_zero plus band[k] (band NULL: none; rw_engine.c "fast modes"). No branch: most
 * substeps end with none. */
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

static unsigned suspects_of(const rw_engine *e, const double za[RW_NZ], const double dza[RW_NZ],
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

/* Earliest s in (a->s, b->s] where an indicator of `suspects` (suspects_of) changes its state
 * e->b[k], including a dip through zero and back inside the substep. Returns 1 and *s_event, or 0. */
static int first_event(const rw_engine *e, const rw_regime *m, const rw_span *sp, const rw_point *a, const rw_point *b,
                       unsigned suspects, double *s_event, int *k_event, double x_event[RW_NX])
{
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
        double lo = a->s, flo = a->z[k], hi = b->s, fhi = b->z[k], s, x_root[RW_NX];
        int x_valid;
        if (found && x_known && !crossed_before(e, k, was, a, best, x_event)) continue;
        if (guess[k] == INFINITY && !dip(e, m, sp, k, was, a, b, 0, &lo, &flo, &hi, &fhi)) continue;
        if ((flo > 0.0) != was) flo = was ? DBL_MIN : 0.0; /* the state at lo is the tracked one */
        if (found && lo >= best) continue;
        s = refine_root(e, m, sp, k, was, lo, flo, hi, fhi, guess[k] == INFINITY ? NAN : guess[k], x_root, &x_valid);
        if (!found || s < best) {
            best = s;
            *k_event = k;
            x_known = x_valid;
            if (x_valid) memcpy(x_event, x_root, sizeof x_root);
        }
        found = 1;
    }
    *s_event = best;
    if (found && !x_known) span_eval(sp, best, NULL, x_event, NULL);
    return found;
}

/* A range that holds hermite_range's (below) (wider, no extremum, no square root): the interpolant is a
 * convex combination of za, zb plus at most 4/27 of |ma| + |mb|. A substep quiet under it is quiet
 * under the exact range; only the others need that. */
static void hermite_range_bound(double za, double da, double zb, double db, double L, double *lo, double *hi)
{
    const double ma = L * da, mb = L * db;
    const double margin = 0.05 * (fabs(ma) + fabs(mb) + fabs(zb - za)), swing = 4.0 / 27.0 * (fabs(ma) + fabs(mb));
    *lo = rw_min2(za, zb) - swing - margin;
    *hi = rw_max2(za, zb) + swing + margin;
}

/* ---- peaks and output grid along a span ----------------------------------------------------- */
/* s1 or s2 (rw_s1, rw_s2: linear in the rotations; their coefficients are taken from them in
 * rw_engine_init, so that a peak costs no call) */
static double s_of(const rw_engine *e, int which, const double x[RW_NX])
{
    return e->s_coef[which][0] * x[0] + e->s_coef[which][1] * x[1];
}

static double rate_of_s(const rw_engine *e, const rw_regime *m, const rw_span *sp, int which, double s)
{
    double x[RW_NX], v[RW_NX] = {0, 0, 0, 0};
    (void)m;
    span_eval(sp, s, NULL, x, NULL);
    v[0] = x[2];
    v[1] = x[3];
    return s_of(e, which, v);
}

static void track_peak(rw_engine *e, int which, double value)
{
    double *peak = which == 0 ? &e->peak_s1 : &e->peak_s2;
    if (fabs(value) > *peak) *peak = fabs(value);
}

/* peaks over [a, b] of the span: the ends and an interior turning point of s1, s2 */
static void peaks_on(rw_engine *e, const rw_regime *m, const rw_span *sp, const double xa[RW_NX], double sa,
                     const double xb[RW_NX], double sb)
{
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
            const double s = find_switch(rate_of_s, e, m, sp, w, sa, ra, sb, rb, 1e-9, NAN);
            double x[RW_NX];
            span_eval(sp, s, NULL, x, NULL);
            track_peak(e, w, s_of(e, w, x));
        }
    }
}

static void record_output(rw_engine *e, const double x[RW_NX])
{
    size_t i = e->i_out;
    if (e->x_out) memcpy(e->x_out + RW_NX * i, x, sizeof(double) * RW_NX);
    if (e->s1_out) e->s1_out[i] = rw_s1(&e->P, x);
    if (e->s2_out) e->s2_out[i] = rw_s2(&e->P, x);
    e->i_out++;
}

/* grid times in (t0 + sa, t0 + sb] */
static void outputs_on(rw_engine *e, const rw_span *sp, double sb)
{
    while (e->i_out < e->n_out && e->t_out[e->i_out] <= sp->t0 + sb) {
        double x[RW_NX];
        span_eval(sp, e->t_out[e->i_out] - sp->t0, NULL, x, NULL);
        record_output(e, x);
    }
}

/* ---- events ----------------------------------------------------------------------------------- */
/* the tracked indicator states (z > 0), and the same as +-1 for suspects_of */
static void track_states(rw_engine *e, const double z[RW_NZ])
{
    int k;
    for (k = 0; k < RW_NZ; k++) {
        e->b[k] = z[k] > 0.0;
        e->b_sign[k] = e->b[k] ? 1.0 : -1.0;
    }
}

static void set_indicator_states(rw_engine *e, const rw_regime *m, const rw_input *in, const double x[RW_NX])
{
    double z[RW_NZ];
    rw_event_indicators(&e->P, &e->D, m, in, x, z);
    track_states(e, z);
}

/* The model's event iteration at t (as the FMU's hosts run it), then its collapse test.
 * Returns 0, 1 on collapse, or an error code + 1 (Zeno). */
static int apply_event(rw_engine *e, rw_regime *m, double x[RW_NX], double t, const rw_input *in)
{
    rw_event_result r;
    int rounds = 0;
    e->events++;
    if (t <= e->t_last_event + 1e-14 * rw_max2(1.0, fabs(t))) {
        if (++e->same_instant > e->max_same_instant) {
            snprintf(e->msg, sizeof e->msg, "more than %d events at t = %.17g (Zeno): stopped", e->max_same_instant, t);
            return RW_ENGINE_ZENO + 1;
        }
    } else {
        e->same_instant = 0;
    }
    e->t_last_event = t;
    e->region_valid = e->carry_valid = e->slow_carry_valid = e->pending_valid = 0;
    do {
        /* the energy only for those who read it: the FMU's dissipated output and the impact log */
        const int energy_wanted = e->track_dissipated || e->impact_t;
        const double energy = energy_wanted ? rw_energy(&e->P, &e->D, m, in, x) : 0.0;
        rw_event_update(&e->P, &e->D, m, in, x, &r, NULL, NULL);
        if (r.states_changed && e->track_dissipated) e->dissipated += energy - rw_energy(&e->P, &e->D, m, in, x);
        if (r.impacts && e->impact_t && (size_t)e->impacts < e->impact_cap) {
            e->impact_t[e->impacts] = t;
            e->impact_energy[e->impacts] = energy;
        }
        e->impacts += r.impacts;
    } while ((r.regime_changed || r.states_changed) && ++rounds < RW_MAX_EVENT_ROUNDS);
    e->b_stale = 1; /* the indicator states at x: from the start point of the next span (advance) */
    e->reason = rw_collapse_reason(&e->P, &e->D, m, in, x);
    if (e->reason != RW_STANDING) {
        e->collapsed = 1;
        e->t_collapse = t;
        return 1;
    }
    return 0;
}

/* The direction that picks the region on a breakpoint: dq a moment later (the acceleration is
 * continuous across a breakpoint, so this decides a grazing touch by its curvature). */
static void selection_rate(const rw_engine *e, const rw_regime *m, const rw_input *in, const double x[RW_NX],
                           double dq_sel[2])
{
    double dx[RW_NX];
    rw_derivatives(&e->P, &e->D, m, in, x, dx);
    dq_sel[0] = x[2] + RW_SELECT_DT * dx[2];
    dq_sel[1] = x[3] + RW_SELECT_DT * dx[3];
}

/* Stumpff coefficients of a full substep h, cached per region. A length within rounding of the
 * absolute time t of a cached one takes its coefficients: the record's sample spacing, t[i+1] - t[i],
 * differs from one segment to the next by the rounding of t, and so does the motion's time. */
static const double (*substep_coefficients(rw_cache_entry *c, double h, double t))[4]
{
    const double same = 4.0 * DBL_EPSILON * (fabs(t) + h);
    int j, i;
    for (j = 0; j < 2; j++)
        if (c->h_valid[j] && fabs(c->h[j] - h) <= same) {
            c->h_next = j ^ 1; /* least recently used: the sample spacing stays after an event's odd remainder */
            return (const double(*)[4])c->C[j];
        }
    j = c->h_next;
    c->h_next ^= 1;
    c->h[j] = h;
    c->h_valid[j] = 1;
    for (i = 0; i < 2; i++) stumpff(c->E.lam[i] * h * h, c->C[j][i]);
    return (const double(*)[4])c->C[j];
}

/* ---- resolving a span ----------------------------------------------------------------------------- */
/* Substeps: the counted rate turns by at most RW_PHASE_PER_SUBSTEP per substep, and none is
 * longer than a quarter radian of the wall's own rocking rate p = sqrt(3g/4R) (Housner), which
 * bounds the polynomial motion of zero-stiffness regions (a plateau, a closed hinge). A span
 * longer than RW_MAX_SUBSTEPS substeps covers a part (*len shortened); the caller continues. */
static double rocking_rate(const rw_engine *e)
{
    return sqrt(e->D.p2) * RW_PHASE_PER_SUBSTEP / 0.25;
}

static int substeps_for(double rate, double *len)
{
    const double turns = *len * rate / RW_PHASE_PER_SUBSTEP;
    int n;
    if (!(turns <= RW_MAX_SUBSTEPS)) {
        *len *= RW_MAX_SUBSTEPS / turns;
        return (int)RW_MAX_SUBSTEPS;
    }
    n = (int)turns; /* ceil, without libm's call */
    n += n < turns;
    return n < 1 ? 1 : n;
}

/* Does one substep cover a span of length len in region R, whatever modes count: does every mode,
 * and the rocking rate that bounds the polynomial motions, turn by at most RW_PHASE_PER_SUBSTEP? */
static int one_substep_covers(const rw_engine *e, const rw_cache_entry *R, double len)
{
    return rw_max2(e->floor_rate, rw_max2(R->w[0], R->w[1])) * len <= RW_PHASE_PER_SUBSTEP;
}

/* The values and rates of the indicators of `mask` at the state x of the span's motion at s, for
 * the indicators that are lines, the toppling indicator, the collapse form and the closed hinges'
 * form: their rates need the rotations' rates alone (x[2], x[3]), not a propagation to s. */
static void point_from_state(const rw_engine *e, const rw_regime *m, const rw_span *sp, const double x[RW_NX],
                             double s, unsigned mask, rw_point *pt)
{
    const double xd[RW_NX] = {x[2], x[3], 0.0, 0.0};
    const rw_input in = span_input(sp, s);
    pt->s = s;
    if (pt->x != x) memcpy(pt->x, x, sizeof pt->x);
    region_indicators(e, m, sp, &in, pt->x, xd, mask, pt->z, pt->dz);
}

/* The carried end point (rw_engine.carry) as the start point of the span sp, which starts at its
 * time and state: the closed hinges' indicators are taken again at the span's input (in *buf), since
 * their rates follow the input's; the other indicators depend on the state and the rotations'
 * rates alone. */
static const rw_point *carried_with_closed_hinges(const rw_engine *e, const rw_regime *m, const rw_span *sp,
                                                  rw_point *buf)
{
    *buf = e->carry;
    point_from_state(e, m, sp, buf->x, 0.0, e->closed_mask, buf);
    return buf;
}

static const rw_point *carried_start(const rw_engine *e, const rw_regime *m, const rw_span *sp, rw_point *buf)
{
    return e->closed_mask ? carried_with_closed_hinges(e, m, sp, buf) : &e->carry;
}

/* The start point of a span: the end point of the span before, where that holds (carried_start),
 * else evaluated into *buf */
static const rw_point *start_point(rw_engine *e, const rw_regime *m, const rw_span *sp, rw_point *buf)
{
    if (e->carry_valid && e->region_valid && e->carry_t == sp->t0 && memcmp(e->carry.x, sp->x0, sizeof e->carry.x) == 0)
        return carried_start(e, m, sp, buf);
    eval_point(e, m, sp, 0.0, NULL, buf);
    return buf;
}

static void carry_point(rw_engine *e, const rw_point *pb, double t)
{
    e->carry_valid = 1;
    e->carry_t = t;
    e->carry = *pb;
    e->carry.s = 0.0;
}

/* Does q alone fix the span's region? Under a law whose hinge moments depend on q alone, with the
 * region's affine Q. (The rigid law has an affine Q too, but its region also depends on which
 * hinges are closed.) */
static int q_fixes_region(const rw_engine *e, const rw_span *sp)
{
    return rw_moments_of_q_alone(&e->P) && sp->aq.valid;
}

/* After an event of the base or mid-height hinge indicator under a law whose hinge moments depend
 * on q alone (q_fixes_region), the region is the same: the event maps change rates and
 * the regime, never q, and such a law's region is fixed by q, except on a breakpoint itself, where the
 * direction of motion picks it (then it is found again). Only the lines (sides, offsets) change. */
static int hinge_event_keeps_region(const rw_engine *e, const rw_span *sp, int k_event, const double x[RW_NX])
{
    int k;
    if (!q_fixes_region(e, sp) || (k_event != RW_Z_BASE && k_event != RW_Z_MID)) return 0;
    for (k = RW_Z_BREAK; k < RW_Z_BREAK + RW_NBREAK; k++)
        if (fabs(rw_line_value(&e->lines[k], x, NULL, NULL)) < 1e-9 * e->D.q_topple) return 0;
    return 1;
}

static void region_lines(rw_engine *e, const rw_regime *m);

/* What goes on after an event that keeps the region (hinge_event_keeps_region: a hinge's change of
 * side under semiRigidHinge or dohertyHinge), without going back to advance(): the lines and the
 * indicator states change, and
 * - if the event left the state as it was (a mid-height hinge's change of side), the motion goes
 *   on as it was: the span continues, and pb's values are taken again with the new lines;
 * - if it changed the rates (a base impact) and the span is the segment's only piece
 *   (`restart`), a new span of the same region starts at the event and pb is evaluated again at
 *   the segment's end t_end.
 * *at_event: the point at the event with the new lines (its states are the tracked ones, as a new
 * span's start point would give them). The indicators other than lines (toppling, the collapse
 * form) need the rotations' rates alone there, not a propagation. Returns 0 where this does not
 * apply (then the caller goes back to advance()). */
typedef struct {
    const rw_cache_entry *R;
    const double *g0;
    const rw_linear_input *in;
    double t_in, t_end;
    int restart;
} rw_piece;

static int go_on_after_event(rw_engine *e, const rw_regime *m, rw_span *sp, const rw_piece *pc, const double x[RW_NX],
                             int state_kept, double s_ev, rw_point *at_event, rw_point *pb)
{
    const unsigned from_rotations = (1u << RW_Z_TOPPLE) | (1u << RW_Z_COLLAPSE);
    if (!state_kept && !pc->restart) return 0;
    region_lines(e, m);
    if (e->P.support != RW_FLEXIBLE_TOP || !q_fixes_region(e, sp) ||
        (RW_Z_ALL & ~e->line_mask & ~from_rotations))
        return 0;
    e->region_valid = 1; /* apply_event let it go: the same region, with its new lines */
    if (state_kept) {
        point_from_state(e, m, sp, x, s_ev, RW_Z_ALL, at_event);
        point_from_state(e, m, sp, pb->x, pb->s, RW_Z_ALL, pb);
    } else {
        span_start(sp, pc->R, pc->g0, sp->t0 + s_ev, x, pc->in, pc->t_in);
        point_from_state(e, m, sp, x, 0.0, RW_Z_ALL, at_event);
        eval_point(e, m, sp, pc->t_end - sp->t0, NULL, pb);
    }
    track_states(e, at_event->z);
    e->b_stale = 0;
    e->steps++;
    return 1;
}

/* The events of the piece [*pa, pb] of the span (suspects: suspects_of), earliest first: each is
 * applied (x, *t at it); one after which go_on_after_event applies goes on in this piece (*pa
 * becomes *event_point, the point after it). Returns 0 when the piece has no more events (its rest
 * is quiet), -1 when an event ends the span (the caller starts a new one), or a collapse / error
 * code (apply_event). */
static int events_in_piece(rw_engine *e, rw_regime *m, rw_span *sp, const rw_piece *pc, const rw_point **pa,
                           rw_point *pb, unsigned suspects, rw_point *event_point, double x[RW_NX], double *t)
{
    double s_ev = 0.0;
    int k_ev = 0; /* both set by first_event when it finds one */
    while (suspects && first_event(e, m, sp, *pa, pb, suspects, &s_ev, &k_ev, x)) {
        const rw_input ie = span_input(sp, s_ev);
        double x_before[RW_NX];
        int rc, kept;
        peaks_on(e, m, sp, (*pa)->x, (*pa)->s, x, s_ev);
        outputs_on(e, sp, s_ev);
        *t = sp->t0 + s_ev;
        memcpy(x_before, x, sizeof x_before);
        rc = apply_event(e, m, x, *t, &ie);
        if (rc) return rc;
        if (!hinge_event_keeps_region(e, sp, k_ev, x)) return -1;
        kept = memcmp(x_before, x, sizeof x_before) == 0;
        if (!go_on_after_event(e, m, sp, pc, x, kept, s_ev, event_point, pb)) {
            e->region_keep = 1;
            return -1;
        }
        *pa = event_point;
        suspects = suspects_of(e, event_point->z, event_point->dz, pb->z, pb->dz, pb->s - event_point->s);
    }
    return 0;
}

/* Full resolution over [0, len] of the span (which starts at x, *t) in n pieces: events, peaks,
 * outputs. Returns 0 (len reached: x, *t at its end), -1 (an event was applied at *t: the caller
 * starts a new region), or a collapse / error code (apply_event). C: Stumpff coefficients of
 * pieces of length len/n (NULL: computed). */
static int resolve(rw_engine *e, rw_regime *m, rw_span *sp, const rw_cache_entry *R, const double g0[2],
                   const rw_linear_input *in, double t_in, double len, int n, const double (*C)[4], double x[RW_NX],
                   double *t)
{
    const double h = len / n, t_end = sp->t0 + len;
    rw_point buf[2], event_point;
    const rw_point *pa = start_point(e, m, sp, &buf[0]);
    int j;
    for (j = 0; j < n; j++) {
        const double piece = j == n - 1 ? t_end - sp->t0 : h;
        /* the last piece differs from h by rounding of t_end - t0 at most: the same coefficients */
        const int same = fabs(piece - h) <= 4.0 * DBL_EPSILON * (fabs(t_end) + h);
        rw_point *pb = pa == &buf[0] ? &buf[1] : &buf[0];
        unsigned suspects;
        if (j == 0 && n == 1 && e->pending_valid && e->pending_t0 == sp->t0 && e->pending.s == piece) {
            pb = &e->pending; /* rw_engine_quiet_segment evaluated it: the same span, coefficients and start */
            suspects = e->pending_suspects;
        } else {
            eval_point(e, m, sp, piece, same ? C : NULL, pb);
            suspects = suspects_of(e, pa->z, pa->dz, pb->z, pb->dz, pb->s - pa->s);
        }
        e->pending_valid = 0;
        e->steps++;
        if (suspects) {
            const rw_piece pc = {R, g0, in, t_in, t_end, n == 1};
            const int rc = events_in_piece(e, m, sp, &pc, &pa, pb, suspects, &event_point, x, t);
            if (rc) return rc;
        }
        peaks_on(e, m, sp, pa->x, pa->s, pb->x, pb->s);
        outputs_on(e, sp, pb->s);
        memcpy(x, pb->x, sizeof pb->x);
        if (j == n - 1) {
            *t = t_end;
            carry_point(e, pb, t_end);
        } else { /* the next piece starts here */
            span_start(sp, R, g0, sp->t0 + h, pb->x, in, t_in);
            *t = sp->t0;
            pb->s = 0.0;
            pa = pb;
        }
    }
    return 0;
}

/* ---- fast modes: a band around the slow motion ---------------------------------------------------
 * A stiff mode (a stiff spring: up to 1e5 rad/s) would set substeps of microseconds. Its free
 * oscillation is a sinusoid of constant amplitude (dq_fast) about its exact quasi-static solution, so
 * over a substep of the slow modes the motion is the slow part (span_eval_part) within that band.
 * A substep can hold no event when every indicator of the slow part stays farther from zero than
 * what the band can change it by (evaluated at +-dq_fast, doubled), and no new peak when |s1|, |s2|
 * of the slow part plus the band stay below the peaks so far; otherwise the substep is resolved at
 * the fast rate. The slow part between the substep's ends is bounded by its cubic Hermite
 * interpolant with the margin of hermite_keeps_sign. */

/* min and max over [0, 1] of the cubic Hermite interpolant of (z, dz) on [0, L], ends included */
static void hermite_range(double za, double da, double zb, double db, double L, double *lo, double *hi)
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

static int indicator_clear(int state, double lo, double hi, double band)
{
    return state ? lo > band : hi < -band;
}

/* The slow part's ends of a substep [0, L]: the points (indicators with their rates) and the
 * rotations' accelerations there, with which line_crossing bounds a line's slow rate */
typedef struct {
    rw_point a, b;
    double ddq_a[2], ddq_b[2];
} rw_slow_ends;

static void eval_slow_point(const rw_engine *e, const rw_regime *m, const rw_span *sp, double s, const double (*C)[4],
                            const int *fast, rw_point *pt, double ddq[2], double *x_full)
{
    double xd[RW_NX];
    rw_input in = span_input(sp, s);
    pt->s = s;
    if (x_full) span_eval_slow_and_full(sp, s, C, fast, pt->x, xd, x_full);
    else span_eval_part(sp, s, C, fast, pt->x, xd);
    region_indicators(e, m, sp, &in, pt->x, xd, RW_Z_ALL, pt->z, pt->dz);
    ddq[0] = xd[2];
    ddq[1] = xd[3];
}

/* The band of the indicators of `mask` near the slow point a, evaluated: twice the larger change
 * of each at a +- dq_fast */
static void band_by_evaluation(const rw_engine *e, const rw_regime *m, const rw_span *sp, const rw_point *a,
                               const rw_rates *r, unsigned mask, double band[RW_NZ])
{
    double xp[RW_NX], xm[RW_NX], zp[RW_NZ], zm[RW_NZ];
    const rw_input in = span_input(sp, a->s);
    int k;
    memcpy(xp, a->x, sizeof xp);
    memcpy(xm, a->x, sizeof xm);
    xp[0] += r->dq_fast[0], xp[1] += r->dq_fast[1];
    xm[0] -= r->dq_fast[0], xm[1] -= r->dq_fast[1];
    region_indicators(e, m, sp, &in, xp, NULL, mask, zp, NULL);
    region_indicators(e, m, sp, &in, xm, NULL, mask, zm, NULL);
    for (k = 0; k < RW_NZ; k++)
        if ((mask >> k) & 1u) band[k] = 2.0 * rw_max2(fabs(zp[k] - a->z[k]), fabs(zm[k] - a->z[k]));
}

/* How much the band can change each indicator near the slow point a, doubled: for a line
 * c + s|w| + t w of w = a.q, at most (|s| + |t|) |a.dq_fast|; for the toppling indicator,
 * max |dq_fast|/q_topple; the closed hinges' evaluated (band_by_evaluation). The collapse
 * indicator's is evaluated only where substep_suspects needs it. */
static void band_of(const rw_engine *e, const rw_regime *m, const rw_span *sp, const rw_point *a, const rw_rates *r,
                    double band[RW_NZ])
{
    const double d0 = r->dq_fast[0], d1 = r->dq_fast[1];
    const rw_line_arrays *A = &e->line_arrays;
    unsigned rest = RW_Z_ALL & ~e->line_mask & ~(1u << RW_Z_COLLAPSE);
    int k;
    for (k = 0; k < RW_NZ; k++) /* on arrays, which the compiler vectorizes; overwritten below for the rest */
        band[k] = 2.0 * (fabs(A->s[k]) + fabs(A->t[k])) * fabs(A->a0[k] * d0 + A->a1[k] * d1);
    if ((rest & (1u << RW_Z_TOPPLE)) && e->P.support == RW_FLEXIBLE_TOP) {
        band[RW_Z_TOPPLE] = 2.0 * rw_max2(fabs(d0), fabs(d1)) * e->D.inv_q_topple;
        rest &= ~(1u << RW_Z_TOPPLE);
    }
    if (rest) band_by_evaluation(e, m, sp, a, r, rest, band);
}

/* The collapse indicator under the band. Near q = 0 the band turns the direction of q and so
 * moves the scale-free indicator by much, but there it cannot vanish at all on a region whose
 * form G = q.A q - c.q has a positive definite symmetric part (least eigenvalue lam_min > 0):
 * G >= lam_min |q|^2 - |c| |q| > 0 for |q| > |c|/lam_min (collapse_radius, 0 when c is zero to
 * rounding, as in an elastic range). So the wall stands over the substep when the full motion
 * stays beyond that radius: each rotation's slow range, widened by the band, bounds |q| below. */
static int collapse_cannot_vanish(const rw_engine *e, const rw_span *sp, const rw_point *a, const rw_point *b,
                                  const rw_rates *r, double L)
{
    double q_min = 0.0, lo, hi;
    int j;
    if (!sp->aq.valid || !e->b[RW_Z_COLLAPSE] || !(e->collapse_radius < INFINITY)) return 0;
    if (e->collapse_radius == 0.0) return 1;
    for (j = 0; j < 2; j++) {
        hermite_range(a->x[j], a->x[2 + j], b->x[j], b->x[2 + j], L, &lo, &hi);
        q_min = rw_max2(q_min, rw_max2(lo - fabs(r->dq_fast[j]), -hi - fabs(r->dq_fast[j])));
    }
    return q_min > e->collapse_radius;
}

#define RW_PEAKS_SUSPECT (1u << RW_NZ) /* substep_suspects: a new peak is possible under a band that matters */

/* Can |s| (which: 0 for s1, 1 for s2) of the full motion pass its peak so far over [0, L], given the
 * slow part's states xa, xb at the ends? The slow part's range is its cubic Hermite interpolant's,
 * and the band adds its exact reach |s(dq_fast)| (s is linear in q). 1 with the reach and the slow
 * part's largest |s| (*reach, *slow_max), or 0. */
static int peak_possible(const rw_engine *e, int which, const rw_rates *r, const double xa[RW_NX],
                         const double xb[RW_NX], double L, double *reach, double *slow_max)
{
    const double amp[RW_NX] = {r->dq_fast[0], r->dq_fast[1], 0, 0};
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

/* The indicators (a bit each) that the band test does not clear over the substep [0, L] of the
 * span, and RW_PEAKS_SUSPECT when a new peak is possible under a band that is not negligible: 0
 * when the substep is quiet. Then *peaks_full says whether a new peak is possible there: the band
 * is then negligible (below 1e-9 of the peak) and the peaks are taken on the full motion at the
 * substep's resolution. ends: the slow part's ends; x_end: the full state at the end. */
static unsigned substep_suspects(const rw_engine *e, const rw_regime *m, const rw_span *sp, double L,
                                 const double (*C)[4], const rw_rates *r, int *peaks_full, rw_slow_ends *ends,
                                 double x_end[RW_NX])
{
    const unsigned collapse = 1u << RW_Z_COLLAPSE;
    const rw_point *a = &ends->a, *b = &ends->b;
    double band[RW_NZ], lo, hi;
    unsigned suspects;
    int k, w, stands;
    *peaks_full = 0;
    if (e->slow_carry_valid && e->slow_carry_t == sp->t0 && memcmp(e->slow_carry_x0, sp->x0, sizeof sp->x0) == 0) {
        ends->a = e->slow_carry; /* the slow end of the quiet substep before (equal to rounding) */
        memcpy(ends->ddq_a, e->slow_carry_ddq, sizeof ends->ddq_a);
    } else {
        eval_slow_point(e, m, sp, 0.0, NULL, r->fast, &ends->a, ends->ddq_a, NULL);
    }
    eval_slow_point(e, m, sp, L, C, r->fast, &ends->b, ends->ddq_b, x_end);
    band_of(e, m, sp, a, r, band);
    stands = collapse_cannot_vanish(e, sp, a, b, r, L);
    if (stands) band[RW_Z_COLLAPSE] = 0.0;
    else band_by_evaluation(e, m, sp, a, r, collapse, band);
    /* the quick test, then the exact range of the slow part's interpolant for what it leaves */
    suspects = clearance_suspects(e, a->z, a->dz, b->z, b->dz, band, L) & ~(stands ? collapse : 0u);
    for (k = 0; suspects >> k; k++) {
        if (!((suspects >> k) & 1u)) continue;
        hermite_range(a->z[k], a->dz[k], b->z[k], b->dz[k], L, &lo, &hi);
        if (indicator_clear(e->b[k], lo, hi, band[k])) suspects &= ~(1u << k);
    }
    for (w = 0; w < 2; w++) {
        double reach, slow_max;
        if (!peak_possible(e, w, r, a->x, b->x, L, &reach, &slow_max)) continue;
        if (reach > 1e-9 * slow_max) suspects |= RW_PEAKS_SUSPECT;
        else *peaks_full = 1;
    }
    return suspects;
}

/* ---- one crossing through the band ----------------------------------------------------------
 * Near an event the band test fails for the indicator that crosses, and resolving the substep at
 * the fast rate costs many full steps. An indicator that is a line of the rotations, z = c +
 * s|w| + t w with w = a.q, is monotone on the full motion where its slow rate outruns the fastest
 * the band can move it: |a.dq_slow| > w_fast |a.dq_fast| over the whole substep (the slow rate's
 * range from its cubic Hermite interpolant, with that interpolant's margin), with a breakpoint
 * (s != 0) kept on one side of its kink w = 0 (the slow w's range clear of the band). Then it
 * crosses at most once, and the full motion's values at the ends decide: no crossing, or one.
 * Returns -1 (undecided: the caller resolves at the fast rate), 0 (no crossing) or 1 (a crossing,
 * with the line's full values at the ends, z[0] and z[1], and *guess: the slow part's crossing,
 * within the band's width over the slow rate of the full one; NaN when the slow part does not
 * cross). */
static int line_crossing(const rw_engine *e, const rw_span *sp, int k, double L, const rw_rates *r,
                         const rw_slow_ends *ends, const double x_end[RW_NX], double z[2], double *guess)
{
    const rw_indicator_line *line = &e->lines[k];
    const double a0 = line->a[0], a1 = line->a[1];
    const double w_band = fabs(a0 * r->dq_fast[0] + a1 * r->dq_fast[1]);
    const double *xa = ends->a.x, *xb = ends->b.x;
    const double za = ends->a.z[k], zb = ends->b.z[k];
    double lo, hi, slope;
    if (!((e->line_mask >> k) & 1u)) return -1;
    slope = line->t;
    if (line->s != 0.0) { /* a breakpoint: one side of w = 0 throughout */
        hermite_range(a0 * xa[0] + a1 * xa[1], a0 * xa[2] + a1 * xa[3], a0 * xb[0] + a1 * xb[1], a0 * xb[2] + a1 * xb[3],
                      L, &lo, &hi);
        if (!(lo > w_band || hi < -w_band)) return -1;
        slope += lo > w_band ? line->s : -line->s;
    }
    if (slope == 0.0) return -1;
    hermite_range(a0 * xa[2] + a1 * xa[3], a0 * ends->ddq_a[0] + a1 * ends->ddq_a[1], a0 * xb[2] + a1 * xb[3],
                  a0 * ends->ddq_b[0] + a1 * ends->ddq_b[1], L, &lo, &hi);
    if (!(lo > r->fast_rate * w_band || hi < -r->fast_rate * w_band)) return -1; /* not monotone */
    z[0] = rw_line_value(line, sp->x0, NULL, NULL);
    if ((z[0] > 0.0) != e->b[k]) return -1; /* the start is not on the tracked side: let the fast rate decide */
    z[1] = rw_line_value(line, x_end, NULL, NULL);
    if ((z[1] > 0.0) == e->b[k]) return 0;
    *guess = (za > 0.0) != (zb > 0.0) ? L * hermite_root(za, ends->a.dz[k], zb, ends->b.dz[k], L) : NAN;
    return 1;
}

/* The suspects of a substep settled by line_crossing when every one is a line: 1 with the first
 * crossing (*s_event, *k_event, x_event) or 0 with none, or -1 if one is undecided. The crossings
 * are refined the earliest guess first; a later line is monotone over the substep, so one still on
 * its tracked side at the first root crosses after it and needs no refinement. */
static int crossings_through_band(const rw_engine *e, const rw_regime *m, const rw_span *sp, unsigned suspects,
                                  double L, const rw_rates *r, const rw_slow_ends *ends, const double x_end[RW_NX],
                                  double *s_event, int *k_event, double x_event[RW_NX])
{
    int order[RW_NZ], n = 0, i, found = 0;
    double guess[RW_NZ], z_ends[RW_NZ][2];
    if (suspects & ~e->line_mask) return -1; /* a new peak, the collapse or the toppling indicator */
    for (i = 0; suspects >> i; i++) {
        int rc;
        if (!((suspects >> i) & 1u)) continue;
        rc = line_crossing(e, sp, i, L, r, ends, x_end, z_ends[i], &guess[i]);
        if (rc < 0) return -1;
        if (rc == 1) n = insert_by_guess(order, n, guess, i);
    }
    for (i = 0; i < n; i++) {
        const int k = order[i];
        const rw_indicator_line *line = &e->lines[k];
        double s_k, x_k[RW_NX];
        int valid;
        if (found && (rw_line_value(line, x_event, NULL, NULL) > 0.0) == e->b[k]) continue; /* crosses later */
        s_k = refine_root(e, m, sp, k, e->b[k], 0.0, z_ends[k][0], L, z_ends[k][1], guess[k], x_k, &valid);
        if (!valid) span_eval(sp, s_k, NULL, x_k, NULL);
        if (!found || s_k < *s_event) {
            found = 1;
            *s_event = s_k;
            *k_event = k;
            memcpy(x_event, x_k, sizeof x_k);
        }
    }
    return found;
}

/* |s1|, |s2| at the state x as a share of their peaks so far, the larger */
static double peak_share(const rw_engine *e, const double x[RW_NX])
{
    return rw_max2(fabs(s_of(e, 0, x)) / rw_max2(e->peak_s1, DBL_MIN), fabs(s_of(e, 1, x)) / rw_max2(e->peak_s2, DBL_MIN));
}

/* The peaks over [u, v] of the span's full motion where the band matters for them
 * (RW_PEAKS_SUSPECT) and no indicator changes sign: where the slow part plus the band can pass a
 * peak so far (peak_possible), [u, v] is halved until a half turns the fast mode by at most 8 rad,
 * and such a piece takes peaks_on on the full motion at the fast rate. Only the neighbourhood of a
 * new peak is resolved, and without the indicators. xu, xv: the slow part's states at u and v. */
static void peaks_under_band(rw_engine *e, const rw_regime *m, const rw_span *sp, const rw_rates *r, double u,
                             const double xu[RW_NX], double v, const double xv[RW_NX], int depth)
{
    double reach, slow_max, len = v - u, xa[RW_NX], xb[RW_NX];
    int n, j;
    if (!peak_possible(e, 0, r, xu, xv, len, &reach, &slow_max) && !peak_possible(e, 1, r, xu, xv, len, &reach, &slow_max))
        return;
    n = substeps_for(r->fast_rate, &len);
    if (n > 8 && depth < 40) {
        const double mid = u + 0.5 * (v - u);
        double xm[RW_NX];
        span_eval_part(sp, mid, NULL, r->fast, xm, NULL);
        /* the half that reaches higher first: the peak it sets mostly rules the other half out (a
         * growing motion is then searched in log2 of its fast periods, not in all of them) */
        if (peak_share(e, xv) > peak_share(e, xu)) {
            peaks_under_band(e, m, sp, r, mid, xm, v, xv, depth + 1);
            peaks_under_band(e, m, sp, r, u, xu, mid, xm, depth + 1);
        } else {
            peaks_under_band(e, m, sp, r, u, xu, mid, xm, depth + 1);
            peaks_under_band(e, m, sp, r, mid, xm, v, xv, depth + 1);
        }
        return;
    }
    span_eval(sp, u, NULL, xa, NULL);
    for (j = 1; j <= n; j++) {
        const double sa = u + (v - u) * (j - 1) / n, sb = j == n ? v : u + (v - u) * j / n;
        span_eval(sp, sb, NULL, xb, NULL);
        peaks_on(e, m, sp, xa, sa, xb, sb);
        memcpy(xa, xb, sizeof xa);
    }
}

/* The substep [0, L] of the span taken whole (quiet, or quiet but for indicators without a
 * crossing): x, *t at its end x_end, the slow end point carried to the next substep. */
static void accept_substep(rw_engine *e, const rw_regime *m, const rw_span *sp, double L, const double x_end[RW_NX],
                           int peaks_full, const rw_slow_ends *ends, double t_to, double x[RW_NX], double *t)
{
    e->steps++;
    if (peaks_full) peaks_on(e, m, sp, x, 0.0, x_end, L);
    memcpy(x, x_end, sizeof(double) * RW_NX);
    outputs_on(e, sp, L);
    *t = t_to;
    e->slow_carry = ends->b;
    e->slow_carry.s = 0.0; /* the next substep starts here */
    memcpy(e->slow_carry_ddq, ends->ddq_b, sizeof e->slow_carry_ddq);
    e->slow_carry_t = t_to;
    memcpy(e->slow_carry_x0, x, sizeof e->slow_carry_x0);
    e->slow_carry_valid = 1;
}

/* A substep of a span with fast modes, from the span's start to t_to: accepted when quiet or when
 * its suspects are lines that cross at most once (crossings_through_band), else halved until its
 * halves are or are short enough (8 pieces at the fast rate) to be resolved in full, so that only
 * the neighbourhood of an event that the band cannot settle, or of a new peak, is resolved at the
 * fast rate. Returns as resolve(). */
static int fast_substep(rw_engine *e, rw_regime *m, rw_span *sp, const rw_cache_entry *R, const double g0[2],
                        const rw_linear_input *in, double t_in, double t_to, const double (*C)[4], const rw_rates *r,
                        double x[RW_NX], double *t, int depth)
{
    const double L = t_to - sp->t0;
    int peaks_full, nf, rc, k_ev = 0;
    double len = L, s_ev = 0.0, x_ev[RW_NX]; /* s_ev, k_ev, x_ev: set by crossings_through_band when it finds one */
    double x_end[RW_NX];
    rw_slow_ends ends;
    const unsigned suspects = substep_suspects(e, m, sp, L, C, r, &peaks_full, &ends, x_end);
    if (suspects == 0) {
        accept_substep(e, m, sp, L, x_end, peaks_full, &ends, t_to, x, t);
        return 0;
    }
    e->slow_carry_valid = 0;
    rc = suspects & ~RW_PEAKS_SUSPECT
             ? crossings_through_band(e, m, sp, suspects & ~RW_PEAKS_SUSPECT, L, r, &ends, x_end, &s_ev, &k_ev, x_ev)
             : 0;
    if (rc == 0) {
        if (suspects & RW_PEAKS_SUSPECT) peaks_under_band(e, m, sp, r, 0.0, ends.a.x, L, ends.b.x, 0);
        accept_substep(e, m, sp, L, x_end, peaks_full, &ends, t_to, x, t);
        return 0;
    }
    if (rc == 1) { /* the event, as resolve() applies it */
        const rw_input ie = span_input(sp, s_ev);
        e->steps++;
        if (suspects & RW_PEAKS_SUSPECT) {
            double x_slow[RW_NX];
            span_eval_part(sp, s_ev, NULL, r->fast, x_slow, NULL);
            peaks_under_band(e, m, sp, r, 0.0, ends.a.x, s_ev, x_slow, 0);
        }
        if (peaks_full) peaks_on(e, m, sp, x, 0.0, x_ev, s_ev);
        outputs_on(e, sp, s_ev);
        memcpy(x, x_ev, sizeof x_ev);
        *t = sp->t0 + s_ev;
        rc = apply_event(e, m, x, *t, &ie);
        if (rc == 0 && hinge_event_keeps_region(e, sp, k_ev, x)) e->region_keep = 1;
        return rc ? rc : -1;
    }
    nf = substeps_for(r->fast_rate, &len);
    if (nf <= 8 || depth >= 40) return resolve(e, m, sp, R, g0, in, t_in, L, len < L ? (int)RW_MAX_SUBSTEPS : nf, NULL, x, t);
    rc = fast_substep(e, m, sp, R, g0, in, t_in, sp->t0 + 0.5 * L, NULL, r, x, t, depth + 1);
    if (rc) return rc;
    span_start(sp, R, g0, *t, x, in, t_in);
    return fast_substep(e, m, sp, R, g0, in, t_in, t_to, NULL, r, x, t, depth + 1);
}

/* ---- one region on its own (rw_engine.h) ------------------------------------------------------ */
int rw_engine_region_motion(rw_engine *e, const double J[2][2], const double c[2], const rw_linear_input *in,
                            const double x0[RW_NX], double s, double x[RW_NX])
{
    rw_cache_entry R;
    rw_span sp;
    double g0[2];
    if (!e || e->P.support != RW_FLEXIBLE_TOP) return RW_ENGINE_UNSUPPORTED;
    memset(&R, 0, sizeof R);
    if (rw_engine_modes_open(e, J, &R.E) != 0) return RW_ENGINE_UNSUPPORTED;
    rw_engine_modal_force(&R.E, c, g0);
    memset(&sp, 0, sizeof sp);
    span_start(&sp, &R, g0, 0.0, x0, in, 0.0);
    span_eval(&sp, s, NULL, x, NULL);
    return 0;
}

/* ---- the stepper ------------------------------------------------------------------------------ */
/* The indicator states after an event: at the start point of the span that follows, which is kept
 * for resolve() (the region's own evaluation: the lines and the collapse form as the physics gives
 * them, so the same signs as rw_event_indicators) */
static void refresh_indicator_states(rw_engine *e, const rw_regime *m, const rw_span *sp)
{
    rw_point pt;
    eval_point(e, m, sp, 0.0, NULL, &pt);
    track_states(e, pt.z);
    e->b_stale = 0;
    carry_point(e, &pt, sp->t0);
}

/* the indicators that are lines of the rotations under the regime m (they change only at events).
 * Under a law of q alone the mid-height hinge's switch changes nothing in the motion
 * (rw_mid_switch_is_bookkeeping): its line is left out, so the engine does not stop there. Under a
 * wall held at its top that switch comes microseconds after each base crossing, and each such pair
 * of events cost as much as seven quiet segments. The side is brought up to date by the event
 * update at the next event and at the end of every step (rw_engine_step). */
static void region_lines(rw_engine *e, const rw_regime *m)
{
    int k;
    rw_indicator_lines(&e->P, &e->D, m, e->lines);
    if (e->mid_is_bookkeeping) {
        const rw_indicator_line never = {{0.0, 0.0}, 0.0, 0.0, 1.0, 0};
        e->lines[RW_Z_MID] = never;
    }
    e->line_mask = 0;
    for (k = 0; k < RW_NZ; k++) {
        const rw_indicator_line *L = &e->lines[k];
        if (!L->none) e->line_mask |= 1u << k;
        e->line_arrays.a0[k] = L->a[0];
        e->line_arrays.a1[k] = L->a[1];
        e->line_arrays.s[k] = L->s;
        e->line_arrays.t[k] = L->t;
        e->line_arrays.c[k] = L->c;
    }
}

/* The region's collapse form (rw_collapse_form_of) and the radius beyond which it cannot vanish
 * (collapse_cannot_vanish): |c|/lam_min with a 1 % margin, 0 when c is zero to rounding, infinite
 * when the symmetric part of A is not positive definite. */
static void collapse_form_of_region(rw_engine *e)
{
    const rw_collapse_form *f = &e->collapse_form;
    double mean, half_diff, off, lam_min, size, c_norm;
    rw_collapse_form_of(&e->D, e->region_aq.c, (const double(*)[2])e->region_aq.J, &e->collapse_form);
    mean = 0.5 * (f->A[0][0] + f->A[1][1]);
    half_diff = 0.5 * (f->A[0][0] - f->A[1][1]);
    off = 0.5 * (f->A[0][1] + f->A[1][0]);
    lam_min = mean - sqrt(half_diff * half_diff + off * off);
    size = fabs(mean) + fabs(half_diff) + fabs(off);
    c_norm = sqrt(f->c[0] * f->c[0] + f->c[1] * f->c[1]);
    e->collapse_radius = INFINITY;
    if (lam_min > 1e-9 * size)
        e->collapse_radius = c_norm <= 1e-12 * size * e->D.q_topple ? 0.0 : 1.01 * c_norm / lam_min;
}

/* The region of the motion at (x, t): kept from one input segment to the next, since without an
 * event no indicator, so no breakpoint and no regime, has changed; found again after each event. */
static rw_cache_entry *current_region(rw_engine *e, const rw_regime *m, const double x[RW_NX], double t,
                                      const rw_linear_input *in, double t_in, double g0[2], rw_affine_Q *aq)
{
    rw_cache_entry *R;
    if (!e->region_valid && e->region_keep) { /* hinge_event_keeps_region */
        region_lines(e, m);
        e->region_valid = 1;
    }
    e->region_keep = 0;
    if (!e->region_valid) {
        rw_input now;
        double dq_sel[2];
        now.ag = in->ag + in->ag_slope * (t - t_in);
        now.u_top = in->u_top + in->u_slope * (t - t_in);
        if (e->rigid && e->P.support == RW_FLEXIBLE_TOP) { /* its moments depend on the sides alone */
            dq_sel[0] = x[2];
            dq_sel[1] = x[3];
        } else {
            selection_rate(e, m, &now, x, dq_sel);
        }
        R = rw_engine_region_of(e, m, x, dq_sel, e->region_g0, &e->region_aq);
        if (!R) return NULL;
        region_lines(e, m);
        e->closed_mask = rw_closed_hinge_mask(&e->P, m);
        if (e->closed_mask) rw_closed_force_form(&e->P, &e->D, m, &e->closed_form);
        if (e->region_aq.valid)
            collapse_form_of_region(e);
        e->region = (int)(R - e->cache);
        e->region_valid = 1;
    }
    memcpy(g0, e->region_g0, sizeof e->region_g0);
    *aq = e->region_aq;
    return &e->cache[e->region];
}


/* Right after an event under a stiff spring the next one often follows within microseconds (the
 * base and the mid-height hinge of a wall held at its top switch nearly together, under the laws
 * whose moments take the sides: the rigid law, semiRigidPaper). Left to the
 * band (fast_substep), it costs a band test of the rest of the segment before it and another after.
 * So when an indicator of the span's start point (the carried point) heads for zero, linearly,
 * within the piece over which the fast mode turns by RW_PHASE_PER_SUBSTEP, advance() resolves that
 * piece in full first: every mode turns little over it, as resolve() needs. */
static int event_ahead(const rw_engine *e, double piece)
{
    int k;
    for (k = 0; k < RW_NZ; k++)
        if (e->b_sign[k] * (e->carry.z[k] + e->carry.dz[k] * piece) < 0.0) return 1;
    return 0;
}

/* Advance over [t, t_end] with the input linear (in, given at t_in). Returns 0, 1 on collapse
 * (x, t at the collapse), or an error code + 1. */
static int advance(rw_engine *e, rw_regime *m, double x[RW_NX], double *t, double t_end, const rw_linear_input *in,
                   double t_in)
{
    while (*t < t_end) {
        rw_span sp;
        rw_rates r;
        double g0[2], span_len, h, span_end;
        rw_cache_entry *R;
        int n, j, rc = 0, after_event;
        R = current_region(e, m, x, *t, in, t_in, g0, &sp.aq);
        if (!R) return RW_ENGINE_UNSUPPORTED + 1;
        span_start(&sp, R, g0, *t, x, in, t_in);
        after_event = e->b_stale; /* the indicator states are taken again at an event's state */
        if (after_event) refresh_indicator_states(e, m, &sp);
        span_len = t_end - *t;
        if (one_substep_covers(e, R, span_len)) {
            r.any_fast = 0;
            n = 1;
            h = span_len;
            span_end = t_end;
        } else {
            span_rates(e, &sp, e->floor_rate, &r);
            n = substeps_for(r.slow_rate, &span_len);
            h = span_len / n;
            span_end = n * h < t_end - *t ? *t + span_len : t_end;
        }
        if (r.any_fast || n != 1) e->pending_valid = 0;
        if (r.any_fast && after_event) {
            const double piece = RW_PHASE_PER_SUBSTEP / r.fast_rate;
            if (piece < span_len && event_ahead(e, piece)) {
                rc = resolve(e, m, &sp, R, g0, in, t_in, piece, 1, NULL, x, t);
                if (rc > 0) return rc;
                continue; /* from the next event, or from the piece's end */
            }
        }
        if (!r.any_fast) {
            rc = resolve(e, m, &sp, R, g0, in, t_in, span_end - *t, n, substep_coefficients(R, h, span_end), x, t);
            if (rc > 0) return rc;
            continue;
        }
        for (j = 0; j < n && rc == 0; j++) {
            const double t_to = j == n - 1 ? span_end : sp.t0 + h;
            /* the last piece differs from h by rounding at most: the same coefficients */
            const int same = fabs((t_to - sp.t0) - h) <= 4.0 * DBL_EPSILON * (fabs(t_to) + h);
            rc = fast_substep(e, m, &sp, R, g0, in, t_in, t_to, same ? substep_coefficients(R, h, t_to) : NULL, &r, x, t, 0);
            if (rc > 0) return rc;
            if (rc == 0 && j < n - 1) span_start(&sp, R, g0, *t, x, in, t_in);
        }
    }
    return 0;
}

/* ---- a segment at rest ---------------------------------------------------------------------------
 * With both rigid hinges closed (or the simply supported wall's closed) the wall stands still: only
 * the closed hinges' indicators vary, through the input. 1 - |f|/cap + eps_f with f affine in the
 * input, which is linear over a segment, is concave there: when it holds (> 0) at both ends it holds
 * throughout. Such a segment needs its end values alone. */
static int at_rest(const rw_engine *e, const rw_regime *m)
{
    return e->rigid && m->closed_b && (m->closed_m || e->P.support != RW_FLEXIBLE_TOP);
}

/* 1 when the segment to t_end holds every closed hinge (x and the carried point stay, with the
 * closed hinges' values at the end; their rates are taken again at the next segment's start,
 * carried_start), else 0: an end near or past zero, for the general test */
static int rest_holds(rw_engine *e, double t_end, const rw_linear_input *in, double t_in)
{
    const rw_input end = {in->ag + in->ag_slope * (t_end - t_in), in->u_top + in->u_slope * (t_end - t_in)};
    /* only the closed hinges' entries are written and read: z is zeroed because gcc cannot see that
     * (-Wmaybe-uninitialized) */
    double z[RW_NZ] = {0.0}, dz[RW_NZ];
    int k;
    if (closed_hinge_values(e, &end, NULL, e->carry.x, NULL, e->closed_mask, z, dz)) return 0;
    for (k = 0; k < RW_NZ; k++)
        if (((e->closed_mask >> k) & 1u) && !(e->b[k] && e->carry.z[k] > 0.0 && z[k] > 0.0)) return 0;
    for (k = 0; k < RW_NZ; k++)
        if ((e->closed_mask >> k) & 1u) e->carry.z[k] = z[k]; /* the next segment's start */
    return 1;
}

/* ---- a quiet segment: the common case without the general machinery --------------------------
 * Most input segments of a run hold no event: the region, its lines and the end point of the
 * segment before (rw_engine.carry) are known, one substep covers the segment (every mode turns by
 * at most RW_PHASE_PER_SUBSTEP), and the quick test clears every indicator. Such a segment is taken
 * here with the same evaluations as resolve() (so the same numbers), without its set-up; any other
 * segment is left untouched to rw_engine_advance. */
int rw_engine_quiet_segment(rw_engine *e, const rw_regime *m, double x[RW_NX], double *t, double t_end,
                            const rw_linear_input *in, double t_in)
{
    const double len = t_end - *t;
    rw_cache_entry *R;
    rw_span sp;
    rw_point b, buf;
    const rw_point *a;
    unsigned suspects;
    if (!e->region_valid || !e->carry_valid || e->b_stale || e->carry_t != *t) return 0;
    if (e->i_out < e->n_out && e->t_out[e->i_out] <= t_end) return 0;
    R = &e->cache[e->region];
    if (!one_substep_covers(e, R, len)) return 0;
    if (memcmp(e->carry.x, x, sizeof e->carry.x) != 0) return 0;
    if (at_rest(e, m) && rest_holds(e, t_end, in, t_in)) {
        e->steps++;
        *t = e->carry_t = t_end;
        return 1;
    }
    sp.aq = e->region_aq;
    span_start(&sp, R, e->region_g0, *t, x, in, t_in);
    a = carried_start(e, m, &sp, &buf);
    eval_point(e, m, &sp, len, substep_coefficients(R, len, t_end), &b);
    suspects = suspects_of(e, a->z, a->dz, b.z, b.dz, len);
    if (suspects) { /* its end point and suspects, for resolve() (rw_engine.pending) */
        e->pending = b;
        e->pending_t0 = *t;
        e->pending_suspects = suspects;
        e->pending_valid = 1;
        return 0;
    }
    e->steps++;
    peaks_on(e, m, &sp, e->carry.x, 0.0, b.x, len);
    memcpy(x, b.x, sizeof b.x);
    *t = t_end;
    carry_point(e, &b, t_end);
    return 1;
}

/* ---- the engine object ---------------------------------------------------------------------- */
int rw_engine_init(rw_engine *e, const rw_params *p, char *msg, size_t n)
{
    if (!e || !p) {
        snprintf(msg, n, "rw_engine_init: engine and parameters must not be NULL");
        return 1;
    }
    if (rw_params_validate(p, msg, n)) return 1;
    if (p->support == RW_PARAPET) {
        snprintf(msg, n, "the parapet (support = 1, Housner's nonlinear block) is not covered by the exact engine: use CVODE");
        return 1;
    }
    memset(e, 0, sizeof *e);
    e->P = *p;
    rw_derive(p, &e->D);
    e->law = rw_hinge_law_of(p->hingeLaw);
    e->rigid = rw_is_rigid(p);
    e->mid_is_bookkeeping = rw_mid_switch_is_bookkeeping(p);
    e->max_same_instant = 100;
    e->t_last_event = -INFINITY;
    e->floor_rate = rocking_rate(e);
    e->collapse_radius = INFINITY;
    {
        const double unit[2][RW_NX] = {{1.0, 0.0, 0.0, 0.0}, {0.0, 1.0, 0.0, 0.0}};
        int j;
        for (j = 0; j < 2; j++) {
            e->s_coef[0][j] = rw_s1(p, unit[j]);
            e->s_coef[1][j] = rw_s2(p, unit[j]);
        }
    }
    e->t_collapse = NAN;
    return 0;
}

rw_engine *rw_engine_new(const rw_params *p, char *msg, size_t n)
{
    rw_engine *e = (rw_engine *)calloc(1, sizeof *e);
    if (!e) {
        snprintf(msg, n, "out of memory");
        return NULL;
    }
    if (rw_engine_init(e, p, msg, n)) {
        free(e);
        return NULL;
    }
    return e;
}

void rw_engine_free(rw_engine *e)
{
    free(e);
}

/* Did the inputs jump at t (a new step's values) so that an indicator changed sign? Then the
 * model's event iteration at t, as cs_cvode.c does at a communication point. */
static int input_jump(rw_engine *e, rw_regime *m, double x[RW_NX], double t, const rw_input *now)
{
    double z[RW_NZ];
    int k;
    if (!e->b_valid) {
        set_indicator_states(e, m, now, x);
        e->b_valid = 1;
        return 0;
    }
    rw_event_indicators(&e->P, &e->D, m, now, x, z);
    for (k = 0; k < RW_NZ; k++)
        if ((z[k] > 0.0) != e->b[k]) return apply_event(e, m, x, t, now);
    return 0;
}

int rw_engine_step(rw_engine *e, rw_regime *m, double x[RW_NX], double t, double h, const rw_linear_input *in,
                   long *impacts, double *t_reached, char *msg, size_t n)
{
    const long before = e->impacts;
    rw_input now;
    int rc;
    /* the engine may be a byte copy restored from a serialized FMU state (fmi2SetFMUstate), made
     * by another process: its one reference into this binary, the law, is taken again */
    e->law = rw_hinge_law_of(e->P.hingeLaw);
    /* the caller owns x and m between steps */
    e->region_valid = e->region_keep = e->carry_valid = e->slow_carry_valid = e->pending_valid = 0;
    now.ag = in->ag;
    now.u_top = in->u_top;
    *t_reached = t;
    rc = input_jump(e, m, x, t, &now);
    if (rc == 0) rc = advance(e, m, x, t_reached, t + h, in, t);
    if (rc == 0 && e->mid_is_bookkeeping) rw_sync_mid_side(&e->P, &e->D, m, x); /* the `condition` it reports */
    if (rc == 0 && e->b_stale) { /* an event at the step's end: its states, for the next input_jump */
        rw_input end;
        end.ag = in->ag + in->ag_slope * (*t_reached - t);
        end.u_top = in->u_top + in->u_slope * (*t_reached - t);
        set_indicator_states(e, m, &end, x);
        e->b_stale = 0;
    }
    *impacts += e->impacts - before;
    if (rc > 1) snprintf(msg, n, "%s", e->msg);
    return rc;
}

/* ---- for the batch run (rw_engine_internal.h) ------------------------------------------------- */
/* The start of a run at t0 from the state x (the regime from it, the hosts' initial event iteration,
 * the collapse test): 0, 1 if collapsed, or an error code + 1. */
int rw_engine_begin(rw_engine *e, rw_regime *m, double x[RW_NX], double t0, const rw_input *in)
{
    memset(m, 0, sizeof *m);
    rw_init_regime(&e->P, &e->D, in, x, m, NULL, NULL);
    e->t_last_event = t0;
    e->same_instant = 0;
    e->events--; /* the initial iteration is not a located event */
    if (e->n_out > 0 && e->t_out[0] <= t0) record_output(e, x);
    track_peak(e, 0, rw_s1(&e->P, x));
    track_peak(e, 1, rw_s2(&e->P, x));
    return apply_event(e, m, x, t0, in);
}

int rw_engine_advance(rw_engine *e, rw_regime *m, double x[RW_NX], double *t, double t_end, const rw_linear_input *in,
                      double t_in)
{
    return advance(e, m, x, t, t_end, in, t_in);
}

void rw_engine_fill_outputs(rw_engine *e)
{
    while (e->i_out < e->n_out) { /* after a collapse or a Zeno stop: no values */
        const double nan4[RW_NX] = {NAN, NAN, NAN, NAN};
        record_output(e, nan4);
    }
}
