/* Bad input to Building through the FMI 2.0 API (linked statically): every parameter out of its
 * range, NaN and infinite parameters, inputs and start values, Integer parameters out of range,
 * unknown value references, outputs set, calls in forbidden states. Each must return fmi2Error
 * with a reason that names the variable (or value reference, or function) passed to the logger,
 * and so must every Model-Exchange call in a state where FMI 2.0 forbids it (the allowed ones succeed),
 * must not crash, and the instance must still work after fmi2Reset (ASan/UBSan in build-asan
 * check the memory). Also: the floors above nStoreys stay at rest, and a Co-Simulation run. */
#include "check.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "building_variables.h"
#include "fmi2Functions.h"
#include "fmi2_test_logger.h"

enum { S_INST, S_INIT, S_CONT };
static const char *STATE_NAMES[] = {"instantiated", "initializationMode", "continuousTimeMode"};

static fmi2Component in_state(int s, fmi2Type type)
{
    fmi2Component c = fmi2Instantiate("bad", type, BD_GUID, "", &CB, fmi2False, fmi2False);
    if (!c || s == S_INST) return c;
    fmi2SetupExperiment(c, fmi2False, 0, 0, fmi2False, 0);
    fmi2EnterInitializationMode(c);
    if (s == S_INIT) return c;
    fmi2ExitInitializationMode(c);
    if (type == fmi2ModelExchange) fmi2EnterContinuousTimeMode(c);
    return c;
}

/* the call failed with fmi2Error and a logged reason mentioning `mention`; the instance recovers */
static void expect_error(fmi2Component c, fmi2Status got, const char *what, const char *mention)
{
    CHECK(got == fmi2Error, "%s: status %d, expected fmi2Error", what, (int)got);
    CHECK(n_logs > 0 && last_status == fmi2Error, "%s: no error logged", what);
    CHECK(strstr(last_message, mention) != NULL, "%s: log '%s' does not mention '%s'", what, last_message, mention);
    CHECK(fmi2Reset(c) == fmi2OK, "%s: fmi2Reset after the error", what);
    CHECK(fmi2SetupExperiment(c, fmi2False, 0, 0, fmi2False, 0) == fmi2OK && fmi2EnterInitializationMode(c) == fmi2OK &&
              fmi2ExitInitializationMode(c) == fmi2OK,
          "%s: instance not usable after fmi2Reset", what);
}

static void bad_real(int state, fmi2ValueReference vr, double value, const char *mention)
{
    fmi2Component c = in_state(state, fmi2ModelExchange);
    char what[160];
    snprintf(what, sizeof what, "SetReal vr %u = %g in %s", (unsigned)vr, value, STATE_NAMES[state]);
    CHECK(c != NULL, "instantiate");
    if (!c) return;
    n_logs = 0;
    expect_error(c, fmi2SetReal(c, &vr, 1, &value), what, mention);
    fmi2FreeInstance(c);
}

static void bad_integer(fmi2ValueReference vr, int value, const char *mention)
{
    fmi2Component c = in_state(S_INST, fmi2ModelExchange);
    char what[160];
    snprintf(what, sizeof what, "SetInteger %s = %d", mention, value);
    n_logs = 0;
    expect_error(c, fmi2SetInteger(c, &vr, 1, &value), what, mention);
    fmi2FreeInstance(c);
}

