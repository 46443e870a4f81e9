/* The bad-input cases both FMI versions share, on RockingWall, driven through a small adapter per
 * version (test_fmi2_bad_input.c, test_fmi3_bad_input.c): every call of the adapter's table in
 * every state of both interface types, the instantiation's arguments, invalid, NaN and infinite
 * parameters and inputs, unknown value references, wrong types and sizes, the FMU state in every
 * state and bad state blocks. Each bad call must return the version's error status with a reason
 * passed to the logger (that mentions what the case names), must not crash, and the instance must
 * be usable again after a reset (ctest runs this under ASan/UBSan in the sanitizer build). Every
 * allowed (function, state) pair must succeed, so the matrix cannot pass by rejecting everything.
 *
 * The adapter's logger writes last_message, last_status and n_logs; its functions return the
 * version's status as a number, which both versions number alike (OK 0, Error 3). */
#ifndef FMI_BAD_INPUT_CASES_H
#define FMI_BAD_INPUT_CASES_H

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "model_variables.h"

static char last_message[2048];
static int last_status;
static int n_logs = 0;

enum { ST_OK = 0, ST_ERROR = 3 };

/* the states of each interface type (a version may lack some: its name is then NULL) */
enum { S_INST, S_INIT, S_EVENT, S_CONT, S_TERM, S_ERROR, N_ME_STATES };
enum { C_INST, C_INIT, C_EVENT, C_STEP, C_TERM, C_ERROR, N_CS_STATES };
#define B(s) (1u << (s))

typedef void *fmi_inst;

/* one function with valid arguments, and the states of each interface type it is allowed in (0 for
 * the other type: a function of one interface type only) */
typedef struct {
    const char *name;
    int (*call)(fmi_inst c);
    unsigned me_allowed, cs_allowed;
} fmi_call;

typedef struct {
    const char *v;                      /* "fmi2", "fmi3": the functions' prefix */
    const char *token_name;             /* "GUID", "instantiationToken" */
    const char *real_name;              /* "Real", "Float64" */
    const char *nx_name, *nz_name;      /* the size arguments of states and event indicators */
    const char *me_names[N_ME_STATES], *cs_names[N_CS_STATES];
    const fmi_call *calls;
    size_t n_calls;
    /* an instance reached in state s of Model Exchange (cs = 0) or Co-Simulation (cs = 1), NULL if
     * the version has no such state */
    fmi_inst (*in_state)(int cs, int s);
    fmi_inst (*instantiate)(const char *name, const char *token, int with_logger);
    void (*free_instance)(fmi_inst c);
    int (*reset)(fmi_inst c);
    /* start time and tolerance, into Initialization Mode (FMI 2.0: fmi2SetupExperiment and
     * fmi2EnterInitializationMode) */
    int (*enter_init)(fmi_inst c, int tolerance_defined, double tolerance, double start_time);
    int (*exit_init)(fmi_inst c);
    int (*get_reals)(fmi_inst c, const unsigned vr[], size_t n, double v[]);
    int (*set_reals)(fmi_inst c, const unsigned vr[], size_t n, const double v[]);
    int (*get_int)(fmi_inst c, unsigned vr, int *v);
    int (*set_int)(fmi_inst c, unsigned vr, int v);
    int (*get_bool)(fmi_inst c, unsigned vr, int *v);
    int (*set_bool)(fmi_inst c, unsigned vr, int v);
    int (*set_time)(fmi_inst c, double t);
    int (*set_states)(fmi_inst c, const double x[], size_t n);
    int (*get_derivatives)(fmi_inst c, double dx[], size_t n);
    int (*get_event_indicators)(fmi_inst c, double z[], size_t n);
    int (*set_debug_logging)(fmi_inst c, int on, size_t n, const char *const categories[]);
    int (*do_step)(fmi_inst c, double t, double h);
    int (*get_state)(fmi_inst c, void **state);
    int (*set_state)(fmi_inst c, void *state);
    int (*free_state)(fmi_inst c, void **state);
    int (*state_size)(fmi_inst c, void *state, size_t *n);
    int (*serialize)(fmi_inst c, void *state, void *bytes, size_t n);
    int (*deserialize)(fmi_inst c, const void *bytes, size_t n, void **state);
} fmi_adapter;

