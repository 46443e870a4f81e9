/* fmi2GetFMUstate / fmi2SetFMUstate and their serialization, for one FMU
 * (compiled three times: -DTEST_ROCKINGWALL against rw_fmi2_static, -DTEST_DIAPHRAGM against
 * dg_fmi2_static, -DTEST_BUILDING against bd_fmi2_static).
 *  - Co-Simulation: a step taken after fmi2GetFMUstate and the same step taken again after
 *    fmi2SetFMUstate give bitwise equal outputs, at every step of a run with events inside steps
 *    and ramped inputs (RockingWall: the parapet on CVODE, then the 2DOF wall through the exact
 *    engine, whose state is part of the FMU state);
 *  - serialize / deserialize into another instance: the two instances then step identically;
 *  - Model Exchange: restoring a state restores states, inputs, derivatives and outputs bitwise;
 *  - bad input (NULL, wrong size, a wrong GUID, not a state, wrong interface type or phase):
 *    fmi2Error with a logged reason. */
#include "check.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmi2Functions.h"
#include "fmi2_test_logger.h"

#if defined(TEST_ROCKINGWALL)
#include "model_variables.h"
#define GUID RW_GUID
#define NX RW_NUMBER_OF_STATES
static const fmi2ValueReference OUTPUTS[] = {RW_VR_s1, RW_VR_s2, RW_VR_energy, RW_VR_dissipated, RW_VR_P_ground,
                                             RW_VR_q1, RW_VR_q2, RW_VR_dq1, RW_VR_dq2};
static const fmi2ValueReference START_VR = RW_VR_q1, INPUT_VR = RW_VR_ag, MARKER_VR = RW_VR_dissipated;
static const double START = 0.02;
static double INPUT = 0.3;
/* 0: a parapet (CVODE), impacts inside most steps of 0.05 s; 1: the 2DOF wall under semiRigidPaper
 * with a stiff spring, stepped by the exact engine (its band of the fast mode, events inside steps) */
static int exact_engine;
static void structure(fmi2Component c)
{
    const fmi2ValueReference vr[] = {RW_VR_support, RW_VR_hingeLaw}, kd_vr = RW_VR_Kd;
    const fmi2Integer parapet[] = {1, 4}, wall_2dof[] = {3, 2};
    const fmi2Real kd = 5e7;
    fmi2SetInteger(c, vr, 2, exact_engine ? wall_2dof : parapet);
    if (exact_engine) fmi2SetReal(c, &kd_vr, 1, &kd);
}
#elif defined(TEST_DIAPHRAGM)
#include "diaphragm_variables.h"
#define GUID DG_GUID
#define NX DG_NUMBER_OF_STATES
static const fmi2ValueReference OUTPUTS[] = {DG_VR_u, DG_VR_v, DG_VR_energy, DG_VR_P_ground, DG_VR_P_damping, DG_VR_P_wall};
static const fmi2ValueReference START_VR = DG_VR_u, INPUT_VR = DG_VR_F_top, MARKER_VR = DG_VR_energy;
static const double START = 0.01, INPUT = 50.0;
static void structure(fmi2Component c) { (void)c; }
#elif defined(TEST_BUILDING)
#include "building_variables.h"
#define GUID BD_GUID
#define NX BD_NUMBER_OF_STATES
static const fmi2ValueReference OUTPUTS[] = {BD_VR_u_diaph_1, BD_VR_u_diaph_2, BD_VR_a_diaph_2, BD_VR_V_storey_1,
                                             BD_VR_work_storey_1, BD_VR_work_diaph_2, BD_VR_u_top_2};
static const fmi2ValueReference START_VR = BD_VR_u_diaph_2, INPUT_VR = BD_VR_ag, MARKER_VR = BD_VR_work_storey_1;
static const double START = 0.01, INPUT = 2.0;
/* the default two storeys with pinched diaphragms */
static void structure(fmi2Component c)
{
    fmi2ValueReference vr = BD_VR_diaphragmLaw;
    fmi2Integer pinched = 2;
    fmi2SetInteger(c, &vr, 1, &pinched);
}
#else
#error "define TEST_ROCKINGWALL, TEST_DIAPHRAGM or TEST_BUILDING"
#endif

#define N_OUT (sizeof OUTPUTS / sizeof OUTPUTS[0])
#define STEP 0.05
#define N_STEPS 40