static void test_out_of_range(void)
{
    struct { fmi2ValueReference vr; double v; const char *name; } invalid[] = {
        {BD_VR_m_1, 0, "m_1"}, {BD_VR_m_3, -1, "m_3"}, {BD_VR_k_2, 0, "k_2"}, {BD_VR_Fy_5, 0, "Fy_5"},
        {BD_VR_alpha_1, 1.5, "alpha_1"}, {BD_VR_alpha_4, -0.1, "alpha_4"}, {BD_VR_md_2, 0, "md_2"},
        {BD_VR_kd_5, -3, "kd_5"}, {BD_VR_Fyd_1, 0, "Fyd_1"}, {BD_VR_alphad_2, -0.1, "alphad_2"},
        {BD_VR_nBW, 0.5, "nBW"}, {BD_VR_nBW, 101, "nBW"}, {BD_VR_betaBW, 1.2, "betaBW"},
        {BD_VR_pinchSize, 1.0, "pinchSize"}, {BD_VR_pinchWidth, 0, "pinchWidth"}, {BD_VR_pinchCentre, -0.1, "pinchCentre"},
        {BD_VR_rayleighMass, -1, "rayleighMass"}, {BD_VR_rayleighStiffness, -1e-3, "rayleighStiffness"},
        {BD_VR_z_storey_1, 1.5, "z_storey_1"}, {BD_VR_z_diaph_3, -2, "z_diaph_3"},
    };
    size_t i;
    for (i = 0; i < sizeof invalid / sizeof invalid[0]; i++) {
        bad_real(S_INST, invalid[i].vr, invalid[i].v, invalid[i].name);
        bad_real(S_INIT, invalid[i].vr, invalid[i].v, invalid[i].name);
    }
    bad_integer(BD_VR_nStoreys, 0, "nStoreys");
    bad_integer(BD_VR_nStoreys, 6, "nStoreys");
    bad_integer(BD_VR_nStoreys, -2147483647 - 1, "nStoreys");
    bad_integer(BD_VR_storeyLaw, 2, "storeyLaw"); /* no pinching for the storeys */
    bad_integer(BD_VR_storeyLaw, 4, "storeyLaw");  /* one past bilinear, the last law */
    bad_integer(BD_VR_storeyLaw, -1, "storeyLaw");
    bad_integer(BD_VR_diaphragmLaw, 4, "diaphragmLaw");
    bad_integer(BD_VR_diaphragmLaw, -1, "diaphragmLaw");
}

/* every law a storey or a diaphragm takes is accepted: 0 to 3 for a diaphragm (3 bilinear), all
 * but the pinching (2) for a storey */
static void test_laws_accepted(void)
{
    const fmi2ValueReference vr[2] = {BD_VR_storeyLaw, BD_VR_diaphragmLaw};
    int law, k;
    for (k = 0; k < 2; k++)
        for (law = 0; law <= 3; law++) {
            fmi2Component c;
            fmi2Integer v = law, got = -1;
            if (k == 0 && law == 2) continue;
            c = in_state(S_INST, fmi2ModelExchange);
            n_logs = 0;
            CHECK(fmi2SetInteger(c, &vr[k], 1, &v) == fmi2OK, "%s = %d refused: %s", k ? "diaphragmLaw" : "storeyLaw",
                  law, n_logs ? last_message : "");
            fmi2SetupExperiment(c, fmi2False, 0, 0, fmi2False, 0);
            CHECK(fmi2EnterInitializationMode(c) == fmi2OK && fmi2GetInteger(c, &vr[k], 1, &got) == fmi2OK && got == law,
                  "%s: read back %d, set %d", k ? "diaphragmLaw" : "storeyLaw", (int)got, law);
            fmi2FreeInstance(c);
        }
}

static void test_nonfinite(void)
{
    const double nonfinite[] = {NAN, INFINITY, -INFINITY};
    const fmi2ValueReference params[] = {BD_VR_nBW, BD_VR_betaBW, BD_VR_pinchSize, BD_VR_rayleighMass, BD_VR_m_1,
                                         BD_VR_k_3, BD_VR_Fy_5, BD_VR_alphad_2, BD_VR_u_floor_1, BD_VR_z_diaph_4};
    const fmi2ValueReference inputs[] = {BD_VR_ag, BD_VR_F_wall_1, BD_VR_F_wall_5, BD_VR_F_above_1, BD_VR_F_above_5};
    size_t i, k;
    int s;
    for (k = 0; k < 3; k++) {
        for (i = 0; i < sizeof params / sizeof params[0]; i++) {
            bad_real(S_INST, params[i], nonfinite[k], "not a finite number");
            bad_real(S_INIT, params[i], nonfinite[k], "not a finite number");
        }
        for (i = 0; i < sizeof inputs / sizeof inputs[0]; i++)
            for (s = S_INST; s <= S_CONT; s++) bad_real(s, inputs[i], nonfinite[k], "not a finite number");
    }
}

