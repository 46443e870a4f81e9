/* Bad input to the FMI 2.0 Model Exchange API: every ME function called in every state
 * where the standard (FMI 2.0.x, section 3.2.3, the state machine of Model Exchange) forbids it,
 * unknown value references, NULL pointers, invalid, NaN and infinite parameters and inputs.
 * Each must return fmi2Error with a reason passed to the logger (captured here), must not crash,
 * and the instance must still be freeable (ASan/UBSan in build-asan checks the memory). */
#include "check.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmi2Functions.h"
#include "fmi2_test_logger.h"
#include "model_variables.h"

/* ---- the states of Model Exchange and how to reach them ---------------------------------- */
enum { S_INST, S_INIT, S_EVENT, S_CONT, S_TERM, S_ERROR, N_STATES };
static const char *STATE_NAMES[] = {"instantiated", "initializationMode", "eventMode", "continuousTimeMode",
                                    "terminated", "error"};
#define B(s) (1u << (s))
#define ALL (B(S_INST) | B(S_INIT) | B(S_EVENT) | B(S_CONT) | B(S_TERM) | B(S_ERROR))
#define AFTER_INST (B(S_INIT) | B(S_EVENT) | B(S_CONT) | B(S_TERM) | B(S_ERROR))

static fmi2Component in_state(int s)
{
    fmi2Component c = fmi2Instantiate("bad", fmi2ModelExchange, RW_GUID, "", &CB, fmi2False, fmi2False);
    fmi2ValueReference nosuch = 999;
    double v = 0;
    if (!c) return NULL;
    if (s == S_ERROR) { fmi2SetReal(c, &nosuch, 1, &v); return c; }
    if (s == S_INST) return c;
    fmi2SetupExperiment(c, fmi2False, 0, 0, fmi2False, 0);
    fmi2EnterInitializationMode(c);
    if (s == S_INIT) return c;
    fmi2ExitInitializationMode(c);
    if (s == S_EVENT) return c;
    if (s == S_TERM) { fmi2Terminate(c); return c; }
    fmi2EnterContinuousTimeMode(c);
    return c;
}

/* ---- each ME function with valid arguments, and the states the standard allows it in ----- */
static fmi2ValueReference VR_H = RW_VR_h, VR_SUPPORT = RW_VR_support, VR_COLLAPSED = RW_VR_collapsed;
static fmi2Status c_setup(fmi2Component c) { return fmi2SetupExperiment(c, fmi2False, 0, 0, fmi2False, 0); }
static fmi2Status c_enter_init(fmi2Component c) { return fmi2EnterInitializationMode(c); }
static fmi2Status c_exit_init(fmi2Component c) { return fmi2ExitInitializationMode(c); }
static fmi2Status c_terminate(fmi2Component c) { return fmi2Terminate(c); }
static fmi2Status c_get_real(fmi2Component c) { double v; return fmi2GetReal(c, &VR_H, 1, &v); }
static fmi2Status c_get_int(fmi2Component c) { fmi2Integer v; return fmi2GetInteger(c, &VR_SUPPORT, 1, &v); }
static fmi2Status c_get_bool(fmi2Component c) { fmi2Boolean v; return fmi2GetBoolean(c, &VR_COLLAPSED, 1, &v); }
static fmi2Status c_set_real(fmi2Component c) { fmi2ValueReference vr = RW_VR_ag; double v = 0.1; return fmi2SetReal(c, &vr, 1, &v); }
static fmi2Status c_set_int(fmi2Component c) { fmi2Integer v = 3; return fmi2SetInteger(c, &VR_SUPPORT, 1, &v); }
static fmi2Status c_enter_event(fmi2Component c) { return fmi2EnterEventMode(c); }
static fmi2Status c_nds(fmi2Component c) { fmi2EventInfo ei; return fmi2NewDiscreteStates(c, &ei); }
static fmi2Status c_enter_cont(fmi2Component c) { return fmi2EnterContinuousTimeMode(c); }
static fmi2Status c_completed(fmi2Component c)
{
    fmi2Boolean ev, term;
    return fmi2CompletedIntegratorStep(c, fmi2True, &ev, &term);
}
static fmi2Status c_set_time(fmi2Component c) { return fmi2SetTime(c, 0.0); }
static fmi2Status c_set_states(fmi2Component c) { double x[RW_NUMBER_OF_STATES] = {0}; return fmi2SetContinuousStates(c, x, RW_NUMBER_OF_STATES); }
static fmi2Status c_get_der(fmi2Component c) { double dx[RW_NUMBER_OF_STATES]; return fmi2GetDerivatives(c, dx, RW_NUMBER_OF_STATES); }
static fmi2Status c_get_z(fmi2Component c) { double z[RW_NUMBER_OF_EVENT_INDICATORS]; return fmi2GetEventIndicators(c, z, RW_NUMBER_OF_EVENT_INDICATORS); }
static fmi2Status c_get_states(fmi2Component c) { double x[RW_NUMBER_OF_STATES]; return fmi2GetContinuousStates(c, x, RW_NUMBER_OF_STATES); }
static fmi2Status c_get_nom(fmi2Component c) { double x[RW_NUMBER_OF_STATES]; return fmi2GetNominalsOfContinuousStates(c, x, RW_NUMBER_OF_STATES); }

