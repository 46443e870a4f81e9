/* The 2DOF hinge laws (docs/model.md "Hinge laws"), one entry per law: hinge moments and their
 * Jacobian, potential, breakpoints and elastic range. The equations of motion, the event logic
 * and the collapse test call these through rw_hinge_law_of(); nothing else branches on the law,
 * so a fifth law is one more entry here (docs/development.md).
 *
 * The laws that come from a potential write Q = (-cap_b*mu_b + cap_m*mu_m, -cap_m*mu_m), where
 * mu_b(q1) and mu_m(x), x = q2 - q1, are the normalised moments of the base and mid-height hinge
 * and cap_b, cap_m their capacities on the side each turns to (the A_i, B_i of docs/model.md for
 * mu = +-1: the paper's Eq. 3.5-3.8 corrected). A hinge's law takes the data of a direction of the
 * mid-height's motion (rw_direction): the base turning to side s those of s, the mid-height hinge
 * those of -s (docs/model.md "Which direction a hinge takes its law from"); an eccentric top load
 * makes them differ, so a breakpoint may lie at different distances on the two sides. */
#include "rw_physics.h"

#include <math.h>

static double sgn(double v) { return (v > 0.0) - (v < 0.0); }

/* Is |z| past the breakpoint lim? On the breakpoint itself (to rounding) the direction of
 * motion dz decides, so that a located event selects the region the motion goes into. */
static int past(double z, double dz, double lim)
{
    const double a = fabs(z);
    if (fabs(a - lim) > 1e-12 * lim) return a > lim;
    return sgn(z) * dz > 0.0;
}

/* The side of a rotation z: its sign, and at zero the direction of motion dz (+1 if none) */
static double side_of(double z, double dz)
{
    return z != 0.0 ? sgn(z) : (dz != 0.0 ? sgn(dz) : 1.0);
}

/* side_of for the moments, where a hinge at rest at zero (a wall starting from rest on a base that
 * is not yet accelerating) takes the side its regime holds: the side its event line watches, so
 * that a motion the other way is an event that brings the side up to date. Under an eccentric top
 * load the sides' slopes differ there, and a region keyed to another side than the line's would
 * run the wrong law until some other event. */
static double moment_side(double z, double dz, int regime_side)
{
    return z != 0.0 || dz != 0.0 ? side_of(z, dz) : (regime_side < 0 ? -1.0 : 1.0);
}

/* The data of the direction a hinge turning to side s takes: the base's own, the mid-height's
 * the opposite */
static const rw_direction *base_dir(const rw_derived *d, double s) { return &d->dir[RW_SIDE(s)]; }
static const rw_direction *mid_dir(const rw_derived *d, double s) { return &d->dir[RW_SIDE(-s)]; }

/* Q and J from the normalised moments mu_b(q1), mu_m(x), their slopes kb = dmu_b/dq1,
 * km = dmu_m/dx, and the capacities cb, cm of the sides the hinges turn to. */
static void moments_from_mu(double cb, double cm, double mu_b, double kb, double mu_m, double km, double Q[2],
                            double J[2][2])
{
    Q[0] = -cb * mu_b + cm * mu_m;
    Q[1] = -cm * mu_m;
    J[0][0] = -cb * kb - cm * km;
    J[0][1] = J[1][0] = cm * km;
    J[1][1] = -cm * km;
}

/* ---- rigid: mu = sign, set-valued at zero rotation ------------------------------------------ */

static void rigid_moments(const rw_derived *d, int side_b, int side_m, const double q[2], const double dq[2],
                          double Q[2], double J[2][2])
{
    (void)q;
    (void)dq;
    moments_from_mu(rw_cap_b_of(d, side_b), rw_cap_m_of(d, side_m), side_b, 0.0, side_m, 0.0, Q, J);
}

static double rigid_potential(const rw_derived *d, const double q[2])
{
    const double x = q[1] - q[0];
    return rw_cap_b_of(d, q[0]) * fabs(q[0]) + rw_cap_m_of(d, x) * fabs(x);
}

static void no_breakpoints(const rw_derived *d, rw_indicator_line z[RW_NBREAK])
{
    int i;
    (void)d;
    for (i = 0; i < RW_NBREAK; i++) {
        const rw_indicator_line unused = {{0.0, 0.0}, 0.0, 0.0, 1.0, 0};
        z[i] = unused;
    }
}

