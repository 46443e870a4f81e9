/* RockingWall dynamics: the checks that tie parameters together, the derived quantities, and the
 * equations of motion: hinge moments, Doherty's 1DOF force, the state derivatives, the moments a
 * closed rigid hinge resists. Equation numbers "Eq. 3.x" are the paper's; the contract is
 * docs/model.md. The event indicators are rw_indicators.c, the outputs and energy rw_outputs.c, the
 * event rules (impacts, switches, rigid rest / closed-hinge states) rw_events.c. */
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
    if (!(2.0 * p->pointing < p->b)) {
        snprintf(msg, n, "invalid parameters pointing = %g, b = %g: the effective thickness b - 2*pointing = %g must be > 0",
                 p->pointing, p->b, p->b - 2.0 * p->pointing);
        return 1;
    }
    if (!(fabs(p->eTop) <= p->b / 2.0)) {
        snprintf(msg, n, "invalid parameters eTop = %g, b = %g: the top load must bear within b/2 = %g of the centreline",
                 p->eTop, p->b, p->b / 2.0);
        return 1;
    }
    rw_derive(p, &d);
    if (!(d.cap_bs[0] > 0.0 && d.cap_bs[1] > 0.0 && d.cap_ms[0] > 0.0 && d.cap_ms[1] > 0.0)) {
        snprintf(msg, n,
                 "invalid parameters eBaseRatio = %g, eHingeRatio = %g, pointing = %g, eTop = %g, psi = %g, psiWeightOnly = %g: "
                 "the wall cannot stand at rest, a hinge capacity is not positive (base %g, %g; mid-height %g, %g N m/m on "
                 "the sides +1, -1)",
                 p->eBaseRatio, p->eHingeRatio, p->pointing, p->eTop, p->psi, p->psiWeightOnly, d.cap_bs[0], d.cap_bs[1],
                 d.cap_ms[0], d.cap_ms[1]);
        return 1;
    }
    for (i = 0; i < 2; i++) {
        const rw_direction *r = &d.dir[i];
        if (!(r->D1 < r->D2 && r->D2 < r->Du)) {
            snprintf(msg, n,
                     "invalid parameters delta1Ratio = %g, delta2A = %g, delta2B = %g: need Delta_1 < Delta_2 < Delta_u "
                     "(Delta_1 = %g, Delta_2 = %g, Delta_u = %g)",
                     p->delta1Ratio, p->delta2A, p->delta2B, r->D1, r->D2, r->Du);
            return 1;
        }
        if (!(p->hingeSat * r->D1 < r->Du)) {
            snprintf(msg, n,
                     "invalid parameters hingeSat = %g, delta1Ratio = %g: the hinges would saturate at hingeSat*Delta_1 = %g m, "
                     "beyond Delta_u = %g m (need hingeSat*delta1Ratio < 1)",
                     p->hingeSat, p->delta1Ratio, p->hingeSat * r->D1, r->Du);
            return 1;
        }
    }
    return 0;
}

static const rw_hinge_law *law(const rw_params *p)
{
    return rw_hinge_law_of(p->hingeLaw);
}

/* The quantities of the direction `sign` (+1, -1) of the mid-height's motion (docs/model.md
 * "Derived"): Delta_u = ((2 W1 + Wt) e_b + 2 (W1 + Wt) e_m + sign Wd eTop)/(2 (W1 + Wt)), F_r = 4 (W1 + Wt)
 * Delta_u/h, written as Table 5.1's terms in e_b + e_m (the thickness b of the paper's wall) plus what
 * unequal lever arms and the eccentric load add, so that the paper's wall gets Table 5.1's values
 * to the bit. */
