/* RockingWall physics: parameters, derived quantities and the equations of motion.
 * Equation numbers "Eq. 3.x" are the paper's; the contract is docs/model.md.
 * Discrete mode logic (impacts, switches, rigid rest / closed-hinge states) is in rw_modes.c. */
#include "rw_physics.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static double sgn(double v) { return (v > 0.0) - (v < 0.0); }

/* ---- parameters ---------------------------------------------------------------------------- */

int rw_params_validate(const rw_params *p, char *msg, size_t n)
{
    size_t i;
    rw_derived d;
    for (i = 0; i < RW_NUMBER_OF_PARAMETERS; i++)
        if (rw_param_check(&RW_PARAM_INFO[i], rw_param_get(p, &RW_PARAM_INFO[i]), msg, n)) return 1;
    if (!(p->b < p->h)) {
        snprintf(msg, n, "invalid parameter b = %g: must be < h = %g", p->b, p->h);
        return 1;
    }
    rw_derive(p, &d);
    if (!(d.D1 < d.D2 && d.D2 < d.Du)) {
        snprintf(msg, n,
                 "invalid parameters delta1Ratio = %g, delta2A = %g, delta2B = %g: need Delta_1 < Delta_2 < Delta_u "
                 "(Delta_1 = %g, Delta_2 = %g, Delta_u = %g)",
                 p->delta1Ratio, p->delta2A, p->delta2B, d.D1, d.D2, d.Du);
        return 1;
    }
    if (!(p->hingeSat * d.D1 < d.Du)) {
        snprintf(msg, n,
                 "invalid parameters hingeSat = %g, delta1Ratio = %g: the hinges would saturate at hingeSat*Delta_1 = %g m, "
                 "beyond Delta_u = %g m (need hingeSat*delta1Ratio < 1)",
                 p->hingeSat, p->delta1Ratio, p->hingeSat * d.D1, d.Du);
        return 1;
    }
    return 0;
}

static const rw_hinge_law *law(const rw_params *p)
{
    return rw_hinge_law_of(p->hingeLaw);
}

void rw_derive(const rw_params *p, rw_derived *d)
{
    const double h = p->h, b = p->b, g = p->g, Kd = p->Kd;
    const double hg = h * h / g;
    memset(d, 0, sizeof *d);
    d->h = h;
    d->W1 = p->W / 2.0;
    d->Wd = p->psi * d->W1;
    /* Table 5.1 (Doherty) */
    d->Du = b * (1.0 + 0.75 * p->psi) / (1.0 + p->psi);
    d->Fr = (2.0 * b / h) * p->W * (1.0 + 0.75 * p->psi);
    d->F0 = 2.0 * d->Fr;
    d->Rel = 0.75 * d->F0;
    /* Eq. 5.1, 5.2 */
    d->D1 = p->delta1Ratio * d->Du;
    d->D2 = p->delta2A * d->D1 + p->delta2B * d->Du;
    d->Fi = d->Fr * (1.0 - d->D2 / d->Du);
    d->theta_y = 2.0 * p->hingeSat * d->D1 / h;
    d->cap_b = (2.0 * d->W1 + d->Wd) * b / 2.0;
    d->cap_m = (d->W1 + d->Wd) * b / 2.0;
    /* Eq. 3.2 mass matrix */
    d->M[0][0] = (d->W1 / 3.0 + d->Wd / 4.0) * hg;
    d->M[0][1] = d->M[1][0] = (d->W1 / 8.0 + d->Wd / 4.0) * hg;
    d->M[1][1] = (d->W1 / 12.0 + d->Wd / 4.0) * hg;
    /* Eq. 3.3 stiffness matrix (spring minus gravity) */
    d->K[0][0] = Kd * h * h / 4.0 - 0.75 * d->W1 * h - d->Wd * h / 2.0;
    d->K[0][1] = d->K[1][0] = Kd * h * h / 4.0;
    d->K[1][1] = Kd * h * h / 4.0 - d->W1 * h / 4.0 - d->Wd * h / 2.0;
    /* Eq. 3.4 with ag positive toward +x (opposite sign to the paper's p'_eff) */
    d->pa[0] = -(3.0 * d->W1 + 2.0 * d->Wd) * h / (4.0 * g);
    d->pa[1] = -(d->W1 + 2.0 * d->Wd) * h / (4.0 * g);
    d->fu = Kd * h / 2.0;
    /* Housner block */
    d->Bp = b / 2.0;
    d->Hp = h / 2.0;
    d->R = sqrt(d->Bp * d->Bp + d->Hp * d->Hp);
    d->alpha = atan2(d->Bp, d->Hp);
    d->p2 = 3.0 * g / (4.0 * d->R);
    d->zscale = p->W * h;
    d->q_topple = 2.0 * b / h;
    d->inv_q_topple = 1.0 / d->q_topple;
    d->tiny = 1e-10 * b / h;
    law(p)->breakpoints(d, d->breaks);
}

