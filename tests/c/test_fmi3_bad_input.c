/* Bad input to the FMI 3.0 API of RockingWall (fmi3Functions.c linked statically), Model
 * Exchange and Co-Simulation: every function of the matrix below called in every state where the
 * state machines of FMI 3.0 (sections 3.2 and 4.2) forbid it, functions of the other interface
 * type, NULL pointers, unknown value references, wrong types and sizes, out-of-range, NaN and
 * infinite parameters and inputs, and the FMI 3.0 functions for features the FMU does not have.
 * Each must return fmi3Error with a reason passed to the logger (captured here), must not crash,
 * and the instance must be usable again after fmi3Reset (ctest runs this under ASan/UBSan in the
 * sanitizer build). Every allowed (function, state) pair must succeed, so the matrix cannot pass
 * by rejecting everything; the FMU state round trip and the values of time and the event
 * indicators are checked against the other API calls that give them. */
#include "check.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmi3Functions.h"
#include "model_variables.h"

/* ---- logger ------------------------------------------------------------------------------- */
static char last_message[2048];
static fmi3Status last_status;
static int n_logs = 0;

static void logger(fmi3InstanceEnvironment env, fmi3Status status, fmi3String category, fmi3String message)
{
    (void)env;
    (void)category;
    snprintf(last_message, sizeof last_message, "%s", message ? message : "(null)");
    last_status = status;
    n_logs++;
}

/* ---- the states and how to reach them ----------------------------------------------------- */
enum { S_INST, S_INIT, S_EVENT, S_CONT, S_TERM, S_ERROR, N_STATES };
static const char *STATE_NAMES[] = {"Instantiated", "InitializationMode", "EventMode", "ContinuousTimeMode",
                                    "Terminated", "error"};
enum { C_INST, C_INIT, C_EVENT, C_STEP, C_TERM, C_ERROR, N_CS_STATES };
static const char *CS_STATE_NAMES[] = {"Instantiated", "InitializationMode", "EventMode", "StepMode", "Terminated",
                                       "error"};
#define B(s) (1u << (s))

static fmi3Instance me(void)
{
    return fmi3InstantiateModelExchange("bad", RW_GUID, NULL, false, false, NULL, logger);
}

static fmi3Instance cs(int event_mode_used)
{
    return fmi3InstantiateCoSimulation("bad", RW_GUID, NULL, false, false, event_mode_used, false, NULL, 0, NULL,
                                       logger, NULL);
}

static void make_error(fmi3Instance c)
{
    fmi3ValueReference nosuch = 999;
    double v = 0;
    fmi3SetFloat64(c, &nosuch, 1, &v, 1);
}

static fmi3Instance in_state(int s)
{
    fmi3Instance c = me();
    if (!c) return NULL;
    if (s == S_ERROR) { make_error(c); return c; }
    if (s == S_INST) return c;
    fmi3EnterInitializationMode(c, false, 0, 0, false, 0);
    if (s == S_INIT) return c;
    fmi3ExitInitializationMode(c);
    if (s == S_EVENT) return c;
    if (s == S_TERM) { fmi3Terminate(c); return c; }
    fmi3EnterContinuousTimeMode(c);
    return c;
}

/* Co-Simulation instances with eventModeUsed, so that every Co-Simulation state is reachable */
static fmi3Instance in_cs_state(int s)
{
    fmi3Instance c = cs(1);
    if (!c) return NULL;
    if (s == C_ERROR) { make_error(c); return c; }
    if (s == C_INST) return c;
    fmi3EnterInitializationMode(c, false, 0, 0, false, 0);
    if (s == C_INIT) return c;
    fmi3ExitInitializationMode(c); /* into EventMode (eventModeUsed) */
    if (s == C_TERM) fmi3Terminate(c);
    if (s == C_STEP) fmi3EnterStepMode(c);
    return c;
}

