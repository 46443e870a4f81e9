/* Unit tests of the event indicators and the collapse test (fmu_src/wall/rw_indicators.c): values,
 * rates against central differences, the forms the exact engine evaluates (collapse, closed
 * hinges), collapse and toppling. */
#include "check.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "physics_check.h"
#include "rw_physics.h"

static void test_indicators(void)
{
    rw_params p = paper_params();
    rw_derived d;
    rw_regime m;
    rw_input in = {0.5, 0.0};
    double x[RW_NX] = {0.001, 0.0005, -0.1, 0.0}, z1[RW_NZ], z2[RW_NZ], y[RW_NX];
    int law, i;
    for (law = 1; law <= 3; law++) {
        p.hingeLaw = law;
        memcpy(y, x, sizeof y);
        init(&p, &d, &m, &in, y);
        /* continuity and sign change across q1 = 0 with the regime frozen */
        y[0] = 1e-7;
        rw_event_indicators(&p, &d, &m, &in, y, z1);
        y[0] = -1e-7;
        rw_event_indicators(&p, &d, &m, &in, y, z2);
        CHECK(z1[RW_Z_BASE] > 0 && z2[RW_Z_BASE] < 0, "law %d: base indicator %g %g", law, z1[0], z2[0]);
        for (i = 0; i < RW_NZ; i++)
            CHECK(fabs(z1[i] - z2[i]) < 1e-3 * fmax(1.0, fabs(z1[i])) || i == RW_Z_COLLAPSE,
                  "law %d: indicator %d jumps %g -> %g", law, i, z1[i], z2[i]);
        /* breakpoint indicator of the semi-rigid laws */
        if (law != RW_RIGID) {
            y[0] = d.dir[0].theta_y * 0.999;
            rw_event_indicators(&p, &d, &m, &in, y, z1);
            y[0] = d.dir[0].theta_y * 1.001;
            rw_event_indicators(&p, &d, &m, &in, y, z2);
            CHECK(z1[RW_Z_BREAK] < 0 && z2[RW_Z_BREAK] > 0, "law %d: breakpoint indicator", law);
        }
    }
}

/* every indicator at x moved by u along (xd, in_rate) with the regime frozen */
static void indicators_along(const rw_params *p, const rw_derived *d, const rw_regime *m, const rw_input *in,
                             const rw_input *rate, const double x[RW_NX], const double xd[RW_NX], double u,
                             double z[RW_NZ])
{
    const rw_input iu = {in->ag + u * rate->ag, in->u_top + u * rate->u_top};
    double y[RW_NX];
    int i;
    for (i = 0; i < RW_NX; i++) y[i] = x[i] + u * xd[i];
    rw_event_indicators(p, d, m, &iu, y, z);
}

/* The rates the exact engine brackets and refines roots with (rw_event_indicator_rates) against
 * central differences of the indicators along the same motion, for both supports the engine
 * covers, every law, both sides of each hinge and (rigid) every closed state, on the paper's wall
 * and on an eccentric one; the values are the FMU's own. Points where a kink lies within the
 * difference step are skipped (the one-sided differences disagree there). */