static void derive_direction(const rw_params *p, const rw_derived *d, double sign, rw_direction *r)
{
    const double h = p->h, psit = p->psi + p->psiWeightOnly, arms = d->e_b + d->e_m;
    const double uneven = psit * (d->e_m - d->e_b) / 2.0 + sign * p->psi * p->eTop;
    /* Table 5.1 (Doherty), C8's Delta_i */
    r->Du = arms * (1.0 + 0.75 * psit) / (1.0 + psit) + uneven / (2.0 * (1.0 + psit));
    r->Fr = (2.0 * arms / h) * p->W * (1.0 + 0.75 * psit) + (2.0 / h) * (p->W * psit * (d->e_m - d->e_b) / 4.0 + sign * d->Et);
    r->F0 = 2.0 * r->Fr;
    r->Rel = 0.75 * r->F0;
    /* Eq. 5.1, 5.2 */
    r->D1 = p->delta1Ratio * r->Du;
    r->D2 = p->delta2A * r->D1 + p->delta2B * r->Du;
    r->Fi = r->Fr * (1.0 - r->D2 / r->Du);
    r->theta_y = 2.0 * p->hingeSat * r->D1 / h;
}

/* Housner's block pivoting at e_b from the centreline, its mass over the full thickness b: the
 * inertia about the pivot per mass is ((b/2)^2 + H^2)/3 + R^2 = (4/3) R^2 + ((b/2)^2 - e_b^2)/3 */
static void derive_parapet(const rw_params *p, rw_derived *d)
{
    const double B = p->b / 2.0, four_thirds_R2 = 4.0 / 3.0 * (d->e_b * d->e_b + p->h / 2.0 * (p->h / 2.0));
    d->Bp = d->e_b;
    d->Hp = p->h / 2.0;
    d->R = sqrt(d->Bp * d->Bp + d->Hp * d->Hp);
    d->alpha = atan2(d->Bp, d->Hp);
    d->Ir = four_thirds_R2 / (four_thirds_R2 + (B * B - d->e_b * d->e_b) / 3.0);
    d->p2 = 3.0 * p->g / (4.0 * d->R) * d->Ir;
}

void rw_derive(const rw_params *p, rw_derived *d)
{
    const double h = p->h, b = p->b, g = p->g, Kd = p->Kd, t = b - 2.0 * p->pointing;
    const double hg = h * h / g;
    double Wt;
    memset(d, 0, sizeof *d);
    d->h = h;
    d->W1 = p->W / 2.0;
    d->Wd = p->psi * d->W1;
    d->Wo = p->psiWeightOnly * d->W1;
    Wt = d->Wd + d->Wo;
    d->e_b = p->eBaseRatio * t / 2.0;
    d->e_m = p->eHingeRatio * t / 2.0;
    d->Et = d->Wd * p->eTop;
    derive_direction(p, d, 1.0, &d->dir[RW_SIDE(1)]);
    derive_direction(p, d, -1.0, &d->dir[RW_SIDE(-1)]);
    /* the weights' moments about a hinge's pivot; the eccentric load is nearer the pivot of the side
     * it is on */
    d->cap_b = (2.0 * d->W1 + Wt) * d->e_b;
    d->cap_m = (d->W1 + Wt) * d->e_m;
    d->cap_bs[RW_SIDE(1)] = d->cap_b - d->Et;
    d->cap_bs[RW_SIDE(-1)] = d->cap_b + d->Et;
    d->cap_ms[RW_SIDE(1)] = d->cap_m - d->Et;
    d->cap_ms[RW_SIDE(-1)] = d->cap_m + d->Et;
    /* Eq. 3.2 mass matrix */
    d->M[0][0] = (d->W1 / 3.0 + d->Wd / 4.0) * hg;
    d->M[0][1] = d->M[1][0] = (d->W1 / 8.0 + d->Wd / 4.0) * hg;
    d->M[1][1] = (d->W1 / 12.0 + d->Wd / 4.0) * hg;
    /* Eq. 3.3 stiffness matrix (spring minus gravity; the weight-only overburden is in the gravity) */
    d->K[0][0] = Kd * h * h / 4.0 - 0.75 * d->W1 * h - Wt * h / 2.0;
    d->K[0][1] = d->K[1][0] = Kd * h * h / 4.0;
    d->K[1][1] = Kd * h * h / 4.0 - d->W1 * h / 4.0 - Wt * h / 2.0;
    /* Eq. 3.4 with ag positive toward +x (opposite sign to the paper's p'_eff) */
    d->pa[0] = -(3.0 * d->W1 + 2.0 * d->Wd) * h / (4.0 * g);
    d->pa[1] = -(d->W1 + 2.0 * d->Wd) * h / (4.0 * g);
    d->fu = Kd * h / 2.0;
    derive_parapet(p, d);
    d->zscale = p->W * h;
    d->q_topple = 2.0 * b / h;
    d->inv_q_topple = 1.0 / d->q_topple;
    d->tiny = 1e-10 * b / h;
    law(p)->breakpoints(d, d->breaks);
}