/* ---- each function with valid arguments ---------------------------------------------------- */
static fmi3ValueReference VR_H = RW_VR_h, VR_SUPPORT = RW_VR_support, VR_COLLAPSED = RW_VR_collapsed;
static fmi3Status c_enter_init(fmi3Instance c) { return fmi3EnterInitializationMode(c, false, 0, 0, false, 0); }
static fmi3Status c_exit_init(fmi3Instance c) { return fmi3ExitInitializationMode(c); }
static fmi3Status c_terminate(fmi3Instance c) { return fmi3Terminate(c); }
static fmi3Status c_get_f64(fmi3Instance c) { double v; return fmi3GetFloat64(c, &VR_H, 1, &v, 1); }
static fmi3Status c_get_i32(fmi3Instance c) { fmi3Int32 v; return fmi3GetInt32(c, &VR_SUPPORT, 1, &v, 1); }
static fmi3Status c_get_bool(fmi3Instance c) { fmi3Boolean v; return fmi3GetBoolean(c, &VR_COLLAPSED, 1, &v, 1); }
static fmi3Status c_set_input(fmi3Instance c) { fmi3ValueReference vr = RW_VR_ag; double v = 0.1; return fmi3SetFloat64(c, &vr, 1, &v, 1); }
static fmi3Status c_set_i32(fmi3Instance c) { fmi3Int32 v = 3; return fmi3SetInt32(c, &VR_SUPPORT, 1, &v, 1); }
static fmi3Status c_enter_event(fmi3Instance c) { return fmi3EnterEventMode(c); }
static fmi3Status c_update(fmi3Instance c)
{
    fmi3Boolean a, b, d, e, f;
    double t;
    return fmi3UpdateDiscreteStates(c, &a, &b, &d, &e, &f, &t);
}
static fmi3Status c_enter_cont(fmi3Instance c) { return fmi3EnterContinuousTimeMode(c); }
static fmi3Status c_completed(fmi3Instance c)
{
    fmi3Boolean ev, term;
    return fmi3CompletedIntegratorStep(c, true, &ev, &term);
}
static fmi3Status c_set_time(fmi3Instance c) { return fmi3SetTime(c, 0.0); }
static fmi3Status c_set_states(fmi3Instance c) { double x[RW_NUMBER_OF_STATES] = {0}; return fmi3SetContinuousStates(c, x, RW_NUMBER_OF_STATES); }
static fmi3Status c_get_der(fmi3Instance c) { double dx[RW_NUMBER_OF_STATES]; return fmi3GetContinuousStateDerivatives(c, dx, RW_NUMBER_OF_STATES); }
static fmi3Status c_get_z(fmi3Instance c) { double z[RW_NUMBER_OF_EVENT_INDICATORS]; return fmi3GetEventIndicators(c, z, RW_NUMBER_OF_EVENT_INDICATORS); }
static fmi3Status c_get_states(fmi3Instance c) { double x[RW_NUMBER_OF_STATES]; return fmi3GetContinuousStates(c, x, RW_NUMBER_OF_STATES); }
static fmi3Status c_get_nom(fmi3Instance c) { double x[RW_NUMBER_OF_STATES]; return fmi3GetNominalsOfContinuousStates(c, x, RW_NUMBER_OF_STATES); }
static fmi3Status c_enter_step(fmi3Instance c) { return fmi3EnterStepMode(c); }
static fmi3Status c_do_step(fmi3Instance c)
{
    fmi3Boolean ev, term, early;
    double last;
    return fmi3DoStep(c, 0.0, 0.01, true, &ev, &term, &early, &last);
}

typedef struct {
    const char *name;
    fmi3Status (*call)(fmi3Instance);
    unsigned me_allowed; /* states of Model Exchange it is allowed in (0: a Co-Simulation function) */
    unsigned cs_allowed; /* states of Co-Simulation it is allowed in (0: a Model Exchange function) */
} Api;

#define ME_READ (B(S_INIT) | B(S_EVENT) | B(S_CONT) | B(S_TERM))
#define CS_READ (B(C_INIT) | B(C_EVENT) | B(C_STEP) | B(C_TERM))
static const Api API[] = {
    {"fmi3EnterInitializationMode", c_enter_init, B(S_INST), B(C_INST)},
    {"fmi3ExitInitializationMode", c_exit_init, B(S_INIT), B(C_INIT)},
    {"fmi3Terminate", c_terminate, B(S_EVENT) | B(S_CONT), B(C_EVENT) | B(C_STEP)},
    {"fmi3GetFloat64", c_get_f64, ME_READ, CS_READ},
    {"fmi3GetInt32", c_get_i32, ME_READ, CS_READ},
    {"fmi3GetBoolean", c_get_bool, ME_READ, CS_READ},
    {"fmi3SetFloat64", c_set_input, B(S_INST) | B(S_INIT) | B(S_EVENT) | B(S_CONT),
     B(C_INST) | B(C_INIT) | B(C_EVENT) | B(C_STEP)},
    {"fmi3SetInt32", c_set_i32, B(S_INST) | B(S_INIT), B(C_INST) | B(C_INIT)}, /* a parameter */
    {"fmi3UpdateDiscreteStates", c_update, B(S_EVENT), B(C_EVENT)},
    /* Model Exchange only */
    {"fmi3EnterContinuousTimeMode", c_enter_cont, B(S_EVENT), 0},
    {"fmi3CompletedIntegratorStep", c_completed, B(S_CONT), 0},
    {"fmi3SetTime", c_set_time, B(S_EVENT) | B(S_CONT), 0},
    {"fmi3SetContinuousStates", c_set_states, B(S_CONT), 0},
    {"fmi3GetContinuousStateDerivatives", c_get_der, B(S_EVENT) | B(S_CONT) | B(S_TERM), 0},
    {"fmi3GetEventIndicators", c_get_z, ME_READ, 0},
    {"fmi3GetContinuousStates", c_get_states, ME_READ, 0},
    {"fmi3GetNominalsOfContinuousStates", c_get_nom, B(S_INST) | B(S_EVENT) | B(S_CONT) | B(S_TERM), 0},
    /* Co-Simulation only */
    {"fmi3EnterStepMode", c_enter_step, 0, B(C_EVENT)},
    {"fmi3DoStep", c_do_step, 0, B(C_STEP)},
    /* both, with interface-specific states */
    {"fmi3EnterEventMode", c_enter_event, B(S_EVENT) | B(S_CONT), B(C_STEP)},
};
#define N_API (sizeof API / sizeof API[0])