static fmi2Component instance(fmi2Type type, int initialize)
{
    fmi2Component c = fmi2Instantiate("state", type, GUID, "", &CB, fmi2False, fmi2False);
    if (!c) return NULL;
    structure(c);
    fmi2SetReal(c, &START_VR, 1, &START);
    if (!initialize) return c;
    fmi2SetupExperiment(c, fmi2True, 1e-8, 0.0, fmi2False, 0.0);
    fmi2EnterInitializationMode(c);
    if (fmi2ExitInitializationMode(c) != fmi2OK) {
        fmi2FreeInstance(c);
        return NULL;
    }
    fmi2SetReal(c, &INPUT_VR, 1, &INPUT);
    return c;
}

static void outputs(fmi2Component c, double out[N_OUT]) { fmi2GetReal(c, OUTPUTS, N_OUT, out); }

/* The input for step k as a master would set it: a new value with a slope on steps 0, 4, 8, ...,
 * a new value held on steps 2, 6, ..., unchanged on odd steps (then CVODE would go on with its
 * history were it not for the saved state). */
static void set_inputs(fmi2Component c, int k)
{
    const double u = INPUT * cos(0.7 * k), slope = -INPUT * 0.7 * sin(0.7 * k) / STEP;
    const fmi2Integer order = 1;
    if (k % 2) return;
    fmi2SetReal(c, &INPUT_VR, 1, &u);
    if (k % 4 == 0) fmi2SetRealInputDerivatives(c, &INPUT_VR, 1, &order, &slope);
}

static void test_rolled_back_step_reproduces_itself_bitwise(void)
{
    fmi2Component c = instance(fmi2CoSimulation, 1);
    fmi2FMUstate st = NULL;
    double first[N_OUT], again[N_OUT];
    int k, equal = 0;
    CHECK(c != NULL, "instantiate CS: %s", last_log);
    if (!c) return;
    for (k = 0; k < N_STEPS; k++) {
        set_inputs(c, k);
        CHECK(fmi2GetFMUstate(c, &st) == fmi2OK, "GetFMUstate at step %d: %s", k, last_log);
        CHECK(fmi2DoStep(c, k * STEP, STEP, fmi2False) == fmi2OK, "step %d: %s", k, last_log);
        outputs(c, first);
        CHECK(fmi2SetFMUstate(c, st) == fmi2OK, "SetFMUstate at step %d: %s", k, last_log);
        CHECK(fmi2DoStep(c, k * STEP, STEP, fmi2False) == fmi2OK, "step %d again: %s", k, last_log);
        outputs(c, again);
        CHECK(memcmp(first, again, sizeof first) == 0, "step %d rolled back and taken again differs: %.17g vs %.17g", k,
              first[0], again[0]);
        equal += memcmp(first, again, sizeof first) == 0;
    }
    CHECK(get_real(c, MARKER_VR) > 0, "the run had something happen (marker %g)", get_real(c, MARKER_VR));
    printf("  %d of %d rolled-back steps bitwise equal\n", equal, N_STEPS);
    CHECK(fmi2FreeFMUstate(c, &st) == fmi2OK && st == NULL, "FreeFMUstate");
    fmi2FreeInstance(c);
}

static void test_serialized_state_moves_to_another_instance(void)
{
    fmi2Component a = instance(fmi2CoSimulation, 1), b = instance(fmi2CoSimulation, 1);
    fmi2FMUstate st = NULL, copy = NULL;
    fmi2Byte *bytes;
    size_t n = 0;
    double out_a[N_OUT], out_b[N_OUT];
    int k;
    CHECK(a && b, "instantiate");
    if (!a || !b) return;
    for (k = 0; k < 7; k++) {
        set_inputs(a, k);
        fmi2DoStep(a, k * STEP, STEP, fmi2True);
    }
    set_inputs(a, k);
    CHECK(fmi2GetFMUstate(a, &st) == fmi2OK, "GetFMUstate");
    CHECK(fmi2SerializedFMUstateSize(a, st, &n) == fmi2OK && n > 0, "size %u", (unsigned)n);
    bytes = (fmi2Byte *)malloc(n);
    CHECK(fmi2SerializeFMUstate(a, st, bytes, n) == fmi2OK, "serialize: %s", last_log);
    CHECK(fmi2DeSerializeFMUstate(b, bytes, n, &copy) == fmi2OK, "deserialize: %s", last_log);
    CHECK(fmi2SetFMUstate(b, copy) == fmi2OK, "set into b: %s", last_log);
    for (; k < 14; k++) {
        if (k > 7) set_inputs(a, k), set_inputs(b, k);
        CHECK(fmi2DoStep(a, k * STEP, STEP, fmi2True) == fmi2OK && fmi2DoStep(b, k * STEP, STEP, fmi2True) == fmi2OK,
              "step %d: %s", k, last_log);
        outputs(a, out_a);
        outputs(b, out_b);
        CHECK(memcmp(out_a, out_b, sizeof out_a) == 0, "step %d: the instance given the serialized state differs", k);
    }
    fmi2FreeFMUstate(a, &st);
    fmi2FreeFMUstate(b, &copy);
    free(bytes);
    fmi2FreeInstance(a);
    fmi2FreeInstance(b);
}