static void test_value_references_and_settability(void)
{
    const fmi2ValueReference unknown[] = {0, 11, 21, 99, 100, 109, 130, 146, 600, 0xFFFFFFFFu};
    size_t i;
    for (i = 0; i < sizeof unknown / sizeof unknown[0]; i++) {
        char num[32];
        double v = 0;
        fmi2Integer iv = 0;
        fmi2Component c = in_state(S_INIT, fmi2ModelExchange);
        snprintf(num, sizeof num, "%u", (unsigned)unknown[i]);
        n_logs = 0;
        expect_error(c, fmi2GetReal(c, &unknown[i], 1, &v), "GetReal unknown vr", num);
        n_logs = 0;
        expect_error(c, fmi2SetReal(c, &unknown[i], 1, &v), "SetReal unknown vr", num);
        n_logs = 0;
        expect_error(c, fmi2GetInteger(c, &unknown[i], 1, &iv), "GetInteger unknown vr", num);
        fmi2FreeInstance(c);
    }
    bad_real(S_INIT, BD_VR_V_storey_2, 1.0, "cannot be set");        /* an output */
    bad_real(S_CONT, BD_VR_m_1, 3000.0, "can only be set before");   /* a parameter after init */
    bad_real(S_CONT, BD_VR_z_storey_1, 0.1, "fmi2SetContinuousStates"); /* a start value after init */
    {
        fmi2Component c = in_state(S_CONT, fmi2ModelExchange);
        fmi2ValueReference vr = BD_VR_nStoreys;
        fmi2Integer three = 3;
        n_logs = 0;
        expect_error(c, fmi2SetInteger(c, &vr, 1, &three), "SetInteger nStoreys after init", "fmi2SetInteger");
        fmi2FreeInstance(c);
    }
    {   /* calls in a forbidden state and wrong array sizes reach the shared layer's checks */
        fmi2Component c = in_state(S_INST, fmi2ModelExchange);
        double dx[BD_NUMBER_OF_STATES + 1];
        n_logs = 0;
        expect_error(c, fmi2GetDerivatives(c, dx, BD_NUMBER_OF_STATES), "GetDerivatives when instantiated",
                     "fmi2GetDerivatives");
        fmi2FreeInstance(c);
        c = in_state(S_CONT, fmi2ModelExchange);
        n_logs = 0;
        expect_error(c, fmi2GetDerivatives(c, dx, BD_NUMBER_OF_STATES + 1), "GetDerivatives nx + 1", "nx");
        fmi2FreeInstance(c);
    }
}

/* ---- the Model-Exchange state machine: every call in every state, allowed or not ---------- */
enum { M_INST, M_INIT, M_EVENT, M_CONT, M_TERM, M_ERROR, N_ME_STATES };
static const char *ME_STATE_NAMES[] = {"instantiated", "initializationMode", "eventMode", "continuousTimeMode",
                                       "terminated", "error"};
#define BIT(s) (1u << (s))
#define AFTER_INST (BIT(M_INIT) | BIT(M_EVENT) | BIT(M_CONT) | BIT(M_TERM) | BIT(M_ERROR))

static fmi2Component in_me_state(int s)
{
    fmi2Component c = fmi2Instantiate("matrix", fmi2ModelExchange, BD_GUID, "", &CB, fmi2False, fmi2False);
    fmi2ValueReference nosuch = 999;
    double v = 0;
    if (!c) return NULL;
    if (s == M_ERROR) { fmi2SetReal(c, &nosuch, 1, &v); return c; }
    if (s == M_INST) return c;
    fmi2SetupExperiment(c, fmi2False, 0, 0, fmi2False, 0);
    fmi2EnterInitializationMode(c);
    if (s == M_INIT) return c;
    fmi2ExitInitializationMode(c);
    if (s == M_EVENT) return c;
    if (s == M_TERM) { fmi2Terminate(c); return c; }
    fmi2EnterContinuousTimeMode(c);
    return c;
}