/* fmi3Error, an error logged that mentions `mention`; then the instance must recover through
 * fmi3Reset (allowed in every state) */
static void expect_error(fmi3Instance c, fmi3Status got, const char *what, const char *mention)
{
    CHECK(got == fmi3Error, "%s: status %d, expected fmi3Error", what, (int)got);
    CHECK(n_logs > 0 && last_status == fmi3Error, "%s: no error logged", what);
    CHECK(!mention || strstr(last_message, mention), "%s: log '%s' does not mention '%s'", what, last_message, mention);
    if (c) {
        CHECK(fmi3Reset(c) == fmi3OK, "%s: fmi3Reset after the error", what);
        CHECK(c_enter_init(c) == fmi3OK && c_exit_init(c) == fmi3OK, "%s: instance not usable after fmi3Reset", what);
    }
}

static fmi3Instance reach(int cs_instance, int s) { return cs_instance ? in_cs_state(s) : in_state(s); }

/* every call in every state of both interface types: allowed ones succeed, others fail */
static void test_every_call_in_every_state(void)
{
    int rejected = 0, accepted = 0;
    for (int type = 0; type < 2; type++)
        for (size_t f = 0; f < N_API; f++)
            for (int s = 0; s < (type ? N_CS_STATES : N_STATES); s++) {
                const unsigned allowed = type ? API[f].cs_allowed : API[f].me_allowed;
                const int error_state = type ? s == C_ERROR : s == S_ERROR;
                char what[200];
                fmi3Instance c = reach(type, s);
                fmi3Status st;
                if (!c) { CHECK(0, "instantiate"); continue; }
                snprintf(what, sizeof what, "%s on a %s instance in %s", API[f].name, type ? "Co-Simulation" : "Model Exchange",
                         type ? CS_STATE_NAMES[s] : STATE_NAMES[s]);
                n_logs = 0;
                st = API[f].call(c);
                if (allowed & B(s)) {
                    CHECK(st == fmi3OK, "%s: status %d (%s)", what, (int)st, last_message);
                    accepted++;
                } else if (!error_state || !allowed) {
                    expect_error(c, st, what, API[f].name);
                    if (!allowed)
                        CHECK(strstr(last_message, type ? "Model Exchange function" : "Co-Simulation function"),
                              "%s: log '%s' does not say which interface type", what, last_message);
                    rejected++;
                }
                fmi3FreeInstance(c);
            }
    printf("  %d (function, state) pairs rejected, %d accepted\n", rejected, accepted);
    CHECK(rejected >= 100 && accepted >= 40, "only %d rejected / %d accepted pairs exercised", rejected, accepted);
}

static void test_event_mode_of_co_simulation_needs_event_mode_used(void)
{
    fmi3Instance c = cs(0);
    c_enter_init(c);
    c_exit_init(c); /* straight into StepMode */
    n_logs = 0;
    expect_error(c, fmi3EnterEventMode(c), "fmi3EnterEventMode without eventModeUsed", "eventModeUsed");
    fmi3FreeInstance(c);
}