static void test_model_exchange_state_restores_everything(void)
{
    fmi2Component c = instance(fmi2ModelExchange, 1);
    fmi2FMUstate st = NULL;
    double x[NX], x2[NX], dx[NX], dx2[NX], out[N_OUT], out2[N_OUT], moved[NX], u2 = 2 * INPUT;
    int i;
    CHECK(c != NULL, "instantiate ME");
    if (!c) return;
    CHECK(fmi2EnterContinuousTimeMode(c) == fmi2OK, "continuous-time mode");
    fmi2GetContinuousStates(c, x, NX);
    for (i = 0; i < NX; i++) moved[i] = x[i] * 0.5 + 0.001;
    fmi2SetContinuousStates(c, moved, NX); /* a state away from the start value */
    fmi2GetDerivatives(c, dx, NX);
    fmi2GetContinuousStates(c, x, NX);
    outputs(c, out);
    CHECK(fmi2GetFMUstate(c, &st) == fmi2OK, "GetFMUstate ME: %s", last_log);
    for (i = 0; i < NX; i++) moved[i] = -x[i] + 0.003;
    fmi2SetContinuousStates(c, moved, NX);
    fmi2SetReal(c, &INPUT_VR, 1, &u2);
    fmi2SetTime(c, 1.5);
    CHECK(fmi2SetFMUstate(c, st) == fmi2OK, "SetFMUstate ME: %s", last_log);
    fmi2GetContinuousStates(c, x2, NX);
    fmi2GetDerivatives(c, dx2, NX);
    outputs(c, out2);
    CHECK(memcmp(x, x2, sizeof x) == 0 && memcmp(dx, dx2, sizeof dx) == 0 && memcmp(out, out2, sizeof out) == 0,
          "ME: states, derivatives or outputs not restored");
    CHECK(get_real(c, INPUT_VR) == INPUT, "ME: input not restored: %g", get_real(c, INPUT_VR));
    fmi2FreeFMUstate(c, &st);
    fmi2FreeInstance(c);
}

/* one bad call on a fresh instance: fmi2Error, an error logged that mentions `mention` */
static void expect_bad(fmi2Status got, const char *what, const char *mention)
{
    CHECK(got == fmi2Error, "%s: status %d, expected fmi2Error", what, (int)got);
    CHECK(n_logs > 0 && last_status == fmi2Error && strstr(last_message, mention), "%s: log '%s' does not mention '%s'",
          what, last_message, mention);
}

/* a serialized state of an initialized CS instance (malloc'ed, *n bytes) */
static fmi2Byte *serialized_state(size_t *n)
{
    fmi2Component c = instance(fmi2CoSimulation, 1);
    fmi2FMUstate st = NULL;
    fmi2Byte *bytes;
    fmi2GetFMUstate(c, &st);
    fmi2SerializedFMUstateSize(c, st, n);
    bytes = (fmi2Byte *)malloc(*n);
    fmi2SerializeFMUstate(c, st, bytes, *n);
    fmi2FreeFMUstate(c, &st);
    fmi2FreeInstance(c);
    return bytes;
}