static void test_indicator_rates(void)
{
    static const int supports[2] = {RW_SIMPLY_SUPPORTED, RW_FLEXIBLE_TOP};
    unsigned long rng = 12345;
    int compared = 0, si, law, trial;
    for (si = 0; si < 2; si++)
        for (law = 1; law <= 4; law++)
            for (trial = 0; trial < 400; trial++) {
                rw_params p = trial % 8 >= 4 ? eccentric_params() : paper_params(); /* both, every closed state */
                rw_derived d;
                rw_regime m;
                rw_input in, rate;
                double x[RW_NX], xd[RW_NX], z[RW_NZ], dz[RW_NZ], zp[RW_NZ], zm[RW_NZ], zpp[RW_NZ], zmm[RW_NZ];
                const double u = 1e-6;
                int k;
                p.support = supports[si];
                p.hingeLaw = law;
                p.Kd = trial % 2 ? 5e4 : 5e7;
                rw_derive(&p, &d);
                memset(&m, 0, sizeof m);
                m.side_b = uniform(&rng, -1, 1) > 0 ? 1 : -1;
                m.side_m = uniform(&rng, -1, 1) > 0 ? 1 : -1;
                m.zoff_b = m.zoff_m = uniform(&rng, 0, 1e-9);
                if (law == RW_RIGID) {
                    m.closed_b = trial % 4 == 1 || trial % 4 == 3;
                    m.closed_m = p.support == RW_FLEXIBLE_TOP && trial % 4 >= 2;
                }
                for (k = 0; k < RW_NX; k++) {
                    x[k] = uniform(&rng, -1, 1) * (k < 2 ? 0.6 * d.q_topple : 2.0);
                    xd[k] = uniform(&rng, -1, 1) * (k < 2 ? 2.0 : 50.0);
                }
                if (p.support == RW_SIMPLY_SUPPORTED) x[1] = -x[0], xd[1] = -xd[0];
                in.ag = uniform(&rng, -5, 5);
                in.u_top = uniform(&rng, -0.01, 0.01);
                rate.ag = uniform(&rng, -100, 100);
                rate.u_top = uniform(&rng, -0.1, 0.1);
                for (k = 0; k < RW_NZ; k++) z[k] = dz[k] = 7.0;
                rw_event_indicator_rates(&p, &d, &m, &in, &rate, x, xd, NULL, NULL, RW_Z_ALL, z, dz);
                indicators_along(&p, &d, &m, &in, &rate, x, xd, 0.0, zp);
                for (k = 0; k < RW_NZ; k++)
                    CHECK(z[k] == zp[k] || (z[k] == 7.0 && zp[k] == 1.0), "support %d law %d: z[%d] %.17g, FMU's %.17g",
                          p.support, law, k, z[k], zp[k]);
                indicators_along(&p, &d, &m, &in, &rate, x, xd, u, zp);
                indicators_along(&p, &d, &m, &in, &rate, x, xd, -u, zm);
                indicators_along(&p, &d, &m, &in, &rate, x, xd, 2 * u, zpp);
                indicators_along(&p, &d, &m, &in, &rate, x, xd, -2 * u, zmm);
                for (k = 0; k < RW_NZ; k++) {
                    const double fwd = (zpp[k] - zp[k]) / u, bwd = (zm[k] - zmm[k]) / u, mid = (zp[k] - zm[k]) / (2 * u);
                    const double scale = fmax(1e-3, fabs(mid));
                    if (z[k] == 7.0 || fabs(fwd - bwd) > 1e-3 * scale) continue; /* unused, or a kink nearby */
                    CHECK(fabs(dz[k] - mid) <= 1e-5 * scale, "support %d law %d trial %d: dz[%d] = %.12g, difference %.12g",
                          p.support, law, trial, k, dz[k], mid);
                    compared++;
                }
            }
    CHECK(compared > 10000, "indicator rates compared: %d", compared);
}

/* The collapse indicator's form on a region (rw_collapse_form) equals G(q)/|q|^2/zscale from the
 * law's own moments wherever the law's Q is affine in q alone */
static void test_collapse_form(void)
{
    unsigned long rng = 777;
    int law, trial, compared = 0;
    for (law = RW_SEMI_RIGID_HINGE; law <= RW_DOHERTY_HINGE; law++)
        for (trial = 0; trial < 500; trial++) {
            rw_params p = paper_params();
            rw_derived d;
            rw_collapse_form f;
            const rw_hinge_law *L = rw_hinge_law_of(law);
            double x[RW_NX], Q[2], J[2][2], c[2], n2, want, got;
            p.hingeLaw = law;
            p.Kd = trial % 2 ? 5e3 : 5e6;
            rw_derive(&p, &d);
            x[0] = uniform(&rng, -0.5, 0.5) * d.q_topple;
            x[1] = uniform(&rng, -0.5, 0.5) * d.q_topple;
            x[2] = x[3] = 0.1;
            L->moments(&d, 1, 1, x, x + 2, Q, J);
            c[0] = Q[0] - J[0][0] * x[0] - J[0][1] * x[1];
            c[1] = Q[1] - J[1][0] * x[0] - J[1][1] * x[1];
            rw_collapse_form_of(&d, c, (const double(*)[2])J, &f);
            n2 = x[0] * x[0] + x[1] * x[1];
            want = rw_collapse_G_of(&d, x, Q) / n2 / d.zscale;
            got = rw_collapse_form_value(&f, x, NULL, NULL);
            if (want >= RW_COLLAPSE_ZMAX) continue;
            CHECK(fabs(got - want) <= 1e-9 * fmax(1.0, fabs(want)), "law %d: form %.17g, G %.17g", law, got, want);
            compared++;
        }
    CHECK(compared > 500, "collapse forms compared: %d", compared);
}

