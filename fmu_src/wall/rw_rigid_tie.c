/* A stiff tie held rigid (docs/model.md "A stiff tie"): when the top spring K_d is so much stiffer
 * than everything else in the wall that its own mode only adds a tiny quasi-static deflection, the
 * flexible-top wall moves as if its top were held: q2 = -q1 (the top's displacement
 * (q1 + q2) h/2 = 0), one degree of freedom, and the tie's force is the constraint's reaction (its
 * deflection F_top/K_d is what the model reports as s2).
 * An integrator of the full Eq. 3.1 must otherwise resolve the tie's oscillation, at a cost that
 * grows as sqrt(K_d), for an answer that differs from this one by about the ratio of the two
 * stiffnesses (rw_tie_stiffness_ratio). Only where the far end holds still (u_top = 0): a moving
 * far end drives the tie, and its acceleration is not an input. */
#include "rw_physics.h"

#include <math.h>

static const rw_hinge_law *law(const rw_params *p)
{
    return rw_hinge_law_of(p->hingeLaw);
}

/* The largest |lambda| of det(A - lambda M) = 0 for 2 x 2 symmetric A, M (M positive definite) */
static double largest_eigenvalue(const double A[2][2], const double M[2][2])
{
    const double a = M[0][0] * M[1][1] - M[0][1] * M[0][1];
    const double b = -(A[0][0] * M[1][1] + A[1][1] * M[0][0] - 2.0 * A[0][1] * M[0][1]);
    const double c = A[0][0] * A[1][1] - A[0][1] * A[0][1];
    const double disc = sqrt(fmax(b * b - 4.0 * a * c, 0.0));
    return fmax(fabs((-b + disc) / (2.0 * a)), fabs((-b - disc) / (2.0 * a)));
}

/* The gravity's part of Eq. 3.3's K (K less the spring's K_d h^2/4 in every entry), written out
 * rather than subtracted: at K_d = 1e12 the difference would keep only 8 digits. */
static void gravity_stiffness(const rw_derived *d, double Kg[2][2])
{
    const double Wt = d->Wd + d->Wo, h = d->h;
    Kg[0][0] = -0.75 * d->W1 * h - Wt * h / 2.0;
    Kg[0][1] = Kg[1][0] = 0.0;
    Kg[1][1] = -d->W1 * h / 4.0 - Wt * h / 2.0;
}

/* omega^2 of the wall's stiffest mode without the spring, over the tie's omega^2: the elastic
 * hinges' stiffness (the law's Jacobian at rest, both directions) with gravity's, against the
 * spring's rank-one stiffness K_d h^2/4 (1, 1)(1, 1)^T, whose only mode has
 * omega^2 = K_d h^2/4 (1, 1) M^-1 (1, 1)^T. */
double rw_tie_stiffness_ratio(const rw_params *p, const rw_derived *d)
{
    const double det = d->M[0][0] * d->M[1][1] - d->M[0][1] * d->M[1][0];
    const double cMc = (d->M[1][1] + d->M[0][0] - 2.0 * d->M[0][1]) / det;
    const double tie = p->Kd * p->h * p->h / 4.0 * cMc;
    double Kg[2][2], slow = 0.0;
    int s;
    if (!(tie > 0.0)) return INFINITY;
    gravity_stiffness(d, Kg);
    for (s = -1; s <= 1; s += 2) {
        const double q[2] = {0.0, 0.0}, dq[2] = {s, 2.0 * s};
        double Q[2], J[2][2], A[2][2];
        law(p)->moments(d, s, s, q, dq, Q, J);
        A[0][0] = Kg[0][0] - J[0][0];
        A[0][1] = A[1][0] = Kg[0][1] - (J[0][1] + J[1][0]) / 2.0;
        A[1][1] = Kg[1][1] - J[1][1];
        slow = fmax(slow, largest_eigenvalue((const double(*)[2])A, d->M));
    }
    return slow / tie;
}