int rw_wall_statics(const rw_params *p, rw_statics *s, char *msg, size_t n)
{
    rw_derived d;
    int i;
    if (rw_params_validate(p, msg, n)) return 1;
    rw_derive(p, &d);
    for (i = 0; i < 2; i++) {
        s->Du[i] = d.dir[i].Du;
        s->Fr[i] = d.dir[i].Fr;
        s->cap_b[i] = d.cap_bs[i];
        s->cap_m[i] = d.cap_ms[i];
    }
    return 0;
}

int rw_is_rigid(const rw_params *p)
{
    return p->support == RW_PARAPET || law(p)->set_valued;
}

int rw_moments_of_q_alone(const rw_params *p)
{
    /* an eccentric top load gives the hinges capacities and breakpoints of their side: their
     * moments' slope then changes where a rotation passes zero, at the hinges' own events */
    const int symmetric = p->psi == 0.0 || p->eTop == 0.0;
    return law(p)->q_only && symmetric;
}

int rw_mid_switch_is_bookkeeping(const rw_params *p)
{
    return p->support == RW_FLEXIBLE_TOP && rw_moments_of_q_alone(p);
}

/* ---- forces -------------------------------------------------------------------------------- */

/* Q(q) of the open hinges, from the law (docs/model.md "Hinge laws"). */
void rw_hinge_Q(const rw_params *p, const rw_derived *d, const rw_regime *m, const double x[RW_NX], double Q[2])
{
    double J[2][2];
    law(p)->moments(d, m->side_b, m->side_m, x, x + 2, Q, J);
}

