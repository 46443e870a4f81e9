/* Unit tests of the event rules and the energy (fmu_src/wall/rw_events.c, rw_outputs.c): the
 * impact map, rigid hinges' rest and opening, free rocking with er = 1 keeping its energy. */
#include "check.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "physics_check.h"
#include "rw_physics.h"

static void test_impact_map(void)
{
    rw_params p = paper_params();
    rw_derived d;
    rw_regime m;
    rw_input in = {0, 0};
    rw_event_result r;
    double x[RW_NX] = {0.01, 0.0, -0.2, 0.1};
    init(&p, &d, &m, &in, x);
    CHECK(m.side_b == 1 && m.side_m == -1 && !m.closed_b, "initial sides %d %d", m.side_b, m.side_m);
    /* q1 crossed zero (late root): impact, rates times er */
    x[0] = -1e-9;
    rw_event_update(&p, &d, &m, &in, x, &r, NULL, NULL);
    CHECK(r.impacts == 1 && m.side_b == -1, "late root: impacts %d side %d", r.impacts, m.side_b);
    check_close("dq1 after impact", x[2], -0.2 * p.er, 1e-14);
    check_close("dq2 after impact", x[3], 0.1 * p.er, 1e-14);
    CHECK(r.states_changed, "states_changed not set");
    /* repeated call: nothing */
    rw_event_update(&p, &d, &m, &in, x, &r, NULL, NULL);
    CHECK(r.impacts == 0 && !r.states_changed && !r.regime_changed, "second call changed something");
    /* the base swings past its elastic range on the new side (an event at the breakpoint), so
     * the next crossing is an impact that counts */
    x[0] = -0.01;
    x[2] = -0.01;
    rw_event_update(&p, &d, &m, &in, x, &r, NULL, NULL);
    CHECK(r.impacts == 0 && m.uplifted_b, "past the elastic range: impacts %d uplifted %d", r.impacts, m.uplifted_b);
    /* early root: still 1e-13 on the old side but moving toward the other one */
    x[0] = -1e-13;
    x[2] = 0.3;
    rw_event_update(&p, &d, &m, &in, x, &r, NULL, NULL);
    CHECK(r.impacts == 1 && m.side_b == 1, "early root: impacts %d side %d", r.impacts, m.side_b);
    /* a crossing without an uplift since the last one (the base oscillating within its elastic
     * range): the restitution applies, but it is not counted as an impact */
    x[0] = -1e-9;
    x[2] = -0.3;
    rw_event_update(&p, &d, &m, &in, x, &r, NULL, NULL);
    CHECK(m.side_b == -1 && r.impacts == 0 && r.states_changed, "elastic crossing: side %d impacts %d", m.side_b,
          r.impacts);
    check_close("dq1 after an elastic crossing", x[2], -0.3 * p.er, 1e-14);
    x[0] = 1e-9;
    x[2] = 0.3;
    rw_event_update(&p, &d, &m, &in, x, &r, NULL, NULL);
    CHECK(m.side_b == 1 && r.impacts == 0, "second elastic crossing: side %d impacts %d", m.side_b, r.impacts);
    /* at zero but moving away from it (e.g. just opened): no impact */
    x[0] = 1e-13;
    x[2] = 0.3;
    rw_event_update(&p, &d, &m, &in, x, &r, NULL, NULL);
    CHECK(r.impacts == 0, "impact while moving away from zero");
    /* mid-hinge switch: no energy loss */
    x[0] = 0.01; x[1] = 0.01 + 1e-9; x[2] = 0.1; x[3] = 0.2;
    rw_event_update(&p, &d, &m, &in, x, &r, NULL, NULL);
    CHECK(m.side_m == 1 && r.impacts == 0 && !r.states_changed, "mid switch: side %d", m.side_m);
}