static fmi2ValueReference VR_N = BD_VR_nStoreys, VR_AG = BD_VR_ag, VR_M1 = BD_VR_m_1;
static fmi2Status m_setup(fmi2Component c) { return fmi2SetupExperiment(c, fmi2False, 0, 0, fmi2False, 0); }
static fmi2Status m_enter_init(fmi2Component c) { return fmi2EnterInitializationMode(c); }
static fmi2Status m_exit_init(fmi2Component c) { return fmi2ExitInitializationMode(c); }
static fmi2Status m_terminate(fmi2Component c) { return fmi2Terminate(c); }
static fmi2Status m_get_real(fmi2Component c) { double v; return fmi2GetReal(c, &VR_M1, 1, &v); }
static fmi2Status m_get_int(fmi2Component c) { fmi2Integer v; return fmi2GetInteger(c, &VR_N, 1, &v); }
static fmi2Status m_set_real(fmi2Component c) { double v = 0.5; return fmi2SetReal(c, &VR_AG, 1, &v); }
static fmi2Status m_set_int(fmi2Component c) { fmi2Integer v = 3; return fmi2SetInteger(c, &VR_N, 1, &v); }
static fmi2Status m_enter_event(fmi2Component c) { return fmi2EnterEventMode(c); }
static fmi2Status m_nds(fmi2Component c) { fmi2EventInfo ei; return fmi2NewDiscreteStates(c, &ei); }
static fmi2Status m_enter_cont(fmi2Component c) { return fmi2EnterContinuousTimeMode(c); }
static fmi2Status m_completed(fmi2Component c)
{
    fmi2Boolean ev, term;
    return fmi2CompletedIntegratorStep(c, fmi2True, &ev, &term);
}
static fmi2Status m_set_time(fmi2Component c) { return fmi2SetTime(c, 0.0); }
static fmi2Status m_set_states(fmi2Component c) { double x[BD_NUMBER_OF_STATES] = {0}; return fmi2SetContinuousStates(c, x, BD_NUMBER_OF_STATES); }
static fmi2Status m_get_der(fmi2Component c) { double dx[BD_NUMBER_OF_STATES]; return fmi2GetDerivatives(c, dx, BD_NUMBER_OF_STATES); }
static fmi2Status m_get_states(fmi2Component c) { double x[BD_NUMBER_OF_STATES]; return fmi2GetContinuousStates(c, x, BD_NUMBER_OF_STATES); }

static const struct {
    const char *name;
    fmi2Status (*call)(fmi2Component);
    unsigned allowed; /* FMI 2.0 section 3.2.3 */
} ME_API[] = {
    {"fmi2SetupExperiment", m_setup, BIT(M_INST)},
    {"fmi2EnterInitializationMode", m_enter_init, BIT(M_INST)},
    {"fmi2ExitInitializationMode", m_exit_init, BIT(M_INIT)},
    {"fmi2Terminate", m_terminate, BIT(M_EVENT) | BIT(M_CONT)},
    {"fmi2GetReal", m_get_real, AFTER_INST},
    {"fmi2GetInteger", m_get_int, AFTER_INST},
    {"fmi2SetReal", m_set_real, BIT(M_INST) | BIT(M_INIT) | BIT(M_EVENT) | BIT(M_CONT)},
    {"fmi2SetInteger", m_set_int, BIT(M_INST) | BIT(M_INIT)}, /* a parameter: before exit init only */
    {"fmi2EnterEventMode", m_enter_event, BIT(M_EVENT) | BIT(M_CONT)},
    {"fmi2NewDiscreteStates", m_nds, BIT(M_EVENT)},
    {"fmi2EnterContinuousTimeMode", m_enter_cont, BIT(M_EVENT)},
    {"fmi2CompletedIntegratorStep", m_completed, BIT(M_CONT)},
    {"fmi2SetTime", m_set_time, BIT(M_EVENT) | BIT(M_CONT)},
    {"fmi2SetContinuousStates", m_set_states, BIT(M_CONT)},
    {"fmi2GetDerivatives", m_get_der, BIT(M_EVENT) | BIT(M_CONT) | BIT(M_TERM) | BIT(M_ERROR)},
    {"fmi2GetContinuousStates", m_get_states, AFTER_INST},
};

static void test_state_machine(void)
{
    size_t f;
    int s, forbidden = 0;
    for (f = 0; f < sizeof ME_API / sizeof ME_API[0]; f++)
        for (s = 0; s < N_ME_STATES; s++) {
            fmi2Component c = in_me_state(s);
            fmi2Status st;
            char what[160];
            CHECK(c != NULL, "instantiate");
            if (!c) continue;
            snprintf(what, sizeof what, "%s in %s", ME_API[f].name, ME_STATE_NAMES[s]);
            n_logs = 0;
            st = ME_API[f].call(c);
            if (!(ME_API[f].allowed & BIT(s))) {
                expect_error(c, st, what, ME_API[f].name);
                forbidden++;
            } else if (s != M_ERROR) {
                CHECK(st == fmi2OK, "%s: status %d (%s)", what, (int)st, last_message);
            }
            fmi2FreeInstance(c);
        }
    printf("  %d forbidden (function, state) pairs rejected\n", forbidden);
    CHECK(forbidden >= 40, "only %d forbidden pairs exercised", forbidden);
}