/* The closed rigid hinges' moments as data (rw_closed_form) equal rw_closed_forces in every closed
 * state, at any rotations and inputs */
static void test_closed_force_form(void)
{
    unsigned long rng = 4242;
    int state, trial, compared = 0;
    for (state = 1; state < 4; state++)
        for (trial = 0; trial < 200; trial++) {
            rw_params p = paper_params();
            rw_derived d;
            rw_regime m;
            rw_closed_form F;
            double x[RW_NX], fb, fm, want[2];
            rw_input in;
            int j;
            p.hingeLaw = RW_RIGID;
            p.Kd = trial % 2 ? 5e3 : 5e6;
            rw_derive(&p, &d);
            memset(&m, 0, sizeof m);
            m.closed_b = state & 1, m.closed_m = (state >> 1) & 1;
            m.side_b = trial % 3 ? 1 : -1, m.side_m = trial % 5 ? -1 : 1;
            rw_closed_force_form(&p, &d, &m, &F);
            x[0] = uniform(&rng, -0.5, 0.5) * d.q_topple;
            x[1] = uniform(&rng, -0.5, 0.5) * d.q_topple;
            x[2] = uniform(&rng, -1.0, 1.0), x[3] = uniform(&rng, -1.0, 1.0);
            in.ag = uniform(&rng, -10.0, 10.0), in.u_top = uniform(&rng, -0.05, 0.05);
            rw_closed_forces(&p, &d, &m, &in, x, &fb, &fm);
            want[0] = fb, want[1] = fm;
            for (j = 0; j < 2; j++) {
                const double got = F.c[j] + F.G[j][0] * x[0] + F.G[j][1] * x[1] + F.g_ag[j] * in.ag + F.g_u[j] * in.u_top;
                const double scale = fabs(F.c[j]) + fabs(F.g_ag[j] * in.ag) + fabs(F.g_u[j] * in.u_top) +
                                     fabs(F.G[j][0] * x[0]) + fabs(F.G[j][1] * x[1]) + 1e-300;
                CHECK(fabs(got - want[j]) <= 1e-13 * scale, "closed state %d, moment %d: form %.17g, forces %.17g", state, j,
                      got, want[j]);
                compared++;
            }
        }
    CHECK(compared == 1200, "closed forms compared: %d", compared);
}

/* Collapse where the restoring force vanishes: the 2DOF along the simply supported shape and the
 * 1DOF at Delta_u of the direction of motion, the parapet at alpha; the paper's wall (psi = 0) and
 * an eccentric one, whose directions differ */