typedef struct {
    const char *name;
    fmi2Status (*call)(fmi2Component);
    unsigned allowed;
} Api;

static const Api API[] = {
    {"fmi2SetupExperiment", c_setup, B(S_INST)},
    {"fmi2EnterInitializationMode", c_enter_init, B(S_INST)},
    {"fmi2ExitInitializationMode", c_exit_init, B(S_INIT)},
    {"fmi2Terminate", c_terminate, B(S_EVENT) | B(S_CONT)},
    {"fmi2GetReal", c_get_real, AFTER_INST},
    {"fmi2GetInteger", c_get_int, AFTER_INST},
    {"fmi2GetBoolean", c_get_bool, AFTER_INST},
    {"fmi2SetReal", c_set_real, B(S_INST) | B(S_INIT) | B(S_EVENT) | B(S_CONT)},
    {"fmi2SetInteger", c_set_int, B(S_INST) | B(S_INIT)}, /* a parameter: before exit init only */
    {"fmi2EnterEventMode", c_enter_event, B(S_EVENT) | B(S_CONT)},
    {"fmi2NewDiscreteStates", c_nds, B(S_EVENT)},
    {"fmi2EnterContinuousTimeMode", c_enter_cont, B(S_EVENT)},
    {"fmi2CompletedIntegratorStep", c_completed, B(S_CONT)},
    {"fmi2SetTime", c_set_time, B(S_EVENT) | B(S_CONT)},
    {"fmi2SetContinuousStates", c_set_states, B(S_CONT)},
    {"fmi2GetDerivatives", c_get_der, B(S_EVENT) | B(S_CONT) | B(S_TERM) | B(S_ERROR)},
    {"fmi2GetEventIndicators", c_get_z, AFTER_INST},
    {"fmi2GetContinuousStates", c_get_states, AFTER_INST},
    {"fmi2GetNominalsOfContinuousStates", c_get_nom, B(S_INST) | B(S_EVENT) | B(S_CONT) | B(S_TERM) | B(S_ERROR)},
};
#define N_API (sizeof API / sizeof API[0])

/* The call must fail with fmi2Error and a logged error that names the function; the instance
 * must then recover through fmi2Reset (allowed in every state) and be freed. */
static void expect_error(fmi2Component c, fmi2Status got, const char *what, const char *must_mention)
{
    CHECK(got == fmi2Error, "%s: status %d, expected fmi2Error", what, (int)got);
    CHECK(n_logs > 0 && last_status == fmi2Error, "%s: no error logged", what);
    CHECK(!must_mention || strstr(last_message, must_mention), "%s: log '%s' does not mention '%s'", what, last_message,
          must_mention);
    if (c) {
        CHECK(fmi2Reset(c) == fmi2OK, "%s: fmi2Reset after the error", what);
        CHECK(c_setup(c) == fmi2OK && c_enter_init(c) == fmi2OK && c_exit_init(c) == fmi2OK,
              "%s: instance not usable after fmi2Reset", what);
    }
}

