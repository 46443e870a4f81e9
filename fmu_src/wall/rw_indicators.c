/* RockingWall event indicators: the indicators of docs/model.md (hinge crossings, breakpoints of
 * the hinge law, closed rigid hinges' margins, collapse and toppling), as values, as lines of the
 * rotations for the exact engine, and with their rates along a motion; the collapse test. */
#include "rw_physics.h"

#include <math.h>
#include <string.h>

static double sgn(double v) { return (v > 0.0) - (v < 0.0); }

static const rw_hinge_law *law(const rw_params *p)
{
    return rw_hinge_law_of(p->hingeLaw);
}

/* Sides from the signs of the rotations themselves (the tracked side where a rotation is 0), so
 * that for the rigid law -q.Q = cap_b(sign q1)|q1| + cap_m(sign x)|x| >= 0 (docs/model.md "Collapse"). */
static int side_of(double z, int tracked)
{
    return z > 0.0 ? 1 : (z < 0.0 ? -1 : tracked);
}

double rw_collapse_G_of(const rw_derived *d, const double x[RW_NX], const double Q[2])
{
    const double q1 = x[0], q2 = x[1];
    const double Kq1 = d->K[0][0] * q1 + d->K[0][1] * q2, Kq2 = d->K[1][0] * q1 + d->K[1][1] * q2;
    return q1 * Kq1 + q2 * Kq2 - (q1 * Q[0] + q2 * Q[1]);
}

/* The hinge moments the collapse test takes at x: the sides from the rotations themselves */
static void collapse_moments(const rw_params *p, const rw_derived *d, const rw_regime *m, const double x[RW_NX],
                             double Q[2], double J[2][2])
{
    law(p)->moments(d, side_of(x[0], m->side_b), side_of(x[1] - x[0], m->side_m), x, x + 2, Q, J);
}

double rw_collapse_G(const rw_params *p, const rw_derived *d, const rw_regime *m, const rw_input *in,
                     const double x[RW_NX])
{
    double Q[2], J[2][2];
    (void)in; /* the spring counts as if the diaphragm held still (docs/model.md "Collapse") */
    collapse_moments(p, d, m, x, Q, J);
    return rw_collapse_G_of(d, x, Q);
}

void rw_event_indicators(const rw_params *p, const rw_derived *d, const rw_regime *m, const rw_input *in,
                         const double x[RW_NX], double z[RW_NZ])
{
    int i;
    for (i = 0; i < RW_NZ; i++) z[i] = 1.0;
    rw_event_indicators_some(p, d, m, in, x, NULL, RW_Z_ALL, z);
}

static int wanted(unsigned mask, int k)
{
    return (mask >> k) & 1u;
}

/* Where an indicator's rate is wanted (rw_event_indicator_rates): the motion and the rates out */
typedef struct {
    const rw_input *in_rate;
    const double *xd;
    const double (*J)[2]; /* dQ/dq at x (NULL: from the law) */
    double *dz;
} rw_rate_request;

/* 1 - |f|/cap + eps of a closed rigid hinge and its rate: f is affine in the inputs and one
 * rotation (rw_closed_forces), so its rate is the difference over any step along the motion */
static void closed_indicators(const rw_params *p, const rw_derived *d, const rw_regime *m, const rw_input *in,
                              const double x[RW_NX], double cb, double cm, double z[2], const rw_rate_request *r,
                              double dz[2])
{
    double f_b, f_m;
    rw_closed_forces(p, d, m, in, x, &f_b, &f_m);
    z[0] = 1.0 - fabs(f_b) / cb + RW_EPS_F;
    z[1] = 1.0 - fabs(f_m) / cm + RW_EPS_F;
    if (r) {
        const rw_input in1 = {in->ag + r->in_rate->ag, in->u_top + r->in_rate->u_top};
        const double x1[RW_NX] = {x[0] + r->xd[0], x[1] + r->xd[1], x[2] + r->xd[2], x[3] + r->xd[3]};
        double g_b, g_m;
        rw_closed_forces(p, d, m, &in1, x1, &g_b, &g_m);
        dz[0] = -sgn(f_b) * (g_b - f_b) / cb;
        dz[1] = -sgn(f_m) * (g_m - f_m) / cm;
    }
}