static void test_null_pointers(void)
{
    double v[8];
    fmi3Int32 iv;
    fmi3Boolean bv;
    size_t n;
    for (int k = 0; k < 21; k++) {
        const int state = k < 4 ? S_EVENT : (k < 6 ? S_INST : S_CONT);
        fmi3Instance c = in_state(state);
        fmi3Status st = fmi3OK;
        fmi3Boolean a;
        double t;
        n_logs = 0;
        switch (k) {
        case 0: st = fmi3GetFloat64(c, NULL, 1, v, 1); break;
        case 1: st = fmi3GetFloat64(c, &VR_H, 1, NULL, 1); break;
        case 2: st = fmi3GetInt32(c, &VR_SUPPORT, 1, NULL, 1); break;
        case 3: st = fmi3UpdateDiscreteStates(c, NULL, &a, &a, &a, &a, &t); break;
        case 4: st = fmi3SetFloat64(c, NULL, 1, v, 1); break;
        case 5: st = fmi3SetInt32(c, &VR_SUPPORT, 1, NULL, 1); break;
        case 6: st = fmi3CompletedIntegratorStep(c, true, NULL, &a); break;
        case 7: st = fmi3CompletedIntegratorStep(c, true, &a, NULL); break;
        case 8: st = fmi3SetContinuousStates(c, NULL, RW_NUMBER_OF_STATES); break;
        case 9: st = fmi3GetContinuousStateDerivatives(c, NULL, RW_NUMBER_OF_STATES); break;
        case 10: st = fmi3GetEventIndicators(c, NULL, RW_NUMBER_OF_EVENT_INDICATORS); break;
        case 11: st = fmi3GetContinuousStates(c, NULL, RW_NUMBER_OF_STATES); break;
        case 12: st = fmi3GetNominalsOfContinuousStates(c, NULL, RW_NUMBER_OF_STATES); break;
        case 13: st = fmi3GetNumberOfEventIndicators(c, NULL); break;
        case 14: st = fmi3GetNumberOfContinuousStates(c, NULL); break;
        case 15: st = fmi3SetDebugLogging(c, true, 2, NULL); break;
        case 16: st = fmi3GetBoolean(c, NULL, 1, &bv, 1); break;
        case 17: st = fmi3GetFMUState(c, NULL); break;
        case 18: st = fmi3FreeFMUState(c, NULL); break;
        case 19: st = fmi3SetFMUState(c, NULL); break;
        case 20: st = fmi3SerializedFMUStateSize(c, NULL, &n); break;
        }
        (void)iv;
        {
            char what[64];
            snprintf(what, sizeof what, "NULL argument, case %d", k);
            expect_error(c, st, what, "NULL");
        }
        fmi3FreeInstance(c);
    }
    {   /* fmi3DoStep's four outputs */
        for (int k = 0; k < 4; k++) {
            fmi3Instance c = in_cs_state(C_STEP);
            fmi3Boolean a, b, d;
            double last;
            n_logs = 0;
            fmi3Status st = fmi3DoStep(c, 0, 0.01, true, k == 0 ? NULL : &a, k == 1 ? NULL : &b, k == 2 ? NULL : &d,
                                       k == 3 ? NULL : &last);
            expect_error(c, st, "fmi3DoStep with a NULL output", "NULL");
            fmi3FreeInstance(c);
        }
    }
}

/* A NULL instance cannot log (no logger to reach), but must not crash. */
static void test_null_instance(void)
{
    double v[4];
    fmi3Boolean a, b, d, e, f;
    double t;
    CHECK(fmi3EnterInitializationMode(NULL, false, 0, 0, false, 0) == fmi3Error && fmi3ExitInitializationMode(NULL) == fmi3Error, "NULL: init");
    CHECK(fmi3GetFloat64(NULL, &VR_H, 1, v, 1) == fmi3Error && fmi3SetFloat64(NULL, &VR_H, 1, v, 1) == fmi3Error, "NULL: Float64");
    CHECK(fmi3UpdateDiscreteStates(NULL, &a, &b, &d, &e, &f, &t) == fmi3Error, "NULL: update");
    CHECK(fmi3DoStep(NULL, 0, 0.1, true, &a, &b, &d, &t) == fmi3Error, "NULL: step");
    CHECK(fmi3Terminate(NULL) == fmi3Error && fmi3Reset(NULL) == fmi3Error, "NULL: terminate/reset");
    CHECK(fmi3GetFloat32(NULL, &VR_H, 1, NULL, 1) == fmi3Error, "NULL: Float32");
    fmi3FreeInstance(NULL);
}

static void test_instantiate_arguments(void)
{
    n_logs = 0;
    CHECK(fmi3InstantiateModelExchange(NULL, RW_GUID, NULL, false, false, NULL, logger) == NULL, "NULL name");
    CHECK(n_logs == 1 && last_status == fmi3Error && strstr(last_message, "instanceName"), "NULL name: log '%s'", last_message);
    n_logs = 0;
    CHECK(fmi3InstantiateCoSimulation("", RW_GUID, NULL, false, false, false, false, NULL, 0, NULL, logger, NULL) == NULL, "empty name");
    CHECK(n_logs == 1 && strstr(last_message, "instanceName"), "empty name: log '%s'", last_message);
    n_logs = 0;
    CHECK(fmi3InstantiateModelExchange("x", NULL, NULL, false, false, NULL, logger) == NULL, "NULL token");
    CHECK(n_logs == 1 && strstr(last_message, "instantiationToken"), "NULL token: log '%s'", last_message);
    n_logs = 0;
    CHECK(fmi3InstantiateModelExchange("x", "{1631bb30-%s%n}", NULL, false, false, NULL, logger) == NULL, "format token");
    CHECK(n_logs == 1 && !strchr(last_message, '%'), "a token with %% reaches the logger as a format: '%s'", last_message);
    CHECK(fmi3InstantiateModelExchange("x", RW_GUID, NULL, false, false, NULL, NULL) == NULL, "no logger");
    n_logs = 0;
    CHECK(fmi3InstantiateScheduledExecution("x", RW_GUID, NULL, false, false, NULL, logger, NULL, NULL, NULL) == NULL,
          "Scheduled Execution");
    CHECK(n_logs == 1 && strstr(last_message, "Scheduled Execution"), "Scheduled Execution: log '%s'", last_message);
}