static void test_every_call_in_every_forbidden_state(void)
{
    int forbidden = 0;
    for (size_t f = 0; f < N_API; f++)
        for (int s = 0; s < N_STATES; s++) {
            char what[160];
            fmi2Component c;
            if (API[f].allowed & B(s)) continue;
            c = in_state(s);
            CHECK(c != NULL, "instantiate");
            if (!c) continue;
            snprintf(what, sizeof what, "%s in %s", API[f].name, STATE_NAMES[s]);
            n_logs = 0;
            expect_error(c, API[f].call(c), what, API[f].name);
            fmi2FreeInstance(c);
            forbidden++;
        }
    printf("  %d forbidden (function, state) pairs rejected\n", forbidden);
    CHECK(forbidden >= 50, "only %d forbidden pairs exercised", forbidden);
}

/* every allowed pair must still work, or the matrix above could pass by rejecting everything */
static void test_every_call_in_an_allowed_state_succeeds(void)
{
    for (size_t f = 0; f < N_API; f++)
        for (int s = 0; s < N_STATES; s++) {
            fmi2Component c;
            fmi2Status st;
            if (!(API[f].allowed & B(s)) || s == S_ERROR) continue;
            c = in_state(s);
            st = API[f].call(c);
            CHECK(st == fmi2OK, "%s in %s: status %d (%s)", API[f].name, STATE_NAMES[s], (int)st, last_message);
            fmi2FreeInstance(c);
        }
}

static void test_null_pointers(void)
{
    fmi2ValueReference vr = RW_VR_h;
    double v[8];
    fmi2Integer iv;
    fmi2Boolean bv, bv2;
    fmi2String sv;
    fmi2EventInfo ei;
    struct { const char *what; int state; int call; } cases[] = {
        {"fmi2GetReal vr", S_EVENT, 0}, {"fmi2GetReal value", S_EVENT, 1}, {"fmi2SetReal vr", S_INST, 2},
        {"fmi2SetReal value", S_INST, 3}, {"fmi2GetInteger vr", S_EVENT, 4}, {"fmi2GetInteger value", S_EVENT, 5},
        {"fmi2SetInteger vr", S_INST, 6}, {"fmi2SetInteger value", S_INST, 7}, {"fmi2GetBoolean value", S_EVENT, 8},
        {"fmi2GetString vr", S_EVENT, 9}, {"fmi2NewDiscreteStates eventInfo", S_EVENT, 10},
        {"fmi2CompletedIntegratorStep enterEventMode", S_CONT, 11},
        {"fmi2CompletedIntegratorStep terminateSimulation", S_CONT, 12},
        {"fmi2SetContinuousStates x", S_CONT, 13}, {"fmi2GetDerivatives dx", S_CONT, 14},
        {"fmi2GetEventIndicators z", S_CONT, 15}, {"fmi2GetContinuousStates x", S_CONT, 16},
        {"fmi2GetNominalsOfContinuousStates x", S_CONT, 17}, {"fmi2SetDebugLogging categories", S_INST, 18},
        {"fmi2SetBoolean vr", S_INST, 19}, {"fmi2SetString vr", S_INST, 20},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        fmi2Component c = in_state(cases[i].state);
        fmi2Status st = fmi2OK;
        n_logs = 0;
        switch (cases[i].call) {
        case 0: st = fmi2GetReal(c, NULL, 1, v); break;
        case 1: st = fmi2GetReal(c, &vr, 1, NULL); break;
        case 2: st = fmi2SetReal(c, NULL, 1, v); break;
        case 3: st = fmi2SetReal(c, &vr, 1, NULL); break;
        case 4: st = fmi2GetInteger(c, NULL, 1, &iv); break;
        case 5: st = fmi2GetInteger(c, &VR_SUPPORT, 1, NULL); break;
        case 6: st = fmi2SetInteger(c, NULL, 1, &iv); break;
        case 7: st = fmi2SetInteger(c, &VR_SUPPORT, 1, NULL); break;
        case 8: st = fmi2GetBoolean(c, &VR_COLLAPSED, 1, NULL); break;
        case 9: st = fmi2GetString(c, NULL, 1, &sv); break;
        case 10: st = fmi2NewDiscreteStates(c, NULL); break;
        case 11: st = fmi2CompletedIntegratorStep(c, fmi2True, NULL, &bv2); break;
        case 12: st = fmi2CompletedIntegratorStep(c, fmi2True, &bv, NULL); break;
        case 13: st = fmi2SetContinuousStates(c, NULL, RW_NUMBER_OF_STATES); break;
        case 14: st = fmi2GetDerivatives(c, NULL, RW_NUMBER_OF_STATES); break;
        case 15: st = fmi2GetEventIndicators(c, NULL, RW_NUMBER_OF_EVENT_INDICATORS); break;
        case 16: st = fmi2GetContinuousStates(c, NULL, RW_NUMBER_OF_STATES); break;
        case 17: st = fmi2GetNominalsOfContinuousStates(c, NULL, RW_NUMBER_OF_STATES); break;
        case 18: st = fmi2SetDebugLogging(c, fmi2True, 2, NULL); break;
        case 19: st = fmi2SetBoolean(c, NULL, 1, &bv); break;
        case 20: st = fmi2SetString(c, NULL, 1, &sv); break;
        }
        (void)ei;
        expect_error(c, st, cases[i].what, "NULL");
        fmi2FreeInstance(c);
    }
}

