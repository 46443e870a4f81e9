/* Bad input to RockingWall's FMI 3.0 API (fmi3Functions.c linked statically), Model Exchange and
 * Co-Simulation: the cases both versions share (fmi_bad_input_cases.h) through the FMI 3.0 adapter
 * below, and the FMI 3.0 ones: Event Mode of Co-Simulation, NULL pointers and instances, Scheduled
 * Execution, `time` and the event indicators as variables, the types, clocks and features the FMU
 * does not have, nValues. The state machines are those of FMI 3.0 sections 3.2 and 4.2. */
#include "fmi_bad_input_cases.h"

#include "fmi3Functions.h"

typedef char fmi3_numbers_statuses_as_the_cases_do[((int)fmi3OK == ST_OK && (int)fmi3Error == ST_ERROR) ? 1 : -1];

static void logger(fmi3InstanceEnvironment env, fmi3Status status, fmi3String category, fmi3String message)
{
    (void)env;
    (void)category;
    snprintf(last_message, sizeof last_message, "%s", message ? message : "(null)");
    last_status = (int)status;
    n_logs++;
}

/* ---- the adapter ---------------------------------------------------------------------------- */

static fmi3Instance me(void) { return fmi3InstantiateModelExchange("bad", RW_GUID, NULL, false, false, NULL, logger); }

/* Co-Simulation with eventModeUsed, so that every Co-Simulation state is reachable */
static fmi3Instance cs(int event_mode_used)
{
    return fmi3InstantiateCoSimulation("bad", RW_GUID, NULL, false, false, event_mode_used, false, NULL, 0, NULL,
                                       logger, NULL);
}

static fmi_inst a_instantiate(const char *name, const char *token, int with_logger)
{
    return fmi3InstantiateModelExchange(name, token, NULL, false, false, NULL, with_logger ? logger : NULL);
}

static fmi_inst a_in_state(int co_simulation, int s)
{
    fmi3Instance c = co_simulation ? cs(1) : me();
    fmi3ValueReference nosuch = 999;
    double v = 0;
    if (!c) return NULL;
    if (s == (co_simulation ? C_ERROR : S_ERROR)) { fmi3SetFloat64(c, &nosuch, 1, &v, 1); return c; }
    if (s == S_INST) return c; /* = C_INST */
    fmi3EnterInitializationMode(c, false, 0, 0, false, 0);
    if (s == S_INIT) return c; /* = C_INIT */
    fmi3ExitInitializationMode(c); /* into Event Mode (Model Exchange, and Co-Simulation with eventModeUsed) */
    if (s == (co_simulation ? C_TERM : S_TERM)) fmi3Terminate(c);
    else if (co_simulation && s == C_STEP) fmi3EnterStepMode(c);
    else if (!co_simulation && s == S_CONT) fmi3EnterContinuousTimeMode(c);
    return c;
}

static void a_free(fmi_inst c) { fmi3FreeInstance(c); }
static int a_reset(fmi_inst c) { return fmi3Reset(c); }
static int a_enter_init(fmi_inst c, int tol_defined, double tol, double start)
{
    return fmi3EnterInitializationMode(c, tol_defined, tol, start, false, 0);
}
static int a_exit_init(fmi_inst c) { return fmi3ExitInitializationMode(c); }
static int a_get_reals(fmi_inst c, const unsigned vr[], size_t n, double v[]) { return fmi3GetFloat64(c, vr, n, v, n); }
static int a_set_reals(fmi_inst c, const unsigned vr[], size_t n, const double v[]) { return fmi3SetFloat64(c, vr, n, v, n); }
static int a_get_int(fmi_inst c, unsigned vr, int *v) { return fmi3GetInt32(c, &vr, 1, v, 1); }
static int a_set_int(fmi_inst c, unsigned vr, int v) { return fmi3SetInt32(c, &vr, 1, &v, 1); }
static int a_get_bool(fmi_inst c, unsigned vr, int *v)
{
    fmi3Boolean b = false;
    const fmi3Status st = fmi3GetBoolean(c, &vr, 1, &b, 1);
    *v = b;
    return st;
}
static int a_set_bool(fmi_inst c, unsigned vr, int v) { fmi3Boolean b = v != 0; return fmi3SetBoolean(c, &vr, 1, &b, 1); }
static int a_set_time(fmi_inst c, double t) { return fmi3SetTime(c, t); }
static int a_set_states(fmi_inst c, const double x[], size_t n) { return fmi3SetContinuousStates(c, x, n); }
static int a_get_derivatives(fmi_inst c, double dx[], size_t n) { return fmi3GetContinuousStateDerivatives(c, dx, n); }
static int a_get_event_indicators(fmi_inst c, double z[], size_t n) { return fmi3GetEventIndicators(c, z, n); }
static int a_set_debug_logging(fmi_inst c, int on, size_t n, const char *const cats[]) { return fmi3SetDebugLogging(c, on, n, cats); }
static int a_do_step(fmi_inst c, double t, double h)
{
    fmi3Boolean ev, term, early;
    double last;
    return fmi3DoStep(c, t, h, true, &ev, &term, &early, &last);
}
static int a_get_state(fmi_inst c, void **st) { return fmi3GetFMUState(c, st); }
static int a_set_state(fmi_inst c, void *st) { return fmi3SetFMUState(c, st); }
static int a_free_state(fmi_inst c, void **st) { return fmi3FreeFMUState(c, st); }
static int a_state_size(fmi_inst c, void *st, size_t *n) { return fmi3SerializedFMUStateSize(c, st, n); }
static int a_serialize(fmi_inst c, void *st, void *b, size_t n) { return fmi3SerializeFMUState(c, st, (fmi3Byte *)b, n); }
static int a_deserialize(fmi_inst c, const void *b, size_t n, void **st)
{
    return fmi3DeserializeFMUState(c, (const fmi3Byte *)b, n, st);
}

