/* Tests of Co-Simulation (fmi2DoStep with CVODE inside, fmu_src/fmi/cs_cvode.c) through the FMI 2.0
 * API of RockingWall, linked statically: the step reaches the right state, events inside a step
 * are located, collapse ends the run with fmi2Discard, and the CS call sequence is enforced. */
#include "check.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmi2Functions.h"
#include "fmi2_test_logger.h"
#include "model_variables.h"

static fmi2Component cs_instance(int model, double q1_start, double tol)
{
    fmi2Component c = fmi2Instantiate("cs", fmi2CoSimulation, RW_GUID, "", &CB, fmi2False, fmi2False);
    fmi2ValueReference vr_support = RW_VR_support, vr_q1 = RW_VR_q1;
    fmi2Integer m = model;
    if (!c) return NULL;
    fmi2SetInteger(c, &vr_support, 1, &m);
    fmi2SetReal(c, &vr_q1, 1, &q1_start);
    fmi2SetupExperiment(c, fmi2True, tol, 0.0, fmi2False, 0.0);
    fmi2EnterInitializationMode(c);
    if (fmi2ExitInitializationMode(c) != fmi2OK) return NULL;
    return c;
}

/* Free rocking of a parapet from rest at a tilt: one step of 0.5 s and fifty of 0.01 s give the
 * same state (events located inside the steps, not at communication points). */
static void test_step_size_independence(void)
{
    const double q0 = 0.02;
    fmi2Component a = cs_instance(1, q0, 1e-9), b = cs_instance(1, q0, 1e-9);
    fmi2ValueReference vr_imp = RW_VR_impacts;
    fmi2Integer ia = 0, ib = 0;
    int k;
    CHECK(a && b, "instantiate CS");
    if (!a || !b) return;
    CHECK(fmi2DoStep(a, 0.0, 0.5, fmi2True) == fmi2OK, "one long step: %s", last_log);
    for (k = 0; k < 50; k++) CHECK(fmi2DoStep(b, k * 0.01, 0.01, fmi2True) == fmi2OK, "short step %d", k);
    fmi2GetInteger(a, &vr_imp, 1, &ia);
    fmi2GetInteger(b, &vr_imp, 1, &ib);
    CHECK(ia >= 1 && ia == ib, "impacts inside the steps: %d vs %d", ia, ib);
    CHECK(fabs(get_real(a, RW_VR_q1) - get_real(b, RW_VR_q1)) < 1e-6, "q1 %g vs %g", get_real(a, RW_VR_q1), get_real(b, RW_VR_q1));
    CHECK(get_real(a, RW_VR_dissipated) > 0 && fabs(get_real(a, RW_VR_energy) - get_real(b, RW_VR_energy)) < 1e-6 * get_real(a, RW_VR_dissipated),
          "impact losses recorded: %g, energies %g vs %g", get_real(a, RW_VR_dissipated), get_real(a, RW_VR_energy), get_real(b, RW_VR_energy));
    fmi2Terminate(a); fmi2FreeInstance(a);
    fmi2Terminate(b); fmi2FreeInstance(b);
}

/* A parapet under a constant ground acceleration far above its uplift threshold collapses: the
 * step ends early with fmi2Discard, fmi2Terminated is true, the last successful time is the
 * collapse time, and further steps are refused with fmi2Discard. */
static void test_collapse_discards(void)
{
    fmi2Component c = cs_instance(1, 0.0, 1e-6);
    fmi2ValueReference vr_ag = RW_VR_ag, vr_col = RW_VR_collapsed;
    const double ag = 5.0;
    fmi2Boolean terminated = fmi2False, collapsed = fmi2False;
    fmi2Real t_last = -1;
    fmi2Status st;
    CHECK(c != NULL, "instantiate");
    if (!c) return;
    CHECK(fmi2SetReal(c, &vr_ag, 1, &ag) == fmi2OK, "set ag");
    st = fmi2DoStep(c, 0.0, 10.0, fmi2True);
    CHECK(st == fmi2Discard, "collapse ends the step with fmi2Discard, got %d", st);
    CHECK(fmi2GetBooleanStatus(c, fmi2Terminated, &terminated) == fmi2OK && terminated, "fmi2Terminated");
    CHECK(fmi2GetRealStatus(c, fmi2LastSuccessfulTime, &t_last) == fmi2OK && t_last > 0 && t_last < 10,
          "last successful time %g", t_last);
    fmi2GetBoolean(c, &vr_col, 1, &collapsed);
    CHECK(collapsed, "collapsed output");
    CHECK(fmi2DoStep(c, t_last, 0.1, fmi2True) == fmi2Discard, "a step after termination");
    CHECK(fmi2Terminate(c) == fmi2OK, "terminate");
    fmi2FreeInstance(c);
}