int rw_is_rigid(const rw_params *p)
{
    return p->support == RW_PARAPET || law(p)->set_valued;
}

int rw_mid_switch_is_bookkeeping(const rw_params *p)
{
    return p->support == RW_FLEXIBLE_TOP && law(p)->q_only;
}

/* ---- forces -------------------------------------------------------------------------------- */

/* Q(q) of the open hinges, from the law (docs/model.md "Hinge laws"). */
void rw_hinge_Q(const rw_params *p, const rw_derived *d, const rw_mode *m, const double x[RW_NX], double Q[2])
{
    double J[2][2];
    law(p)->moments(d, m->side_b, m->side_m, x, x + 2, Q, J);
}

/* Doherty's 1DOF resisting force F(D) (Fig. 5.2). */
double rw_force_1dof(const rw_params *p, const rw_derived *d, const rw_mode *m, double D)
{
    const double a = fabs(D);
    double f;
    if (law(p)->set_valued) /* rigid line, sign from the active side (linear through 0) */
        return -d->Fr * m->side_b + d->Fr * D / d->Du;
    if (a <= d->D1) f = d->Fi * a / d->D1;
    else if (a <= d->D2) f = d->Fi;
    else f = d->Fr * (1.0 - a / d->Du);
    return -sgn(D) * f;
}

static void solve2(const double M[2][2], const double r[2], double a[2])
{
    const double det = M[0][0] * M[1][1] - M[0][1] * M[1][0];
    a[0] = (M[1][1] * r[0] - M[0][1] * r[1]) / det;
    a[1] = (M[0][0] * r[1] - M[1][0] * r[0]) / det;
}

/* F = p(ag) + f_u(u_top) */
static void load(const rw_derived *d, const rw_input *in, double F[2])
{
    F[0] = d->pa[0] * in->ag + d->fu * in->u_top;
    F[1] = d->pa[1] * in->ag + d->fu * in->u_top;
}

/* Base closed, mid open: q2'' from row 2 alone. */
static double q2dd_base_closed(const rw_derived *d, const rw_mode *m, const double F[2], double q2)
{
    return (F[1] - d->K[1][1] * q2 - d->cap_m * m->side_m) / d->M[1][1];
}

/* Mid closed, base open: q1 = q2 = theta moving together. */
static double thdd_mid_closed(const rw_derived *d, const rw_mode *m, const double F[2], double th)
{
    const double mt = d->M[0][0] + 2.0 * d->M[0][1] + d->M[1][1];
    const double kt = d->K[0][0] + 2.0 * d->K[0][1] + d->K[1][1];
    return (F[0] + F[1] - kt * th - d->cap_b * m->side_b) / mt;
}

