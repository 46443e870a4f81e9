/* The 2DOF hinge laws (docs/model.md "Hinge laws"), one entry per law: hinge moments and their
 * Jacobian, potential, breakpoints and elastic range. The equations of motion, the event logic
 * and the collapse test call these through rw_hinge_law_of(); nothing else branches on the law,
 * so a fifth law is one more entry here (docs/development.md).
 *
 * The laws that come from a potential write Q = (-cap_b*mu_b + cap_m*mu_m, -cap_m*mu_m), where
 * mu_b(q1) and mu_m(x), x = q2 - q1, are the normalised moments of the base and mid-height hinge
 * (the A_i, B_i of docs/model.md for mu = +-1: the paper's Eq. 3.5-3.8 corrected). */
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

/* Q and J from the normalised moments mu_b(q1), mu_m(x) and their slopes kb = dmu_b/dq1,
 * km = dmu_m/dx. */
static void moments_from_mu(const rw_derived *d, double mu_b, double kb, double mu_m, double km, double Q[2],
                            double J[2][2])
{
    Q[0] = -d->cap_b * mu_b + d->cap_m * mu_m;
    Q[1] = -d->cap_m * mu_m;
    J[0][0] = -d->cap_b * kb - d->cap_m * km;
    J[0][1] = J[1][0] = d->cap_m * km;
    J[1][1] = -d->cap_m * km;
}

/* ---- rigid: mu = sign, set-valued at zero rotation ------------------------------------------ */

static void rigid_moments(const rw_derived *d, int side_b, int side_m, const double q[2], const double dq[2],
                          double Q[2], double J[2][2])
{
    (void)q;
    (void)dq;
    moments_from_mu(d, side_b, 0.0, side_m, 0.0, Q, J);
}

