/* Unit tests of the stiff tie held rigid (fmu_src/wall/rw_rigid_tie.c): the tie's frequency, when
 * the tie may be held, and the held motion against the full Eq. 3.1 on its slow manifold, where the
 * tie's quasi-static deflection keeps the top's acceleration at zero. */
#include <math.h>
#include <stdio.h>

#include "physics_check.h"
#include "rw_physics.h"

static const int LAWS[] = {RW_SEMI_RIGID_PAPER, RW_SEMI_RIGID_HINGE, RW_DOHERTY_HINGE};

static rw_params stiff_wall(int law, double Kd)
{
    rw_params p = paper_params();
    p.support = RW_FLEXIBLE_TOP;
    p.hingeLaw = law;
    p.Kd = Kd;
    return p;
}

/* the larger root of det(A - w2 M) = 0, written out here from the quadratic */
static double top_eigenvalue(const double A[2][2], const double M[2][2])
{
    const double a = M[0][0] * M[1][1] - M[0][1] * M[1][0];
    const double b = -(A[0][0] * M[1][1] + A[1][1] * M[0][0] - A[0][1] * M[1][0] - A[1][0] * M[0][1]);
    const double c = A[0][0] * A[1][1] - A[0][1] * A[1][0];
    return (-b + sqrt(b * b - 4.0 * a * c)) / (2.0 * a);
}

/* the ratio falls as 1/K_d, and its tie part is the full system's top mode at a stiff K_d */
static void test_ratio(void)
{
    size_t i;
    for (i = 0; i < sizeof LAWS / sizeof LAWS[0]; i++) {
        rw_params p = stiff_wall(LAWS[i], 1e10), p2 = stiff_wall(LAWS[i], 2e10);
        rw_derived d, d2;
        rw_derive(&p, &d);
        rw_derive(&p2, &d2);
        check_close("ratio(2 K_d) * 2 / ratio(K_d)", 2.0 * rw_tie_stiffness_ratio(&p2, &d2) / rw_tie_stiffness_ratio(&p, &d),
                    1.0, 1e-12);
        CHECK(rw_tie_stiffness_ratio(&p, &d) > 0.0 && rw_tie_stiffness_ratio(&p, &d) < 1e-3, "law %d: ratio %g at 1e10",
              LAWS[i], rw_tie_stiffness_ratio(&p, &d));
    }
    {
        /* rigid law (J = 0): the slow part is gravity alone, so ratio * omega_tie^2 is the top
         * eigenvalue of (K at K_d = 0, M) in magnitude, and omega_tie^2 the full system's top one */
        rw_params p = stiff_wall(RW_RIGID, 1e12), p0 = stiff_wall(RW_RIGID, 0.0);
        rw_derived d, d0;
        double Kneg[2][2];
        int r, c;
        rw_derive(&p, &d);
        rw_derive(&p0, &d0);
        for (r = 0; r < 2; r++)
            for (c = 0; c < 2; c++) Kneg[r][c] = -d0.K[r][c]; /* gravity only: negative definite */
        check_close("ratio of the rigid law", rw_tie_stiffness_ratio(&p, &d),
                    top_eigenvalue((const double(*)[2])Kneg, d.M) / top_eigenvalue((const double(*)[2])d.K, d.M), 1e-6);
    }
}