static const char *state_name(const fmi_adapter *A, int cs, int s) { return cs ? A->cs_names[s] : A->me_names[s]; }

static int init(const fmi_adapter *A, fmi_inst c) { return A->enter_init(c, 0, 0, 0) == ST_OK && A->exit_init(c) == ST_OK; }

/* The error status, an error logged that mentions `mention`; then the instance (if given) must
 * recover through a reset (allowed in every state). */
static void expect_error(const fmi_adapter *A, fmi_inst c, int got, const char *what, const char *mention)
{
    CHECK(got == ST_ERROR, "%s: status %d, expected %sError", what, got, A->v);
    CHECK(n_logs > 0 && last_status == ST_ERROR, "%s: no error logged", what);
    CHECK(!mention || strstr(last_message, mention), "%s: log '%s' does not mention '%s'", what, last_message, mention);
    if (c) {
        CHECK(A->reset(c) == ST_OK, "%s: reset after the error", what);
        CHECK(init(A, c), "%s: instance not usable after the reset", what);
    }
}

/* a fresh instance in a state, one bad call on it (CALL uses c), the error expected, freed */
#define BAD_CALL(A, CS, STATE, CALL, WHAT, MENTION)           \
    do {                                                      \
        fmi_inst c = (A)->in_state((CS), (STATE));            \
        n_logs = 0;                                           \
        expect_error((A), c, (CALL), (WHAT), (MENTION));      \
        (A)->free_instance(c);                                \
    } while (0)

/* ---- every call in every state of both interface types ------------------------------------ */

static void test_every_call_in_every_state(const fmi_adapter *A)
{
    int rejected = 0, accepted = 0, cs;
    for (cs = 0; cs < 2; cs++)
        for (size_t f = 0; f < A->n_calls; f++)
            for (int s = 0; s < (cs ? N_CS_STATES : N_ME_STATES); s++) {
                const fmi_call *F = &A->calls[f];
                const unsigned allowed = cs ? F->cs_allowed : F->me_allowed;
                char what[200];
                fmi_inst c;
                int st;
                if (!state_name(A, cs, s)) continue; /* the version has no such state */
                c = A->in_state(cs, s);
                if (!c) { CHECK(0, "instantiate"); continue; }
                snprintf(what, sizeof what, "%s on a %s instance in %s", F->name, cs ? "Co-Simulation" : "Model Exchange",
                         state_name(A, cs, s));
                n_logs = 0;
                if (allowed & B(s)) {
                    if (s != (cs ? C_ERROR : S_ERROR)) { /* allowed in the error state: not asserted */
                        st = F->call(c);
                        CHECK(st == ST_OK, "%s: status %d (%s)", what, st, last_message);
                        accepted++;
                    }
                } else {
                    expect_error(A, c, F->call(c), what, F->name);
                    if (!allowed)
                        CHECK(strstr(last_message, cs ? "Model Exchange function" : "Co-Simulation function"),
                              "%s: log '%s' does not say which interface type", what, last_message);
                    rejected++;
                }
                A->free_instance(c);
            }
    printf("  %d (function, state) pairs rejected, %d accepted\n", rejected, accepted);
    CHECK(rejected >= 100 && accepted >= 40, "only %d rejected / %d accepted pairs exercised", rejected, accepted);
}

/* ---- instantiation ------------------------------------------------------------------------ */

static void test_instantiate_arguments(const fmi_adapter *A)
{
    n_logs = 0;
    CHECK(A->instantiate(NULL, RW_GUID, 1) == NULL, "NULL name");
    CHECK(n_logs == 1 && last_status == ST_ERROR && strstr(last_message, "instanceName"), "NULL name: log '%s'", last_message);
    n_logs = 0;
    CHECK(A->instantiate("", RW_GUID, 1) == NULL, "empty name");
    CHECK(n_logs == 1 && strstr(last_message, "instanceName"), "empty name: log '%s'", last_message);
    n_logs = 0;
    CHECK(A->instantiate("x", NULL, 1) == NULL, "NULL %s", A->token_name);
    CHECK(n_logs == 1 && strstr(last_message, A->token_name), "NULL %s: log '%s'", A->token_name, last_message);
    n_logs = 0;
    CHECK(A->instantiate("x", "{1631bb30-%s%n}", 1) == NULL, "format %s", A->token_name);
    CHECK(n_logs == 1 && !strchr(last_message, '%'), "a %s with %% reaches the logger as a format: '%s'", A->token_name,
          last_message);
    CHECK(A->instantiate("x", RW_GUID, 0) == NULL, "no logger");
}

