/* Tests of the FMI 2.0 Model Exchange wrapper (fmu_src/fmi/fmi2Functions.c), linked statically. */
#include "check.h"
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmi2Functions.h"
#include "fmi2_test_logger.h"
#include "model_variables.h"
#include "rw_physics.h"

static fmi2Component inst(const char *name)
{
    return fmi2Instantiate(name, fmi2ModelExchange, RW_GUID, "", &CB, fmi2False, fmi2False);
}

static fmi2Status init_inst(fmi2Component c)
{
    fmi2Status s = fmi2SetupExperiment(c, fmi2False, 0, 0, fmi2False, 0);
    if (s == fmi2OK) s = fmi2EnterInitializationMode(c);
    if (s == fmi2OK) s = fmi2ExitInitializationMode(c);
    return s;
}

static void test_two_instances(void)
{
    fmi2Component a = inst("a"), b = inst("b");
    fmi2ValueReference vr_support = RW_VR_support, vr_q1 = RW_VR_q1, vr_h = RW_VR_h;
    fmi2Integer one = 1, got = 0;
    double q = 0.01, h = 3.0;
    fmi2EventInfo ei;
    CHECK(a && b && a != b, "two instances");
    CHECK(fmi2SetInteger(a, &vr_support, 1, &one) == fmi2OK, "set support");
    CHECK(fmi2SetReal(a, &vr_q1, 1, &q) == fmi2OK, "set q1 start");
    CHECK(fmi2SetReal(b, &vr_h, 1, &h) == fmi2OK, "set h");
    CHECK(init_inst(a) == fmi2OK && init_inst(b) == fmi2OK, "init");
    CHECK(fmi2NewDiscreteStates(a, &ei) == fmi2OK && fmi2NewDiscreteStates(b, &ei) == fmi2OK, "event iteration");
    fmi2GetInteger(b, &vr_support, 1, &got);
    CHECK(got == 3, "instance b support = %d (must not see a's value)", got);
    CHECK(get_real(a, RW_VR_q2) == 0.01, "parapet slaves q2 = q1: %g", get_real(a, RW_VR_q2));
    CHECK(get_real(b, RW_VR_h) == 3.0 && get_real(a, RW_VR_h) == 2.5, "h differs per instance");
    CHECK(fabs(get_real(a, RW_VR_s2) - 0.01 * 2.5) < 1e-15, "parapet s2 = theta*h");
    CHECK(fmi2EnterContinuousTimeMode(a) == fmi2OK, "enter CT");
    {
        double x[4], dx[4], z[RW_NZ], nom[4];
        CHECK(fmi2GetContinuousStates(a, x, 4) == fmi2OK && x[0] == 0.01, "get states");
        CHECK(fmi2GetDerivatives(a, dx, 4) == fmi2OK && dx[2] < 0, "free rocking decelerates back: %g", dx[2]);
        CHECK(fmi2GetEventIndicators(a, z, RW_NZ) == fmi2OK && z[RW_Z_BASE] > 0 && z[RW_Z_COLLAPSE] > 0, "indicators");
        CHECK(fmi2GetNominalsOfContinuousStates(a, nom, 4) == fmi2OK && nom[0] == 0.01 && nom[2] == 0.1, "nominals");
        CHECK(fmi2GetDerivatives(a, dx, 3) == fmi2Error, "wrong nx accepted");
    }
    CHECK(fmi2Terminate(b) == fmi2OK, "terminate from event mode");
    CHECK(fmi2GetReal(b, &vr_h, 1, &h) == fmi2OK && h == 3.0, "GetReal after terminate");
    fmi2FreeInstance(a);
    fmi2FreeInstance(b);
}