static void bad_float64(int state, fmi3ValueReference vr, double value, const char *mention)
{
    fmi3Instance c = in_state(state);
    char what[128];
    snprintf(what, sizeof what, "SetFloat64 vr %u = %g in %s", (unsigned)vr, value, STATE_NAMES[state]);
    n_logs = 0;
    expect_error(c, fmi3SetFloat64(c, &vr, 1, &value, 1), what, mention);
    fmi3FreeInstance(c);
}

static void test_invalid_parameters_and_inputs(void)
{
    const double nonfinite[] = {NAN, INFINITY, -INFINITY};
    const fmi3ValueReference reals[] = {RW_VR_h, RW_VR_b, RW_VR_W, RW_VR_psi, RW_VR_Kd, RW_VR_er, RW_VR_g,
                                        RW_VR_delta1Ratio, RW_VR_delta2A, RW_VR_delta2B, RW_VR_hingeSat,
                                        RW_VR_restRate, RW_VR_q1, RW_VR_q2, RW_VR_dq1, RW_VR_dq2};
    struct { fmi3ValueReference vr; double v; const char *name; } out_of_range[] = {
        {RW_VR_h, 0, "h"}, {RW_VR_h, 31, "h"}, {RW_VR_b, -0.1, "b"}, {RW_VR_W, 0, "W"}, {RW_VR_psi, -1, "psi"},
        {RW_VR_Kd, -1, "Kd"}, {RW_VR_er, 1.5, "er"}, {RW_VR_g, 0, "g"}, {RW_VR_delta1Ratio, 1.0, "delta1Ratio"},
        {RW_VR_hingeSat, 0, "hingeSat"}, {RW_VR_restRate, 0, "restRate"},
    };
    const fmi3Int32 bad_ints[] = {0, 5, -1, 2147483647};
    for (size_t i = 0; i < sizeof reals / sizeof reals[0]; i++)
        for (size_t k = 0; k < 3; k++) {
            bad_float64(S_INST, reals[i], nonfinite[k], "not a finite number");
            bad_float64(S_INIT, reals[i], nonfinite[k], "not a finite number");
        }
    for (size_t i = 0; i < sizeof out_of_range / sizeof out_of_range[0]; i++)
        bad_float64(S_INST, out_of_range[i].vr, out_of_range[i].v, out_of_range[i].name);
    for (int s = S_INST; s <= S_CONT; s++)
        for (size_t k = 0; k < 3; k++) {
            bad_float64(s, RW_VR_ag, nonfinite[k], "ag");
            bad_float64(s, RW_VR_u_top, nonfinite[k], "u_top");
        }
    bad_float64(S_EVENT, RW_VR_h, 3.0, "can only be set before");        /* fixed parameter after init */
    bad_float64(S_CONT, RW_VR_q1, 0.01, "fmi3SetContinuousStates");      /* state start value after init */
    bad_float64(S_EVENT, RW_VR_s1, 0.01, "cannot be set");               /* an output */
    bad_float64(S_INST, 0, 1.0, "time");                                  /* the independent variable */
    bad_float64(S_INST, 50, 1.0, "event indicator");
    for (size_t k = 0; k < sizeof bad_ints / sizeof bad_ints[0]; k++) {
        fmi3ValueReference vrs[2] = {RW_VR_support, RW_VR_hingeLaw};
        for (int j = 0; j < 2; j++) {
            fmi3Instance c = in_state(S_INST);
            n_logs = 0;
            expect_error(c, fmi3SetInt32(c, &vrs[j], 1, &bad_ints[k], 1), "bad Int32 parameter", j ? "hingeLaw" : "support");
            fmi3FreeInstance(c);
        }
    }
    {   /* cross-parameter: b >= h is only known at fmi3ExitInitializationMode */
        fmi3Instance c = in_state(S_INIT);
        fmi3ValueReference vr = RW_VR_b;
        double b = 2.5;
        CHECK(fmi3SetFloat64(c, &vr, 1, &b, 1) == fmi3OK, "b alone");
        n_logs = 0;
        expect_error(c, fmi3ExitInitializationMode(c), "b = h at exit init", "b");
        fmi3FreeInstance(c);
    }
    {   /* non-finite time, start time, tolerance, states, step sizes */
        double x[RW_NUMBER_OF_STATES] = {0, 0, NAN, 0};
        fmi3Boolean a, b, d;
        double last;
        fmi3Instance c = in_state(S_CONT);
        n_logs = 0;
        expect_error(c, fmi3SetTime(c, NAN), "SetTime NaN", "time");
        fmi3FreeInstance(c);
        c = in_state(S_CONT);
        n_logs = 0;
        expect_error(c, fmi3SetContinuousStates(c, x, RW_NUMBER_OF_STATES), "SetContinuousStates NaN", "not finite");
        fmi3FreeInstance(c);
        c = in_state(S_INST);
        n_logs = 0;
        expect_error(c, fmi3EnterInitializationMode(c, false, 0, INFINITY, false, 0), "startTime inf", "startTime");
        fmi3FreeInstance(c);
        c = in_state(S_INST);
        n_logs = 0;
        expect_error(c, fmi3EnterInitializationMode(c, true, 2.0, 0, false, 0), "tolerance 2", "tolerance");
        fmi3FreeInstance(c);
        c = in_cs_state(C_STEP);
        n_logs = 0;
        expect_error(c, fmi3DoStep(c, 0, -0.1, true, &a, &b, &d, &last), "DoStep negative step", "step size");
        fmi3FreeInstance(c);
        c = in_cs_state(C_STEP);
        n_logs = 0;
        expect_error(c, fmi3DoStep(c, 1.0, 0.1, true, &a, &b, &d, &last), "DoStep at the wrong time", "currentCommunicationPoint");
        fmi3FreeInstance(c);
    }
}