/* ---- values -------------------------------------------------------------------------------- */

/* one value set in a state where the call is allowed: the error expected, with `mention` */
static void bad_real(const fmi_adapter *A, int state, unsigned vr, double value, const char *mention)
{
    char what[128];
    snprintf(what, sizeof what, "set %s vr %u = %g in %s", A->real_name, vr, value, A->me_names[state]);
    BAD_CALL(A, 0, state, A->set_reals(c, &vr, 1, &value), what, mention);
}

static void test_non_finite_and_out_of_range_values(const fmi_adapter *A)
{
    const double nonfinite[] = {NAN, INFINITY, -INFINITY};
    const unsigned reals[] = {RW_VR_h, RW_VR_b, RW_VR_W, RW_VR_psi, RW_VR_Kd, RW_VR_er, RW_VR_g, RW_VR_delta1Ratio,
                              RW_VR_delta2A, RW_VR_delta2B, RW_VR_hingeSat, RW_VR_restRate, RW_VR_q1, RW_VR_q2,
                              RW_VR_dq1, RW_VR_dq2};
    struct { unsigned vr; double v; const char *name; } invalid[] = {
        {RW_VR_h, 0, "h"}, {RW_VR_h, -2.5, "h"}, {RW_VR_h, 31, "h"}, {RW_VR_b, 0, "b"}, {RW_VR_b, -0.1, "b"},
        {RW_VR_W, 0, "W"}, {RW_VR_psi, -1, "psi"}, {RW_VR_Kd, -1, "Kd"}, {RW_VR_er, 1.5, "er"}, {RW_VR_er, -0.1, "er"},
        {RW_VR_g, 0, "g"}, {RW_VR_delta1Ratio, 1.0, "delta1Ratio"}, {RW_VR_delta1Ratio, 0, "delta1Ratio"},
        {RW_VR_hingeSat, 0, "hingeSat"}, {RW_VR_restRate, 0, "restRate"},
    };
    const int bad_ints[] = {0, 5, -1, 2147483647};
    for (size_t i = 0; i < sizeof reals / sizeof reals[0]; i++)
        for (size_t k = 0; k < 3; k++) {
            bad_real(A, S_INST, reals[i], nonfinite[k], "not a finite number");
            bad_real(A, S_INIT, reals[i], nonfinite[k], "not a finite number");
        }
    for (size_t i = 0; i < sizeof invalid / sizeof invalid[0]; i++) bad_real(A, S_INST, invalid[i].vr, invalid[i].v, invalid[i].name);
    for (int s = S_INST; s <= S_CONT; s++)
        for (size_t k = 0; k < 3; k++) {
            bad_real(A, s, RW_VR_ag, nonfinite[k], "ag");
            bad_real(A, s, RW_VR_u_top, nonfinite[k], "u_top");
        }
    for (size_t k = 0; k < sizeof bad_ints / sizeof bad_ints[0]; k++) {
        BAD_CALL(A, 0, S_INST, A->set_int(c, RW_VR_support, bad_ints[k]), "bad integer parameter", "support");
        BAD_CALL(A, 0, S_INST, A->set_int(c, RW_VR_hingeLaw, bad_ints[k]), "bad integer parameter", "hingeLaw");
    }
}