void rw_derivatives(const rw_params *p, const rw_derived *d, const rw_mode *m, const rw_input *in,
                    const double x[RW_NX], double dx[RW_NX])
{
    dx[0] = x[2];
    dx[1] = x[3];
    dx[2] = dx[3] = 0.0;
    switch (p->support) {
    case RW_PARAPET: { /* Housner: theta'' = -p^2 [sin(s a - theta) + (ag/g) cos(s a - theta)] */
        const double th = x[0], s = m->side_b;
        double a;
        if (m->closed_b) { dx[0] = dx[1] = 0.0; return; }
        a = -d->p2 * (sin(s * d->alpha - th) + in->ag / p->g * cos(s * d->alpha - th));
        dx[1] = x[2];
        dx[2] = dx[3] = a;
        return;
    }
    case RW_SIMPLY_SUPPORTED: { /* (W/3g) D'' = -(W/2g) ag + F(D), D = q1 h/2, q2 = -q1 */
        const double D = x[0] * p->h / 2.0;
        double Ddd, a;
        if (m->closed_b) { dx[0] = dx[1] = 0.0; return; }
        Ddd = -1.5 * in->ag + 3.0 * p->g / p->W * rw_force_1dof(p, d, m, D);
        a = 2.0 * Ddd / p->h;
        dx[1] = -x[2];
        dx[2] = a;
        dx[3] = -a;
        return;
    }
    default: { /* flexibleTop, Eq. 3.1: M q'' + K q = p + f_u + Q(q) */
        double F[2], Q[2], r[2], a[2];
        load(d, in, F);
        if (rw_is_rigid(p) && (m->closed_b || m->closed_m)) {
            if (m->closed_b && m->closed_m) {
                dx[0] = dx[1] = 0.0;
            } else if (m->closed_b) {
                dx[0] = 0.0;
                dx[3] = q2dd_base_closed(d, m, F, x[1]);
            } else {
                dx[1] = x[2]; /* q2 follows q1 */
                dx[2] = dx[3] = thdd_mid_closed(d, m, F, x[0]);
            }
            return;
        }
        rw_hinge_Q(p, d, m, x, Q);
        r[0] = F[0] - d->K[0][0] * x[0] - d->K[0][1] * x[1] + Q[0];
        r[1] = F[1] - d->K[1][0] * x[0] - d->K[1][1] * x[1] + Q[1];
        solve2(d->M, r, a);
        dx[2] = a[0];
        dx[3] = a[1];
        return;
    }
    }
}

/* Generalised moment a closed hinge must resist (reaction = -f), spec "Opening tendency".
 * Parapet: f_b = -ag (cap g tan(alpha)); simplySupported: f_b = -W ag/(2g) (cap F_r). */
void rw_closed_forces(const rw_params *p, const rw_derived *d, const rw_mode *m, const rw_input *in,
                      const double x[RW_NX], double *f_b, double *f_m)
{
    double F[2];
    *f_b = *f_m = 0.0;
    if (p->support == RW_PARAPET) { *f_b = -in->ag; return; }
    if (p->support == RW_SIMPLY_SUPPORTED) { *f_b = -p->W * in->ag / (2.0 * p->g); return; }
    load(d, in, F);
    if (m->closed_b && m->closed_m) {
        *f_b = F[0] + F[1];
        *f_m = F[1];
    } else if (m->closed_b) {
        const double q2dd = q2dd_base_closed(d, m, F, x[1]);
        *f_b = F[0] - d->K[0][1] * x[1] + d->cap_m * m->side_m - d->M[0][1] * q2dd;
    } else if (m->closed_m) {
        const double th = x[0], thdd = thdd_mid_closed(d, m, F, th);
        *f_m = F[1] - (d->K[0][1] + d->K[1][1]) * th - (d->M[0][1] + d->M[1][1]) * thdd;
    }
}

/* rw_closed_forces is affine in the rotations and the inputs under one mode: its coefficients are
 * its differences over unit steps of each, so that the engine's values are this function's */
void rw_closed_force_form(const rw_params *p, const rw_derived *d, const rw_mode *m, rw_closed_form *f)
{
    const double x0[RW_NX] = {0.0, 0.0, 0.0, 0.0}, x1[RW_NX] = {1.0, 0.0, 0.0, 0.0}, x2[RW_NX] = {0.0, 1.0, 0.0, 0.0};
    const rw_input none = {0.0, 0.0}, ag = {1.0, 0.0}, u = {0.0, 1.0};
    double cb, cm, b, mid;
    rw_closed_forces(p, d, m, &none, x0, &f->c[0], &f->c[1]);
    rw_closed_forces(p, d, m, &none, x1, &b, &mid);
    f->G[0][0] = b - f->c[0], f->G[1][0] = mid - f->c[1];
    rw_closed_forces(p, d, m, &none, x2, &b, &mid);
    f->G[0][1] = b - f->c[0], f->G[1][1] = mid - f->c[1];
    rw_closed_forces(p, d, m, &ag, x0, &b, &mid);
    f->g_ag[0] = b - f->c[0], f->g_ag[1] = mid - f->c[1];
    rw_closed_forces(p, d, m, &u, x0, &b, &mid);
    f->g_u[0] = b - f->c[0], f->g_u[1] = mid - f->c[1];
    rw_caps(p, d, &cb, &cm);
    f->inv_cap[0] = 1.0 / cb;
    f->inv_cap[1] = 1.0 / cm;
}

