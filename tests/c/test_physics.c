/* Unit tests of the RockingWall physics module (fmu_src/wall/: rw_dynamics.c, rw_indicators.c, rw_outputs.c, rw_events.c).
 * Usage: test_physics derive_equations.json  (written by scripts/derive_equations.py --json) */
#include "check.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model_variables.h"
#include "rw_physics.h"



static void check_close(const char *what, double got, double want, double rtol)
{
    const double tol = rtol * fmax(1.0, fabs(want));
    CHECK(fabs(got - want) <= tol, "%s = %.12g, expected %.12g", what, got, want);
}

/* ---- tiny JSON number extractor: follows a path of keys, then reads the n next numbers ------ */
static char *read_file(const char *path)
{
    FILE *f = fopen(path, "rb");
    long n;
    char *buf;
    if (!f) return NULL;
    fseek(f, 0, SEEK_END);
    n = ftell(f);
    fseek(f, 0, SEEK_SET);
    buf = (char *)malloc((size_t)n + 1);
    if (buf && fread(buf, 1, (size_t)n, f) != (size_t)n) { free(buf); buf = NULL; }
    if (buf) buf[n] = '\0';
    fclose(f);
    return buf;
}

/* keys: NULL-terminated path, e.g. {"conditions", "1", "A", NULL}; returns count read */
static int json_numbers(const char *text, const char *const *keys, double *out, int n)
{
    const char *p = text;
    int k = 0;
    char pat[64];
    for (; *keys; keys++) {
        snprintf(pat, sizeof pat, "\"%s\"", *keys);
        p = strstr(p, pat);
        if (!p) return 0;
        p += strlen(pat);
    }
    while (k < n && *p) {
        if (strchr("-+0123456789.", *p)) {
            char *end;
            out[k++] = strtod(p, &end);
            p = end;
        } else if (*p == '"' || *p == '}') {
            break; /* next key or end of object */
        } else {
            p++;
        }
    }
    return k;
}

static rw_params paper_params(void)
{
    rw_params p;
    rw_params_default(&p);
    p.h = 2.5; p.b = 0.15; p.W = 6622.0; p.psi = 0.5; p.Kd = 1e5; p.g = 9.81;
    return p;
}

/* ---- tests ---------------------------------------------------------------------------------- */

static void test_defaults_valid(void)
{
    rw_params p;
    char msg[256];
    rw_params_default(&p);
    CHECK(rw_params_validate(&p, msg, sizeof msg) == 0, "defaults invalid: %s", msg);
    CHECK(p.support == RW_FLEXIBLE_TOP && p.h == 2.5 && p.W == 6622.0, "defaults not from the table");
}

/* every parameter's range: both bounds accepted, just beyond each refused with the range named */
static void test_ranges(void)
{
    size_t i;
    char msg[512];
    for (i = 0; i < RW_NUMBER_OF_PARAMETERS; i++) {
        const rw_param_info *q = &RW_PARAM_INFO[i];
        const double step = q->is_integer ? 1.0 : 1e-6 * fmax(fabs(q->hi), 1e-300);
        CHECK(rw_param_check(q, q->lo, msg, sizeof msg) == 0, "%s: lower bound refused: %s", q->name, msg);
        CHECK(rw_param_check(q, q->hi, msg, sizeof msg) == 0, "%s: upper bound refused: %s", q->name, msg);
        CHECK(rw_param_check(q, q->hi + step, msg, sizeof msg) && strstr(msg, q->name) && strstr(msg, "allowed ["),
              "%s: above range accepted: %s", q->name, msg);
        CHECK(rw_param_check(q, q->lo - (q->is_integer ? 1.0 : fmax(1e-6 * fabs(q->lo), 1e-300)), msg, sizeof msg),
              "%s: below range accepted", q->name);
        CHECK(rw_param_check(q, NAN, msg, sizeof msg), "%s: NaN accepted", q->name);
        CHECK(rw_param_by_vr(q->vr) == q && rw_param_by_name(q->name) == q, "%s: lookup", q->name);
    }
}

