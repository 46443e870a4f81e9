/* Unit tests of the hinge laws (fmu_src/wall/rw_hinge_laws.c): Jacobians and potentials, the
 * dohertyHinge law against Doherty's trilinear law, every kink of Q(q) a breakpoint. */
#include "check.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "physics_check.h"
#include "rw_physics.h"

/* every law: J = dQ/dq by central differences inside a region, and Q = -grad V_h where the law
 * has a potential; at points in each region of each hinge, on both sides, for the paper's wall and
 * for an eccentric one (capacities and breakpoints that differ between the sides) */
static void test_hinge_laws_jacobian_and_potential(void)
{
    const double fr[] = {0.3, 1.5, 3.0, 8.0}; /* fractions of the first breakpoint rotation */
    int wall, sign, law, i, j, k;
    for (wall = 0; wall < 2; wall++)
        for (sign = -1; sign <= 1; sign += 2)
            for (law = 1; law <= 4; law++) {
                rw_params p = wall ? eccentric_params() : paper_params();
                rw_derived d;
                const rw_hinge_law *L = rw_hinge_law_of(law);
                double r1;
                rw_derive(&p, &d);
                /* the smaller of the two sides' first breakpoints */
                r1 = law == RW_DOHERTY_HINGE ? 2 * fmin(d.dir[0].D1, d.dir[1].D1) / p.h
                                             : fmin(d.dir[0].theta_y, d.dir[1].theta_y);
                CHECK(L && L->id == law, "law %d missing", law);
                for (i = 0; i < 4; i++)
                    for (j = 0; j < 4; j++) {
                        /* off every kink; q1 on the side `sign`, x = q2 - q1 on the other */
                        double q[2] = {sign * fr[i] * r1,
                                       sign * (-fr[j] * r1 * (law == RW_DOHERTY_HINGE ? 2.0 : 1.0) + fr[i] * r1 * 0.37)};
                        const double dq[2] = {0.1 * sign, -0.1 * sign}, e = 1e-7 * r1;
                        double Q[2], J[2][2], Qp[2], Qm[2], Jx[2][2];
                        L->moments(&d, sign, -sign, q, dq, Q, J);
                        for (k = 0; k < 2; k++) {
                            double qp[2] = {q[0], q[1]}, qm[2] = {q[0], q[1]};
                            qp[k] += e;
                            qm[k] -= e;
                            L->moments(&d, sign, -sign, qp, dq, Qp, Jx);
                            L->moments(&d, sign, -sign, qm, dq, Qm, Jx);
                            check_close("dQ0/dq", J[0][k], (Qp[0] - Qm[0]) / (2 * e), 1e-5);
                            check_close("dQ1/dq", J[1][k], (Qp[1] - Qm[1]) / (2 * e), 1e-5);
                            if (law != RW_SEMI_RIGID_PAPER) /* the paper's law has no potential */
                                check_close("-dV/dq", -(L->potential(&d, qp) - L->potential(&d, qm)) / (2 * e), Q[k], 1e-5);
                        }
                    }
            }
}

/* The rigid law's moments at mu = +-1 are the capacities of the sides, computed here from the
 * weights' moments about each pivot (docs/model.md "Derived"): an eccentric top load toward +x is
 * nearer the +x pivots, so each hinge carries less turning to +x than to -x */
static void test_capacities_per_side(void)
{
    rw_params p = eccentric_params();
    rw_derived d;
    const double t = p.b - 2 * p.pointing, eb = p.eBaseRatio * t / 2, em = p.eHingeRatio * t / 2;
    const double W1 = p.W / 2, Wd = p.psi * W1, Wo = p.psiWeightOnly * W1;
    int s;
    rw_derive(&p, &d);
    for (s = -1; s <= 1; s += 2) {
        /* base pivot at s*eb: the bodies and the weight-only overburden on the centreline, the top
         * load at eTop; mid-height pivot at s*em: the upper body, the loads */
        const double cap_b = 2 * W1 * eb + Wo * eb + Wd * (eb - s * p.eTop);
        const double cap_m = W1 * em + Wo * em + Wd * (em - s * p.eTop);
        const rw_regime m = {.side_b = s, .side_m = s};
        double q[RW_NX] = {0.01 * s, 0.02 * s, 0, 0}, Q[2];
        check_close("cap_b(s)", rw_cap_b_of(&d, s), cap_b, 1e-14);
        check_close("cap_m(s)", rw_cap_m_of(&d, s), cap_m, 1e-14);
        p.hingeLaw = RW_RIGID;
        rw_hinge_Q(&p, &d, &m, q, Q); /* condition 3 or 4: Q2 = -cap_m(s) s, Q1 + Q2 = -cap_b(s) s */
        check_close("rigid Q2", Q[1], -s * cap_m, 1e-12);
        check_close("rigid Q1 + Q2", Q[0] + Q[1], -s * cap_b, 1e-12);
    }
    CHECK(rw_cap_b_of(&d, 1) < rw_cap_b_of(&d, -1) && rw_cap_m_of(&d, 1) < rw_cap_m_of(&d, -1),
          "the eccentric load toward +x does not lower the +x capacities");
}

/* dohertyHinge along the simply supported shape q2 = -q1: the generalised force on D of the hinges
 * plus gravity equals Doherty's trilinear F(D) of the 1DOF, in every branch, both directions, on
 * the paper's wall and on an eccentric one */
