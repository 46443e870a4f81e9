/* Bad input to RockingWall's FMI 2.0 API (fmi2Functions.c linked statically), Model Exchange and
 * Co-Simulation: the cases both versions share (fmi_bad_input_cases.h) through the FMI 2.0 adapter
 * below, and the FMI 2.0 ones: NULL pointers and instances, String variables, directional
 * derivatives. The state machines are those of FMI 2.0 sections 3.2.3 and 4.2.4. */
#include "fmi_bad_input_cases.h"

#include <stdlib.h>

#include "fmi2Functions.h"

typedef char fmi2_numbers_statuses_as_the_cases_do[((int)fmi2OK == ST_OK && (int)fmi2Error == ST_ERROR) ? 1 : -1];

static void logger(fmi2ComponentEnvironment env, fmi2String name, fmi2Status status, fmi2String category,
                   fmi2String message, ...)
{
    (void)env; (void)name; (void)category;
    snprintf(last_message, sizeof last_message, "%s", message ? message : "(null)");
    last_status = (int)status;
    n_logs++;
}

static const fmi2CallbackFunctions CB = {logger, calloc, free, NULL, NULL};
static const fmi2CallbackFunctions NO_LOGGER = {NULL, calloc, free, NULL, NULL};

/* ---- the adapter ---------------------------------------------------------------------------- */

static fmi_inst a_instantiate(const char *name, const char *token, int with_logger)
{
    return fmi2Instantiate(name, fmi2ModelExchange, token, "", with_logger ? &CB : &NO_LOGGER, fmi2False, fmi2False);
}

static int a_enter_init(fmi_inst c, int tol_defined, double tol, double start)
{
    const fmi2Status st = fmi2SetupExperiment(c, tol_defined, tol, start, fmi2False, 0);
    return st == fmi2OK ? fmi2EnterInitializationMode(c) : st;
}

static fmi_inst a_in_state(int cs, int s)
{
    fmi2Component c = fmi2Instantiate("bad", cs ? fmi2CoSimulation : fmi2ModelExchange, RW_GUID, "", &CB, fmi2False,
                                      fmi2False);
    fmi2ValueReference nosuch = 999;
    double v = 0;
    if (!c || (cs && s == C_EVENT)) { fmi2FreeInstance(c); return NULL; } /* no Event Mode in FMI 2.0 Co-Simulation */
    if (s == (cs ? C_ERROR : S_ERROR)) { fmi2SetReal(c, &nosuch, 1, &v); return c; }
    if (s == S_INST) return c; /* = C_INST */
    a_enter_init(c, 0, 0, 0);
    if (s == S_INIT) return c; /* = C_INIT */
    fmi2ExitInitializationMode(c);
    if (s == (cs ? C_TERM : S_TERM)) fmi2Terminate(c);
    else if (!cs && s == S_CONT) fmi2EnterContinuousTimeMode(c);
    return c;
}

static void a_free(fmi_inst c) { fmi2FreeInstance(c); }
static int a_reset(fmi_inst c) { return fmi2Reset(c); }
static int a_exit_init(fmi_inst c) { return fmi2ExitInitializationMode(c); }
static int a_get_reals(fmi_inst c, const unsigned vr[], size_t n, double v[]) { return fmi2GetReal(c, vr, n, v); }
static int a_set_reals(fmi_inst c, const unsigned vr[], size_t n, const double v[]) { return fmi2SetReal(c, vr, n, v); }
static int a_get_int(fmi_inst c, unsigned vr, int *v) { return fmi2GetInteger(c, &vr, 1, v); }
static int a_set_int(fmi_inst c, unsigned vr, int v) { return fmi2SetInteger(c, &vr, 1, &v); }
static int a_get_bool(fmi_inst c, unsigned vr, int *v) { return fmi2GetBoolean(c, &vr, 1, v); }
static int a_set_bool(fmi_inst c, unsigned vr, int v) { return fmi2SetBoolean(c, &vr, 1, &v); }
static int a_set_time(fmi_inst c, double t) { return fmi2SetTime(c, t); }
static int a_set_states(fmi_inst c, const double x[], size_t n) { return fmi2SetContinuousStates(c, x, n); }
static int a_get_derivatives(fmi_inst c, double dx[], size_t n) { return fmi2GetDerivatives(c, dx, n); }
static int a_get_event_indicators(fmi_inst c, double z[], size_t n) { return fmi2GetEventIndicators(c, z, n); }
static int a_set_debug_logging(fmi_inst c, int on, size_t n, const char *const cats[]) { return fmi2SetDebugLogging(c, on, n, cats); }
static int a_do_step(fmi_inst c, double t, double h) { return fmi2DoStep(c, t, h, fmi2True); }
static int a_get_state(fmi_inst c, void **st) { return fmi2GetFMUstate(c, st); }
static int a_set_state(fmi_inst c, void *st) { return fmi2SetFMUstate(c, st); }
static int a_free_state(fmi_inst c, void **st) { return fmi2FreeFMUstate(c, st); }
static int a_state_size(fmi_inst c, void *st, size_t *n) { return fmi2SerializedFMUstateSize(c, st, n); }
static int a_serialize(fmi_inst c, void *st, void *b, size_t n) { return fmi2SerializeFMUstate(c, st, (fmi2Byte *)b, n); }
static int a_deserialize(fmi_inst c, const void *b, size_t n, void **st)
{
    return fmi2DeSerializeFMUstate(c, (const fmi2Byte *)b, n, st);
}

