/* The exact engine's C API (fmu_src/rw_engine.h), built into the ASan/UBSan run as every ctest:
 * a run of each support / hinge law with an output grid and an impact log, the stepper, the
 * Zeno guard's report, and an error code with a message for each kind of bad input. Agreement
 * with CVODE is tested in tests/python/test_engine.py. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "rw_engine.h"

#define NS 401
static double T[NS], AG[NS];

/* a Gaussian displacement impulse (paper Sec. 5.3) sampled every 0.01 s */
static void make_record(double D, double Tp)
{
    const double sigma = Tp / 8, t0 = Tp / 2;
    int i;
    for (i = 0; i < NS; i++) {
        const double t = 0.01 * i, z = t - t0, s2 = sigma * sigma;
        T[i] = t;
        AG[i] = D * exp(-z * z / (2 * s2)) * (z * z / (s2 * s2) - 1 / s2);
    }
}

static void test_every_law(void)
{
    static const int cases[][2] = {{3, 1}, {3, 2}, {3, 3}, {3, 4}, {2, 1}, {2, 4}};
    double t_out[41], x_out[41 * RW_NX], s1[41], s2[41], imp_t[500], imp_e[500];
    size_t c;
    int i;
    for (i = 0; i < 41; i++) t_out[i] = 0.1 * i;
    for (c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        rw_params p;
        rw_record rec = {NS, T, AG, NULL};
        double ag_big[NS];
        rw_engine_options o;
        rw_engine_result r;
        int rc;
        memset(&o, 0, sizeof o);
        memset(&r, 0, sizeof r);
        rw_params_default(&p);
        p.support = cases[c][0];
        p.hingeLaw = cases[c][1];
        p.Kd = 5e4;
        if (p.support == 2 && p.hingeLaw == 1) { /* the rigid 1DOF needs |ag| > (4b/h) g to rock */
            for (i = 0; i < NS; i++) ag_big[i] = 2.0 * AG[i];
            rec.ag = ag_big;
        }
        o.t_start = 0.0;
        o.t_end = 4.0;
        o.t_out = t_out;
        o.n_out = 41;
        r.x_out = x_out;
        r.s1_out = s1;
        r.s2_out = s2;
        r.impact_t = imp_t;
        r.impact_energy = imp_e;
        r.impact_cap = 500;
        rc = rw_engine_run(&p, &rec, &o, &r);
        CHECK(rc == 0, "support %d law %d: rc %d (%s)", p.support, p.hingeLaw, rc, r.message);
        CHECK(r.peak_s1 > 0.0 && isfinite(r.peak_s1), "support %d law %d: peak %g", p.support, p.hingeLaw, r.peak_s1);
        CHECK(r.impacts > 0 && !r.collapsed, "support %d law %d: impacts %ld collapsed %d", p.support, p.hingeLaw,
              r.impacts, r.collapsed);
        for (i = 0; i < 41; i++)
            CHECK(fabs(s1[i]) <= r.peak_s1 * (1 + 1e-12), "grid value above the peak at %g", t_out[i]);
        CHECK(imp_t[0] > 0.0 && imp_t[0] < 4.0, "first impact at %g", imp_t[0]);
    }
}

static void test_stepper(void)
{
    rw_params p;
    rw_derived d;
    rw_mode m;
    rw_input in = {0.0, 0.0};
    double x[RW_NX] = {0.01, -0.01, 0.0, 0.0}, t = 0.0, reached;
    long impacts = 0;
    char msg[256];
    rw_engine *e;
    int k, rc = 0;
    rw_params_default(&p);
    rw_derive(&p, &d);
    rw_init_modes(&p, &d, &in, x, &m, NULL, NULL);
    e = rw_engine_new(&p, msg, sizeof msg);
    CHECK(e != NULL, "rw_engine_new: %s", msg);
    if (!e) return;
    for (k = 0; k < 100 && rc == 0; k++) {
        const rw_linear_input li = {0.0, 0.0, 0.0, 0.0};
        rc = rw_engine_step(e, &m, x, t, 0.05, &li, &impacts, &reached, msg, sizeof msg);
        t = reached;
    }
    CHECK(rc == 0 && fabs(t - 5.0) < 1e-12, "stepper: rc %d t %g", rc, t);
    /* counted only while the rocking exceeds the base's elastic range (docs/model.md "Impacts"):
     * from 12.5 mm the amplitude falls below Delta_1 = 7.5 mm within a few impacts */
    CHECK(impacts >= 2, "stepper: %ld impacts in 5 s of free rocking", impacts);
    rw_engine_free(e);
}

static void expect_error(const rw_params *p, const rw_record *rec, const rw_engine_options *o, int code,
                         const char *what)
{
    rw_engine_result r;
    int rc;
    memset(&r, 0, sizeof r);
    rc = rw_engine_run(p, rec, o, &r);
    CHECK(rc == code && strlen(r.message) > 10, "%s: rc %d (want %d), message '%s'", what, rc, code, r.message);
}

static void test_bad_input(void)
{
    rw_params p;
    const double t_bad[3] = {0.0, 1.0, 1.0}, a3[3] = {0, 0, 0}, a_nan[2] = {0.0, NAN}, t2[2] = {0.0, 1.0};
    rw_record good = {2, t2, a3, NULL}, bad_t = {3, t_bad, a3, NULL}, bad_a = {2, t2, a_nan, NULL};
    rw_record empty = {0, t2, a3, NULL};
    rw_engine_options o;
    rw_engine_result r;
    memset(&o, 0, sizeof o);
    o.t_end = 1.0;
    rw_params_default(&p);
    expect_error(&p, &bad_t, &o, RW_ENGINE_BAD_ARGUMENT, "times not increasing");
    expect_error(&p, &bad_a, &o, RW_ENGINE_BAD_ARGUMENT, "NaN acceleration");
    expect_error(&p, &empty, &o, RW_ENGINE_BAD_ARGUMENT, "empty record");
    o.t_end = -1.0;
    expect_error(&p, &good, &o, RW_ENGINE_BAD_ARGUMENT, "t_end before t_start");
    o.t_end = 1.0;
    expect_error(NULL, &good, &o, RW_ENGINE_BAD_ARGUMENT, "NULL parameters");
    p.b = 3.0;
    p.h = 2.0;
    expect_error(&p, &good, &o, RW_ENGINE_BAD_PARAMETERS, "b > h");
    rw_params_default(&p);
    p.support = 1;
    expect_error(&p, &good, &o, RW_ENGINE_UNSUPPORTED, "parapet");
    CHECK(rw_engine_run(&p, &good, &o, NULL) == RW_ENGINE_BAD_ARGUMENT, "NULL result");
    (void)r;
}

int main(void)
{
    make_record(0.03, 1.0);
    test_every_law();
    test_stepper();
    test_bad_input();
    printf("%d checks, %d failures\n", checks, failures);
    return failures != 0;
}