/* the breakpoint |a0 q1 + a1 q2| = lim_p on the positive side, lim_n on the negative (rw_kink_line) */
static rw_indicator_line kink(double a0, double a1, double lim_p, double lim_n)
{
    return rw_kink_line(a0, a1, lim_p, lim_n);
}

static int rigid_elastic(const rw_derived *d, const double q[2], const double dq[2])
{
    (void)dq;
    return fabs(q[0]) <= d->tiny && fabs(q[1]) <= d->tiny;
}

/* ---- semiRigidHinge: each hinge saturates on its own rotation at theta_y -------------------- */

/* mu = sat(z/ty) and its slope */
static double sat_mu(double z, double dz, double ty, double *slope)
{
    if (past(z, dz, ty)) {
        *slope = 0.0;
        return sgn(z);
    }
    *slope = 1.0 / ty;
    return z / ty;
}

static void hinge_moments(const rw_derived *d, int side_b, int side_m, const double q[2], const double dq[2],
                          double Q[2], double J[2][2])
{
    const double x = q[1] - q[0], dx = dq[1] - dq[0], sb = moment_side(q[0], dq[0], side_b),
                 sm = moment_side(x, dx, side_m);
    double kb, km, mu_b, mu_m;
    mu_b = sat_mu(q[0], dq[0], base_dir(d, sb)->theta_y, &kb);
    mu_m = sat_mu(x, dx, mid_dir(d, sm)->theta_y, &km);
    moments_from_mu(rw_cap_b_of(d, sb), rw_cap_m_of(d, sm), mu_b, kb, mu_m, km, Q, J);
}

/* ty*Phi(z/ty), Phi(u) = u^2/2 (|u| <= 1), |u| - 1/2 beyond */
static double sat_potential(double z, double ty)
{
    const double u = fabs(z) / ty;
    return ty * (u <= 1.0 ? 0.5 * u * u : u - 0.5);
}

static double hinge_potential(const rw_derived *d, const double q[2])
{
    const double x = q[1] - q[0];
    return rw_cap_b_of(d, q[0]) * sat_potential(q[0], base_dir(d, q[0])->theta_y) +
           rw_cap_m_of(d, x) * sat_potential(x, mid_dir(d, x)->theta_y);
}

/* theta_y on the positive and the negative side of the base and of the mid-height hinge */
static void hinge_breakpoints(const rw_derived *d, rw_indicator_line z[RW_NBREAK])
{
    no_breakpoints(d, z);
    z[0] = kink(1.0, 0.0, base_dir(d, 1.0)->theta_y, base_dir(d, -1.0)->theta_y);
    z[2] = kink(-1.0, 1.0, mid_dir(d, 1.0)->theta_y, mid_dir(d, -1.0)->theta_y);
}

static int hinge_elastic(const rw_derived *d, const double q[2], const double dq[2])
{
    const double x = q[1] - q[0], dx = dq[1] - dq[0];
    return !past(q[0], dq[0], base_dir(d, side_of(q[0], dq[0]))->theta_y) &&
           !past(x, dx, mid_dir(d, side_of(x, dx))->theta_y);
}

/* ---- semiRigidPaper: Fig. 4.1/4.2, finite stiffness on q1 and on the absolute q2 ------------ */

/* Q1 = A_c min(1,|q1|/ty), Q2 = B_c min(1,|q2|/ty), A_c, B_c of the condition of the sides.
 * min(1,|q1|/ty)*sign(q1) = sat(q1/ty), so the base part is written with sat (continuous at 0);
 * the mid-height part of Q1 takes |sat(q1/ty)| and Q2 takes |q2|: both have a kink at 0, which is
 * therefore a breakpoint. (The base indicator's root is at q1 = 0 too, but not always: a base
 * crossing within `tiny` of zero is taken at an event just before, by its direction of motion,
 * and the indicator's offset then moves its root past zero, rw_events.c.) The saturation on q1
 * takes the direction sign(q1), the one on q2 the direction -sign(q2) (along q2 = -q1, that of q1);
 * the base's capacity is of the side sign(q1), which is continuous as sat vanishes at 0. */