/* A NULL instance cannot log (no logger to reach), but must not crash. */
static void test_null_instance(void)
{
    double v[4];
    fmi2EventInfo ei;
    fmi2Boolean a, b;
    CHECK(fmi2SetupExperiment(NULL, fmi2False, 0, 0, fmi2False, 0) == fmi2Error, "NULL c: setup");
    CHECK(fmi2EnterInitializationMode(NULL) == fmi2Error && fmi2ExitInitializationMode(NULL) == fmi2Error, "NULL c: init");
    CHECK(fmi2GetReal(NULL, &VR_H, 1, v) == fmi2Error && fmi2SetReal(NULL, &VR_H, 1, v) == fmi2Error, "NULL c: real");
    CHECK(fmi2NewDiscreteStates(NULL, &ei) == fmi2Error && fmi2EnterContinuousTimeMode(NULL) == fmi2Error, "NULL c: event");
    CHECK(fmi2CompletedIntegratorStep(NULL, fmi2True, &a, &b) == fmi2Error && fmi2SetTime(NULL, 0) == fmi2Error, "NULL c: step");
    CHECK(fmi2GetDerivatives(NULL, v, 4) == fmi2Error && fmi2SetContinuousStates(NULL, v, 4) == fmi2Error, "NULL c: states");
    CHECK(fmi2Terminate(NULL) == fmi2Error && fmi2Reset(NULL) == fmi2Error, "NULL c: terminate/reset");
    CHECK(fmi2SetDebugLogging(NULL, fmi2True, 0, NULL) == fmi2Error, "NULL c: logging");
    fmi2FreeInstance(NULL);
}

static void test_instantiate_arguments(void)
{
    fmi2CallbackFunctions no_logger = CB;
    no_logger.logger = NULL;
    n_logs = 0;
    CHECK(fmi2Instantiate(NULL, fmi2ModelExchange, RW_GUID, "", &CB, fmi2False, fmi2False) == NULL, "NULL name");
    CHECK(n_logs == 1 && last_status == fmi2Error && strstr(last_message, "instanceName"), "NULL name: log '%s'", last_message);
    n_logs = 0;
    CHECK(fmi2Instantiate("", fmi2ModelExchange, RW_GUID, "", &CB, fmi2False, fmi2False) == NULL, "empty name");
    CHECK(n_logs == 1 && strstr(last_message, "instanceName"), "empty name: log '%s'", last_message);
    n_logs = 0;
    CHECK(fmi2Instantiate("x", fmi2ModelExchange, NULL, "", &CB, fmi2False, fmi2False) == NULL, "NULL GUID");
    CHECK(n_logs == 1 && strstr(last_message, "GUID"), "NULL GUID: log '%s'", last_message);
    n_logs = 0;
    CHECK(fmi2Instantiate("x", fmi2ModelExchange, "{1631bb30-%s%n}", "", &CB, fmi2False, fmi2False) == NULL, "format GUID");
    CHECK(n_logs == 1 && !strchr(last_message, '%'), "a GUID with %% reaches the logger as a format: '%s'", last_message);
    CHECK(fmi2Instantiate("x", fmi2ModelExchange, RW_GUID, "", &no_logger, fmi2False, fmi2False) == NULL, "no logger");
    {   /* fmuResourceLocation is optional for this FMU (it has no resources): NULL is accepted */
        fmi2Component c = fmi2Instantiate("x", fmi2ModelExchange, RW_GUID, NULL, &CB, fmi2False, fmi2False);
        CHECK(c != NULL, "NULL resource location rejected");
        fmi2FreeInstance(c);
    }
}