/* ---- each function with valid arguments, and the states FMI 2.0 allows it in --------------- */
static fmi2ValueReference VR_H = RW_VR_h, VR_SUPPORT = RW_VR_support, VR_COLLAPSED = RW_VR_collapsed;
static int c_setup(fmi_inst c) { return fmi2SetupExperiment(c, fmi2False, 0, 0, fmi2False, 0); }
static int c_enter_init(fmi_inst c) { return fmi2EnterInitializationMode(c); }
static int c_terminate(fmi_inst c) { return fmi2Terminate(c); }
static int c_get_real(fmi_inst c) { double v; return fmi2GetReal(c, &VR_H, 1, &v); }
static int c_get_int(fmi_inst c) { fmi2Integer v; return fmi2GetInteger(c, &VR_SUPPORT, 1, &v); }
static int c_get_bool(fmi_inst c) { fmi2Boolean v; return fmi2GetBoolean(c, &VR_COLLAPSED, 1, &v); }
static int c_set_real(fmi_inst c) { fmi2ValueReference vr = RW_VR_ag; double v = 0.1; return fmi2SetReal(c, &vr, 1, &v); }
static int c_set_int(fmi_inst c) { fmi2Integer v = 3; return fmi2SetInteger(c, &VR_SUPPORT, 1, &v); }
static int c_enter_event(fmi_inst c) { return fmi2EnterEventMode(c); }
static int c_nds(fmi_inst c) { fmi2EventInfo ei; return fmi2NewDiscreteStates(c, &ei); }
static int c_enter_cont(fmi_inst c) { return fmi2EnterContinuousTimeMode(c); }
static int c_completed(fmi_inst c)
{
    fmi2Boolean ev, term;
    return fmi2CompletedIntegratorStep(c, fmi2True, &ev, &term);
}
static int c_set_time(fmi_inst c) { return fmi2SetTime(c, 0.0); }
static int c_set_states(fmi_inst c) { double x[RW_NUMBER_OF_STATES] = {0}; return fmi2SetContinuousStates(c, x, RW_NUMBER_OF_STATES); }
static int c_get_der(fmi_inst c) { double dx[RW_NUMBER_OF_STATES]; return fmi2GetDerivatives(c, dx, RW_NUMBER_OF_STATES); }
static int c_get_z(fmi_inst c) { double z[RW_NUMBER_OF_EVENT_INDICATORS]; return fmi2GetEventIndicators(c, z, RW_NUMBER_OF_EVENT_INDICATORS); }
static int c_get_states(fmi_inst c) { double x[RW_NUMBER_OF_STATES]; return fmi2GetContinuousStates(c, x, RW_NUMBER_OF_STATES); }
static int c_get_nom(fmi_inst c) { double x[RW_NUMBER_OF_STATES]; return fmi2GetNominalsOfContinuousStates(c, x, RW_NUMBER_OF_STATES); }
static int c_real_in_der(fmi_inst c)
{
    fmi2ValueReference vr = RW_VR_ag;
    fmi2Integer order = 1;
    double v = 0.0;
    return fmi2SetRealInputDerivatives(c, &vr, 1, &order, &v);
}
static int c_do_step(fmi_inst c) { return fmi2DoStep(c, 0.0, 0.01, fmi2True); }
static int c_status(fmi_inst c) { fmi2Status v; return fmi2GetStatus(c, fmi2DoStepStatus, &v); }
static int c_real_status(fmi_inst c) { double v; return fmi2GetRealStatus(c, fmi2LastSuccessfulTime, &v); }
static int c_bool_status(fmi_inst c) { fmi2Boolean v; return fmi2GetBooleanStatus(c, fmi2Terminated, &v); }
static int c_string_status(fmi_inst c) { fmi2String v; return fmi2GetStringStatus(c, fmi2PendingStatus, &v); }