/* nStoreys = 2: start values given for floor 4 are dropped, floors 3-5 do not move */
static void test_floors_above_rest(void)
{
    fmi2Component c = fmi2Instantiate("rest", fmi2ModelExchange, BD_GUID, "", &CB, fmi2False, fmi2False);
    fmi2ValueReference vr_n = BD_VR_nStoreys, vr_u4 = BD_VR_u_floor_4, vr_ag = BD_VR_ag, vr_f = BD_VR_F_wall_3;
    fmi2Integer two = 2;
    double u4 = 0.1, ag = 2.0, force = 1e3, x[BD_NUMBER_OF_STATES], dx[BD_NUMBER_OF_STATES];
    int i, moving = 0;
    CHECK(fmi2SetInteger(c, &vr_n, 1, &two) == fmi2OK && fmi2SetReal(c, &vr_u4, 1, &u4) == fmi2OK, "set up");
    fmi2SetupExperiment(c, fmi2False, 0, 0, fmi2False, 0);
    fmi2EnterInitializationMode(c);
    fmi2ExitInitializationMode(c);
    fmi2EnterContinuousTimeMode(c);
    CHECK(fmi2SetReal(c, &vr_ag, 1, &ag) == fmi2OK && fmi2SetReal(c, &vr_f, 1, &force) == fmi2OK, "inputs");
    CHECK(fmi2GetContinuousStates(c, x, BD_NUMBER_OF_STATES) == fmi2OK, "states");
    CHECK(fmi2GetDerivatives(c, dx, BD_NUMBER_OF_STATES) == fmi2OK, "derivatives");
    for (i = 2 * 8; i < BD_NUMBER_OF_STATES; i++) {
        CHECK(x[i] == 0.0 && dx[i] == 0.0, "floor %d state %d: x = %g, dx = %g (above nStoreys = 2)", i / 8 + 1, i % 8,
              x[i], dx[i]);
    }
    for (i = 0; i < 2 * 8; i++) moving += dx[i] != 0.0;
    CHECK(moving > 0, "the two storeys do not move under ag = 2");
    {   /* with floor 2 displaced, the first unused floor's outputs still read 0 (not -floor 2) */
        const fmi2ValueReference unused[] = {BD_VR_a_diaph_3, BD_VR_u_top_3, BD_VR_V_storey_3, BD_VR_drift_3,
                                             BD_VR_F_diaph_3, BD_VR_d_diaph_3, BD_VR_u_top_4};
        size_t k;
        x[8 + 0] = 0.01;  /* u_floor_2 */
        x[8 + 3] = 0.015; /* u_diaph_2 */
        CHECK(fmi2SetContinuousStates(c, x, BD_NUMBER_OF_STATES) == fmi2OK, "states");
        for (k = 0; k < sizeof unused / sizeof unused[0]; k++)
            CHECK(get_real(c, unused[k]) == 0.0, "output vr %u of an unused floor = %g", (unsigned)unused[k],
                  get_real(c, unused[k]));
    }
    fmi2FreeInstance(c);
}

/* Co-Simulation through CVODE: a run, then a non-finite input refused with the instance intact */
static void test_cosim(void)
{
    fmi2Component c = in_state(S_CONT, fmi2CoSimulation);
    fmi2ValueReference vr_ag = BD_VR_ag;
    double ag = 1.0, bad = NAN, t = 0.0;
    int k, ok = 1;
    CHECK(fmi2SetReal(c, &vr_ag, 1, &ag) == fmi2OK, "CS input");
    for (k = 0; k < 100 && ok; k++, t += 0.01) ok = fmi2DoStep(c, t, 0.01, fmi2True) == fmi2OK;
    CHECK(ok, "CS run: %s", last_message);
    CHECK(fabs(get_real(c, BD_VR_u_diaph_1)) > 1e-4, "CS run did not move: %g", get_real(c, BD_VR_u_diaph_1));
    n_logs = 0;
    CHECK(fmi2SetReal(c, &vr_ag, 1, &bad) == fmi2Error && strstr(last_message, "ag"), "CS NaN ag: '%s'", last_message);
    fmi2FreeInstance(c);
}

int main(void)
{
    test_out_of_range();
    test_laws_accepted();
    test_nonfinite();
    test_value_references_and_settability();
    test_state_machine();
    test_floors_above_rest();
    test_cosim();
    printf("%d checks, %d failures\n", checks, failures);
    return failures ? 1 : 0;
}