static void paper_moments(const rw_derived *d, int side_b, int side_m, const double q[2], const double dq[2],
                          double Q[2], double J[2][2])
{
    const double s1 = side_of(q[0], dq[0]), s2 = side_of(q[1], dq[1]);
    const double ty1 = base_dir(d, s1)->theta_y, ty2 = base_dir(d, -s2)->theta_y;
    const double cb = rw_cap_b_of(d, s1), cm = rw_cap_m_of(d, side_m);
    double k1, k2, r2;
    const double sat1 = sat_mu(q[0], dq[0], ty1, &k1);
    const int in2 = !past(q[1], dq[1], ty2);
    (void)side_b;
    r2 = in2 ? fabs(q[1]) / ty2 : 1.0;
    k2 = in2 ? s2 / ty2 : 0.0;
    Q[0] = -cb * sat1 + cm * side_m * fabs(sat1);
    Q[1] = -cm * side_m * r2;
    J[0][0] = -cb * k1 + cm * side_m * sgn(q[0] != 0.0 ? q[0] : dq[0]) * k1;
    J[0][1] = 0.0;
    J[1][0] = 0.0;
    J[1][1] = -cm * side_m * k2;
}

static void paper_breakpoints(const rw_derived *d, rw_indicator_line z[RW_NBREAK])
{
    const double ty = base_dir(d, 1.0)->theta_y; /* a scale of the sign lines only */
    const rw_indicator_line sign_q1 = {{1.0 / ty, 0.0}, 0.0, 1.0, 0.0, 0}; /* the kink of |sat(q1)| at 0 */
    const rw_indicator_line sign_q2 = {{0.0, 1.0 / ty}, 0.0, 1.0, 0.0, 0}; /* the kink of |q2| at 0 */
    no_breakpoints(d, z);
    z[0] = kink(1.0, 0.0, base_dir(d, 1.0)->theta_y, base_dir(d, -1.0)->theta_y);
    z[1] = sign_q1;
    z[2] = kink(0.0, 1.0, base_dir(d, -1.0)->theta_y, base_dir(d, 1.0)->theta_y);
    z[3] = sign_q2;
}

static int paper_elastic(const rw_derived *d, const double q[2], const double dq[2])
{
    return !past(q[0], dq[0], base_dir(d, side_of(q[0], dq[0]))->theta_y) &&
           !past(q[1], dq[1], base_dir(d, -side_of(q[1], dq[1]))->theta_y);
}

/* ---- dohertyHinge: Doherty's trilinear shape in each hinge's own mid-height displacement ----
 * Along the simply supported shape (q2 = -q1) the mid-height displacement is D = h q1/2, and the
 * mid-height hinge turns by |x| = 2|q1|, i.e. D = h|x|/4. With mu(D) = c(D)/F_r,
 *   c(D) = (F_i/Delta_1 + F_r/Delta_u) D        for D <= Delta_1,
 *          F_i + (F_r/Delta_u) D                for Delta_1 < D <= Delta_2,
 *          F_r                                  beyond,
 * (Doherty's trilinear force with the gravity slope F_r/Delta_u, which K already carries, taken
 * out), the hinge force on D is (2/h)(cap_b + 2 cap_m) mu = F_r mu = c(D): the 2DOF reduces to
 * Doherty's 1DOF exactly when the spring pins the top (scripts/derive_equations.py checks it). */

/* mu(D) for D >= 0 of the direction r and its slope dmu/dD; the rate dD decides on a breakpoint */
static double doherty_shape(const rw_direction *r, double D, double dD, double *slope)
{
    const double g = r->Fr / r->Du; /* the gravity slope */
    if (!past(D, dD, r->D1)) {
        *slope = (r->Fi / r->D1 + g) / r->Fr;
        return D * *slope;
    }
    if (!past(D, dD, r->D2)) {
        *slope = g / r->Fr;
        return (r->Fi + g * D) / r->Fr;
    }
    *slope = 0.0;
    return 1.0;
}

/* mu of a hinge whose rotation z maps to the mid-height displacement D = c |z|, with the data r of
 * its direction; slope dmu/dz */
static double doherty_mu(const rw_direction *r, double z, double dz, double c, double *slope)
{
    const double mu = doherty_shape(r, c * fabs(z), c * (z != 0.0 ? sgn(z) * dz : fabs(dz)), slope);
    *slope *= c;
    return sgn(z) * mu;
}