static double rigid_potential(const rw_derived *d, const double q[2])
{
    return d->cap_b * fabs(q[0]) + d->cap_m * fabs(q[1] - q[0]);
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

/* the breakpoint |a0 q1 + a1 q2| = lim */
static rw_indicator_line kink(double a0, double a1, double lim)
{
    const rw_indicator_line line = {{a0, a1}, 1.0, 0.0, -lim, 0};
    return line;
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
    double kb, km, mu_b, mu_m;
    (void)side_b;
    (void)side_m;
    mu_b = sat_mu(q[0], dq[0], d->theta_y, &kb);
    mu_m = sat_mu(q[1] - q[0], dq[1] - dq[0], d->theta_y, &km);
    moments_from_mu(d, mu_b, kb, mu_m, km, Q, J);
}

/* ty*Phi(z/ty), Phi(u) = u^2/2 (|u| <= 1), |u| - 1/2 beyond */
static double sat_potential(double z, double ty)
{
    const double u = fabs(z) / ty;
    return ty * (u <= 1.0 ? 0.5 * u * u : u - 0.5);
}

static double hinge_potential(const rw_derived *d, const double q[2])
{
    return d->cap_b * sat_potential(q[0], d->theta_y) + d->cap_m * sat_potential(q[1] - q[0], d->theta_y);
}

static void hinge_breakpoints(const rw_derived *d, rw_indicator_line z[RW_NBREAK])
{
    no_breakpoints(d, z);
    z[0] = kink(1.0, 0.0, d->theta_y);
    z[2] = kink(-1.0, 1.0, d->theta_y);
}

static int hinge_elastic(const rw_derived *d, const double q[2], const double dq[2])
{
    return !past(q[0], dq[0], d->theta_y) && !past(q[1] - q[0], dq[1] - dq[0], d->theta_y);
}

/* ---- semiRigidPaper: Fig. 4.1/4.2, finite stiffness on q1 and on the absolute q2 ------------ */

/* Q1 = A_c min(1,|q1|/ty), Q2 = B_c min(1,|q2|/ty), A_c, B_c of the condition of the sides.
 * min(1,|q1|/ty)*sign(q1) = sat(q1/ty), so the base part is written with sat (continuous at 0);
 * the mid-height part of Q1 takes |sat(q1/ty)| and Q2 takes |q2|: both have a kink at 0, which is
 * therefore a breakpoint. (The base indicator's root is at q1 = 0 too, but not always: a base
 * crossing within `tiny` of zero is taken at an event just before, by its direction of motion,
 * and the indicator's offset then moves its root past zero, rw_events.c.) */
static void paper_moments(const rw_derived *d, int side_b, int side_m, const double q[2], const double dq[2],
                          double Q[2], double J[2][2])
{
    const double ty = d->theta_y;
    double k1, k2, r2;
    const double sat1 = sat_mu(q[0], dq[0], ty, &k1);
    const double s2 = q[1] != 0.0 ? sgn(q[1]) : (dq[1] != 0.0 ? sgn(dq[1]) : 1.0);
    const int in2 = !past(q[1], dq[1], ty);
    (void)side_b;
    r2 = in2 ? fabs(q[1]) / ty : 1.0;
    k2 = in2 ? s2 / ty : 0.0;
    Q[0] = -d->cap_b * sat1 + d->cap_m * side_m * fabs(sat1);
    Q[1] = -d->cap_m * side_m * r2;
    J[0][0] = -d->cap_b * k1 + d->cap_m * side_m * sgn(q[0] != 0.0 ? q[0] : dq[0]) * k1;
    J[0][1] = 0.0;
    J[1][0] = 0.0;
    J[1][1] = -d->cap_m * side_m * k2;
}

static void paper_breakpoints(const rw_derived *d, rw_indicator_line z[RW_NBREAK])
{
    const rw_indicator_line sign_q1 = {{1.0 / d->theta_y, 0.0}, 0.0, 1.0, 0.0, 0}; /* the kink of |sat(q1)| at 0 */
    const rw_indicator_line sign_q2 = {{0.0, 1.0 / d->theta_y}, 0.0, 1.0, 0.0, 0}; /* the kink of |q2| at 0 */
    no_breakpoints(d, z);
    z[0] = kink(1.0, 0.0, d->theta_y);
    z[1] = sign_q1;
    z[2] = kink(0.0, 1.0, d->theta_y);
    z[3] = sign_q2;
}

static int paper_elastic(const rw_derived *d, const double q[2], const double dq[2])
{
    return !past(q[0], dq[0], d->theta_y) && !past(q[1], dq[1], d->theta_y);
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

/* mu(D) for D >= 0 and its slope dmu/dD; `moving_out` decides on a breakpoint */
static double doherty_shape(const rw_derived *d, double D, double dD, double *slope)
{
    const double g = d->Fr / d->Du; /* the gravity slope */
    if (!past(D, dD, d->D1)) {
        *slope = (d->Fi / d->D1 + g) / d->Fr;
        return D * *slope;
    }
    if (!past(D, dD, d->D2)) {
        *slope = g / d->Fr;
        return (d->Fi + g * D) / d->Fr;
    }
    *slope = 0.0;
    return 1.0;
}

/* mu of a hinge whose rotation z maps to the mid-height displacement D = c z; slope dmu/dz */
static double doherty_mu(const rw_derived *d, double z, double dz, double c, double *slope)
{
    const double s = sgn(z);
    const double mu = doherty_shape(d, c * fabs(z), c * (s != 0.0 ? s * dz : fabs(dz)), slope);
    *slope *= c;
    return s * mu;
}

static void doherty_moments(const rw_derived *d, int side_b, int side_m, const double q[2], const double dq[2],
                            double Q[2], double J[2][2])
{
    double kb, km;
    const double mu_b = doherty_mu(d, q[0], dq[0], d->h / 2.0, &kb);
    const double mu_m = doherty_mu(d, q[1] - q[0], dq[1] - dq[0], d->h / 4.0, &km);
    (void)side_b;
    (void)side_m;
    moments_from_mu(d, mu_b, kb, mu_m, km, Q, J);
}

/* integral of mu from 0 to D (D >= 0) */
static double doherty_shape_integral(const rw_derived *d, double D)
{
    const double g = d->Fr / d->Du, k1 = (d->Fi / d->D1 + g) / d->Fr;
    const double at1 = 0.5 * k1 * d->D1 * d->D1;
    const double at2 = at1 + (d->Fi * (d->D2 - d->D1) + 0.5 * g * (d->D2 * d->D2 - d->D1 * d->D1)) / d->Fr;
    if (D <= d->D1) return 0.5 * k1 * D * D;
    if (D <= d->D2) return at1 + (d->Fi * (D - d->D1) + 0.5 * g * (D * D - d->D1 * d->D1)) / d->Fr;
    return at2 + (D - d->D2);
}

/* V = cap * integral of mu dz = cap * (1/c) * integral of mu dD */
static double doherty_potential(const rw_derived *d, const double q[2])
{
    const double cb = d->h / 2.0, cm = d->h / 4.0;
    return d->cap_b / cb * doherty_shape_integral(d, cb * fabs(q[0])) +
           d->cap_m / cm * doherty_shape_integral(d, cm * fabs(q[1] - q[0]));
}

static void doherty_breakpoints(const rw_derived *d, rw_indicator_line z[RW_NBREAK])
{
    /* D1, D2 in the rotation of each hinge (D = h|q1|/2, h|x|/4), so that all indicators have the
     * scale of a rotation */
    const double cb = 2.0 / d->h, cm = 4.0 / d->h;
    z[0] = kink(1.0, 0.0, d->D1 * cb);
    z[1] = kink(1.0, 0.0, d->D2 * cb);
    z[2] = kink(-1.0, 1.0, d->D1 * cm);
    z[3] = kink(-1.0, 1.0, d->D2 * cm);
}

static int doherty_elastic(const rw_derived *d, const double q[2], const double dq[2])
{
    return !past(q[0], dq[0], 2.0 * d->D1 / d->h) && !past(q[1] - q[0], dq[1] - dq[0], 4.0 * d->D1 / d->h);
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