static void test_validation(void)
{
    rw_params p;
    char msg[256];
    CHECK(rw_param_check(rw_param_by_name("h"), -1.0, msg, sizeof msg) && strstr(msg, "h = -1"), "h=-1 accepted: %s", msg);
    CHECK(rw_param_check(rw_param_by_name("er"), 1.5, msg, sizeof msg), "er=1.5 accepted");
    CHECK(rw_param_check(rw_param_by_name("Kd"), 0.0, msg, sizeof msg) == 0, "Kd=0 rejected");
    CHECK(rw_param_check(rw_param_by_name("support"), 4, msg, sizeof msg), "support=4 accepted");
    CHECK(rw_param_check(rw_param_by_name("hingeLaw"), 2.5, msg, sizeof msg), "hingeLaw=2.5 accepted");
    CHECK(rw_param_check(rw_param_by_name("hingeSat"), 1e300, msg, sizeof msg), "hingeSat=1e300 accepted");
    CHECK(rw_param_by_name("model") == NULL, "a parameter called model remains");
    rw_params_default(&p);
    p.b = 2.9;
    p.h = 2.5;
    CHECK(rw_params_validate(&p, msg, sizeof msg) && strstr(msg, "b = 2.9"), "b >= h accepted: %s", msg);
    rw_params_default(&p);
    p.delta2B = 0.99;
    CHECK(rw_params_validate(&p, msg, sizeof msg) && strstr(msg, "delta"), "Delta_2 > Delta_u accepted");
    rw_params_default(&p);
    p.hingeSat = 19.0;
    p.delta1Ratio = 0.1;
    CHECK(rw_params_validate(&p, msg, sizeof msg) && strstr(msg, "hingeSat"), "saturation past Delta_u accepted");
}

static void test_against_sympy(const char *json_path)
{
    rw_params p = paper_params();
    rw_derived d;
    char *json = json_path ? read_file(json_path) : NULL;
    double v[4];
    int i, j;
    static const int sides[5][2] = {{0, 0}, {1, -1}, {-1, 1}, {1, 1}, {-1, -1}}; /* condition: side_b, side_m */
    rw_derive(&p, &d);
    if (!json) {
        printf("FAIL: cannot read %s (run scripts/derive_equations.py --json)\n", json_path ? json_path : "(none)");
        failures++;
        return;
    }
    {
        const char *k[] = {"params", "psi", NULL};
        CHECK(json_numbers(json, k, v, 1) == 1 && v[0] == p.psi, "JSON params differ from the test's");
    }
    {
        const char *k[] = {"M", NULL};
        CHECK(json_numbers(json, k, v, 4) == 4, "M not found");
        for (i = 0; i < 2; i++)
            for (j = 0; j < 2; j++) check_close("M", d.M[i][j], v[2 * i + j], 1e-12);
    }
    {
        const char *k[] = {"K", NULL};
        CHECK(json_numbers(json, k, v, 4) == 4, "K not found");
        for (i = 0; i < 2; i++)
            for (j = 0; j < 2; j++) check_close("K", d.K[i][j], v[2 * i + j], 1e-12);
    }
    {
        const char *k[] = {"p_per_ag", NULL};
        CHECK(json_numbers(json, k, v, 2) == 2, "p_per_ag not found");
        check_close("p1/ag", d.pa[0], v[0], 1e-12);
        check_close("p2/ag", d.pa[1], v[1], 1e-12);
    }
    {
        const char *k1[] = {"cap_b", NULL}, *k2[] = {"cap_m", NULL};
        CHECK(json_numbers(json, k1, v, 1) == 1, "cap_b not found");
        check_close("cap_b", d.cap_b, v[0], 1e-12);
        CHECK(json_numbers(json, k2, v, 1) == 1, "cap_m not found");
        check_close("cap_m", d.cap_m, v[0], 1e-12);
    }
    {   /* F_base = -base_mass*ag - base_per_qdd . q'' - F_top: each coefficient alone (q = 0, u_top = 0) */
        const char *km[] = {"base_mass", NULL}, *kc[] = {"base_per_qdd", NULL};
        const double x0[RW_NX] = {0, 0, 0, 0};
        double mass, c[2];
        rw_regime m = {0, 0, 1, -1, 0, 0, 0};
        rw_input in = {1.0, 0.0};
        double dx[RW_NX] = {0, 0, 0, 0};
        CHECK(json_numbers(json, km, &mass, 1) == 1 && json_numbers(json, kc, c, 2) == 2, "base force not found");
        check_close("F_base per ag", rw_F_base(&p, &d, &m, &in, x0, dx), -mass, 1e-12);
        in.ag = 0.0;
        for (i = 0; i < 2; i++) {
            dx[2] = i == 0 ? 1.0 : 0.0;
            dx[3] = i == 1 ? 1.0 : 0.0;
            check_close("F_base per q''", rw_F_base(&p, &d, &m, &in, x0, dx), -c[i], 1e-12);
        }
    }
    /* A_c, B_c: the rigid hinge terms Q with the sides of condition c */
    p.hingeLaw = RW_RIGID;
    for (i = 1; i <= 4; i++) {
        char cond[2] = {(char)('0' + i), 0};
        const char *ka[] = {"conditions", cond, "A", NULL}, *kb[] = {"conditions", cond, "B", NULL};
        rw_regime m = {0, 0, sides[i][0], sides[i][1], 0, 0, 0};
        double q[RW_NX] = {0.01 * sides[i][0], 0.01 * sides[i][0] + 0.01 * sides[i][1], 0, 0}, Q[2], a, b;
        rw_hinge_Q(&p, &d, &m, q, Q);
        CHECK(json_numbers(json, ka, &a, 1) == 1 && json_numbers(json, kb, &b, 1) == 1, "condition %d missing", i);
        check_close("A_c", Q[0], a, 1e-12);
        check_close("B_c", Q[1], b, 1e-12);
        CHECK(rw_condition(&p, &m) == i, "condition from sides = %d, expected %d", rw_condition(&p, &m), i);
    }
    free(json);
}