static void test_when_held(void)
{
    rw_params p = stiff_wall(RW_DOHERTY_HINGE, 1e12);
    rw_derived d;
    const double on[RW_NX] = {0.01, -0.01, 0.2, -0.2}, off[RW_NX] = {0.01, -0.009, 0.2, -0.2};
    const rw_input still = {1.0, 0.0}, driven = {1.0, 1e-6};
    rw_regime open = {0, 0, 1, -1, 0.0, 0.0, 0, 0}, half = open;
    half.closed_m = 1;
    rw_derive(&p, &d);
    CHECK(rw_tie_holds_rigid(&p, &d, &open, &still, on), "a 1e12 tie on dohertyHinge must be held");
    CHECK(!rw_tie_holds_rigid(&p, &d, &open, &driven, on), "not with the far end moving");
    CHECK(!rw_tie_holds_rigid(&p, &d, &open, &still, off), "not with the top displaced");
    p.Kd = 1e5;
    rw_derive(&p, &d);
    CHECK(!rw_tie_holds_rigid(&p, &d, &open, &still, on), "not a soft tie");
    p = stiff_wall(RW_RIGID, 1e12);
    rw_derive(&p, &d);
    CHECK(rw_tie_holds_rigid(&p, &d, &open, &still, on), "the rigid law at 1e12");
    CHECK(!rw_tie_holds_rigid(&p, &d, &half, &still, on), "not a rigid law with one hinge closed");
    p.Kd = 1e10; /* its ratio counts RW_RIGID_LAW_TIE_FACTOR times: 4e-7 x 100 > 1e-5 */
    rw_derive(&p, &d);
    CHECK(!rw_tie_holds_rigid(&p, &d, &open, &still, on), "not the rigid law at 1e10");
    p = stiff_wall(RW_DOHERTY_HINGE, 1e12);
    p.support = RW_SIMPLY_SUPPORTED;
    rw_derive(&p, &d);
    CHECK(!rw_tie_holds_rigid(&p, &d, &open, &still, on), "not a wall without the spring");
}

/* a1 + a2 of the full model at x with the top displaced by delta rotations */
static double top_acceleration(const rw_params *p, const rw_derived *d, const rw_regime *m, const rw_input *in,
                               const double x[RW_NX], double delta, double dx[RW_NX])
{
    const double xd[RW_NX] = {x[0], x[1] + delta, x[2], x[3]};
    rw_derivatives(p, d, m, in, xd, dx);
    return dx[2] + dx[3];
}

/* On the slow manifold (the deflection delta at which the full model's top does not accelerate),
 * the full model's q1'' and spring force are the held tie's, to about the ratio of the stiffnesses.
 * K_d at most 1e10: beyond, the full model's own rounding (K q ~ 1e10 for forces ~ 1e3) is larger
 * than the difference sought. */
static void test_motion_on_slow_manifold(void)
{
    const double thetas[] = {1e-5, 0.004, -0.012}, K_ds[] = {1e8, 1e10};
    size_t i, j, k;
    for (i = 0; i < sizeof LAWS / sizeof LAWS[0]; i++)
        for (j = 0; j < sizeof thetas / sizeof thetas[0]; j++)
            for (k = 0; k < sizeof K_ds / sizeof K_ds[0]; k++) {
                rw_params p = stiff_wall(LAWS[i], K_ds[k]);
                rw_derived d;
                rw_regime m;
                const rw_input in = {2.5, 0.0};
                double x[RW_NX] = {thetas[j], -thetas[j], 0.05, -0.05}, dx[RW_NX], held[RW_NX], F_held, ratio;
                double f0, f1, delta, tol;
                char what[96];
                rw_derive(&p, &d);
                rw_init_regime(&p, &d, &in, x, &m, NULL, NULL);
                ratio = rw_tie_stiffness_ratio(&p, &d);
                f0 = top_acceleration(&p, &d, &m, &in, x, 0.0, dx);
                f1 = top_acceleration(&p, &d, &m, &in, x, 1e3 / p.Kd, dx); /* about the deflection a kN/m force gives */
                delta = -f0 * (1e3 / p.Kd) / (f1 - f0);
                top_acceleration(&p, &d, &m, &in, x, delta, dx);
                rw_rigid_tie_motion(&p, &d, &m, &in, x, held, &F_held);
                tol = 10.0 * ratio + 1e-9;
                snprintf(what, sizeof what, "law %d theta %g Kd %g: held q1''", LAWS[i], thetas[j], K_ds[k]);
                CHECK(fabs(held[2] - dx[2]) <= tol * fabs(dx[2]), "%s = %.12g, full %.12g (tol %g)", what, held[2], dx[2],
                      tol);
                CHECK(held[3] == -held[2] && held[0] == x[2] && held[1] == x[3], "%s: q2'' = -q1''", what);
                snprintf(what, sizeof what, "law %d theta %g Kd %g: F_top", LAWS[i], thetas[j], K_ds[k]);
                {
                    const double F_full = p.Kd * delta * p.h / 2.0;
                    CHECK(fabs(F_held - F_full) <= tol * fabs(F_full), "%s = %.12g, full %.12g", what, F_held, F_full);
                }
            }
}