/* capacities matching rw_closed_forces */
void rw_caps(const rw_params *p, const rw_derived *d, double *cb, double *cm)
{
    if (p->support == RW_PARAPET) { *cb = p->g * tan(d->alpha); *cm = 1.0; }
    else if (p->support == RW_SIMPLY_SUPPORTED) { *cb = d->Fr; *cm = 1.0; }
    else { *cb = d->cap_b; *cm = d->cap_m; }
}

/* Sides from the signs of the rotations themselves (the tracked side where a rotation is 0), so
 * that for the rigid law -q.Q = cap_b|q1| + cap_m|x| >= 0 (docs/model.md "Collapse"). */
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
static void collapse_moments(const rw_params *p, const rw_derived *d, const rw_mode *m, const double x[RW_NX],
                             double Q[2], double J[2][2])
{
    law(p)->moments(d, side_of(x[0], m->side_b), side_of(x[1] - x[0], m->side_m), x, x + 2, Q, J);
}

double rw_collapse_G(const rw_params *p, const rw_derived *d, const rw_mode *m, const rw_input *in,
                     const double x[RW_NX])
{
    double Q[2], J[2][2];
    (void)in; /* the spring counts as if the diaphragm held still (docs/model.md "Collapse") */
    collapse_moments(p, d, m, x, Q, J);
    return rw_collapse_G_of(d, x, Q);
}