static void test_rigid_open_close(void)
{
    rw_params p = paper_params();
    rw_derived d;
    rw_regime m;
    rw_input in = {0.1, 0.0};
    rw_event_result r;
    double x[RW_NX] = {0, 0, 0, 0}, z[RW_NZ];
    p.hingeLaw = RW_RIGID;
    init(&p, &d, &m, &in, x);
    CHECK(m.closed_b && m.closed_m, "rest not closed: %d %d", m.closed_b, m.closed_m);
    rw_event_indicators(&p, &d, &m, &in, x, z);
    CHECK(z[RW_Z_BASE] > 0 && z[RW_Z_MID] > 0, "rest indicators %g %g", z[0], z[1]);
    /* strong ground acceleration toward +x: wall rocks toward -x */
    in.ag = 5.0;
    rw_event_indicators(&p, &d, &m, &in, x, z);
    CHECK(z[RW_Z_BASE] < 0 || z[RW_Z_MID] < 0, "overload not signalled %g %g", z[0], z[1]);
    rw_event_update(&p, &d, &m, &in, x, &r, NULL, NULL);
    CHECK(r.regime_changed && (!m.closed_b || !m.closed_m), "nothing opened");
    CHECK(m.closed_b || m.side_b == -1, "base opened on side %d", m.side_b);
    {
        double dx[RW_NX];
        rw_derivatives(&p, &d, &m, &in, x, dx);
        CHECK(dx[2] <= 0 && dx[3] <= 0 && (dx[2] < 0 || dx[3] < 0), "opened wall accelerates toward -x: %g %g", dx[2], dx[3]);
    }
    /* closing: base impact with a rate below restRate */
    init(&p, &d, &m, &in, x);
    in.ag = 0.0;
    x[0] = 1e-3; x[1] = 1e-3; x[2] = 0.1; x[3] = 0.1;
    init(&p, &d, &m, &in, x);
    CHECK(!m.closed_b && m.closed_m && m.side_b == 1, "mid not closed for q1 = q2");
    x[0] = -1e-13; x[1] = -1e-13; x[2] = -1e-6; x[3] = -1e-6;
    rw_event_update(&p, &d, &m, &in, x, &r, NULL, NULL);
    CHECK(m.closed_b && m.closed_m && x[0] == 0 && x[1] == 0 && x[2] == 0 && x[3] == 0, "did not come to rest");
    /* parapet uplift threshold |ag| > g tan(alpha) */
    p.support = RW_PARAPET;
    rw_derive(&p, &d);
    memset(x, 0, sizeof x);
    in.ag = 0.99 * p.g * tan(d.alpha);
    init(&p, &d, &m, &in, x);
    CHECK(m.closed_b, "parapet opened below the threshold");
    in.ag = -1.01 * p.g * tan(d.alpha);
    init(&p, &d, &m, &in, x);
    CHECK(!m.closed_b && m.side_b == 1, "parapet: closed %d side %d above the threshold", m.closed_b, m.side_b);
    /* simply supported rigid: uplift at |ag| > (4b/h)(1 + 0.75 psi) g */
    p.support = RW_SIMPLY_SUPPORTED;
    {
        const double thr = 4 * p.b / p.h * (1 + 0.75 * p.psi) * p.g;
        in.ag = 0.999 * thr;
        init(&p, &d, &m, &in, x);
        CHECK(m.closed_b, "1DOF opened below the threshold");
        in.ag = 1.001 * thr;
        init(&p, &d, &m, &in, x);
        CHECK(!m.closed_b && m.side_b == -1, "1DOF: closed %d side %d above the threshold", m.closed_b, m.side_b);
    }
}

/* free rocking with er = 1: RK4 between impacts keeps the energy */
static void test_energy(void)
{
    rw_params p = paper_params();
    rw_derived d;
    rw_regime m;
    rw_input in = {0, 0};
    rw_event_result r;
    double x[RW_NX] = {0.03, -0.01, 0, 0}, E0, E;
    int law, k, i;
    p.er = 1.0;
    for (law = 1; law <= 3; law += 2) {
        double t = 0, hstep = 2e-5;
        p.hingeLaw = law;
        x[0] = 0.03; x[1] = -0.01; x[2] = x[3] = 0;
        init(&p, &d, &m, &in, x);
        E0 = rw_energy(&p, &d, &m, &in, x);
        for (k = 0; k < 50000; k++) {
            double k1[4], k2[4], k3[4], k4[4], y[4];
            rw_derivatives(&p, &d, &m, &in, x, k1);
            for (i = 0; i < 4; i++) y[i] = x[i] + 0.5 * hstep * k1[i];
            rw_derivatives(&p, &d, &m, &in, y, k2);
            for (i = 0; i < 4; i++) y[i] = x[i] + 0.5 * hstep * k2[i];
            rw_derivatives(&p, &d, &m, &in, y, k3);
            for (i = 0; i < 4; i++) y[i] = x[i] + hstep * k3[i];
            rw_derivatives(&p, &d, &m, &in, y, k4);
            for (i = 0; i < 4; i++) x[i] += hstep / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
            t += hstep;
            rw_event_update(&p, &d, &m, &in, x, &r, NULL, NULL);
        }
        E = rw_energy(&p, &d, &m, &in, x);
        CHECK(fabs(E - E0) < 2e-3 * fabs(E0), "law %d: energy %g -> %g after %g s", law, E0, E, t);
    }
}

int main(void)
{
    test_impact_map();
    test_rigid_open_close();
    test_energy();
    printf("%d checks, %d failures\n", checks, failures);
    return failures ? 1 : 0;
}