static void test_cs_call_sequence(void)
{
    fmi2Component me = fmi2Instantiate("me", fmi2ModelExchange, RW_GUID, "", &CB, fmi2False, fmi2False);
    fmi2Component c = cs_instance(3, 0.0, 1e-6);
    fmi2ValueReference vr_h = RW_VR_h, vr_ag = RW_VR_ag;
    fmi2Integer order = 1, order2 = 2;
    double x[4], h = 3.0, slope = 1.0;
    fmi2EventInfo ei;
    CHECK(me && c, "instantiate");
    if (!me || !c) return;
    CHECK(fmi2DoStep(me, 0.0, 0.1, fmi2True) == fmi2Error && strstr(last_log, "Co-Simulation function"),
          "fmi2DoStep on a Model Exchange instance: %s", last_log);
    CHECK(fmi2GetContinuousStates(c, x, 4) == fmi2Error && strstr(last_log, "Model Exchange function"),
          "ME function on a CS instance: %s", last_log);
    fmi2FreeInstance(c);
    c = cs_instance(3, 0.0, 1e-6);
    CHECK(fmi2NewDiscreteStates(c, &ei) == fmi2Error, "fmi2NewDiscreteStates on CS");
    fmi2FreeInstance(c);
    c = cs_instance(3, 0.0, 1e-6);
    CHECK(fmi2DoStep(c, 0.0, 0.0, fmi2True) == fmi2Error && strstr(last_log, "step size"), "h = 0: %s", last_log);
    fmi2FreeInstance(c);
    c = cs_instance(3, 0.0, 1e-6);
    CHECK(fmi2DoStep(c, 1.0, 0.1, fmi2True) == fmi2Error && strstr(last_log, "FMU is at t"), "wrong t: %s", last_log);
    fmi2FreeInstance(c);
    c = cs_instance(3, 0.0, 1e-6);
    CHECK(fmi2SetReal(c, &vr_h, 1, &h) == fmi2Error && strstr(last_log, "only be set before"), "parameter in step mode");
    fmi2FreeInstance(c);
    c = cs_instance(3, 0.0, 1e-6);
    CHECK(fmi2SetRealInputDerivatives(c, &vr_ag, 1, &order2, &slope) == fmi2Error, "second derivative refused");
    fmi2FreeInstance(c);
    c = cs_instance(3, 0.0, 1e-6);
    CHECK(fmi2SetRealInputDerivatives(c, &vr_h, 1, &order, &slope) == fmi2Error && strstr(last_log, "not an input"),
          "derivative of a parameter: %s", last_log);
    fmi2FreeInstance(c);
    c = cs_instance(3, 0.0, 1e-6);
    CHECK(fmi2SetRealInputDerivatives(c, &vr_ag, 1, &order, &slope) == fmi2OK, "ramp ag");
    CHECK(fmi2DoStep(c, 0.0, 0.1, fmi2True) == fmi2OK, "step with a ramped input");
    CHECK(fabs(get_real(c, RW_VR_ag) - 0.1) < 1e-12, "the input ramped to the end of the step: %g", get_real(c, RW_VR_ag));
    CHECK(fmi2Terminate(c) == fmi2OK, "terminate");
    fmi2FreeInstance(c);
    fmi2FreeInstance(me);
}

/* A CVODE failure inside fmi2DoStep is an fmi2Error whose message names the
 * CVODE call and CVODE's flag, and leaks nothing (CVodeGetReturnFlagName's string is freed; the
 * ASan build's leak check sees it). A tolerance of 1e-300 asks CVODE for more accuracy than
 * doubles have. */
static void test_finding15_cvode_failure_reported_without_leak(void)
{
    fmi2Component c = cs_instance(1, 0.02, 1e-300);
    fmi2Status st;
    CHECK(c != NULL, "instantiate");
    if (!c) return;
    n_logs = 0;
    st = fmi2DoStep(c, 0.0, 0.5, fmi2True);
    CHECK(st == fmi2Error, "finding 15: DoStep at rtol 1e-300: status %d, expected fmi2Error", (int)st);
    printf("  %s\n", last_message);
    CHECK(n_logs > 0 && strstr(last_message, "fmi2DoStep") && strstr(last_message, "CV_"),
          "finding 15: the message names CVODE's flag: '%s'", last_message);
    fmi2FreeInstance(c);
}

int main(void)
{
    test_step_size_independence();
    test_collapse_discards();
    test_cs_call_sequence();
    test_finding15_cvode_failure_reported_without_leak();
    printf("%d checks, %d failures\n", checks, failures);
    return failures ? 1 : 0;
}