/* one value: set it where the standard allows, expect fmi2Error with `mention` in the log */
static void bad_real(int state, fmi2ValueReference vr, double value, const char *mention)
{
    fmi2Component c = in_state(state);
    char what[128];
    snprintf(what, sizeof what, "SetReal vr %u = %g in %s", (unsigned)vr, value, STATE_NAMES[state]);
    n_logs = 0;
    expect_error(c, fmi2SetReal(c, &vr, 1, &value), what, mention);
    fmi2FreeInstance(c);
}

static void test_invalid_parameters_and_inputs(void)
{
    const double nonfinite[] = {NAN, INFINITY, -INFINITY};
    const fmi2ValueReference reals[] = {RW_VR_h, RW_VR_b, RW_VR_W, RW_VR_psi, RW_VR_Kd, RW_VR_er, RW_VR_g,
                                        RW_VR_delta1Ratio, RW_VR_delta2A, RW_VR_delta2B, RW_VR_hingeSat,
                                        RW_VR_restRate, RW_VR_q1, RW_VR_q2, RW_VR_dq1, RW_VR_dq2};
    struct { fmi2ValueReference vr; double v; const char *name; } invalid[] = {
        {RW_VR_h, 0, "h"}, {RW_VR_h, -2.5, "h"}, {RW_VR_b, 0, "b"}, {RW_VR_b, -0.1, "b"}, {RW_VR_W, 0, "W"},
        {RW_VR_psi, -1, "psi"}, {RW_VR_Kd, -1, "Kd"}, {RW_VR_er, 1.5, "er"}, {RW_VR_er, -0.1, "er"},
        {RW_VR_g, 0, "g"}, {RW_VR_delta1Ratio, 1.0, "delta1Ratio"}, {RW_VR_delta1Ratio, 0, "delta1Ratio"},
        {RW_VR_hingeSat, 0, "hingeSat"}, {RW_VR_restRate, 0, "restRate"},
    };
    const fmi2Integer bad_ints[] = {0, 5, -1, 2147483647};
    for (size_t i = 0; i < sizeof reals / sizeof reals[0]; i++)
        for (size_t k = 0; k < 3; k++) {
            bad_real(S_INST, reals[i], nonfinite[k], "not a finite number");
            bad_real(S_INIT, reals[i], nonfinite[k], "not a finite number");
        }
    for (size_t i = 0; i < sizeof invalid / sizeof invalid[0]; i++) bad_real(S_INST, invalid[i].vr, invalid[i].v, invalid[i].name);
    for (int s = S_INST; s <= S_CONT; s++)
        for (size_t k = 0; k < 3; k++) {
            bad_real(s, RW_VR_ag, nonfinite[k], "ag");
            bad_real(s, RW_VR_u_top, nonfinite[k], "u_top");
        }
    bad_real(S_EVENT, RW_VR_h, 3.0, "can only be set before");      /* fixed parameter after init */
    bad_real(S_CONT, RW_VR_q1, 0.01, "fmi2SetContinuousStates");    /* state start value after init */
    bad_real(S_EVENT, RW_VR_s1, 0.01, "cannot be set");             /* an output */
    for (size_t k = 0; k < sizeof bad_ints / sizeof bad_ints[0]; k++) {
        fmi2ValueReference vrs[2] = {RW_VR_support, RW_VR_hingeLaw};
        for (int j = 0; j < 2; j++) {
            fmi2Component c = in_state(S_INST);
            n_logs = 0;
            expect_error(c, fmi2SetInteger(c, &vrs[j], 1, &bad_ints[k]), "bad integer parameter", j ? "hingeLaw" : "support");
            fmi2FreeInstance(c);
        }
    }
    {   /* cross-parameter: b >= h is only known at fmi2ExitInitializationMode */
        fmi2Component c = in_state(S_INIT);
        fmi2ValueReference vr = RW_VR_b;
        double b = 2.5;
        CHECK(fmi2SetReal(c, &vr, 1, &b) == fmi2OK, "b alone");
        n_logs = 0;
        expect_error(c, fmi2ExitInitializationMode(c), "b = h at exit init", "b");
        fmi2FreeInstance(c);
    }
    {   /* non-finite time, start time and states */
        double x[RW_NUMBER_OF_STATES] = {0, 0, NAN, 0};
        fmi2Component c = in_state(S_CONT);
        n_logs = 0;
        expect_error(c, fmi2SetTime(c, NAN), "SetTime NaN", "time");
        fmi2FreeInstance(c);
        c = in_state(S_CONT);
        n_logs = 0;
        expect_error(c, fmi2SetTime(c, INFINITY), "SetTime inf", "time");
        fmi2FreeInstance(c);
        c = in_state(S_CONT);
        n_logs = 0;
        expect_error(c, fmi2SetContinuousStates(c, x, RW_NUMBER_OF_STATES), "SetContinuousStates NaN", "not finite");
        fmi2FreeInstance(c);
        c = in_state(S_INST);
        n_logs = 0;
        expect_error(c, fmi2SetupExperiment(c, fmi2False, 0, NAN, fmi2False, 0), "startTime NaN", "startTime");
        fmi2FreeInstance(c);
    }
}