#define ME_AFTER_INST (B(S_INIT) | B(S_EVENT) | B(S_CONT) | B(S_TERM) | B(S_ERROR))
#define CS_AFTER_INST (B(C_INIT) | B(C_STEP) | B(C_TERM) | B(C_ERROR))
static const fmi_call CALLS[] = {
    {"fmi2SetupExperiment", c_setup, B(S_INST), B(C_INST)},
    {"fmi2EnterInitializationMode", c_enter_init, B(S_INST), B(C_INST)},
    {"fmi2ExitInitializationMode", a_exit_init, B(S_INIT), B(C_INIT)},
    {"fmi2Terminate", c_terminate, B(S_EVENT) | B(S_CONT), B(C_STEP)},
    {"fmi2GetReal", c_get_real, ME_AFTER_INST, CS_AFTER_INST},
    {"fmi2GetInteger", c_get_int, ME_AFTER_INST, CS_AFTER_INST},
    {"fmi2GetBoolean", c_get_bool, ME_AFTER_INST, CS_AFTER_INST},
    {"fmi2SetReal", c_set_real, B(S_INST) | B(S_INIT) | B(S_EVENT) | B(S_CONT), B(C_INST) | B(C_INIT) | B(C_STEP)},
    {"fmi2SetInteger", c_set_int, B(S_INST) | B(S_INIT), B(C_INST) | B(C_INIT)}, /* a parameter: before exit init only */
    /* Model Exchange only */
    {"fmi2EnterEventMode", c_enter_event, B(S_EVENT) | B(S_CONT), 0},
    {"fmi2NewDiscreteStates", c_nds, B(S_EVENT), 0},
    {"fmi2EnterContinuousTimeMode", c_enter_cont, B(S_EVENT), 0},
    {"fmi2CompletedIntegratorStep", c_completed, B(S_CONT), 0},
    {"fmi2SetTime", c_set_time, B(S_EVENT) | B(S_CONT), 0},
    {"fmi2SetContinuousStates", c_set_states, B(S_CONT), 0},
    {"fmi2GetDerivatives", c_get_der, B(S_EVENT) | B(S_CONT) | B(S_TERM) | B(S_ERROR), 0},
    {"fmi2GetEventIndicators", c_get_z, ME_AFTER_INST, 0},
    {"fmi2GetContinuousStates", c_get_states, ME_AFTER_INST, 0},
    {"fmi2GetNominalsOfContinuousStates", c_get_nom, B(S_INST) | B(S_EVENT) | B(S_CONT) | B(S_TERM) | B(S_ERROR), 0},
    /* Co-Simulation only */
    {"fmi2SetRealInputDerivatives", c_real_in_der, 0, B(C_INST) | B(C_INIT) | B(C_STEP)},
    {"fmi2DoStep", c_do_step, 0, B(C_STEP)},
    {"fmi2GetStatus", c_status, 0, B(C_STEP) | B(C_TERM)},
    {"fmi2GetRealStatus", c_real_status, 0, B(C_STEP) | B(C_TERM)},
    {"fmi2GetBooleanStatus", c_bool_status, 0, B(C_STEP) | B(C_TERM)},
    {"fmi2GetStringStatus", c_string_status, 0, B(C_STEP) | B(C_TERM)},
};