static void test_value_references_types_and_sizes(void)
{
    const fmi3ValueReference unknown[] = {24, 29, 22, 39, 46, 49, 58, 999, 0xFFFFFFFFu};
    for (size_t i = 0; i < sizeof unknown / sizeof unknown[0]; i++) {
        char num[32];
        double v = 0;
        fmi3Int32 iv = 0;
        fmi3Boolean bv = 0;
        fmi3Instance c;
        snprintf(num, sizeof num, "%u", (unsigned)unknown[i]);
#define BAD_VR(STATE, CALL, WHAT)                     \
        c = in_state(STATE); n_logs = 0;              \
        expect_error(c, CALL, WHAT, num);             \
        fmi3FreeInstance(c)
        BAD_VR(S_EVENT, fmi3GetFloat64(c, &unknown[i], 1, &v, 1), "GetFloat64 unknown vr");
        BAD_VR(S_INST, fmi3SetFloat64(c, &unknown[i], 1, &v, 1), "SetFloat64 unknown vr");
        BAD_VR(S_EVENT, fmi3GetInt32(c, &unknown[i], 1, &iv, 1), "GetInt32 unknown vr");
        BAD_VR(S_INST, fmi3SetInt32(c, &unknown[i], 1, &iv, 1), "SetInt32 unknown vr");
        BAD_VR(S_EVENT, fmi3GetBoolean(c, &unknown[i], 1, &bv, 1), "GetBoolean unknown vr");
        BAD_VR(S_INST, fmi3SetBoolean(c, &unknown[i], 1, &bv, 1), "SetBoolean unknown vr");
#undef BAD_VR
    }
    {   /* known value references through a getter of another type, each FMI 3.0 type the FMU lacks */
        fmi3Instance c = in_state(S_EVENT);
        fmi3Int32 iv;
        float f;
        fmi3String sv;
        fmi3ValueReference z = 50, t = 0;
        n_logs = 0;
        expect_error(c, fmi3GetInt32(c, &VR_H, 1, &iv, 1), "GetInt32 of a Float64", "Float64");
        expect_error(c, fmi3GetInt32(c, &z, 1, &iv, 1), "GetInt32 of an event indicator", "Float64");
        expect_error(c, fmi3GetBoolean(c, &t, 1, (fmi3Boolean *)&iv, 1), "GetBoolean of time", "Float64");
        expect_error(c, fmi3GetFloat32(c, &VR_H, 1, &f, 1), "GetFloat32 of a Float64", "Float64");
        expect_error(c, fmi3GetString(c, &VR_H, 1, &sv, 1), "GetString", "String");
        expect_error(c, fmi3GetUInt64(c, &unknown[7], 1, NULL, 1), "GetUInt64", "UInt64");
        expect_error(c, fmi3SetInt8(c, &unknown[7], 1, NULL, 1), "SetInt8", "Int8");
        expect_error(c, fmi3GetBinary(c, &unknown[7], 1, NULL, NULL, 1), "GetBinary", "Binary");
        expect_error(c, fmi3GetClock(c, &unknown[7], 1, NULL), "GetClock", "Clock");
        fmi3FreeInstance(c);
    }
    {   /* nValues must match: every variable is a scalar */
        fmi3Instance c = in_state(S_EVENT);
        fmi3ValueReference vrs[2] = {RW_VR_h, RW_VR_b};
        double v[3];
        n_logs = 0;
        expect_error(c, fmi3GetFloat64(c, vrs, 2, v, 1), "GetFloat64 nValues 1 for 2", "nValues");
        expect_error(c, fmi3GetFloat64(c, vrs, 2, v, 3), "GetFloat64 nValues 3 for 2", "nValues");
        fmi3FreeInstance(c);
    }
    {   /* array sizes of the continuous-time functions */
        double a[16];
        size_t sizes[] = {0, RW_NUMBER_OF_STATES - 1, RW_NUMBER_OF_STATES + 1};
        for (size_t k = 0; k < 3; k++) {
            fmi3Instance c = in_state(S_CONT);
            memset(a, 0, sizeof a);
            n_logs = 0;
            expect_error(c, fmi3GetContinuousStateDerivatives(c, a, sizes[k]), "GetContinuousStateDerivatives n", "nContinuousStates");
            fmi3EnterContinuousTimeMode(c); /* expect_error left it in Event Mode */
            expect_error(c, fmi3SetContinuousStates(c, a, sizes[k]), "SetContinuousStates n", "nContinuousStates");
            expect_error(c, fmi3GetEventIndicators(c, a, sizes[k] + 1), "GetEventIndicators n", "nEventIndicators");
            fmi3FreeInstance(c);
        }
    }
    {   /* unknown log category */
        fmi3String cats[1] = {"noSuchCategory"};
        fmi3Instance c = in_state(S_INST);
        n_logs = 0;
        expect_error(c, fmi3SetDebugLogging(c, true, 1, cats), "unknown category", "noSuchCategory");
        fmi3FreeInstance(c);
    }
}