static void doherty_moments(const rw_derived *d, int side_b, int side_m, const double q[2], const double dq[2],
                            double Q[2], double J[2][2])
{
    const double x = q[1] - q[0], dx = dq[1] - dq[0], sb = moment_side(q[0], dq[0], side_b),
                 sm = moment_side(x, dx, side_m);
    double kb, km;
    const double mu_b = doherty_mu(base_dir(d, sb), q[0], dq[0], d->h / 2.0, &kb);
    const double mu_m = doherty_mu(mid_dir(d, sm), x, dx, d->h / 4.0, &km);
    moments_from_mu(rw_cap_b_of(d, sb), rw_cap_m_of(d, sm), mu_b, kb, mu_m, km, Q, J);
}

/* integral of mu from 0 to D (D >= 0) of the direction r */
static double doherty_shape_integral(const rw_direction *r, double D)
{
    const double g = r->Fr / r->Du, k1 = (r->Fi / r->D1 + g) / r->Fr;
    const double at1 = 0.5 * k1 * r->D1 * r->D1;
    const double at2 = at1 + (r->Fi * (r->D2 - r->D1) + 0.5 * g * (r->D2 * r->D2 - r->D1 * r->D1)) / r->Fr;
    if (D <= r->D1) return 0.5 * k1 * D * D;
    if (D <= r->D2) return at1 + (r->Fi * (D - r->D1) + 0.5 * g * (D * D - r->D1 * r->D1)) / r->Fr;
    return at2 + (D - r->D2);
}

/* V = cap * integral of mu dz = cap * (1/c) * integral of mu dD */
static double doherty_potential(const rw_derived *d, const double q[2])
{
    const double cb = d->h / 2.0, cm = d->h / 4.0, x = q[1] - q[0];
    return rw_cap_b_of(d, q[0]) / cb * doherty_shape_integral(base_dir(d, q[0]), cb * fabs(q[0])) +
           rw_cap_m_of(d, x) / cm * doherty_shape_integral(mid_dir(d, x), cm * fabs(x));
}

static void doherty_breakpoints(const rw_derived *d, rw_indicator_line z[RW_NBREAK])
{
    /* D1, D2 in the rotation of each hinge (D = h|q1|/2, h|x|/4), so that all indicators have the
     * scale of a rotation; each side of its direction */
    const double cb = 2.0 / d->h, cm = 4.0 / d->h;
    const rw_direction *bp = base_dir(d, 1.0), *bn = base_dir(d, -1.0), *mp = mid_dir(d, 1.0), *mn = mid_dir(d, -1.0);
    z[0] = kink(1.0, 0.0, bp->D1 * cb, bn->D1 * cb);
    z[1] = kink(1.0, 0.0, bp->D2 * cb, bn->D2 * cb);
    z[2] = kink(-1.0, 1.0, mp->D1 * cm, mn->D1 * cm);
    z[3] = kink(-1.0, 1.0, mp->D2 * cm, mn->D2 * cm);
}

static int doherty_elastic(const rw_derived *d, const double q[2], const double dq[2])
{
    const double x = q[1] - q[0], dx = dq[1] - dq[0];
    return !past(q[0], dq[0], 2.0 * base_dir(d, side_of(q[0], dq[0]))->D1 / d->h) &&
           !past(x, dx, 4.0 * mid_dir(d, side_of(x, dx))->D1 / d->h);
}

/* ---- the table ------------------------------------------------------------------------------ */

static const rw_hinge_law LAWS[] = {
    {RW_RIGID, "rigid", 1, rigid_moments, rigid_potential, no_breakpoints, rigid_elastic, 0},
    {RW_SEMI_RIGID_PAPER, "semiRigidPaper", 0, paper_moments, hinge_potential, paper_breakpoints, paper_elastic, 0},
    {RW_SEMI_RIGID_HINGE, "semiRigidHinge", 0, hinge_moments, hinge_potential, hinge_breakpoints, hinge_elastic, 1},
    {RW_DOHERTY_HINGE, "dohertyHinge", 0, doherty_moments, doherty_potential, doherty_breakpoints, doherty_elastic, 1},
};

const rw_hinge_law *rw_hinge_law_of(int id)
{
    size_t i;
    /* the table is in id order: the direct look-up first (every event indicator evaluation asks) */
    if (id >= 1 && (size_t)id <= sizeof LAWS / sizeof LAWS[0] && LAWS[id - 1].id == id) return &LAWS[id - 1];
    for (i = 0; i < sizeof LAWS / sizeof LAWS[0]; i++)
        if (LAWS[i].id == id) return &LAWS[i];
    return 0;
}
