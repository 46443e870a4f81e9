/* RockingWall outputs and energy: s1, s2, F_top, F_base, the mechanical energy, the power of the
 * ground motion, and the `condition` output (docs/model.md). */
#include "rw_physics.h"

#include <math.h>

static const rw_hinge_law *law(const rw_params *p)
{
    return rw_hinge_law_of(p->hingeLaw);
}

double rw_energy(const rw_params *p, const rw_derived *d, const rw_regime *m, const rw_input *in,
                 const double x[RW_NX])
{
    const double q1 = x[0], q2 = x[1], v1 = x[2], v2 = x[3];
    switch (p->support) {
    case RW_PARAPET: {
        const double s = m->closed_b ? 1.0 : m->side_b;
        return 0.5 * (4.0 / 3.0) * (p->W / p->g) * d->R * d->R * v1 * v1 / d->Ir +
               p->W * d->R * (cos(s * d->alpha - q1) - cos(d->alpha));
    }
    case RW_SIMPLY_SUPPORTED: {
        const double D = fabs(q1 * p->h / 2.0), dD = v1 * p->h / 2.0;
        const rw_direction *r = &d->dir[RW_SIDE(q1)]; /* the integral of F(D) in the direction of D */
        double V;
        if (law(p)->set_valued) V = r->Fr * (D - D * D / (2.0 * r->Du));
        else if (D <= r->D1) V = r->Fi * D * D / (2.0 * r->D1);
        else if (D <= r->D2) V = r->Fi * r->D1 / 2.0 + r->Fi * (D - r->D1);
        else V = r->Fi * r->D1 / 2.0 + r->Fi * (r->D2 - r->D1) +
                 r->Fr * ((D - r->D2) - (D * D - r->D2 * r->D2) / (2.0 * r->Du));
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
double rw_ground_power(const rw_params *p, const rw_derived *d, const rw_regime *m, const rw_input *in,
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
double rw_F_base(const rw_params *p, const rw_derived *d, const rw_regime *m, const rw_input *in,
                 const double x[RW_NX], const double dx[RW_NX])
{
    return rw_F_base_given_top(p, d, m, in, x, dx, rw_F_top(p, in, x));
}

double rw_F_base_given_top(const rw_params *p, const rw_derived *d, const rw_regime *m, const rw_input *in,
                           const double x[RW_NX], const double dx[RW_NX], double F_top)
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
        return -(m_wall + m_over) * in->ag + d->pa[0] * dx[2] + d->pa[1] * dx[3] - F_top;
    }
}

int rw_condition(const rw_params *p, const rw_regime *m)
{
    if (rw_is_rigid(p) && (m->closed_b || m->closed_m)) return 0;
    if (p->support != RW_FLEXIBLE_TOP) return m->side_b > 0 ? 1 : 2;
    if (m->side_b > 0) return m->side_m < 0 ? 1 : 3;
    return m->side_m > 0 ? 2 : 4;
}