/* the functions of features the FMU does not declare: fmi3Error with the reason */
static void test_unsupported_features(void)
{
    fmi3Instance c = in_state(S_EVENT);
    fmi3ValueReference vr = RW_VR_s1, vu = RW_VR_ag;
    double seed = 1, sens;
    size_t n;
    n_logs = 0;
    expect_error(c, fmi3GetDirectionalDerivative(c, &vr, 1, &vu, 1, &seed, 1, &sens, 1), "directional", "not supported");
    expect_error(c, fmi3GetAdjointDerivative(c, &vr, 1, &vu, 1, &seed, 1, &sens, 1), "adjoint", "not supported");
    expect_error(c, fmi3GetNumberOfVariableDependencies(c, vr, &n), "dependencies", "not supported");
    expect_error(c, fmi3EnterConfigurationMode(c), "configuration", "structural parameters");
    expect_error(c, fmi3GetIntervalDecimal(c, &vr, 1, &sens, NULL), "interval", "clocks");
    expect_error(c, fmi3ActivateModelPartition(c, 1, 0.0), "partition", "Scheduled Execution");
    fmi3FreeInstance(c);
    c = in_cs_state(C_STEP);
    {
        fmi3Int32 order = 1;
        n_logs = 0;
        expect_error(c, fmi3GetOutputDerivatives(c, &vr, 1, &order, &sens, 1), "output derivatives", "maxOutputDerivativeOrder");
    }
    fmi3FreeInstance(c);
}

/* time (vr 0) and the event indicators (vr 50..57) read as Float64 equal fmi3SetTime's time and
 * fmi3GetEventIndicators' values */