static void test_collapse(void)
{
    rw_regime m;
    rw_input in = {0, 0};
    double x[RW_NX];
    int wall, k, law;
    for (wall = 0; wall < 2; wall++)
        for (k = 0; k < 2; k++) {
            rw_params p = wall ? eccentric_params() : paper_params();
            rw_derived d;
            const double s = k == 0 ? 1.0 : -1.0;
            if (!wall) p.psi = 0.0;
            for (law = 1; law <= 3; law++) {
                /* 2DOF along the simply supported shape q2 = -q1: G(q) = 0 at D = Delta_u (outside elastic range) */
                double th;
                p.hingeLaw = law;
                rw_derive(&p, &d);
                th = s * 2 * d.dir[k].Du / p.h;
                x[0] = 0.999 * th; x[1] = -x[0]; x[2] = x[3] = 0;
                init(&p, &d, &m, &in, x);
                if (law != RW_SEMI_RIGID_PAPER) /* the paper law's Q is not a potential: its root differs */
                    CHECK(!rw_collapse_reason(&p, &d, &m, &in, x), "wall %d law %d side %+g collapsed before Delta_u", wall,
                          law, s);
                x[0] = 1.001 * th; x[1] = -x[0];
                init(&p, &d, &m, &in, x);
                if (law != RW_SEMI_RIGID_PAPER)
                    CHECK(rw_collapse_reason(&p, &d, &m, &in, x), "wall %d law %d side %+g not collapsed past Delta_u",
                          wall, law, s);
            }
            p.support = RW_SIMPLY_SUPPORTED;
            rw_derive(&p, &d);
            x[0] = s * 2 * d.dir[k].Du / p.h * 0.9999;
            x[1] = -x[0];
            CHECK(!rw_collapse_reason(&p, &d, &m, &in, x), "wall %d: 1DOF collapsed before Delta_u(%+g)", wall, s);
            x[0] = s * 2 * d.dir[k].Du / p.h * 1.0001;
            x[1] = -x[0];
            CHECK(rw_collapse_reason(&p, &d, &m, &in, x), "wall %d: 1DOF not collapsed past Delta_u(%+g)", wall, s);
            p.support = RW_PARAPET;
            rw_derive(&p, &d);
            x[0] = s * d.alpha * 0.999;
            CHECK(!rw_collapse_reason(&p, &d, &m, &in, x), "parapet collapsed before alpha");
            x[0] = s * d.alpha * 1.001;
            CHECK(rw_collapse_reason(&p, &d, &m, &in, x), "parapet not collapsed past alpha");
        }
}

/* The collapse test at the event where a hinge leaves its elastic range: the state sits on the
 * range's end to rounding, and the direction of motion decides (past instability when the wall
 * moves out with G <= 0; standing when it moves back in). The state is the one of a wall without
 * a spring (K_d = 0, dohertyHinge) at its base's first breakpoint, found by the engine's longer
 * random study: the FMU kept the wall standing there and declared the collapse 32 ms later. */
static void test_collapse_where_the_elastic_range_ends(void)
{
    rw_params p;
    rw_derived d;
    rw_regime m;
    rw_input in = {0.0, 0.0};
    double x[RW_NX], G;
    rw_params_default(&p);
    p.h = 0.6391264126739408; p.b = 0.06893094565554227; p.W = 948.586498217323; p.psi = 2.43956223451747;
    p.er = 0.5190288381649051; p.delta1Ratio = 0.19495750897142883; p.hingeSat = 2.326972415937138;
    p.hingeLaw = RW_DOHERTY_HINGE; p.Kd = 0.0;
    rw_derive(&p, &d);
    x[0] = -2.0 * d.dir[RW_SIDE(-1)].D1 / p.h * (1.0 - 1e-13); /* the breakpoint, on the elastic side by rounding */
    x[1] = x[0] - 0.0512;
    x[2] = -0.2039; x[3] = -0.7509;            /* moving out of the elastic range */
    init(&p, &d, &m, &in, x);
    G = rw_collapse_G(&p, &d, &m, &in, x);
    CHECK(G < 0.0, "the test state should be past instability but for the elastic range: G = %g", G);
    CHECK(rw_collapse_reason(&p, &d, &m, &in, x) == RW_PAST_INSTABILITY,
          "leaving the elastic range with G = %g < 0: not collapsed", G);
    x[2] = -x[2]; x[3] = -x[3];               /* moving back in */
    CHECK(rw_collapse_reason(&p, &d, &m, &in, x) == RW_STANDING, "entering the elastic range: collapsed");
}

int main(void)
{
    test_indicators();
    test_indicator_rates();
    test_collapse_form();
    test_closed_force_form();
    test_collapse();
    test_collapse_where_the_elastic_range_ends();
    printf("%d checks, %d failures\n", checks, failures);
    return failures ? 1 : 0;
}