static void test_table_5_1(void)
{
    /* Delta_u [m], R_el [kN/m], F0/W for psi = 0, 0.5, 1 */
    static const double want[3][4] = {{0.0, 0.150, 1.192, 0.180}, {0.5, 0.138, 1.639, 0.248}, {1.0, 0.131, 2.086, 0.315}};
    int i;
    for (i = 0; i < 3; i++) {
        rw_params p = paper_params();
        rw_derived d;
        p.psi = want[i][0];
        rw_derive(&p, &d);
        CHECK(fabs(d.Du - want[i][1]) < 0.0006, "Delta_u(psi=%g) = %g", p.psi, d.Du);
        CHECK(fabs(d.Rel / 1000.0 - want[i][2]) < 0.0006, "R_el(psi=%g) = %g", p.psi, d.Rel);
        CHECK(fabs(d.Rel / p.W - want[i][3]) < 0.0006, "F0/W(psi=%g) = %g", p.psi, d.Rel / p.W);
    }
}

static void test_trilinear(void)
{
    rw_params p = paper_params();
    rw_derived d;
    rw_regime m = {0, 0, 1, 1, 0, 0, 0};
    p.support = RW_SIMPLY_SUPPORTED;
    rw_derive(&p, &d);
    check_close("F(D1/2)", rw_force_1dof(&p, &d, &m, d.D1 / 2), -d.Fi / 2, 1e-12);
    check_close("F(D1)", rw_force_1dof(&p, &d, &m, d.D1), -d.Fi, 1e-12);
    check_close("F((D1+D2)/2)", rw_force_1dof(&p, &d, &m, (d.D1 + d.D2) / 2), -d.Fi, 1e-12);
    check_close("F(D2)", rw_force_1dof(&p, &d, &m, d.D2), -d.Fi, 1e-12);
    check_close("F(D2+)", rw_force_1dof(&p, &d, &m, d.D2 * (1 + 1e-12)), -d.Fi, 1e-9);
    check_close("F(Du)", rw_force_1dof(&p, &d, &m, d.Du), 0.0, 1e-9);
    check_close("F(-0.1)", rw_force_1dof(&p, &d, &m, -0.1), -rw_force_1dof(&p, &d, &m, 0.1), 1e-12);
    check_close("F_i", d.Fi, d.Fr * (1 - d.D2 / d.Du), 1e-12);
    check_close("Delta_1", d.D1, 0.05 * d.Du, 1e-12);
    check_close("Delta_2", d.D2, 0.92 * d.D1 + 0.21 * d.Du, 1e-12);
}

static void init(const rw_params *p, rw_derived *d, rw_regime *m, const rw_input *in, double x[RW_NX])
{
    rw_derive(p, d);
    rw_init_regime(p, d, in, x, m, NULL, NULL);
}

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
            y[0] = d.theta_y * 0.999;
            rw_event_indicators(&p, &d, &m, &in, y, z1);
            y[0] = d.theta_y * 1.001;
            rw_event_indicators(&p, &d, &m, &in, y, z2);
            CHECK(z1[RW_Z_BREAK] < 0 && z2[RW_Z_BREAK] > 0, "law %d: breakpoint indicator", law);
        }
    }
}