static void test_doherty_hinge_reduces_to_trilinear(void)
{
    const double Ds[] = {0.2, 0.9, 1.5, 3.0, 5.0, 15.0, 19.0}; /* in units of Delta_1 */
    int wall, k, i;
    for (wall = 0; wall < 2; wall++)
        for (k = 0; k < 2; k++) {
            rw_params p = wall ? eccentric_params() : paper_params();
            rw_derived d;
            const int s = k == 0 ? 1 : -1;
            rw_regime m = {.side_b = s, .side_m = -s};
            p.hingeLaw = RW_DOHERTY_HINGE;
            p.Kd = 0.0; /* the spring does no work along q2 = -q1 */
            rw_derive(&p, &d);
            for (i = 0; i < 7; i++) {
                const rw_direction *r = &d.dir[k];
                const double D = s * Ds[i] * r->D1, q1 = 2 * D / p.h;
                double x[RW_NX] = {q1, -q1, 0, 0}, Q[2];
                /* generalised force on D: (dq/dD).(Q - K q), dq/dD = (2/h)(1, -1) */
                const double Kq0 = d.K[0][0] * x[0] + d.K[0][1] * x[1], Kq1 = d.K[1][0] * x[0] + d.K[1][1] * x[1];
                double F2dof;
                if (fabs(D) >= r->Du) break;
                rw_hinge_Q(&p, &d, &m, x, Q);
                F2dof = 2.0 / p.h * ((Q[0] - Kq0) - (Q[1] - Kq1));
                p.support = RW_SIMPLY_SUPPORTED;
                check_close("F(D) 2DOF dohertyHinge vs 1DOF trilinear", F2dof / r->Fr, rw_force_1dof(&p, &d, &m, D) / r->Fr,
                            1e-12);
                p.support = RW_FLEXIBLE_TOP;
            }
        }
}

/* every kink of Q(q) is a breakpoint: with the sides fixed, Q is affine along any short segment
 * over which no breakpoint indicator changes sign (the exact engine takes Q = c + J q on such a
 * region). The segments cross q1 = 0, q2 = 0 and q2 = q1, where a law may hide a kink; the
 * eccentric wall's breakpoints lie at different distances on the two sides, and its moments'
 * slopes change where a hinge's rotation passes zero, at the hinge's own event
 * (rw_moments_of_q_alone). */
static void test_hinge_laws_kinks_are_breakpoints(void)
{
    const double dirs[4][2] = {{1, 0}, {0, 1}, {1, 1}, {1, -1}};
    int wall, law, sb, sm, i, j, k, n;
    for (wall = 0; wall < 2; wall++) for (law = RW_SEMI_RIGID_PAPER; law <= RW_DOHERTY_HINGE; law++) {
        rw_params p = wall ? eccentric_params() : paper_params();
        rw_derived d;
        const rw_hinge_law *L = rw_hinge_law_of(law);
        double r1, len;
        rw_derive(&p, &d);
        r1 = law == RW_DOHERTY_HINGE ? 2 * d.dir[0].D1 / p.h : d.dir[0].theta_y;
        len = 0.1 * r1;
        const double dq[2] = {0.0, 0.0};
        rw_indicator_line lines[RW_NBREAK];
        L->breakpoints(&d, lines);
        for (sb = -1; sb <= 1; sb += 2)
            for (sm = -1; sm <= 1; sm += 2)
                for (i = -6; i <= 6; i++)
                    for (j = -6; j <= 6; j++)
                        for (k = 0; k < 4; k++) {
                            /* a segment of length len through (i, j) * len/2, off the grid's symmetry */
                            const double c0 = (i + 0.013) * len / 2, c1 = (j - 0.021) * len / 2;
                            const double a[2] = {c0 - dirs[k][0] * len / 2, c1 - dirs[k][1] * len / 2};
                            const double b[2] = {c0 + dirs[k][0] * len / 2, c1 + dirs[k][1] * len / 2};
                            const double c[2] = {c0, c1};
                            double Qa[2], Qb[2], Qc[2], J[2][2];
                            int crosses = 0;
                            for (n = 0; n < RW_NBREAK; n++)
                                crosses |= (rw_line_value(&lines[n], a, NULL, NULL) > 0.0) !=
                                           (rw_line_value(&lines[n], b, NULL, NULL) > 0.0);
                            if (!rw_moments_of_q_alone(&p)) /* the hinges' own events at zero rotation */
                                crosses |= (a[0] > 0.0) != (b[0] > 0.0) || (a[1] - a[0] > 0.0) != (b[1] - b[0] > 0.0);
                            if (crosses) continue;
                            L->moments(&d, sb, sm, a, dq, Qa, J);
                            L->moments(&d, sb, sm, b, dq, Qb, J);
                            L->moments(&d, sb, sm, c, dq, Qc, J);
                            CHECK(fabs(Qc[0] - 0.5 * (Qa[0] + Qb[0])) <= 1e-9 * d.cap_b &&
                                      fabs(Qc[1] - 0.5 * (Qa[1] + Qb[1])) <= 1e-9 * d.cap_b,
                                  "law %d, sides %+d %+d: Q has a kink between (%g, %g) and (%g, %g) that no "
                                  "breakpoint marks", law, sb, sm, a[0], a[1], b[0], b[1]);
                        }
    }
}

int main(void)
{
    test_hinge_laws_jacobian_and_potential();
    test_capacities_per_side();
    test_doherty_hinge_reduces_to_trilinear();
    test_hinge_laws_kinks_are_breakpoints();
    printf("%d checks, %d failures\n", checks, failures);
    return failures ? 1 : 0;
}