/* Doherty's 1DOF resisting force F(D) (Fig. 5.2), of the direction of D. */
double rw_force_1dof(const rw_params *p, const rw_derived *d, const rw_regime *m, double D)
{
    const double a = fabs(D);
    const rw_direction *r;
    double f;
    if (law(p)->set_valued) { /* rigid line, sign from the active side (linear through 0) */
        r = &d->dir[RW_SIDE(m->side_b)];
        return -r->Fr * m->side_b + r->Fr * D / r->Du;
    }
    r = &d->dir[RW_SIDE(D)];
    if (a <= r->D1) f = r->Fi * a / r->D1;
    else if (a <= r->D2) f = r->Fi;
    else f = r->Fr * (1.0 - a / r->Du);
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
static double q2dd_base_closed(const rw_derived *d, const rw_regime *m, const double F[2], double q2)
{
    return (F[1] - d->K[1][1] * q2 - rw_cap_m_of(d, m->side_m) * m->side_m) / d->M[1][1];
}

/* Mid closed, base open: q1 = q2 = theta moving together. */
static double thdd_mid_closed(const rw_derived *d, const rw_regime *m, const double F[2], double th)
{
    const double mt = d->M[0][0] + 2.0 * d->M[0][1] + d->M[1][1];
    const double kt = d->K[0][0] + 2.0 * d->K[0][1] + d->K[1][1];
    return (F[0] + F[1] - kt * th - rw_cap_b_of(d, m->side_b) * m->side_b) / mt;
}

void rw_derivatives(const rw_params *p, const rw_derived *d, const rw_regime *m, const rw_input *in,
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
        if (m->tie_held) {
            rw_rigid_tie_motion(p, d, m, in, x, dx, &F[0]);
            return;
        }
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

/* The asymmetry (cap(+1) - cap(-1))/2 of two capacities */
static double asymmetry(const double cap[2])
{
    return (cap[RW_SIDE(1)] - cap[RW_SIDE(-1)]) / 2.0;
}

/* Generalised moment a closed hinge must resist (reaction = -f), spec "Opening tendency", less the
 * asymmetry of its capacities (rw_physics.h). Parapet: f_b = -ag (cap g tan(alpha));
 * simplySupported: f_b = -W ag/(2g) (cap F_r of the direction). */
void rw_closed_forces(const rw_params *p, const rw_derived *d, const rw_regime *m, const rw_input *in,
                      const double x[RW_NX], double *f_b, double *f_m)
{
    double F[2];
    *f_b = *f_m = 0.0;
    if (p->support == RW_PARAPET) { *f_b = -in->ag; return; }
    if (p->support == RW_SIMPLY_SUPPORTED) {
        const double Fr[2] = {d->dir[0].Fr, d->dir[1].Fr};
        *f_b = -p->W * in->ag / (2.0 * p->g) - asymmetry(Fr);
        return;
    }
    if (m->tie_held && m->closed_b && m->closed_m) {
        rw_rigid_tie_closed_forces(p, d, in, f_b, f_m);
        return;
    }
    load(d, in, F);
    if (m->closed_b && m->closed_m) {
        *f_b = F[0] + F[1];
        *f_m = F[1];
    } else if (m->closed_b) {
        const double q2dd = q2dd_base_closed(d, m, F, x[1]);
        *f_b = F[0] - d->K[0][1] * x[1] + rw_cap_m_of(d, m->side_m) * m->side_m - d->M[0][1] * q2dd;
    } else if (m->closed_m) {
        const double th = x[0], thdd = thdd_mid_closed(d, m, F, th);
        *f_m = F[1] - (d->K[0][1] + d->K[1][1]) * th - (d->M[0][1] + d->M[1][1]) * thdd;
    }
    *f_b -= asymmetry(d->cap_bs);
    *f_m -= asymmetry(d->cap_ms);
}

/* rw_closed_forces is affine in the rotations and the inputs under one regime: its coefficients are
 * its differences over unit steps of each, so that the engine's values are this function's */
void rw_closed_force_form(const rw_params *p, const rw_derived *d, const rw_regime *m, rw_closed_form *f)
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

/* capacities matching rw_closed_forces: the means over both sides */
void rw_caps(const rw_params *p, const rw_derived *d, double *cb, double *cm)
{
    if (p->support == RW_PARAPET) { *cb = p->g * tan(d->alpha); *cm = 1.0; }
    else if (p->support == RW_SIMPLY_SUPPORTED) { *cb = (d->dir[0].Fr + d->dir[1].Fr) / 2.0; *cm = 1.0; }
    else {
        *cb = (d->cap_bs[0] + d->cap_bs[1]) / 2.0;
        *cm = (d->cap_ms[0] + d->cap_ms[1]) / 2.0;
    }
}

/* ---- for the exact engine (fmu_src/engine/) --------------------------------------------------
 * Doherty's 1DOF force as an affine function F = F0 + F1*D on the region the motion goes into:
 * on a breakpoint (to rounding) the direction dD decides, as the 2DOF laws' past() does. F is
 * continuous at the breakpoints, so F0 = F(D) - F1*D is the same from both sides. */
void rw_force_1dof_affine(const rw_params *p, const rw_derived *d, const rw_regime *m, double D, double dD,
                          double *F0, double *F1)
{
    const double a = fabs(D), out = sgn(D != 0.0 ? D : dD) * dD; /* > 0: moving away from 0 */
    int region; /* 0 inner, 1 plateau, 2 beyond Delta_2 */
    if (law(p)->set_valued) {
        const rw_direction *r = &d->dir[RW_SIDE(m->side_b)];
        *F1 = r->Fr / r->Du;
    } else {
        const rw_direction *r = &d->dir[RW_SIDE(D != 0.0 ? D : dD)];
        if (fabs(a - r->D1) <= 1e-12 * r->D1) region = out > 0.0 ? 1 : 0;
        else if (fabs(a - r->D2) <= 1e-12 * r->D2) region = out > 0.0 ? 2 : 1;
        else region = a < r->D1 ? 0 : (a < r->D2 ? 1 : 2);
        *F1 = region == 0 ? -r->Fi / r->D1 : (region == 1 ? 0.0 : r->Fr / r->Du);
    }
    *F0 = rw_force_1dof(p, d, m, D) - *F1 * D;
}
