/* The exact motion along a span, inline in every file that evaluates it.
 * The Stumpff functions, the closed form of both modes from the span's start, and the points of a
 * span with their indicators: the engine's hottest arithmetic. */
#ifndef RW_ENGINE_SPAN_H
#define RW_ENGINE_SPAN_H

#include <math.h>
#include <string.h>

#include "rw_engine_internal.h"

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

static inline void stumpff(double z, double c[4])
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

/* the span of region R (modal forcing g0 of its constant terms) from the state x at t0, under the
 * input segment in (given at t_in) */
static inline void span_start(rw_span *sp, const rw_cache_entry *R, const double g0[2], double t0,
                              const double x[RW_NX], const rw_linear_input *in, double t_in)
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

/* the modal motion at s as changes from the span's start: deta = eta(s) - eta(0), dv = v(s) - v(0),
 * and the modal accelerations a */
typedef struct {
    double deta[2], dv[2], a[2];
} rw_modal;

/* Mode i's motion at s into md, with the Stumpff coefficients C of each mode at lam s^2 (NULL:
 * computed), as changes from the start (with c0 = 1 - z c2, free of cancellation). Written as
 * changes, the state at s = 0 is the start state itself, not its image through P Pi: an indicator
 * that set an event's state keeps its sign where the next span begins. slow_part leaves out the
 * mode's free oscillation: its exact particular solution (f0 + f1 s)/lam alone, the slow part of a
 * stiff mode. */
static inline void mode_motion(const rw_span *sp, int i, double s, const double C[2][4], int slow_part, rw_modal *md)
{
    double c[4];
    const double lam = sp->R->E.lam[i], eta0 = sp->eta[i], v0 = sp->v[i];
    const double f0 = sp->f0[i], f1 = sp->f1[i];
    if (slow_part) {
        md->deta[i] = (f0 + f1 * s) / lam - eta0;
        md->dv[i] = f1 / lam - v0;
        md->a[i] = 0.0;
        return;
    }
    if (C) memcpy(c, C[i], sizeof c);
    else stumpff(lam * s * s, c);
    md->deta[i] = s * (v0 * c[1] + s * ((f0 - lam * eta0) * c[2] + s * f1 * c[3]));
    md->dv[i] = s * ((f0 - lam * eta0) * c[1] + s * (f1 - lam * v0) * c[2]);
    md->a[i] = -lam * (eta0 + md->deta[i]) + f0 + f1 * s;
}

/* both modes at s (fast[i], fast may be NULL: mode i's slow part alone) */
static inline void span_modal(const rw_span *sp, double s, const double C[2][4], const int *fast, rw_modal *md)
{
    int i;
    for (i = 0; i < 2; i++) mode_motion(sp, i, s, C, fast && fast[i], md);
}

static inline void to_physical(const rw_span *sp, const rw_modal *md, double x[RW_NX])
{
    const rw_modes2 *E = &sp->R->E;
    const double *deta = md->deta, *dv = md->dv;
    x[0] = sp->x0[0] + (E->P[0][0] * deta[0] + E->P[0][1] * deta[1]);
    x[1] = sp->x0[1] + (E->P[1][0] * deta[0] + E->P[1][1] * deta[1]);
    x[2] = sp->x0[2] + (E->P[0][0] * dv[0] + E->P[0][1] * dv[1]);
    x[3] = sp->x0[3] + (E->P[1][0] * dv[0] + E->P[1][1] * dv[1]);
}

/* the state x and, if xd is not NULL, its time derivative from the modal motion */
static inline void modal_to_state(const rw_span *sp, const rw_modal *md, double x[RW_NX], double *xd)
{
    to_physical(sp, md, x);
    if (xd) {
        xd[0] = x[2];
        xd[1] = x[3];
        xd[2] = sp->R->E.P[0][0] * md->a[0] + sp->R->E.P[0][1] * md->a[1];
        xd[3] = sp->R->E.P[1][0] * md->a[0] + sp->R->E.P[1][1] * md->a[1];
    }
}