static void test_value_references_and_sizes(void)
{
    const fmi2ValueReference unknown[] = {0, 24, 29, 22, 39, 46, 999, 0xFFFFFFFFu};
    for (size_t i = 0; i < sizeof unknown / sizeof unknown[0]; i++) {
        char num[32];
        double v = 0;
        fmi2Integer iv = 0;
        fmi2Boolean bv = 0;
        fmi2String sv = NULL;
        fmi2Component c;
        snprintf(num, sizeof num, "%u", (unsigned)unknown[i]);
#define BAD_VR(STATE, CALL, WHAT)                     \
        c = in_state(STATE); n_logs = 0;              \
        expect_error(c, CALL, WHAT, num);             \
        fmi2FreeInstance(c)
        BAD_VR(S_EVENT, fmi2GetReal(c, &unknown[i], 1, &v), "GetReal unknown vr");
        BAD_VR(S_INST, fmi2SetReal(c, &unknown[i], 1, &v), "SetReal unknown vr");
        BAD_VR(S_EVENT, fmi2GetInteger(c, &unknown[i], 1, &iv), "GetInteger unknown vr");
        BAD_VR(S_INST, fmi2SetInteger(c, &unknown[i], 1, &iv), "SetInteger unknown vr");
        BAD_VR(S_EVENT, fmi2GetBoolean(c, &unknown[i], 1, &bv), "GetBoolean unknown vr");
        BAD_VR(S_INST, fmi2SetBoolean(c, &unknown[i], 1, &bv), "SetBoolean unknown vr");
        BAD_VR(S_EVENT, fmi2GetString(c, &unknown[i], 1, &sv), "GetString unknown vr");
        BAD_VR(S_INST, fmi2SetString(c, &unknown[i], 1, &sv), "SetString unknown vr");
#undef BAD_VR
    }
    {   /* a known vr of the wrong type, and one bad vr at the end of a valid list */
        fmi2ValueReference mixed[3] = {RW_VR_h, RW_VR_b, 999};
        double v[3];
        fmi2Integer iv;
        fmi2Component c = in_state(S_EVENT);
        n_logs = 0;
        expect_error(c, fmi2GetInteger(c, &VR_H, 1, &iv), "GetInteger of a Real", "Real");
        fmi2FreeInstance(c);
        c = in_state(S_EVENT);
        n_logs = 0;
        expect_error(c, fmi2GetReal(c, mixed, 3, v), "GetReal list with a bad vr", "999");
        fmi2FreeInstance(c);
    }
    {   /* wrong array sizes */
        double a[16];
        size_t sizes[] = {0, RW_NUMBER_OF_STATES - 1, RW_NUMBER_OF_STATES + 1};
        for (size_t k = 0; k < 3; k++) {
            fmi2Component c = in_state(S_CONT);
            memset(a, 0, sizeof a);
            n_logs = 0;
            expect_error(c, fmi2GetDerivatives(c, a, sizes[k]), "GetDerivatives nx", "nx");
            fmi2FreeInstance(c);
            c = in_state(S_CONT);
            n_logs = 0;
            expect_error(c, fmi2SetContinuousStates(c, a, sizes[k]), "SetContinuousStates nx", "nx");
            fmi2FreeInstance(c);
            c = in_state(S_CONT);
            n_logs = 0;
            expect_error(c, fmi2GetEventIndicators(c, a, sizes[k] + 1), "GetEventIndicators ni", "ni");
            fmi2FreeInstance(c);
        }
    }
    {   /* unknown log category */
        fmi2String cats[1] = {"noSuchCategory"};
        fmi2Component c = in_state(S_INST);
        n_logs = 0;
        expect_error(c, fmi2SetDebugLogging(c, fmi2True, 1, cats), "unknown category", "noSuchCategory");
        fmi2FreeInstance(c);
    }
}