static void test_time_and_event_indicators_as_variables(void)
{
    fmi3Instance c = in_state(S_CONT);
    fmi3ValueReference vrs[1 + RW_NUMBER_OF_EVENT_INDICATORS];
    double by_vr[1 + RW_NUMBER_OF_EVENT_INDICATORS], z[RW_NUMBER_OF_EVENT_INDICATORS];
    double x[RW_NUMBER_OF_STATES] = {0.004, 0.006, 0.1, -0.2};
    size_t nz = 0, nx = 0;
    vrs[0] = 0;
    for (int k = 0; k < RW_NUMBER_OF_EVENT_INDICATORS; k++) vrs[1 + k] = 50 + (fmi3ValueReference)k;
    CHECK(fmi3SetTime(c, 1.25) == fmi3OK && fmi3SetContinuousStates(c, x, RW_NUMBER_OF_STATES) == fmi3OK, "set");
    CHECK(fmi3GetFloat64(c, vrs, 1 + RW_NUMBER_OF_EVENT_INDICATORS, by_vr, 1 + RW_NUMBER_OF_EVENT_INDICATORS) == fmi3OK,
          "GetFloat64 of time and z: %s", last_message);
    CHECK(fmi3GetEventIndicators(c, z, RW_NUMBER_OF_EVENT_INDICATORS) == fmi3OK, "GetEventIndicators");
    CHECK(by_vr[0] == 1.25, "time = %g, expected 1.25", by_vr[0]);
    for (int k = 0; k < RW_NUMBER_OF_EVENT_INDICATORS; k++)
        CHECK(by_vr[1 + k] == z[k], "event indicator %d: %g by value reference, %g by fmi3GetEventIndicators", k,
              by_vr[1 + k], z[k]);
    CHECK(fmi3GetNumberOfEventIndicators(c, &nz) == fmi3OK && nz == RW_NUMBER_OF_EVENT_INDICATORS, "nz = %u", (unsigned)nz);
    CHECK(fmi3GetNumberOfContinuousStates(c, &nx) == fmi3OK && nx == RW_NUMBER_OF_STATES, "nx = %u", (unsigned)nx);
    fmi3FreeInstance(c);
}

/* in every state: a state taken can be serialized, read back and set; bad blocks are rejected */
static void test_fmu_state(void)
{
    static fmi3Byte buf[1 << 16];
    for (int type = 0; type < 2; type++)
        for (int s = 0; s < (type ? N_CS_STATES : N_STATES); s++) {
            fmi3Instance c = reach(type, s);
            fmi3FMUState st = NULL, back = NULL;
            size_t n = 0;
            const char *name = type ? CS_STATE_NAMES[s] : STATE_NAMES[s];
            CHECK(fmi3GetFMUState(c, &st) == fmi3OK, "GetFMUState in %s: %s", name, last_message);
            CHECK(fmi3SerializedFMUStateSize(c, st, &n) == fmi3OK && n > 0 && n <= sizeof buf, "size %u", (unsigned)n);
            CHECK(n <= sizeof buf && fmi3SerializeFMUState(c, st, buf, n) == fmi3OK, "SerializeFMUState in %s", name);
            CHECK(fmi3DeserializeFMUState(c, buf, n, &back) == fmi3OK, "DeserializeFMUState in %s: %s", name, last_message);
            CHECK(fmi3SetFMUState(c, back) == fmi3OK, "SetFMUState in %s: %s", name, last_message);
            CHECK(fmi3FreeFMUState(c, &st) == fmi3OK && fmi3FreeFMUState(c, &back) == fmi3OK && !st && !back, "FreeFMUState");
            fmi3FreeInstance(c);
        }
    {
        fmi3Instance c = in_state(S_EVENT), other = in_cs_state(C_STEP);
        fmi3FMUState st = NULL, cs_state = NULL;
        size_t n = 0;
        static fmi3Byte garbage[4096];
        CHECK(fmi3GetFMUState(c, &st) == fmi3OK && fmi3SerializedFMUStateSize(c, st, &n) == fmi3OK, "state");
        n_logs = 0;
        expect_error(NULL, fmi3SerializeFMUState(c, st, buf, n - 1), "SerializeFMUState wrong size", "size");
        expect_error(NULL, fmi3DeserializeFMUState(c, buf, 10, &cs_state), "DeserializeFMUState truncated", "header");
        memset(garbage, 0x5a, sizeof garbage);
        expect_error(NULL, fmi3DeserializeFMUState(c, garbage, sizeof garbage, &cs_state), "garbage", "not an FMU state");
        expect_error(NULL, fmi3SetFMUState(c, (fmi3FMUState)garbage), "SetFMUState of garbage", "not an FMU state");
        CHECK(fmi3GetFMUState(other, &cs_state) == fmi3OK, "CS state");
        expect_error(NULL, fmi3SetFMUState(c, cs_state), "SetFMUState CS into ME", "Co-Simulation");
        fmi3FreeFMUState(other, &cs_state);
        fmi3FreeFMUState(c, &st);
        fmi3FreeInstance(c);
        fmi3FreeInstance(other);
    }
}

int main(void)
{
    test_every_call_in_every_state();
    test_event_mode_of_co_simulation_needs_event_mode_used();
    test_null_pointers();
    test_null_instance();
    test_instantiate_arguments();
    test_invalid_parameters_and_inputs();
    test_value_references_types_and_sizes();
    test_unsupported_features();
    test_time_and_event_indicators_as_variables();
    test_fmu_state();
    printf("%d checks, %d failures\n", checks, failures);
    return failures ? 1 : 0;
}