/* State x and its time derivative xd at t0 + s (span_eval_part: without the fast modes' free
 * oscillation). */
static inline void span_eval_part(const rw_span *sp, double s, const double C[2][4], const int *fast, double x[RW_NX],
                                  double xd[RW_NX])
{
    rw_modal md;
    span_modal(sp, s, C, fast, &md);
    modal_to_state(sp, &md, x, xd);
}

static inline void span_eval(const rw_span *sp, double s, const double C[2][4], double x[RW_NX], double xd[RW_NX])
{
    span_eval_part(sp, s, C, NULL, x, xd);
}

/* span_eval_part with the fast modes left out (x_slow, xd_slow) and the full state x_full at once:
 * the other modes' terms are the same in both */
static inline void span_eval_slow_and_full(const rw_span *sp, double s, const double C[2][4], const int fast[2],
                                           double x_slow[RW_NX], double xd_slow[RW_NX], double x_full[RW_NX])
{
    rw_modal md;
    int i;
    span_modal(sp, s, C, fast, &md);
    modal_to_state(sp, &md, x_slow, xd_slow);
    for (i = 0; i < 2; i++)
        if (fast[i]) mode_motion(sp, i, s, C, 0, &md);
    to_physical(sp, &md, x_full);
}

static inline rw_input span_input(const rw_span *sp, double s)
{
    rw_input in;
    in.ag = sp->ag0 + sp->ag1 * s;
    in.u_top = sp->u0 + sp->u1 * s;
    return in;
}

/* a new span of the same region from (t0, x) */
static inline void restart_span(rw_span_ctx *sc, double t0, const double x[RW_NX])
{
    span_start(&sc->sp, sc->R, sc->g0, t0, x, sc->in, sc->t_in);
}

static inline void eval_point(const rw_span_ctx *sc, double s, const double C[2][4], rw_point *pt)
{
    double xd[RW_NX];
    rw_input in = span_input(&sc->sp, s);
    pt->s = s;
    span_eval(&sc->sp, s, C, pt->x, xd);
    rwe_region_indicators(sc, &in, pt->x, xd, RW_Z_ALL, pt->z, pt->dz);
}

/* The values and rates of the indicators of `mask` at the state x of the span's motion at s, for
 * the indicators that are lines, the toppling indicator, the collapse form and the closed hinges'
 * form: their rates need the rotations' rates alone (x[2], x[3]), not a propagation to s. */
static inline void point_from_state(const rw_span_ctx *sc, const double x[RW_NX], double s, unsigned mask, rw_point *pt)
{
    const double xd[RW_NX] = {x[2], x[3], 0.0, 0.0};
    const rw_input in = span_input(&sc->sp, s);
    pt->s = s;
    if (pt->x != x) memcpy(pt->x, x, sizeof pt->x);
    rwe_region_indicators(sc, &in, pt->x, xd, mask, pt->z, pt->dz);
}

/* The carried end point (rw_engine.carry) as the start point of the span sp, which starts at its
 * time and state: the closed hinges' indicators are taken again at the span's input (in *buf), since
 * their rates follow the input's; the other indicators depend on the state and the rotations'
 * rates alone. */
static inline const rw_point *carried_with_closed_hinges(const rw_span_ctx *sc, rw_point *buf)
{
    *buf = sc->e->carry;
    point_from_state(sc, buf->x, 0.0, sc->e->closed_mask, buf);
    return buf;
}

static inline const rw_point *carried_start(const rw_span_ctx *sc, rw_point *buf)
{
    return sc->e->closed_mask ? carried_with_closed_hinges(sc, buf) : &sc->e->carry;
}

static inline void carry_point(rw_engine *e, const rw_point *pb, double t)
{
    e->carry_valid = 1;
    e->carry_t = t;
    e->carry = *pb;
    e->carry.s = 0.0;
}

#endif