/* a reproducible uniform number in [lo, hi) */
static double uniform(unsigned long *state, double lo, double hi)
{
    *state = *state * 6364136223846793005UL + 1442695040888963407UL;
    return lo + (hi - lo) * (double)(*state >> 11) / 9007199254740992.0;
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
 * covers, every law, both sides of each hinge and (rigid) every closed state; the values are the
 * FMU's own. Points where a kink lies within the difference step are skipped (the one-sided
 * differences disagree there). */
static void test_indicator_rates(void)
{
    static const int supports[2] = {RW_SIMPLY_SUPPORTED, RW_FLEXIBLE_TOP};
    unsigned long rng = 12345;
    int compared = 0, si, law, trial;
    for (si = 0; si < 2; si++)
        for (law = 1; law <= 4; law++)
            for (trial = 0; trial < 400; trial++) {
                rw_params p = paper_params();
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

static void test_collapse(void)
{
    rw_params p = paper_params();
    rw_derived d;
    rw_regime m;
    rw_input in = {0, 0};
    double x[RW_NX];
    int law;
    p.psi = 0.0;
    for (law = 1; law <= 3; law++) {
        /* 2DOF along the simply supported shape q2 = -q1: G(q) = 0 at D = Delta_u (outside elastic range) */
        double th;
        p.hingeLaw = law;
        rw_derive(&p, &d);
        th = 2 * d.Du / p.h;
        x[0] = 0.999 * th; x[1] = -x[0]; x[2] = x[3] = 0;
        init(&p, &d, &m, &in, x);
        if (law != RW_SEMI_RIGID_PAPER) /* the paper law's Q is not a potential: its root differs */
            CHECK(!rw_collapse_reason(&p, &d, &m, &in, x), "law %d collapsed before Delta_u", law);
        x[0] = 1.001 * th; x[1] = -x[0];
        init(&p, &d, &m, &in, x);
        if (law != RW_SEMI_RIGID_PAPER)
            CHECK(rw_collapse_reason(&p, &d, &m, &in, x), "law %d not collapsed past Delta_u", law);
    }
    p.support = RW_SIMPLY_SUPPORTED;
    rw_derive(&p, &d);
    x[0] = 2 * d.Du / p.h * 1.0001;
    CHECK(rw_collapse_reason(&p, &d, &m, &in, x), "1DOF not collapsed past Delta_u");
    p.support = RW_PARAPET;
    rw_derive(&p, &d);
    x[0] = d.alpha * 0.999;
    CHECK(!rw_collapse_reason(&p, &d, &m, &in, x), "parapet collapsed before alpha");
    x[0] = -d.alpha * 1.001;
    CHECK(rw_collapse_reason(&p, &d, &m, &in, x), "parapet not collapsed past alpha");
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

/* every law: J = dQ/dq by central differences inside a region, and Q = -grad V_h where the law
 * has a potential; at points in each region of each hinge */
static void test_hinge_laws_jacobian_and_potential(void)
{
    rw_params p = paper_params();
    rw_derived d;
    const double fr[] = {0.3, 1.5, 3.0, 8.0}; /* fractions of the first breakpoint rotation */
    int law, i, j, k;
    rw_derive(&p, &d);
    for (law = 1; law <= 4; law++) {
        const rw_hinge_law *L = rw_hinge_law_of(law);
        const double r1 = law == RW_DOHERTY_HINGE ? 2 * d.D1 / p.h : d.theta_y;
        CHECK(L && L->id == law, "law %d missing", law);
        for (i = 0; i < 4; i++)
            for (j = 0; j < 4; j++) {
                double q[2] = {fr[i] * r1, -fr[j] * r1 * (law == RW_DOHERTY_HINGE ? 2.0 : 1.0) + fr[i] * r1 * 0.37}; /* off every kink */
                const double dq[2] = {0.1, -0.1}, e = 1e-7 * r1;
                double Q[2], J[2][2], Qp[2], Qm[2], Jx[2][2];
                L->moments(&d, 1, -1, q, dq, Q, J);
                for (k = 0; k < 2; k++) {
                    double qp[2] = {q[0], q[1]}, qm[2] = {q[0], q[1]};
                    qp[k] += e;
                    qm[k] -= e;
                    L->moments(&d, 1, -1, qp, dq, Qp, Jx);
                    L->moments(&d, 1, -1, qm, dq, Qm, Jx);
                    check_close("dQ0/dq", J[0][k], (Qp[0] - Qm[0]) / (2 * e), 1e-5);
                    check_close("dQ1/dq", J[1][k], (Qp[1] - Qm[1]) / (2 * e), 1e-5);
                    if (law != RW_SEMI_RIGID_PAPER) /* the paper's law has no potential */
                        check_close("-dV/dq", -(L->potential(&d, qp) - L->potential(&d, qm)) / (2 * e), Q[k], 1e-5);
                }
            }
    }
}

/* dohertyHinge along the simply supported shape q2 = -q1: the generalised force on D of the hinges
 * plus gravity equals Doherty's trilinear F(D) of the 1DOF, in every branch */
static void test_doherty_hinge_reduces_to_trilinear(void)
{
    rw_params p = paper_params();
    rw_derived d;
    rw_regime m = {0, 0, 1, -1, 0, 0, 0};
    const double Ds[] = {0.2, 0.9, 1.5, 3.0, 5.0, 15.0, 19.0}; /* in units of Delta_1 */
    int i;
    p.hingeLaw = RW_DOHERTY_HINGE;
    p.Kd = 0.0; /* the spring does no work along q2 = -q1 */
    rw_derive(&p, &d);
    for (i = 0; i < 7; i++) {
        const double D = Ds[i] * d.D1, q1 = 2 * D / p.h;
        double x[RW_NX] = {q1, -q1, 0, 0}, Q[2];
        /* generalised force on D: (dq/dD).(Q - K q), dq/dD = (2/h)(1, -1) */
        const double Kq0 = d.K[0][0] * x[0] + d.K[0][1] * x[1], Kq1 = d.K[1][0] * x[0] + d.K[1][1] * x[1];
        double F2dof;
        if (D >= d.Du) break;
        rw_hinge_Q(&p, &d, &m, x, Q);
        F2dof = 2.0 / p.h * ((Q[0] - Kq0) - (Q[1] - Kq1));
        p.support = RW_SIMPLY_SUPPORTED;
        check_close("F(D) 2DOF dohertyHinge vs 1DOF trilinear", F2dof / d.Fr, rw_force_1dof(&p, &d, &m, D) / d.Fr, 1e-12);
        p.support = RW_FLEXIBLE_TOP;
    }
}

/* every kink of Q(q) is a breakpoint: with the sides fixed, Q is affine along any short segment
 * over which no breakpoint indicator changes sign (the exact engine takes Q = c + J q on such a
 * region). The segments cross q1 = 0, q2 = 0 and q2 = q1, where a law may hide a kink. */
static void test_hinge_laws_kinks_are_breakpoints(void)
{
    rw_params p = paper_params();
    rw_derived d;
    const double dirs[4][2] = {{1, 0}, {0, 1}, {1, 1}, {1, -1}};
    int law, sb, sm, i, j, k, n;
    rw_derive(&p, &d);
    for (law = RW_SEMI_RIGID_PAPER; law <= RW_DOHERTY_HINGE; law++) {
        const rw_hinge_law *L = rw_hinge_law_of(law);
        const double r1 = law == RW_DOHERTY_HINGE ? 2 * d.D1 / p.h : d.theta_y, len = 0.1 * r1;
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
    x[0] = -2.0 * d.D1 / p.h * (1.0 - 1e-13); /* the breakpoint, on the elastic side by rounding */
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

int main(int argc, char **argv)
{
    test_defaults_valid();
    test_ranges();
    test_validation();
    test_against_sympy(argc > 1 ? argv[1] : NULL);
    test_table_5_1();
    test_trilinear();
    test_impact_map();
    test_indicators();
    test_indicator_rates();
    test_collapse_form();
    test_closed_force_form();
    test_rigid_open_close();
    test_collapse();
    test_energy();
    test_hinge_laws_jacobian_and_potential();
    test_doherty_hinge_reduces_to_trilinear();
    test_hinge_laws_kinks_are_breakpoints();
    test_collapse_where_the_elastic_range_ends();
    printf("%d checks, %d failures\n", checks, failures);
    return failures ? 1 : 0;
}