/* ---- each function with valid arguments, and the states FMI 3.0 allows it in --------------- */
static fmi3ValueReference VR_H = RW_VR_h, VR_SUPPORT = RW_VR_support, VR_COLLAPSED = RW_VR_collapsed;
static int c_enter_init(fmi_inst c) { return fmi3EnterInitializationMode(c, false, 0, 0, false, 0); }
static int c_terminate(fmi_inst c) { return fmi3Terminate(c); }
static int c_get_f64(fmi_inst c) { double v; return fmi3GetFloat64(c, &VR_H, 1, &v, 1); }
static int c_get_i32(fmi_inst c) { fmi3Int32 v; return fmi3GetInt32(c, &VR_SUPPORT, 1, &v, 1); }
static int c_get_bool(fmi_inst c) { fmi3Boolean v; return fmi3GetBoolean(c, &VR_COLLAPSED, 1, &v, 1); }
static int c_set_input(fmi_inst c) { fmi3ValueReference vr = RW_VR_ag; double v = 0.1; return fmi3SetFloat64(c, &vr, 1, &v, 1); }
static int c_set_i32(fmi_inst c) { fmi3Int32 v = 3; return fmi3SetInt32(c, &VR_SUPPORT, 1, &v, 1); }
static int c_enter_event(fmi_inst c) { return fmi3EnterEventMode(c); }
static int c_update(fmi_inst c)
{
    fmi3Boolean a, b, d, e, f;
    double t;
    return fmi3UpdateDiscreteStates(c, &a, &b, &d, &e, &f, &t);
}
static int c_enter_cont(fmi_inst c) { return fmi3EnterContinuousTimeMode(c); }
static int c_completed(fmi_inst c)
{
    fmi3Boolean ev, term;
    return fmi3CompletedIntegratorStep(c, true, &ev, &term);
}
static int c_set_time(fmi_inst c) { return fmi3SetTime(c, 0.0); }
static int c_set_states(fmi_inst c) { double x[RW_NUMBER_OF_STATES] = {0}; return fmi3SetContinuousStates(c, x, RW_NUMBER_OF_STATES); }
static int c_get_der(fmi_inst c) { double dx[RW_NUMBER_OF_STATES]; return fmi3GetContinuousStateDerivatives(c, dx, RW_NUMBER_OF_STATES); }
static int c_get_z(fmi_inst c) { double z[RW_NUMBER_OF_EVENT_INDICATORS]; return fmi3GetEventIndicators(c, z, RW_NUMBER_OF_EVENT_INDICATORS); }
static int c_get_states(fmi_inst c) { double x[RW_NUMBER_OF_STATES]; return fmi3GetContinuousStates(c, x, RW_NUMBER_OF_STATES); }
static int c_get_nom(fmi_inst c) { double x[RW_NUMBER_OF_STATES]; return fmi3GetNominalsOfContinuousStates(c, x, RW_NUMBER_OF_STATES); }
static int c_enter_step(fmi_inst c) { return fmi3EnterStepMode(c); }
static int c_do_step(fmi_inst c) { return a_do_step(c, 0.0, 0.01); }