/* A held tie's rigid wall at rest opens as a mechanism q = theta (1, -1): both hinges at once, at the
 * ground acceleration where Doherty's simply supported rigid wall opens, 4 g (b/h)(1 + 0.75 psi)
 * (W ag/(2g) = F_r, Table 5.1 with both lever arms b/2) */
static void test_held_rigid_law_opens_as_the_simply_supported_wall(void)
{
    const double psis[] = {0.0, 0.5, 2.0};
    size_t i;
    for (i = 0; i < sizeof psis / sizeof psis[0]; i++) {
        rw_params p = stiff_wall(RW_RIGID, 1e12);
        rw_derived d;
        int sign;
        p.psi = psis[i];
        rw_derive(&p, &d);
        for (sign = -1; sign <= 1; sign += 2) {
            const double ag_open = 4.0 * p.g * p.b / p.h * (1.0 + 0.75 * p.psi);
            const rw_input below = {sign * ag_open * (1.0 - 1e-9), 0.0}, above = {sign * ag_open * (1.0 + 1e-9), 0.0};
            double x[RW_NX] = {0.0, 0.0, 0.0, 0.0}, dx[RW_NX], F_top;
            const rw_input none = {0.0, 0.0};
            rw_regime m;
            rw_init_regime(&p, &d, &none, x, &m, NULL, NULL);
            m.tie_held = 1;
            CHECK(m.closed_b && m.closed_m, "psi %g: the wall starts at rest", p.psi);
            CHECK(!rw_open_hinges(&p, &d, &m, &below, x, NULL, NULL), "psi %g, sign %d: holds just below", p.psi, sign);
            CHECK(rw_open_hinges(&p, &d, &m, &above, x, NULL, NULL) && !m.closed_b && !m.closed_m,
                  "psi %g, sign %d: both hinges open just above", p.psi, sign);
            /* it turns away from the ground's acceleration, the mid-height hinge to the other side */
            CHECK(m.side_b == -sign && m.side_m == sign, "psi %g: sides %d %d", p.psi, m.side_b, m.side_m);
            rw_rigid_tie_motion(&p, &d, &m, &above, x, dx, &F_top);
            CHECK(m.side_b * dx[2] >= 0.0 && dx[3] == -dx[2], "psi %g: it accelerates to its side (%g)", p.psi, dx[2]);
        }
    }
}

/* A slow impact of a held tie's rigid wall closes both hinges and leaves the wall at rest */
static void test_held_rigid_law_rests_with_both_hinges(void)
{
    rw_params p = stiff_wall(RW_RIGID, 1e12);
    rw_derived d;
    rw_regime m = {0, 0, 1, -1, 0.0, 0.0, 0, 1};
    const rw_input in = {0.0, 0.0};
    const double v = -0.5 * p.restRate / p.er;
    double x[RW_NX] = {-1e-13, 1e-13, v, -v};
    rw_event_result r;
    rw_derive(&p, &d);
    rw_event_update(&p, &d, &m, &in, x, &r, NULL, NULL);
    CHECK(m.closed_b && m.closed_m, "both hinges closed (%d %d)", m.closed_b, m.closed_m);
    CHECK(x[0] == 0.0 && x[1] == 0.0 && x[2] == 0.0 && x[3] == 0.0, "at rest: %g %g %g %g", x[0], x[1], x[2], x[3]);
    {
        /* the mid-height hinge's root found first (its indicator's offset differs from the base's):
         * it switches side and stays open, for the base's event just after to close both */
        rw_regime early = {0, 0, 1, 1, 0.0, 0.0, 0, 1}; /* mid-height side +1: x = -4e-11 has crossed */
        double y[RW_NX] = {2e-11, -2e-11, -0.2 * p.restRate, 0.2 * p.restRate};
        rw_event_update(&p, &d, &early, &in, y, &r, NULL, NULL);
        CHECK(!early.closed_m && !early.closed_b, "the mid-height hinge must not rest alone (%d %d)", early.closed_b,
              early.closed_m);
    }
}

int main(void)
{
    test_ratio();
    test_when_held();
    test_motion_on_slow_manifold();
    test_held_rigid_law_opens_as_the_simply_supported_wall();
    test_held_rigid_law_rests_with_both_hinges();
    printf("%d checks, %d failures\n", checks, failures);
    return failures ? 1 : 0;
}