static void test_wrong_guid(void)
{
    fmi2Component c;
    n_logs = 0;
    c = fmi2Instantiate("x", fmi2ModelExchange, "{00000000-0000-0000-0000-000000000000}", "", &CB, fmi2False, fmi2False);
    CHECK(c == NULL, "wrong GUID accepted");
    CHECK(n_logs == 1 && strstr(last_log, "GUID"), "wrong GUID not logged: %s", last_log);
    c = fmi2Instantiate("x", (fmi2Type)7, RW_GUID, "", &CB, fmi2False, fmi2False);
    CHECK(c == NULL && strstr(last_log, "fmuType"), "fmuType 7 instantiated: %s", last_log);
    CHECK(fmi2Instantiate("x", fmi2ModelExchange, RW_GUID, "", NULL, fmi2False, fmi2False) == NULL, "NULL callbacks");
}

static void test_bad_values(void)
{
    fmi2Component c = inst("bad");
    fmi2ValueReference vr_h = RW_VR_h, vr_ag = RW_VR_ag, vr_law = RW_VR_hingeLaw, vr_bad = 9999, vr_s1 = RW_VR_s1;
    double v = -1.0, nan = NAN;
    fmi2Integer law = 7;
    CHECK(fmi2SetReal(c, &vr_h, 1, &v) == fmi2Error && strstr(last_log, "h = -1"), "h = -1: %s", last_log);
    fmi2FreeInstance(c);

    c = inst("nan");
    CHECK(init_inst(c) == fmi2OK, "init");
    CHECK(fmi2EnterContinuousTimeMode(c) == fmi2OK, "EnterContinuousTimeMode");
    CHECK(fmi2SetReal(c, &vr_ag, 1, &nan) == fmi2Error && strstr(last_log, "ag = nan"), "NaN input in CT mode: %s", last_log);
    fmi2FreeInstance(c);

    c = inst("nan2");
    CHECK(init_inst(c) == fmi2OK, "init");
    {
        fmi2EventInfo ei;
        CHECK(fmi2NewDiscreteStates(c, &ei) == fmi2OK, "nds");
    }
    CHECK(fmi2SetReal(c, &vr_ag, 1, &nan) == fmi2Error && strstr(last_log, "ag"), "NaN input: %s", last_log);
    CHECK(fmi2SetReal(c, &vr_ag, 1, &v) == fmi2Error, "error state must reject further calls");
    CHECK(fmi2Reset(c) == fmi2OK, "reset from error");
    CHECK(fmi2SetInteger(c, &vr_law, 1, &law) == fmi2Error && strstr(last_log, "hingeLaw = 7"), "hingeLaw 7: %s", last_log);
    fmi2Reset(c);
    CHECK(fmi2SetReal(c, &vr_bad, 1, &v) == fmi2Error && strstr(last_log, "9999"), "bad VR: %s", last_log);
    fmi2Reset(c);
    CHECK(fmi2SetReal(c, &vr_s1, 1, &v) == fmi2Error, "output settable");
    fmi2Reset(c);
    CHECK(fmi2SetReal(c, NULL, 1, &v) == fmi2Error, "NULL vr accepted");
    fmi2Reset(c);
    CHECK(fmi2GetReal(c, &vr_h, 1, &v) == fmi2Error, "GetReal in instantiated state accepted");
    fmi2Reset(c);
    {   /* b >= h is a cross-parameter error reported at fmi2ExitInitializationMode */
        fmi2ValueReference vr_b = RW_VR_b;
        double b = 3.0;
        CHECK(fmi2SetReal(c, &vr_b, 1, &b) == fmi2OK, "b alone is fine");
        CHECK(init_inst(c) == fmi2Error && strstr(last_log, "b = 3"), "b >= h: %s", last_log);
    }
    fmi2FreeInstance(c);
}