static void test_what_cannot_be_set_now(const fmi_adapter *A)
{
    char set_states[64];
    snprintf(set_states, sizeof set_states, "%sSetContinuousStates", A->v);
    bad_real(A, S_EVENT, RW_VR_h, 3.0, "can only be set before"); /* a fixed parameter after initialization */
    bad_real(A, S_CONT, RW_VR_q1, 0.01, set_states);               /* a state's start value after initialization */
    bad_real(A, S_EVENT, RW_VR_s1, 0.01, "cannot be set");         /* an output */
    BAD_CALL(A, 0, S_INST, A->set_bool(c, RW_VR_collapsed, 1), "set the output collapsed", "cannot be set");
    {   /* cross-parameter: b >= h is only known at the end of initialization */
        fmi_inst c = A->in_state(0, S_INIT);
        double b = 2.5;
        unsigned vr = RW_VR_b;
        CHECK(A->set_reals(c, &vr, 1, &b) == ST_OK, "b alone");
        n_logs = 0;
        expect_error(A, c, A->exit_init(c), "b = h at the end of initialization", "b");
        A->free_instance(c);
    }
}

static void test_non_finite_time_states_and_steps(const fmi_adapter *A)
{
    double x[RW_NUMBER_OF_STATES] = {0, 0, NAN, 0};
    BAD_CALL(A, 0, S_CONT, A->set_time(c, NAN), "set time NaN", "time");
    BAD_CALL(A, 0, S_CONT, A->set_time(c, INFINITY), "set time inf", "time");
    BAD_CALL(A, 0, S_CONT, A->set_states(c, x, RW_NUMBER_OF_STATES), "set states NaN", "not finite");
    BAD_CALL(A, 0, S_INST, A->enter_init(c, 0, 0, NAN), "startTime NaN", "startTime");
    BAD_CALL(A, 0, S_INST, A->enter_init(c, 0, 0, INFINITY), "startTime inf", "startTime");
    BAD_CALL(A, 0, S_INST, A->enter_init(c, 1, 2.0, 0), "tolerance 2", "tolerance");
    BAD_CALL(A, 1, C_STEP, A->do_step(c, 0, -0.1), "step of negative size", "step size");
    BAD_CALL(A, 1, C_STEP, A->do_step(c, 0, NAN), "step of size NaN", "step size");
    BAD_CALL(A, 1, C_STEP, A->do_step(c, 1.0, 0.1), "step at the wrong time", "currentCommunicationPoint");
}

/* ---- value references, types, sizes -------------------------------------------------------- */

/* vr is no variable: every getter and setter of the model's types refuses it, naming it */
static void unknown_value_reference(const fmi_adapter *A, unsigned vr)
{
    char num[32];
    double v = 0;
    int iv = 0;
    snprintf(num, sizeof num, "%u", vr);
    BAD_CALL(A, 0, S_EVENT, A->get_reals(c, &vr, 1, &v), "get Real of an unknown vr", num);
    BAD_CALL(A, 0, S_INST, A->set_reals(c, &vr, 1, &v), "set Real of an unknown vr", num);
    BAD_CALL(A, 0, S_EVENT, A->get_int(c, vr, &iv), "get Integer of an unknown vr", num);
    BAD_CALL(A, 0, S_INST, A->set_int(c, vr, iv), "set Integer of an unknown vr", num);
    BAD_CALL(A, 0, S_EVENT, A->get_bool(c, vr, &iv), "get Boolean of an unknown vr", num);
    BAD_CALL(A, 0, S_INST, A->set_bool(c, vr, iv), "set Boolean of an unknown vr", num);
}

static void test_value_references_types_and_sizes(const fmi_adapter *A)
{
    /* none of these is a variable in either version (FMI 3.0 adds time, 0, and the event indicators, 50-57) */
    const unsigned unknown[] = {24, 29, 22, 39, 46, 49, 58, 999, 0xFFFFFFFFu};
    const unsigned mixed[3] = {RW_VR_h, RW_VR_b, 999};
    const size_t sizes[] = {0, RW_NUMBER_OF_STATES - 1, RW_NUMBER_OF_STATES + 1};
    const char *const no_such[1] = {"noSuchCategory"};
    double a[16];
    int iv;
    for (size_t i = 0; i < sizeof unknown / sizeof unknown[0]; i++) unknown_value_reference(A, unknown[i]);
    BAD_CALL(A, 0, S_EVENT, A->get_int(c, RW_VR_h, &iv), "get Integer of a Real", A->real_name);
    BAD_CALL(A, 0, S_EVENT, A->get_bool(c, RW_VR_h, &iv), "get Boolean of a Real", A->real_name);
    BAD_CALL(A, 0, S_EVENT, A->get_reals(c, mixed, 3, a), "get Reals, a bad vr last in the list", "999");
    memset(a, 0, sizeof a);
    for (size_t k = 0; k < 3; k++) {
        BAD_CALL(A, 0, S_CONT, A->get_derivatives(c, a, sizes[k]), "derivatives of a wrong size", A->nx_name);
        BAD_CALL(A, 0, S_CONT, A->set_states(c, a, sizes[k]), "states of a wrong size", A->nx_name);
        BAD_CALL(A, 0, S_CONT, A->get_event_indicators(c, a, sizes[k] + 1), "event indicators of a wrong size",
                 A->nz_name);
    }
    BAD_CALL(A, 0, S_INST, A->set_debug_logging(c, 1, 1, no_such), "unknown log category", "noSuchCategory");
}