/* ---- a function of the other interface type ------------------------ */

/* Co-Simulation states, reached the same way as in_state's */
enum { CS_INST, CS_INIT, CS_STEP, CS_TERM, CS_ERROR, N_CS_STATES };
static const char *CS_STATE_NAMES[] = {"instantiated", "initializationMode", "stepComplete", "terminated", "error"};

static fmi2Component in_cs_state(int s)
{
    fmi2Component c = fmi2Instantiate("bad", fmi2CoSimulation, RW_GUID, "", &CB, fmi2False, fmi2False);
    fmi2ValueReference nosuch = 999;
    double v = 0;
    if (!c) return NULL;
    if (s == CS_ERROR) { fmi2SetReal(c, &nosuch, 1, &v); return c; }
    if (s == CS_INST) return c;
    fmi2SetupExperiment(c, fmi2False, 0, 0, fmi2False, 0);
    fmi2EnterInitializationMode(c);
    if (s == CS_INIT) return c;
    fmi2ExitInitializationMode(c);
    if (s == CS_TERM) fmi2Terminate(c);
    return c;
}

static fmi2Status c_real_in_der(fmi2Component c)
{
    fmi2ValueReference vr = RW_VR_ag;
    fmi2Integer order = 1;
    double v = 0.0;
    return fmi2SetRealInputDerivatives(c, &vr, 1, &order, &v);
}
static fmi2Status c_do_step(fmi2Component c) { return fmi2DoStep(c, 0.0, 0.01, fmi2True); }
static fmi2Status c_status(fmi2Component c) { fmi2Status v; return fmi2GetStatus(c, fmi2DoStepStatus, &v); }
static fmi2Status c_real_status(fmi2Component c) { double v; return fmi2GetRealStatus(c, fmi2LastSuccessfulTime, &v); }
static fmi2Status c_bool_status(fmi2Component c) { fmi2Boolean v; return fmi2GetBooleanStatus(c, fmi2Terminated, &v); }
static fmi2Status c_string_status(fmi2Component c) { fmi2String v; return fmi2GetStringStatus(c, fmi2PendingStatus, &v); }

/* every Model-Exchange-only function of API[] (fmi2EnterEventMode onwards) */
#define FIRST_ME_ONLY 9
static const Api CS_ONLY[] = {
    {"fmi2SetRealInputDerivatives", c_real_in_der, 0}, {"fmi2DoStep", c_do_step, 0},
    {"fmi2GetStatus", c_status, 0}, {"fmi2GetRealStatus", c_real_status, 0},
    {"fmi2GetBooleanStatus", c_bool_status, 0}, {"fmi2GetStringStatus", c_string_status, 0},
};

/* Found by a hostile-input pass: 7 of 147 forbidden calls returned fmi2OK with nothing logged, all of them
 * Model-Exchange functions on a Co-Simulation instance in a state where Model Exchange allows
 * them (fmi2GetNominalsOfContinuousStates when instantiated; fmi2GetEventIndicators,
 * fmi2GetContinuousStates in initialization; fmi2GetDerivatives and others when terminated).
 * Every function of one interface type on an instance of the other, in every state, must fail
 * with a logged reason that names the function and says which interface it belongs to. */