int rw_tie_holds_rigid(const rw_params *p, const rw_derived *d, const rw_regime *m, const rw_input *in,
                       const double x[RW_NX])
{
    const int rigid = law(p)->set_valued;
    const double factor = rigid ? RW_RIGID_LAW_TIE_FACTOR : 1.0;
    return p->support == RW_FLEXIBLE_TOP && in->u_top == 0.0 && x[0] + x[1] == 0.0 && x[2] + x[3] == 0.0 &&
           !(rigid && m->closed_b != m->closed_m) && factor * rw_tie_stiffness_ratio(p, d) <= RW_RIGID_TIE_RATIO;
}

int rw_tie_held_from_rest(const rw_params *p)
{
    double x[RW_NX] = {0.0, 0.0, 0.0, 0.0};
    const rw_input still = {0.0, 0.0};
    rw_derived d;
    rw_regime m;
    rw_derive(p, &d);
    rw_init_regime(p, &d, &still, x, &m, NULL, NULL);
    return rw_hold_tie(p, &d, &m, &still, x, NULL, NULL);
}

void rw_rigid_tie_closed_forces(const rw_params *p, const rw_derived *d, const rw_input *in, double *f_b,
                                double *f_m)
{
    /* theta turning to side s turns the base to s and the mid-height hinge (x = -2 theta) to -s:
     * the mechanism resists C(s) = cap_b(s) + 2 cap_m(-s) against the load (pa1 - pa2) ag */
    const double C_pos = d->cap_bs[RW_SIDE(1)] + 2.0 * d->cap_ms[RW_SIDE(-1)];
    const double C_neg = d->cap_bs[RW_SIDE(-1)] + 2.0 * d->cap_ms[RW_SIDE(1)];
    const double mean = (C_pos + C_neg) / 2.0, asym = (C_pos - C_neg) / 2.0;
    double cap_b, cap_m;
    rw_caps(p, d, &cap_b, &cap_m); /* the closed base's indicator divides by cap_b */
    *f_b = ((d->pa[0] - d->pa[1]) * in->ag - asym) * cap_b / mean;
    *f_m = 0.0;
}

/* Eq. 3.1 with q = theta (1, -1) and the spring's force replaced by the constraint's reaction
 * lambda (1, 1): row 1 - row 2 gives theta'', row 1 then lambda. */
void rw_rigid_tie_motion(const rw_params *p, const rw_derived *d, const rw_regime *m, const rw_input *in,
                         const double x[RW_NX], double dx[RW_NX], double *F_top)
{
    double Kg[2][2], Q[2], r[2], thdd, lambda;
    if (m->closed_b && m->closed_m) { /* at rest: the closed hinges carry the load, the tie nothing */
        dx[0] = dx[1] = dx[2] = dx[3] = 0.0;
        *F_top = 0.0;
        return;
    }
    gravity_stiffness(d, Kg);
    rw_hinge_Q(p, d, m, x, Q);
    r[0] = d->pa[0] * in->ag - Kg[0][0] * x[0] - Kg[0][1] * x[1] + Q[0];
    r[1] = d->pa[1] * in->ag - Kg[1][0] * x[0] - Kg[1][1] * x[1] + Q[1];
    thdd = (r[0] - r[1]) / (d->M[0][0] - 2.0 * d->M[0][1] + d->M[1][1]);
    lambda = (d->M[0][0] - d->M[0][1]) * thdd - r[0];
    dx[0] = x[2];
    dx[1] = x[3];
    dx[2] = thdd;
    dx[3] = -thdd;
    /* the spring's generalised force is -(h/2) F_top (1, 1) */
    *F_top = -2.0 * lambda / p->h;
}

double rw_tie_force(const rw_params *p, const rw_derived *d, const rw_regime *m, const rw_input *in,
                    const double x[RW_NX])
{
    double dx[RW_NX], F_top;
    if (!m->tie_held) return rw_F_top(p, in, x);
    rw_rigid_tie_motion(p, d, m, in, x, dx, &F_top);
    return F_top;
}