static const fmi_adapter FMI2 = {
    .v = "fmi2", .token_name = "GUID", .real_name = "Real", .nx_name = "nx", .nz_name = "ni",
    .me_names = {"instantiated", "initializationMode", "eventMode", "continuousTimeMode", "terminated", "error"},
    .cs_names = {"instantiated", "initializationMode", NULL, "stepComplete", "terminated", "error"},
    .calls = CALLS, .n_calls = sizeof CALLS / sizeof CALLS[0],
    .in_state = a_in_state, .instantiate = a_instantiate, .free_instance = a_free, .reset = a_reset,
    .enter_init = a_enter_init, .exit_init = a_exit_init, .get_reals = a_get_reals, .set_reals = a_set_reals,
    .get_int = a_get_int, .set_int = a_set_int, .get_bool = a_get_bool, .set_bool = a_set_bool,
    .set_time = a_set_time, .set_states = a_set_states, .get_derivatives = a_get_derivatives,
    .get_event_indicators = a_get_event_indicators, .set_debug_logging = a_set_debug_logging, .do_step = a_do_step,
    .get_state = a_get_state, .set_state = a_set_state, .free_state = a_free_state, .state_size = a_state_size,
    .serialize = a_serialize, .deserialize = a_deserialize,
};

/* ---- FMI 2.0 only ---------------------------------------------------------------------------- */

static void test_null_pointers(void)
{
    fmi2ValueReference vr = RW_VR_h;
    double v[8];
    fmi2Integer iv;
    fmi2Boolean bv, bv2;
    fmi2String sv;
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
        fmi2Component c = a_in_state(0, cases[i].state);
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
        expect_error(&FMI2, c, st, cases[i].what, "NULL");
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

static void test_instantiate_arguments_of_fmi2(void)
{
    fmi2Component c;
    n_logs = 0;
    CHECK(fmi2Instantiate("x", (fmi2Type)7, RW_GUID, "", &CB, fmi2False, fmi2False) == NULL, "fmuType 7");
    CHECK(n_logs == 1 && strstr(last_message, "fmuType"), "fmuType 7: log '%s'", last_message);
    /* fmuResourceLocation is optional for this FMU (it has no resources): NULL is accepted */
    c = fmi2Instantiate("x", fmi2ModelExchange, RW_GUID, NULL, &CB, fmi2False, fmi2False);
    CHECK(c != NULL, "NULL resource location rejected");
    fmi2FreeInstance(c);
}

/* vr 0 is no variable in FMI 2.0 (FMI 3.0's time); the model has no String variables */
static void test_value_references_of_fmi2(void)
{
    const fmi2ValueReference unknown[] = {0, 24, 29, 22, 39, 46, 999, 0xFFFFFFFFu};
    unknown_value_reference(&FMI2, 0);
    for (size_t i = 0; i < sizeof unknown / sizeof unknown[0]; i++) {
        char num[32];
        fmi2String sv = NULL;
        snprintf(num, sizeof num, "%u", (unsigned)unknown[i]);
        BAD_CALL(&FMI2, 0, S_EVENT, fmi2GetString(c, &unknown[i], 1, &sv), "GetString unknown vr", num);
        BAD_CALL(&FMI2, 0, S_INST, fmi2SetString(c, &unknown[i], 1, &sv), "SetString unknown vr", num);
    }
    BAD_CALL(&FMI2, 1, C_INST, fmi2SetRealInputDerivatives(c, &VR_H, 1, (const fmi2Integer[]){1}, (const double[]){0}),
             "a derivative of a parameter", "not an input");
}

/* providesDirectionalDerivative is false: each call is an error, in every state */
static void test_directional_derivatives_in_every_state(void)
{
    for (int s = 0; s < N_ME_STATES; s++) {
        fmi2ValueReference vr = RW_VR_s1, vu = RW_VR_ag;
        double dv = 1, dz;
        BAD_CALL(&FMI2, 0, s, fmi2GetDirectionalDerivative(c, &vr, 1, &vu, 1, &dv, &dz), "GetDirectionalDerivative",
                 "not supported");
    }
}

int main(void)
{
    run_shared_bad_input_cases(&FMI2);
    test_null_pointers();
    test_null_instance();
    test_instantiate_arguments_of_fmi2();
    test_value_references_of_fmi2();
    test_directional_derivatives_in_every_state();
    printf("%d checks, %d failures\n", checks, failures);
    return failures ? 1 : 0;
}