void rw_indicator_lines(const rw_params *p, const rw_derived *d, const rw_regime *m, rw_indicator_line L[RW_NZ])
{
    /* Hinge indicators carry a small offset so that none is exactly zero when integration restarts
     * after the event that set the regime (CVODE ignores a root function that starts at zero):
     * open: side*rotation + eps_q, root just past zero (|rotation| < tiny, so the direction of
     * motion decides in rw_event_update); closed: margin + eps_f, root just past |f| = cap. */
    const rw_indicator_line unused = {{0.0, 0.0}, 0.0, 0.0, 1.0, 0}, none = {{0.0, 0.0}, 0.0, 0.0, 0.0, 1};
    const double eps_q = RW_EPS_Q(d);
    const int rigid = rw_is_rigid(p);
    int k;
    for (k = 0; k < RW_NZ; k++) L[k] = unused;
    if (rigid && m->closed_b) {
        L[RW_Z_BASE] = none;
    } else {
        const rw_indicator_line base = {{m->side_b, 0.0}, 0.0, 1.0, fmax(eps_q, m->zoff_b), 0};
        L[RW_Z_BASE] = base;
    }
    if (p->support == RW_FLEXIBLE_TOP) {
        const rw_indicator_line mid = {{-m->side_m, m->side_m}, 0.0, 1.0, fmax(eps_q, m->zoff_m), 0};
        L[RW_Z_MID] = rigid && m->closed_m ? none : mid;
        memcpy(L + RW_Z_BREAK, d->breaks, sizeof d->breaks); /* the law's kinks of Q(q) */
        L[RW_Z_TOPPLE] = none;
    } else if (p->support == RW_SIMPLY_SUPPORTED && !rigid) {
        /* |D| = Delta_1, Delta_2 of the direction of D, in the rotation q1 = 2D/h */
        const rw_direction *pos = &d->dir[RW_SIDE(1)], *neg = &d->dir[RW_SIDE(-1)];
        L[RW_Z_BREAK] = rw_kink_line(1.0, 0.0, 2.0 * pos->D1 / p->h, 2.0 * neg->D1 / p->h);
        L[RW_Z_BREAK + 1] = rw_kink_line(1.0, 0.0, 2.0 * pos->D2 / p->h, 2.0 * neg->D2 / p->h);
    }
    L[RW_Z_COLLAPSE] = none;
}

unsigned rw_closed_hinge_mask(const rw_params *p, const rw_regime *m)
{
    if (!rw_is_rigid(p)) return 0u;
    return (m->closed_b ? 1u << RW_Z_BASE : 0u) | (p->support == RW_FLEXIBLE_TOP && m->closed_m ? 1u << RW_Z_MID : 0u);
}

/* the indicators of closed rigid hinges (1 - |f|/cap + eps_f, rw_indicator_lines) */
static void closed_hinge_indicators(const rw_params *p, const rw_derived *d, const rw_regime *m, const rw_input *in,
                                    const double x[RW_NX], unsigned mask, double z[RW_NZ], const rw_rate_request *r)
{
    double cb, cm, zc[2], dzc[2];
    rw_caps(p, d, &cb, &cm);
    closed_indicators(p, d, m, in, x, cb, cm, zc, r, dzc);
    if (m->closed_b && wanted(mask, RW_Z_BASE)) {
        z[RW_Z_BASE] = zc[0];
        if (r) r->dz[RW_Z_BASE] = dzc[0];
    }
    if (p->support == RW_FLEXIBLE_TOP && m->closed_m && wanted(mask, RW_Z_MID)) {
        z[RW_Z_MID] = zc[1];
        if (r) r->dz[RW_Z_MID] = dzc[1];
    }
}

void rw_collapse_form_of(const rw_derived *d, const double c[2], const double J[2][2], rw_collapse_form *f)
{
    int i, j;
    for (i = 0; i < 2; i++) {
        f->c[i] = c[i];
        for (j = 0; j < 2; j++) f->A[i][j] = d->K[i][j] - J[i][j];
    }
    f->zscale = d->zscale;
    f->inv_zscale = 1.0 / d->zscale;
}

/* G(q)/|q|^2/zscale of the 2DOF, clipped, from the hinge moments Q at x (NULL: the law's), and its
 * rate (rw_collapse_form) */
static double collapse_2dof(const rw_params *p, const rw_derived *d, const rw_regime *m, const double x[RW_NX],
                            const double *Q, const rw_rate_request *r, double *dz)
{
    const double q1 = x[0], q2 = x[1], n2 = q1 * q1 + q2 * q2;
    double Ql[2], J[2][2], v;
    const double *Qx = Q;
    const double (*Jx)[2] = r ? r->J : NULL;
    if (dz) *dz = 0.0;
    if (!(n2 > 0.0)) return RW_COLLAPSE_ZMAX; /* +large near q = 0 for rigid hinges */
    if (!Qx) {
        collapse_moments(p, d, m, x, Ql, J);
        Qx = Ql;
        Jx = (const double(*)[2])J;
    }
    v = rw_collapse_G_of(d, x, Qx) / n2 / d->zscale;
    if (v > RW_COLLAPSE_ZMAX) return RW_COLLAPSE_ZMAX;
    if (r) { /* the rate of the form of the region through x */
        const double c[2] = {Qx[0] - Jx[0][0] * q1 - Jx[0][1] * q2, Qx[1] - Jx[1][0] * q1 - Jx[1][1] * q2};
        rw_collapse_form f;
        rw_collapse_form_of(d, c, Jx, &f);
        rw_collapse_form_value(&f, x, r->xd, dz);
    }
    return v;
}