static void test_call_sequence(void)
{
    fmi2Component c = inst("seq");
    double x[4] = {0}, dx[4];
    fmi2EventInfo ei;
    CHECK(fmi2GetDerivatives(c, dx, 4) == fmi2Error && strstr(last_log, "illegal call sequence"), "GetDerivatives before init");
    fmi2Reset(c);
    CHECK(fmi2SetupExperiment(c, fmi2False, 0, 0, fmi2False, 0) == fmi2OK, "setup");
    CHECK(fmi2EnterInitializationMode(c) == fmi2OK, "enter init");
    CHECK(fmi2SetContinuousStates(c, x, 4) == fmi2Error, "SetContinuousStates in init mode accepted");
    fmi2Reset(c);
    CHECK(fmi2NewDiscreteStates(c, &ei) == fmi2Error, "NewDiscreteStates in instantiated");
    fmi2Reset(c);
    CHECK(init_inst(c) == fmi2OK, "init");
    CHECK(fmi2NewDiscreteStates(c, NULL) == fmi2Error, "NULL eventInfo accepted");
    fmi2Reset(c);
    CHECK(fmi2DoStep(c, 0, 0.1, fmi2True) == fmi2Error, "DoStep accepted");
    fmi2FreeInstance(c);
    fmi2FreeInstance(NULL);
}

/* A small event-driven simulation through the API: parapet free rocking (explicit RK2 with a
 * bisection-free event check): impacts counted, amplitude decays, no collapse. */
static void test_simulation(void)
{
    fmi2Component c = inst("sim");
    fmi2ValueReference vr_support = RW_VR_support, vr_q1 = RW_VR_q1, vr_imp = RW_VR_impacts, vr_col = RW_VR_collapsed;
    fmi2Integer model = 1, impacts = 0;
    fmi2Boolean collapsed = fmi2True;
    double q = 0.04, x[4], dx[4], y[4], z[RW_NZ], zn[RW_NZ], t = 0, h = 1e-4, E0, E1;
    fmi2EventInfo ei;
    int k, i;
    fmi2SetInteger(c, &vr_support, 1, &model);
    fmi2SetReal(c, &vr_q1, 1, &q);
    CHECK(init_inst(c) == fmi2OK, "init");
    do { fmi2NewDiscreteStates(c, &ei); } while (ei.newDiscreteStatesNeeded);
    fmi2EnterContinuousTimeMode(c);
    E0 = get_real(c, RW_VR_energy);
    fmi2GetContinuousStates(c, x, 4);
    fmi2GetEventIndicators(c, z, RW_NZ);
    for (k = 0; k < 30000; k++) {
        fmi2GetDerivatives(c, dx, 4);
        for (i = 0; i < 4; i++) y[i] = x[i] + 0.5 * h * dx[i];
        fmi2SetTime(c, t + 0.5 * h);
        fmi2SetContinuousStates(c, y, 4);
        fmi2GetDerivatives(c, dx, 4);
        for (i = 0; i < 4; i++) x[i] += h * dx[i];
        t += h;
        fmi2SetTime(c, t);
        fmi2SetContinuousStates(c, x, 4);
        fmi2GetEventIndicators(c, zn, RW_NZ);
        for (i = 0; i < RW_NZ; i++)
            if ((z[i] > 0) != (zn[i] > 0)) break;
        if (i < RW_NZ) {
            fmi2EnterEventMode(c);
            do { CHECK(fmi2NewDiscreteStates(c, &ei) == fmi2OK, "nds"); } while (ei.newDiscreteStatesNeeded && !ei.terminateSimulation);
            if (ei.terminateSimulation) break;
            fmi2EnterContinuousTimeMode(c);
            fmi2GetContinuousStates(c, x, 4);
            fmi2GetEventIndicators(c, zn, RW_NZ);
        }
        memcpy(z, zn, sizeof z);
    }
    E1 = get_real(c, RW_VR_energy);
    fmi2GetInteger(c, &vr_imp, 1, &impacts);
    fmi2GetBoolean(c, &vr_col, 1, &collapsed);
    CHECK(impacts >= 3, "impacts = %d", impacts);
    CHECK(!collapsed, "collapsed");
    CHECK(E1 < E0 && E1 >= 0, "energy %g -> %g", E0, E1);
    CHECK(fmi2Terminate(c) == fmi2OK, "terminate");
    fmi2FreeInstance(c);
}

int main(void)
{
    print_errors = 1;
    test_two_instances();
    test_wrong_guid();
    test_bad_values();
    test_call_sequence();
    test_simulation();
    printf("%d checks, %d failures\n", checks, failures);
    return failures ? 1 : 0;
}