static void test_finding14_functions_of_the_other_interface_type(void)
{
    int rejected = 0;
    for (size_t f = FIRST_ME_ONLY; f < N_API; f++)
        for (int s = 0; s < N_CS_STATES; s++) {
            char what[160];
            fmi2Component c = in_cs_state(s);
            if (!c) { CHECK(0, "instantiate CS"); continue; }
            snprintf(what, sizeof what, "finding 14: %s on a Co-Simulation instance in %s", API[f].name, CS_STATE_NAMES[s]);
            n_logs = 0;
            expect_error(NULL, API[f].call(c), what, API[f].name);
            CHECK(strstr(last_message, "Model Exchange function"), "%s: log '%s' does not say why", what, last_message);
            fmi2FreeInstance(c);
            rejected++;
        }
    for (size_t f = 0; f < sizeof CS_ONLY / sizeof CS_ONLY[0]; f++)
        for (int s = 0; s < N_STATES; s++) {
            char what[160];
            fmi2Component c = in_state(s);
            if (!c) { CHECK(0, "instantiate ME"); continue; }
            snprintf(what, sizeof what, "finding 14: %s on a Model Exchange instance in %s", CS_ONLY[f].name, STATE_NAMES[s]);
            n_logs = 0;
            expect_error(NULL, CS_ONLY[f].call(c), what, CS_ONLY[f].name);
            CHECK(strstr(last_message, "Co-Simulation function"), "%s: log '%s' does not say why", what, last_message);
            fmi2FreeInstance(c);
            rejected++;
        }
    printf("  %d calls of the other interface type rejected\n", rejected);
}

/* providesDirectionalDerivative is false: each call is an error. canGetAndSetFMUstate and
 * canSerializeFMUstate are true: in every state, a state taken can be
 * serialized, read back and set (test_fmu_state.c tests what it restores). */
static void test_unsupported_functions_and_fmu_state_in_every_state(void)
{
    for (int s = 0; s < N_STATES; s++) {
        fmi2Component c = in_state(s);
        fmi2FMUstate st = NULL, back = NULL;
        size_t n = 0;
        static fmi2Byte buf[1 << 16]; /* the state holds the exact engine with its cache, ~18 KiB */
        fmi2ValueReference vr = RW_VR_s1, vu = RW_VR_ag;
        double dv = 1, dz;
        n_logs = 0; CHECK(fmi2GetDirectionalDerivative(c, &vr, 1, &vu, 1, &dv, &dz) == fmi2Error && n_logs, "GetDirectionalDerivative");
        fmi2FreeInstance(c);
        c = in_state(s);
        CHECK(fmi2GetFMUstate(c, &st) == fmi2OK, "GetFMUstate in %s: %s", STATE_NAMES[s], last_message);
        CHECK(fmi2SerializedFMUstateSize(c, st, &n) == fmi2OK && n > 0 && n <= sizeof buf, "SerializedFMUstateSize %u", (unsigned)n);
        CHECK(n <= sizeof buf && fmi2SerializeFMUstate(c, st, buf, n) == fmi2OK, "SerializeFMUstate in %s", STATE_NAMES[s]);
        CHECK(fmi2DeSerializeFMUstate(c, buf, n, &back) == fmi2OK, "DeSerializeFMUstate in %s: %s", STATE_NAMES[s], last_message);
        CHECK(fmi2SetFMUstate(c, back) == fmi2OK, "SetFMUstate in %s: %s", STATE_NAMES[s], last_message);
        CHECK(fmi2FreeFMUstate(c, &st) == fmi2OK && fmi2FreeFMUstate(c, &back) == fmi2OK && !st && !back, "FreeFMUstate");
        fmi2FreeInstance(c);
    }
}

int main(void)
{
    test_every_call_in_every_forbidden_state();
    test_every_call_in_an_allowed_state_succeeds();
    test_null_pointers();
    test_null_instance();
    test_instantiate_arguments();
    test_invalid_parameters_and_inputs();
    test_value_references_and_sizes();
    test_unsupported_functions_and_fmu_state_in_every_state();
    test_finding14_functions_of_the_other_interface_type();
    printf("%d checks, %d failures\n", checks, failures);
    return failures ? 1 : 0;
}