/* the collapse indicator (Q: the hinge moments at x, NULL = from the law) */
static double collapse_indicator(const rw_params *p, const rw_derived *d, const rw_regime *m, const double x[RW_NX],
                                 const double *Q, const rw_rate_request *r)
{
    double *dz = r ? &r->dz[RW_Z_COLLAPSE] : NULL;
    if (p->support == RW_PARAPET) {
        if (dz) *dz = -sgn(x[0]) * (r->xd[0]) / d->alpha;
        return 1.0 - fabs(x[0]) / d->alpha;
    }
    if (p->support == RW_SIMPLY_SUPPORTED) { /* Delta_u of the direction of D */
        const double Du = d->dir[RW_SIDE(x[0])].Du;
        if (dz) *dz = -sgn(x[0]) * r->xd[0] * p->h / 2.0 / Du;
        return 1.0 - fabs(x[0] * p->h / 2.0) / Du;
    }
    return collapse_2dof(p, d, m, x, Q, r, dz);
}

static void indicators_of(const rw_params *p, const rw_derived *d, const rw_regime *m, const rw_input *in,
                          const double x[RW_NX], const double *Q, unsigned mask, double z[RW_NZ],
                          const rw_rate_request *r)
{
    const unsigned never_lines = (1u << RW_Z_COLLAPSE) | (1u << RW_Z_TOPPLE);
    const unsigned closed_mask = rw_closed_hinge_mask(p, m);
    if (mask & ~never_lines & ~closed_mask) { /* a closed hinge's indicator is no line */
        rw_indicator_line L[RW_NZ];
        int k;
        rw_indicator_lines(p, d, m, L);
        for (k = 0; k < RW_NZ; k++)
            if (wanted(mask, k) && !L[k].none)
                z[k] = rw_line_value(&L[k], x, r ? r->xd : NULL, r ? &r->dz[k] : NULL);
    }
    if (mask & closed_mask) closed_hinge_indicators(p, d, m, in, x, mask, z, r);
    if (p->support == RW_FLEXIBLE_TOP && wanted(mask, RW_Z_TOPPLE)) z[RW_Z_TOPPLE] = rw_topple_value(d, x, r ? r->xd : NULL, r ? &r->dz[RW_Z_TOPPLE] : NULL);
    if (wanted(mask, RW_Z_COLLAPSE)) z[RW_Z_COLLAPSE] = collapse_indicator(p, d, m, x, Q, r);
}

void rw_event_indicators_some(const rw_params *p, const rw_derived *d, const rw_regime *m, const rw_input *in,
                              const double x[RW_NX], const double *Q, unsigned mask, double z[RW_NZ])
{
    indicators_of(p, d, m, in, x, Q, mask, z, NULL);
}

void rw_event_indicator_rates(const rw_params *p, const rw_derived *d, const rw_regime *m, const rw_input *in,
                              const rw_input *in_rate, const double x[RW_NX], const double xd[RW_NX],
                              const double *Q, const double (*J)[2], unsigned mask, double z[RW_NZ],
                              double dz[RW_NZ])
{
    const rw_rate_request r = {in_rate, xd, J, dz};
    indicators_of(p, d, m, in, x, Q, mask, z, &r);
}

int rw_collapse_reason(const rw_params *p, const rw_derived *d, const rw_regime *m, const rw_input *in,
                       const double x[RW_NX])
{
    int past;
    if (p->support == RW_PARAPET) return fabs(x[0]) >= d->alpha ? RW_PAST_INSTABILITY : RW_STANDING;
    if (p->support == RW_SIMPLY_SUPPORTED)
        return fabs(x[0] * p->h / 2.0) >= d->dir[RW_SIDE(x[0])].Du ? RW_PAST_INSTABILITY : RW_STANDING;
    past = !law(p)->elastic(d, x, x + 2) && rw_collapse_G(p, d, m, in, x) <= 0.0;
    if (past) return RW_PAST_INSTABILITY;
    /* a guard on states the linearised model cannot describe (an importer's unstable integrator
     * may reach them): no body turns past the point where its weight passes over its pivot */
    return rw_topple_value(d, x, NULL, NULL) <= 0.0 ? RW_PAST_TOPPLING_LIMIT : RW_STANDING;
}