void rw_event_indicators(const rw_params *p, const rw_derived *d, const rw_mode *m, const rw_input *in,
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
static void closed_indicators(const rw_params *p, const rw_derived *d, const rw_mode *m, const rw_input *in,
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

void rw_indicator_lines(const rw_params *p, const rw_derived *d, const rw_mode *m, rw_indicator_line L[RW_NZ])
{
    /* Hinge indicators carry a small offset so that none is exactly zero when integration restarts
     * after the event that set the mode (CVODE ignores a root function that starts at zero):
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
        const rw_indicator_line d1 = {{1.0, 0.0}, 1.0, 0.0, -2.0 * d->D1 / p->h, 0};
        const rw_indicator_line d2 = {{1.0, 0.0}, 1.0, 0.0, -2.0 * d->D2 / p->h, 0};
        L[RW_Z_BREAK] = d1;
        L[RW_Z_BREAK + 1] = d2;
    }
    L[RW_Z_COLLAPSE] = none;
}

unsigned rw_closed_hinge_mask(const rw_params *p, const rw_mode *m)
{
    if (!rw_is_rigid(p)) return 0u;
    return (m->closed_b ? 1u << RW_Z_BASE : 0u) | (p->support == RW_FLEXIBLE_TOP && m->closed_m ? 1u << RW_Z_MID : 0u);
}

/* the indicators of closed rigid hinges (1 - |f|/cap + eps_f, rw_indicator_lines) */
static void closed_hinge_indicators(const rw_params *p, const rw_derived *d, const rw_mode *m, const rw_input *in,
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
static double collapse_2dof(const rw_params *p, const rw_derived *d, const rw_mode *m, const double x[RW_NX],
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
static double collapse_indicator(const rw_params *p, const rw_derived *d, const rw_mode *m, const double x[RW_NX],
                                 const double *Q, const rw_rate_request *r)
{
    double *dz = r ? &r->dz[RW_Z_COLLAPSE] : NULL;
    if (p->support == RW_PARAPET) {
        if (dz) *dz = -sgn(x[0]) * (r->xd[0]) / d->alpha;
        return 1.0 - fabs(x[0]) / d->alpha;
    }
    if (p->support == RW_SIMPLY_SUPPORTED) {
        if (dz) *dz = -sgn(x[0]) * r->xd[0] * p->h / 2.0 / d->Du;
        return 1.0 - fabs(x[0] * p->h / 2.0) / d->Du;
    }
    return collapse_2dof(p, d, m, x, Q, r, dz);
}

static void indicators_of(const rw_params *p, const rw_derived *d, const rw_mode *m, const rw_input *in,
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

void rw_event_indicators_some(const rw_params *p, const rw_derived *d, const rw_mode *m, const rw_input *in,
                              const double x[RW_NX], const double *Q, unsigned mask, double z[RW_NZ])
{
    indicators_of(p, d, m, in, x, Q, mask, z, NULL);
}

void rw_event_indicator_rates(const rw_params *p, const rw_derived *d, const rw_mode *m, const rw_input *in,
                              const rw_input *in_rate, const double x[RW_NX], const double xd[RW_NX],
                              const double *Q, const double (*J)[2], unsigned mask, double z[RW_NZ],
                              double dz[RW_NZ])
{
    const rw_rate_request r = {in_rate, xd, J, dz};
    indicators_of(p, d, m, in, x, Q, mask, z, &r);
}

int rw_collapse_reason(const rw_params *p, const rw_derived *d, const rw_mode *m, const rw_input *in,
                       const double x[RW_NX])
{
    int past;
    if (p->support == RW_PARAPET) return fabs(x[0]) >= d->alpha ? RW_PAST_INSTABILITY : RW_STANDING;
    if (p->support == RW_SIMPLY_SUPPORTED)
        return fabs(x[0] * p->h / 2.0) >= d->Du ? RW_PAST_INSTABILITY : RW_STANDING;
    past = !law(p)->elastic(d, x, x + 2) && rw_collapse_G(p, d, m, in, x) <= 0.0;
    if (past) return RW_PAST_INSTABILITY;
    /* a guard on states the linearised model cannot describe (an importer's unstable integrator
     * may reach them): no body turns past the point where its weight passes over its pivot */
    return rw_topple_value(d, x, NULL, NULL) <= 0.0 ? RW_PAST_TOPPLING_LIMIT : RW_STANDING;
}

double rw_energy(const rw_params *p, const rw_derived *d, const rw_mode *m, const rw_input *in,
                 const double x[RW_NX])
{
    const double q1 = x[0], q2 = x[1], v1 = x[2], v2 = x[3];
    switch (p->support) {
    case RW_PARAPET: {
        const double s = m->closed_b ? 1.0 : m->side_b;
        return 0.5 * (4.0 / 3.0) * (p->W / p->g) * d->R * d->R * v1 * v1 +
               p->W * d->R * (cos(s * d->alpha - q1) - cos(d->alpha));
    }
    case RW_SIMPLY_SUPPORTED: {
        const double D = fabs(q1 * p->h / 2.0), dD = v1 * p->h / 2.0;
        double V;
        if (law(p)->set_valued) V = d->Fr * (D - D * D / (2.0 * d->Du));
        else if (D <= d->D1) V = d->Fi * D * D / (2.0 * d->D1);
        else if (D <= d->D2) V = d->Fi * d->D1 / 2.0 + d->Fi * (D - d->D1);
        else V = d->Fi * d->D1 / 2.0 + d->Fi * (d->D2 - d->D1) +
                 d->Fr * ((D - d->D2) - (D * D - d->D2 * d->D2) / (2.0 * d->Du));
        return 0.5 * p->W / (3.0 * p->g) * dD * dD + V;
    }
    default: {
        const double T = 0.5 * (d->M[0][0] * v1 * v1 + 2.0 * d->M[0][1] * v1 * v2 + d->M[1][1] * v2 * v2);
        const double U = 0.5 * (d->K[0][0] * q1 * q1 + 2.0 * d->K[0][1] * q1 * q2 + d->K[1][1] * q2 * q2) -
                         d->fu * in->u_top * (q1 + q2) + 0.5 * p->Kd * in->u_top * in->u_top;
        return T + U + law(p)->potential(d, x);
    }
    }
}

/* Power of the ground motion on the wall, the rate of work of the inertia load -m ag in the frame
 * of the ground: dE/dt = P_ground - F_top du_top/dt between impacts (E = rw_energy). */
double rw_ground_power(const rw_params *p, const rw_derived *d, const rw_mode *m, const rw_input *in,
                       const double x[RW_NX])
{
    if (m->closed_b) return 0.0; /* at rest on the base: nothing moves */
    switch (p->support) {
    case RW_PARAPET: /* generalised force -(W/g) ag R cos(s alpha - theta) (Housner) */
        return -(p->W / p->g) * d->R * in->ag * cos(m->side_b * d->alpha - x[0]) * x[2];
    case RW_SIMPLY_SUPPORTED: /* force -(W/2g) ag on the mid-height displacement D = q1 h/2 */
        return -(p->W / (2.0 * p->g)) * in->ag * x[2] * p->h / 2.0;
    default: /* Eq. 3.4: p = pa ag on (dq1, dq2) */
        return in->ag * (d->pa[0] * x[2] + d->pa[1] * x[3]);
    }
}

double rw_s1(const rw_params *p, const double x[RW_NX])
{
    return x[0] * p->h / 2.0;
}

double rw_s2(const rw_params *p, const double x[RW_NX])
{
    if (p->support == RW_PARAPET) return x[0] * p->h;
    if (p->support == RW_SIMPLY_SUPPORTED) return 0.0;
    return (x[0] + x[1]) * p->h / 2.0;
}

double rw_F_top(const rw_params *p, const rw_input *in, const double x[RW_NX])
{
    if (p->support != RW_FLEXIBLE_TOP) return 0.0;
    return p->Kd * (rw_s2(p, x) - in->u_top);
}

/* Horizontal momentum balance of the wall: sum_i m_i (ag + x_i'') = R - F_top, where R is the
 * support's reaction on the wall and -F_top the spring's force on it; the wall puts -R on its
 * base. scripts/derive_equations.py derives the coefficients (c = -p of Eq. 3.4). */
double rw_F_base(const rw_params *p, const rw_derived *d, const rw_mode *m, const rw_input *in,
                 const double x[RW_NX], const double dx[RW_NX])
{
    const double m_wall = p->W / p->g, m_over = d->Wd / p->g;
    switch (p->support) {
    case RW_PARAPET: { /* one block, its centroid at R from the pivot: x_G'' = R cos(s a - th) th'' + R sin(s a - th) th'^2 */
        const double s = m->side_b, arm = s * d->alpha - x[0];
        if (m->closed_b) return -m_wall * in->ag;
        return -m_wall * (in->ag + d->R * (cos(arm) * dx[2] + sin(arm) * x[2] * x[2]));
    }
    case RW_SIMPLY_SUPPORTED: /* both centroids at h q1/4; the top (and the overburden) move with the ground.
                                 Base and top support together: the top's reaction is not split off */
        return -(m_wall + m_over) * in->ag - m_wall * p->h / 4.0 * dx[2];
    default: /* c . q'' with c = -pa */
        return -(m_wall + m_over) * in->ag + d->pa[0] * dx[2] + d->pa[1] * dx[3] - rw_F_top(p, in, x);
    }
}

int rw_condition(const rw_params *p, const rw_mode *m)
{
    if (rw_is_rigid(p) && (m->closed_b || m->closed_m)) return 0;
    if (p->support != RW_FLEXIBLE_TOP) return m->side_b > 0 ? 1 : 2;
    if (m->side_b > 0) return m->side_m < 0 ? 1 : 3;
    return m->side_m > 0 ? 2 : 4;
}

/* ---- for the exact engine (rw_engine.c) ------------------------------------------------------
 * Doherty's 1DOF force as an affine function F = F0 + F1*D on the region the motion goes into:
 * on a breakpoint (to rounding) the direction dD decides, as the 2DOF laws' past() does. F is
 * continuous at the breakpoints, so F0 = F(D) - F1*D is the same from both sides. */
void rw_force_1dof_affine(const rw_params *p, const rw_derived *d, const rw_mode *m, double D, double dD,
                          double *F0, double *F1)
{
    const double a = fabs(D), out = sgn(D != 0.0 ? D : dD) * dD; /* > 0: moving away from 0 */
    int region; /* 0 inner, 1 plateau, 2 beyond Delta_2 */
    if (law(p)->set_valued) {
        *F1 = d->Fr / d->Du;
    } else {
        if (fabs(a - d->D1) <= 1e-12 * d->D1) region = out > 0.0 ? 1 : 0;
        else if (fabs(a - d->D2) <= 1e-12 * d->D2) region = out > 0.0 ? 2 : 1;
        else region = a < d->D1 ? 0 : (a < d->D2 ? 1 : 2);
        *F1 = region == 0 ? -d->Fi / d->D1 : (region == 1 ? 0.0 : d->Fr / d->Du);
    }
    *F0 = rw_force_1dof(p, d, m, D) - *F1 * D;
}