static void test_bad_input(void)
{
    size_t n = 0, m = 0;
    fmi2Byte *good = serialized_state(&n), *bad = (fmi2Byte *)malloc(n);
    fmi2FMUstate st = NULL, me_state = NULL, early = NULL;
    fmi2Component c, me, pre;
    char *guid;
#define FRESH(TYPE) (n_logs = 0, c = instance(TYPE, 1))
    FRESH(fmi2CoSimulation);
    expect_bad(fmi2GetFMUstate(c, NULL), "GetFMUstate NULL", "NULL");
    fmi2FreeInstance(c);
    FRESH(fmi2CoSimulation);
    expect_bad(fmi2SetFMUstate(c, NULL), "SetFMUstate NULL", "NULL");
    fmi2FreeInstance(c);
    FRESH(fmi2CoSimulation);
    expect_bad(fmi2FreeFMUstate(c, NULL), "FreeFMUstate NULL", "NULL");
    fmi2FreeInstance(c);
    FRESH(fmi2CoSimulation);
    fmi2GetFMUstate(c, &st);
    n_logs = 0;
    expect_bad(fmi2SerializedFMUstateSize(c, st, NULL), "SerializedFMUstateSize NULL size", "NULL");
    fmi2FreeFMUstate(c, &st);
    fmi2FreeInstance(c);
    FRESH(fmi2CoSimulation);
    fmi2GetFMUstate(c, &st);
    n_logs = 0;
    expect_bad(fmi2SerializeFMUstate(c, st, bad, n - 1), "SerializeFMUstate wrong size", "size");
    fmi2FreeFMUstate(c, &st);
    fmi2FreeInstance(c);
    FRESH(fmi2CoSimulation);
    expect_bad(fmi2DeSerializeFMUstate(c, good, n - 1, &st), "DeSerializeFMUstate wrong size", "bytes");
    CHECK(st == NULL, "a failed deserialization returned a state");
    fmi2FreeInstance(c);
    FRESH(fmi2CoSimulation);
    expect_bad(fmi2DeSerializeFMUstate(c, good, 10, &st), "DeSerializeFMUstate truncated", "header");
    fmi2FreeInstance(c);
    memcpy(bad, good, n);
    guid = strchr((char *)bad + 8, '{');
    if (guid) guid[1] = guid[1] == '0' ? '1' : '0';
    FRESH(fmi2CoSimulation);
    expect_bad(fmi2DeSerializeFMUstate(c, bad, n, &st), "DeSerializeFMUstate wrong GUID", "GUID");
    fmi2FreeInstance(c);
    memset(bad, 0x5a, n);
    FRESH(fmi2CoSimulation);
    expect_bad(fmi2DeSerializeFMUstate(c, bad, n, &st), "DeSerializeFMUstate garbage", "not an FMU state");
    fmi2FreeInstance(c);
    FRESH(fmi2CoSimulation);
    expect_bad(fmi2SetFMUstate(c, (fmi2FMUstate)bad), "SetFMUstate of garbage", "not an FMU state");
    fmi2FreeInstance(c);
    /* a Model Exchange state into a Co-Simulation instance */
    me = instance(fmi2ModelExchange, 1);
    fmi2GetFMUstate(me, &me_state);
    FRESH(fmi2CoSimulation);
    expect_bad(fmi2SetFMUstate(c, me_state), "SetFMUstate ME into CS", "Model Exchange");
    fmi2FreeInstance(c);
    fmi2FreeFMUstate(me, &me_state);
    fmi2FreeInstance(me);
    /* a state from before initialization into an initialized instance */
    pre = instance(fmi2CoSimulation, 0);
    fmi2GetFMUstate(pre, &early);
    fmi2SerializedFMUstateSize(pre, early, &m);
#ifdef TEST_WITHOUT_CVODE /* cs_without_cvode.c: no integrator part after initialization either */
    CHECK(m > 0 && m == n, "a state before initialization has the size of one after (%u vs %u bytes)", (unsigned)m, (unsigned)n);
#else
    CHECK(m > 0 && m < n, "a state before initialization has no integrator part (%u vs %u bytes)", (unsigned)m, (unsigned)n);
#endif
    FRESH(fmi2CoSimulation);
    expect_bad(fmi2SetFMUstate(c, early), "SetFMUstate before-init state after init", "ExitInitializationMode");
    fmi2FreeInstance(c);
    CHECK(fmi2SetFMUstate(pre, early) == fmi2OK, "a state before initialization into the same phase: %s", last_log);
    fmi2FreeFMUstate(pre, &early);
    fmi2FreeInstance(pre);
#undef FRESH
    free(good);
    free(bad);
}

int main(void)
{
    test_rolled_back_step_reproduces_itself_bitwise();
    test_serialized_state_moves_to_another_instance();
    test_model_exchange_state_restores_everything();
    test_bad_input();
#if defined(TEST_ROCKINGWALL)
    exact_engine = 1;
    INPUT = 3.0;
    test_rolled_back_step_reproduces_itself_bitwise();
    test_serialized_state_moves_to_another_instance();
#endif
    printf("%d checks, %d failures\n", checks, failures);
    return failures ? 1 : 0;
}