#define ME_READ (B(S_INIT) | B(S_EVENT) | B(S_CONT) | B(S_TERM) | B(S_ERROR))
#define CS_READ (B(C_INIT) | B(C_EVENT) | B(C_STEP) | B(C_TERM) | B(C_ERROR))
static const fmi_call CALLS[] = {
    {"fmi3EnterInitializationMode", c_enter_init, B(S_INST), B(C_INST)},
    {"fmi3ExitInitializationMode", a_exit_init, B(S_INIT), B(C_INIT)},
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
    {"fmi3GetContinuousStateDerivatives", c_get_der, B(S_EVENT) | B(S_CONT) | B(S_TERM) | B(S_ERROR), 0},
    {"fmi3GetEventIndicators", c_get_z, ME_READ, 0},
    {"fmi3GetContinuousStates", c_get_states, ME_READ, 0},
    {"fmi3GetNominalsOfContinuousStates", c_get_nom, B(S_INST) | B(S_EVENT) | B(S_CONT) | B(S_TERM) | B(S_ERROR), 0},
    /* Co-Simulation only */
    {"fmi3EnterStepMode", c_enter_step, 0, B(C_EVENT)},
    {"fmi3DoStep", c_do_step, 0, B(C_STEP)},
    /* both, with interface-specific states */
    {"fmi3EnterEventMode", c_enter_event, B(S_EVENT) | B(S_CONT), B(C_STEP)},
};

static const fmi_adapter FMI3 = {
    .v = "fmi3", .token_name = "instantiationToken", .real_name = "Float64", .nx_name = "nContinuousStates",
    .nz_name = "nEventIndicators",
    .me_names = {"Instantiated", "InitializationMode", "EventMode", "ContinuousTimeMode", "Terminated", "error"},
    .cs_names = {"Instantiated", "InitializationMode", "EventMode", "StepMode", "Terminated", "error"},
    .calls = CALLS, .n_calls = sizeof CALLS / sizeof CALLS[0],
    .in_state = a_in_state, .instantiate = a_instantiate, .free_instance = a_free, .reset = a_reset,
    .enter_init = a_enter_init, .exit_init = a_exit_init, .get_reals = a_get_reals, .set_reals = a_set_reals,
    .get_int = a_get_int, .set_int = a_set_int, .get_bool = a_get_bool, .set_bool = a_set_bool,
    .set_time = a_set_time, .set_states = a_set_states, .get_derivatives = a_get_derivatives,
    .get_event_indicators = a_get_event_indicators, .set_debug_logging = a_set_debug_logging, .do_step = a_do_step,
    .get_state = a_get_state, .set_state = a_set_state, .free_state = a_free_state, .state_size = a_state_size,
    .serialize = a_serialize, .deserialize = a_deserialize,
};

/* ---- FMI 3.0 only ---------------------------------------------------------------------------- */

static void test_event_mode_of_co_simulation_needs_event_mode_used(void)
{
    fmi3Instance c = cs(0);
    c_enter_init(c);
    a_exit_init(c); /* straight into Step Mode */
    n_logs = 0;
    expect_error(&FMI3, c, fmi3EnterEventMode(c), "fmi3EnterEventMode without eventModeUsed", "eventModeUsed");
    fmi3FreeInstance(c);
}