/* ---- FMU state ------------------------------------------------------------------------------ */

/* in every state of both interface types: a state taken can be serialized, read back and set */
static void test_fmu_state_in_every_state(const fmi_adapter *A)
{
    static unsigned char buf[1 << 16]; /* the state holds the exact engine with its cache, ~18 KiB */
    for (int cs = 0; cs < 2; cs++)
        for (int s = 0; s < (cs ? N_CS_STATES : N_ME_STATES); s++) {
            const char *name = state_name(A, cs, s);
            void *st = NULL, *back = NULL;
            size_t n = 0;
            fmi_inst c;
            if (!name) continue;
            c = A->in_state(cs, s);
            CHECK(A->get_state(c, &st) == ST_OK, "get the FMU state in %s: %s", name, last_message);
            CHECK(A->state_size(c, st, &n) == ST_OK && n > 0 && n <= sizeof buf, "serialized size %u", (unsigned)n);
            CHECK(n <= sizeof buf && A->serialize(c, st, buf, n) == ST_OK, "serialize in %s", name);
            CHECK(A->deserialize(c, buf, n, &back) == ST_OK, "deserialize in %s: %s", name, last_message);
            CHECK(A->set_state(c, back) == ST_OK, "set the FMU state in %s: %s", name, last_message);
            CHECK(A->free_state(c, &st) == ST_OK && A->free_state(c, &back) == ST_OK && !st && !back, "free the FMU states");
            A->free_instance(c);
        }
}

/* blocks that are not this instance's FMU state: refused with the reason */
static void test_bad_fmu_state_blocks(const fmi_adapter *A)
{
    static unsigned char buf[1 << 16], garbage[4096];
    fmi_inst c = A->in_state(0, S_EVENT), other = A->in_state(1, C_STEP);
    void *st = NULL, *cs_state = NULL;
    size_t n = 0;
    CHECK(A->get_state(c, &st) == ST_OK && A->state_size(c, st, &n) == ST_OK, "state");
    n_logs = 0;
    expect_error(A, NULL, A->serialize(c, st, buf, n - 1), "serialize with a wrong size", "size");
    expect_error(A, NULL, A->deserialize(c, buf, 10, &cs_state), "deserialize a truncated block", "header");
    memset(garbage, 0x5a, sizeof garbage);
    expect_error(A, NULL, A->deserialize(c, garbage, sizeof garbage, &cs_state), "deserialize garbage", "not an FMU state");
    expect_error(A, NULL, A->set_state(c, garbage), "set garbage", "not an FMU state");
    CHECK(A->get_state(other, &cs_state) == ST_OK, "a Co-Simulation state");
    expect_error(A, NULL, A->set_state(c, cs_state), "set a Co-Simulation state into Model Exchange", "Co-Simulation");
    A->free_state(other, &cs_state);
    A->free_state(c, &st);
    A->free_instance(c);
    A->free_instance(other);
}

/* every case of this header */
static void run_shared_bad_input_cases(const fmi_adapter *A)
{
    test_every_call_in_every_state(A);
    test_instantiate_arguments(A);
    test_non_finite_and_out_of_range_values(A);
    test_what_cannot_be_set_now(A);
    test_non_finite_time_states_and_steps(A);
    test_value_references_types_and_sizes(A);
    test_fmu_state_in_every_state(A);
    test_bad_fmu_state_blocks(A);
}

#endif
