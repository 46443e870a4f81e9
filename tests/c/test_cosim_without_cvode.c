/* Co-Simulation of a binary built without SUNDIALS (fmu_src/fmi/cs_without_cvode.c in place of cs_cvode.c):
 * the Windows binaries, and a build from the FMU's sources. Compiled twice:
 *  -DTEST_ROCKINGWALL: supports 2 and 3 step through the exact engine (fmu_model.exact_step) and
 *   reach the states the engine's own batch run (rw_engine_run) gives, whatever the step size;
 *   the parapet (support 1) is refused at its first step with fmi2Error and a logged reason;
 *  -DTEST_DIAPHRAGM: the Diaphragm's exact steps (closed form for inputs linear over a step), with
 *   ramped inputs, agree with a fine Runge-Kutta integration, damped, critically damped, undamped;
 *  -DTEST_BUILDING: the Building (hysteretic, no exact step) has its steps refused with a reason.
 * Built for Linux (ctest) and cross-compiled for Windows (run under wine). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "fmi2Functions.h"
#include "fmi2_test_logger.h"

#if defined(TEST_ROCKINGWALL)
#include "model_variables.h"
#include "rw_engine.h"
#define GUID RW_GUID
#elif defined(TEST_DIAPHRAGM)
#include "diaphragm_variables.h"
#define GUID DG_GUID
#elif defined(TEST_BUILDING)
#include "building_variables.h"
#define GUID BD_GUID
#else
#error "define TEST_ROCKINGWALL, TEST_DIAPHRAGM or TEST_BUILDING"
#endif

#define NOT_AVAILABLE "not available in this binary"

static fmi2Component cs_instance(void)
{
    fmi2Component c = fmi2Instantiate("cs", fmi2CoSimulation, GUID, "", &CB, fmi2False, fmi2False);
    if (c) fmi2SetupExperiment(c, fmi2False, 0.0, 0.0, fmi2False, 0.0);
    return c;
}

#if defined(TEST_BUILDING)
/* an initialized Co-Simulation instance whose first step is refused with fmi2Error and a reason */
static void expect_refused_step(fmi2Component c, const char *reason)
{
    CHECK(c != NULL, "instantiate");
    if (!c) return;
    fmi2EnterInitializationMode(c);
    CHECK(fmi2ExitInitializationMode(c) == fmi2OK, "fmi2ExitInitializationMode: %s", last_log);
    CHECK(fmi2DoStep(c, 0.0, 0.01, fmi2True) == fmi2Error, "the step was not refused");
    CHECK(last_status == fmi2Error && strstr(last_message, NOT_AVAILABLE) && strstr(last_message, reason),
          "the logged reason: %s", last_log);
    fmi2FreeInstance(c);
}
#endif

#if defined(TEST_ROCKINGWALL)
static const double Q0[RW_NX] = {0.01, -0.01, 0.0, 0.0}; /* free rocking from a tilt */

static fmi2Component rocking_wall(int support)
{
    fmi2Component c = cs_instance();
    const fmi2ValueReference vr_support = RW_VR_support, vr_q[2] = {RW_VR_q1, RW_VR_q2};
    const fmi2Integer s = support;
    if (!c) return NULL;
    fmi2SetInteger(c, &vr_support, 1, &s);
    fmi2SetReal(c, vr_q, 2, Q0);
    fmi2EnterInitializationMode(c);
    CHECK(fmi2ExitInitializationMode(c) == fmi2OK, "support %d: fmi2ExitInitializationMode: %s", support, last_log);
    return c;
}

/* the engine's batch run of the same wall (the FMU's start values are rw_params_default) */
static void engine_run(int support, double t_end, rw_engine_result *r)
{
    static const double t0[1] = {0.0}, ag0[1] = {0.0};
    const rw_record rec = {1, t0, ag0, NULL};
    rw_engine_options o;
    rw_params p;
    memset(&o, 0, sizeof o);
    memset(r, 0, sizeof *r);
    rw_params_default(&p);
    p.support = support;
    o.t_start = 0.0;
    o.t_end = t_end;
    o.x0 = Q0;
    CHECK(rw_engine_run(&p, &rec, &o, r) == 0, "support %d: rw_engine_run: %s", support, r->message);
}

/* n steps of h; the states at the end (NaN if a step failed) */
static void run_steps(fmi2Component c, int n, double h, double x[RW_NX], int *impacts)
{
    const fmi2ValueReference vr_x[RW_NX] = RW_STATE_VRS, vr_impacts = RW_VR_impacts;
    int k, ok = 1;
    for (k = 0; k < n && ok; k++) ok = fmi2DoStep(c, k * h, h, fmi2True) == fmi2OK;
    CHECK(ok, "step %d of %g s: %s", k, h, last_log);
    for (k = 0; k < RW_NX; k++) x[k] = NAN;
    if (ok) fmi2GetReal(c, vr_x, RW_NX, x);
    fmi2GetInteger(c, &vr_impacts, 1, impacts);
}

static void test_exact_steps_match_the_engine(int support)
{
    const double t_end = 2.0, tol = 1e-9; /* one closed-form solution, split at different times */
    const struct { int n; double h; } grids[] = {{1, 2.0}, {200, 0.01}};
    rw_engine_result ref;
    size_t g;
    int i;
    engine_run(support, t_end, &ref);
    CHECK(ref.impacts >= 2, "support %d: the reference run has %ld impacts", support, ref.impacts);
    for (g = 0; g < sizeof grids / sizeof grids[0]; g++) {
        fmi2Component c = rocking_wall(support);
        double x[RW_NX];
        int impacts = -1;
        CHECK(c != NULL, "instantiate");
        if (!c) return;
        run_steps(c, grids[g].n, grids[g].h, x, &impacts);
        CHECK(impacts == (int)ref.impacts, "support %d, %d steps: %d impacts, the engine %ld", support, grids[g].n,
              impacts, ref.impacts);
        for (i = 0; i < RW_NX; i++)
            CHECK(fabs(x[i] - ref.x_end[i]) <= tol * (1.0 + fabs(ref.x_end[i])),
                  "support %d, %d steps: state %d = %.12g, the engine %.12g", support, grids[g].n, i, x[i], ref.x_end[i]);
        fmi2Terminate(c);
        fmi2FreeInstance(c);
    }
}