static void test_null_pointers(void)
{
    double v[8];
    fmi3Boolean bv;
    size_t n;
    for (int k = 0; k < 21; k++) {
        const int state = k < 4 ? S_EVENT : (k < 6 ? S_INST : S_CONT);
        fmi3Instance c = a_in_state(0, state);
        fmi3Status st = fmi3OK;
        fmi3Boolean a;
        double t;
        char what[64];
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
        snprintf(what, sizeof what, "NULL argument, case %d", k);
        expect_error(&FMI3, c, st, what, "NULL");
        fmi3FreeInstance(c);
    }
    for (int k = 0; k < 4; k++) { /* fmi3DoStep's four outputs */
        fmi3Boolean a, b, d;
        double last;
        BAD_CALL(&FMI3, 1, C_STEP,
                 fmi3DoStep(c, 0, 0.01, true, k == 0 ? NULL : &a, k == 1 ? NULL : &b, k == 2 ? NULL : &d,
                            k == 3 ? NULL : &last),
                 "fmi3DoStep with a NULL output", "NULL");
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

static void test_instantiate_arguments_of_fmi3(void)
{
    n_logs = 0;
    CHECK(fmi3InstantiateCoSimulation("", RW_GUID, NULL, false, false, false, false, NULL, 0, NULL, logger, NULL) == NULL,
          "empty name, Co-Simulation");
    CHECK(n_logs == 1 && strstr(last_message, "instanceName"), "empty name: log '%s'", last_message);
    n_logs = 0;
    CHECK(fmi3InstantiateScheduledExecution("x", RW_GUID, NULL, false, false, NULL, logger, NULL, NULL, NULL) == NULL,
          "Scheduled Execution");
    CHECK(n_logs == 1 && strstr(last_message, "Scheduled Execution"), "Scheduled Execution: log '%s'", last_message);
}

/* time (vr 0) and the event indicators (50..57) are Float64 variables the FMU computes */
static void test_time_and_event_indicators_cannot_be_set(void)
{
    bad_real(&FMI3, S_INST, 0, 1.0, "time");
    bad_real(&FMI3, S_INST, 50, 1.0, "event indicator");
}

/* known value references through a getter of another type, each FMI 3.0 type the FMU lacks */
static void test_other_types(void)
{
    fmi3Instance c = a_in_state(0, S_EVENT);
    const fmi3ValueReference unknown = 999;
    fmi3Int32 iv;
    float f;
    fmi3String sv;
    fmi3ValueReference z = 50, t = 0;
    n_logs = 0;
    expect_error(&FMI3, c, fmi3GetInt32(c, &z, 1, &iv, 1), "GetInt32 of an event indicator", "Float64");
    expect_error(&FMI3, c, fmi3GetBoolean(c, &t, 1, (fmi3Boolean *)&iv, 1), "GetBoolean of time", "Float64");
    expect_error(&FMI3, c, fmi3GetFloat32(c, &VR_H, 1, &f, 1), "GetFloat32 of a Float64", "Float64");
    expect_error(&FMI3, c, fmi3GetString(c, &VR_H, 1, &sv, 1), "GetString", "String");
    expect_error(&FMI3, c, fmi3GetUInt64(c, &unknown, 1, NULL, 1), "GetUInt64", "UInt64");
    expect_error(&FMI3, c, fmi3SetInt8(c, &unknown, 1, NULL, 1), "SetInt8", "Int8");
    expect_error(&FMI3, c, fmi3GetBinary(c, &unknown, 1, NULL, NULL, 1), "GetBinary", "Binary");
    expect_error(&FMI3, c, fmi3GetClock(c, &unknown, 1, NULL), "GetClock", "Clock");
    fmi3FreeInstance(c);
}

/* nValues must match: every variable is a scalar */
static void test_n_values(void)
{
    fmi3ValueReference vrs[2] = {RW_VR_h, RW_VR_b};
    double v[3];
    BAD_CALL(&FMI3, 0, S_EVENT, fmi3GetFloat64(c, vrs, 2, v, 1), "GetFloat64 nValues 1 for 2", "nValues");
    BAD_CALL(&FMI3, 0, S_EVENT, fmi3GetFloat64(c, vrs, 2, v, 3), "GetFloat64 nValues 3 for 2", "nValues");
}

/* the functions of features the FMU does not declare: fmi3Error with the reason */
static void test_unsupported_features(void)
{
    fmi3Instance c = a_in_state(0, S_EVENT);
    fmi3ValueReference vr = RW_VR_s1, vu = RW_VR_ag;
    fmi3Int32 order = 1;
    double seed = 1, sens;
    size_t n;
    n_logs = 0;
    expect_error(&FMI3, c, fmi3GetDirectionalDerivative(c, &vr, 1, &vu, 1, &seed, 1, &sens, 1), "directional", "not supported");
    expect_error(&FMI3, c, fmi3GetAdjointDerivative(c, &vr, 1, &vu, 1, &seed, 1, &sens, 1), "adjoint", "not supported");
    expect_error(&FMI3, c, fmi3GetNumberOfVariableDependencies(c, vr, &n), "dependencies", "not supported");
    expect_error(&FMI3, c, fmi3EnterConfigurationMode(c), "configuration", "structural parameters");
    expect_error(&FMI3, c, fmi3GetIntervalDecimal(c, &vr, 1, &sens, NULL), "interval", "clocks");
    expect_error(&FMI3, c, fmi3ActivateModelPartition(c, 1, 0.0), "partition", "Scheduled Execution");
    fmi3FreeInstance(c);
    BAD_CALL(&FMI3, 1, C_STEP, fmi3GetOutputDerivatives(c, &vr, 1, &order, &sens, 1), "output derivatives",
             "maxOutputDerivativeOrder");
}

/* time (vr 0) and the event indicators (vr 50..57) read as Float64 equal fmi3SetTime's time and
 * fmi3GetEventIndicators' values */
static void test_time_and_event_indicators_as_variables(void)
{
    fmi3Instance c = a_in_state(0, S_CONT);
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

int main(void)
{
    run_shared_bad_input_cases(&FMI3);
    test_event_mode_of_co_simulation_needs_event_mode_used();
    test_null_pointers();
    test_null_instance();
    test_instantiate_arguments_of_fmi3();
    test_time_and_event_indicators_cannot_be_set();
    test_other_types();
    test_n_values();
    test_unsupported_features();
    test_time_and_event_indicators_as_variables();
    printf("%d checks, %d failures\n", checks, failures);
    return failures ? 1 : 0;
}