static void test_parapet_refused(void)
{
    fmi2Component c = rocking_wall(1);
    CHECK(c != NULL, "instantiate");
    if (!c) return;
    CHECK(fmi2DoStep(c, 0.0, 0.01, fmi2True) == fmi2Error, "the parapet's step was not refused");
    CHECK(last_status == fmi2Error && strstr(last_message, NOT_AVAILABLE) && strstr(last_message, "parapet"),
          "the logged reason: %s", last_log);
    fmi2FreeInstance(c);
}
#endif

#if defined(TEST_DIAPHRAGM)
/* The diaphragm's equation with inputs ramped from t = 0, m (u'' + ag) = F_top - c u' - k u,
 * integrated by classical Runge-Kutta with a step far below the period (the independent result). */
typedef struct {
    double m, k, c, ag0, ag1, F0, F1;
} dg_case;

static void dg_rhs(const dg_case *d, double t, const double x[2], double dx[2])
{
    const double ag = d->ag0 + d->ag1 * t, F = d->F0 + d->F1 * t;
    dx[0] = x[1];
    dx[1] = (F - d->c * x[1] - d->k * x[0]) / d->m - ag;
}

static void rk4(const dg_case *d, double t_end, double x[2])
{
    const int n = 200000;
    const double dt = t_end / n;
    int i, j;
    for (i = 0; i < n; i++) {
        const double t = i * dt;
        double k1[2], k2[2], k3[2], k4[2], y[2];
        dg_rhs(d, t, x, k1);
        for (j = 0; j < 2; j++) y[j] = x[j] + 0.5 * dt * k1[j];
        dg_rhs(d, t + 0.5 * dt, y, k2);
        for (j = 0; j < 2; j++) y[j] = x[j] + 0.5 * dt * k2[j];
        dg_rhs(d, t + 0.5 * dt, y, k3);
        for (j = 0; j < 2; j++) y[j] = x[j] + dt * k3[j];
        dg_rhs(d, t + dt, y, k4);
        for (j = 0; j < 2; j++) x[j] += dt / 6.0 * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]);
    }
}

/* n steps of h with the inputs ramped over every step (fmi2SetRealInputDerivatives before each):
 * the states at the end, against Runge-Kutta from the same start */
static void test_diaphragm_exact_steps(double zeta, int n, double h)
{
    const fmi2ValueReference vr_par[3] = {DG_VR_m, DG_VR_k, DG_VR_zeta}, vr_x[2] = {DG_VR_u, DG_VR_v};
    const fmi2ValueReference vr_in[2] = {DG_VR_ag, DG_VR_F_top};
    const fmi2Integer order[2] = {1, 1};
    const double par[3] = {2000.0, 7e5, zeta}, x0[2] = {0.01, -0.05};
    dg_case d = {2000.0, 7e5, 0.0, 0.3, -1.5, 100.0, 800.0};
    const double in0[2] = {d.ag0, d.F0}, slopes[2] = {d.ag1, d.F1};
    double x[2], ref[2] = {x0[0], x0[1]};
    fmi2Component c = cs_instance();
    int k, ok = 1, i;
    CHECK(c != NULL, "instantiate");
    if (!c) return;
    d.c = 2.0 * zeta * sqrt(d.k * d.m);
    fmi2SetReal(c, vr_par, 3, par);
    fmi2SetReal(c, vr_x, 2, x0);
    fmi2SetReal(c, vr_in, 2, in0);
    fmi2EnterInitializationMode(c);
    CHECK(fmi2ExitInitializationMode(c) == fmi2OK, "fmi2ExitInitializationMode: %s", last_log);
    for (k = 0; k < n && ok; k++)
        ok = fmi2SetRealInputDerivatives(c, vr_in, 2, order, slopes) == fmi2OK &&
             fmi2DoStep(c, k * h, h, fmi2True) == fmi2OK;
    CHECK(ok, "zeta %g: step %d: %s", zeta, k, last_log);
    fmi2GetReal(c, vr_x, 2, x);
    rk4(&d, n * h, ref);
    for (i = 0; i < 2; i++) /* Runge-Kutta's own error is ~1e-14 of the amplitude at this step */
        CHECK(fabs(x[i] - ref[i]) <= 1e-9 * (fabs(ref[i]) + (i ? 0.1 : 0.01)),
              "zeta %g, %d steps of %g: state %d = %.15g, Runge-Kutta %.15g", zeta, n, h, i, x[i], ref[i]);
    fmi2FreeInstance(c);
}
#endif

int main(void)
{
#if defined(TEST_ROCKINGWALL)
    test_exact_steps_match_the_engine(2);
    test_exact_steps_match_the_engine(3);
    test_parapet_refused();
#elif defined(TEST_BUILDING)
    expect_refused_step(cs_instance(), "no exact step");
#else
    test_diaphragm_exact_steps(0.05, 1, 2.0);
    test_diaphragm_exact_steps(0.05, 200, 0.01);
    test_diaphragm_exact_steps(1.0, 50, 0.04); /* critically damped */
    test_diaphragm_exact_steps(0.0, 3, 0.7);   /* undamped */
#endif
    printf("%d checks, %d failures\n", checks, failures);
    return failures ? 1 : 0;
}
