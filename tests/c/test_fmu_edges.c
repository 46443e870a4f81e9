/* RockingWall's edges, through both FMI layers (fmi2Functions.c and fmi3Functions.c linked
 * statically), each a finding measured on the code and named here:
 *  - a finite input whose step is not finite (ag = 1e308): the step or the call is an error with
 *    the reason logged, never OK with NaN outputs;
 *  - a step to t = 1e300 never returned: refused with the bound in the message; a long step at
 *    rest (1e7 s took 8.5 s) is cheap;
 *  - deserializing another FMU's state copied 64 raw bytes of the blob into the log message: the
 *    message is printable text. */
#include "check.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "fmi2Functions.h"
#include "fmi3Functions.h"
#include "model_variables.h"

static char last_message[2048];
static int n_errors = 0;

static void remember(int status, const char *message)
{
    snprintf(last_message, sizeof last_message, "%s", message ? message : "(null)");
    if (status >= 3) n_errors++; /* fmi2Error, fmi3Error and worse */
}

static void logger2(fmi2ComponentEnvironment env, fmi2String name, fmi2Status status, fmi2String category,
                    fmi2String message, ...)
{
    (void)env; (void)name; (void)category;
    remember((int)status, message);
}

static void logger3(fmi3InstanceEnvironment env, fmi3Status status, fmi3String category, fmi3String message)
{
    (void)env; (void)category;
    remember((int)status, message);
}

static const fmi2CallbackFunctions CB = {logger2, calloc, free, NULL, NULL};
static const fmi2ValueReference VR_AG = RW_VR_ag;
static const fmi2ValueReference RESULTS[] = {RW_VR_s1, RW_VR_s2, RW_VR_F_top, RW_VR_F_base, RW_VR_energy,
                                             RW_VR_P_ground, RW_VR_dissipated, RW_VR_q1, RW_VR_q2, RW_VR_dq1, RW_VR_dq2};
#define N_RESULTS (sizeof RESULTS / sizeof RESULTS[0])

/* ---- one initialized instance of each version, and what the cases do with it ---------------- */

typedef struct {
    int version;
    void *c;
} inst;

static inst make(int version, int co_simulation)
{
    inst I = {version, NULL};
    if (version == 2) {
        I.c = fmi2Instantiate("edge", co_simulation ? fmi2CoSimulation : fmi2ModelExchange, RW_GUID, "", &CB, fmi2False,
                              fmi2False);
        fmi2SetupExperiment(I.c, fmi2False, 0, 0, fmi2False, 0);
        fmi2EnterInitializationMode(I.c);
        fmi2ExitInitializationMode(I.c);
    } else {
        I.c = co_simulation ? fmi3InstantiateCoSimulation("edge", RW_GUID, NULL, false, false, false, false, NULL, 0, NULL,
                                                          logger3, NULL)
                            : fmi3InstantiateModelExchange("edge", RW_GUID, NULL, false, false, NULL, logger3);
        fmi3EnterInitializationMode(I.c, false, 0, 0, false, 0);
        fmi3ExitInitializationMode(I.c);
    }
    return I;
}

static void drop(inst I)
{
    if (I.version == 2) fmi2FreeInstance(I.c);
    else fmi3FreeInstance(I.c);
}

static int set_ag(inst I, double ag)
{
    return I.version == 2 ? (int)fmi2SetReal(I.c, &VR_AG, 1, &ag) : (int)fmi3SetFloat64(I.c, &VR_AG, 1, &ag, 1);
}

static int do_step(inst I, double t, double h)
{
    fmi3Boolean ev, term, early;
    double last;
    if (I.version == 2) return (int)fmi2DoStep(I.c, t, h, fmi2True);
    return (int)fmi3DoStep(I.c, t, h, true, &ev, &term, &early, &last);
}

static int get_results(inst I, double v[N_RESULTS])
{
    return I.version == 2 ? (int)fmi2GetReal(I.c, RESULTS, N_RESULTS, v) : (int)fmi3GetFloat64(I.c, RESULTS, N_RESULTS, v, N_RESULTS);
}

/* Model Exchange: the event iteration after initialization, then Continuous-Time Mode */
static void to_continuous_time(inst I)
{
    if (I.version == 2) {
        fmi2EventInfo e;
        do fmi2NewDiscreteStates(I.c, &e); while (e.newDiscreteStatesNeeded && !e.terminateSimulation);
        fmi2EnterContinuousTimeMode(I.c);
    } else {
        fmi3Boolean more, term, nom, changed, defined;
        double next;
        do fmi3UpdateDiscreteStates(I.c, &more, &term, &nom, &changed, &defined, &next); while (more && !term);
        fmi3EnterContinuousTimeMode(I.c);
    }
}

static int derivatives(inst I, double dx[RW_NUMBER_OF_STATES])
{
    return I.version == 2 ? (int)fmi2GetDerivatives(I.c, dx, RW_NUMBER_OF_STATES)
                          : (int)fmi3GetContinuousStateDerivatives(I.c, dx, RW_NUMBER_OF_STATES);
}

/* ---- the cases ------------------------------------------------------------------------------- */

/* ag = 1e308 is finite, but a step under it is not: doStep returned OK with s1, s2, F_top and
 * the energy NaN and collapsed false. The step must be an error that says what is not finite. */
static void test_finite_input_with_non_finite_step_is_an_error(int version)
{
    inst I = make(version, 1);
    double v[N_RESULTS];
    int st, finite = 1;
    size_t k;
    CHECK(set_ag(I, 1e308) == 0, "FMI %d: ag = 1e308 refused: %s", version, last_message);
    n_errors = 0;
    st = do_step(I, 0.0, 0.01);
    if (st == 0 && get_results(I, v) == 0)
        for (k = 0; k < N_RESULTS; k++) finite &= isfinite(v[k]) != 0;
    CHECK(st == 3 || (st == 0 && finite), "FMI %d: the step under ag = 1e308 returned %d with non-finite results", version, st);
    CHECK(st != 3 || (n_errors == 1 && strstr(last_message, "not finite")), "FMI %d: no reason logged: '%s'", version,
          last_message);
    drop(I);
}

/* the same input in Model Exchange: the derivatives the importer would integrate are not finite */
static void test_finite_input_with_non_finite_derivatives_is_an_error(int version)
{
    inst I = make(version, 0);
    double dx[RW_NUMBER_OF_STATES];
    int st;
    to_continuous_time(I);
    CHECK(set_ag(I, 1e308) == 0, "FMI %d: ag = 1e308 refused: %s", version, last_message);
    n_errors = 0;
    st = derivatives(I, dx);
    CHECK(st == 3 || (isfinite(dx[2]) && isfinite(dx[3])), "FMI %d: derivatives %g, %g returned with status %d",
          version, dx[2], dx[3], st);
    CHECK(st != 3 || (n_errors == 1 && strstr(last_message, "not finite")), "FMI %d: no reason logged: '%s'", version,
          last_message);
    drop(I);
}

static double cpu_seconds(void) { return (double)clock() / CLOCKS_PER_SEC; }

/* doStep(0, 1e300) never returned (the Building FMU refused at once): refused, the bound named */
static void test_step_to_1e300_is_refused_with_its_bound(int version)
{
    inst I = make(version, 1);
    const double t0 = cpu_seconds();
    int st;
    n_errors = 0;
    st = do_step(I, 0.0, 1e300);
    CHECK(st == 3 && n_errors == 1 && strstr(last_message, "1e+09"), "FMI %d: doStep(0, 1e300): status %d, log '%s'",
          version, st, last_message);
    CHECK(cpu_seconds() - t0 < 1.0, "FMI %d: the refusal took %.2f s", version, cpu_seconds() - t0);
    drop(I);
}

/* At rest under no input nothing moves: a step of 1e7 s (8.5 s of CPU before) is cheap, leaves
 * the wall as it was, and the run goes on. */
static void test_long_step_at_rest_is_cheap(int version)
{
    inst I = make(version, 1);
    double before[N_RESULTS], after[N_RESULTS];
    double t0;
    int st;
    get_results(I, before);
    t0 = cpu_seconds();
    st = do_step(I, 0.0, 1e7);
    CHECK(st == 0, "FMI %d: doStep(0, 1e7) at rest: status %d (%s)", version, st, last_message);
    CHECK(cpu_seconds() - t0 < 0.5, "FMI %d: a step of 1e7 s at rest took %.2f s of CPU", version, cpu_seconds() - t0);
    get_results(I, after);
    CHECK(memcmp(before, after, sizeof before) == 0, "FMI %d: the wall moved at rest", version);
    CHECK(set_ag(I, 0.5) == 0 && do_step(I, 1e7, 0.01) == 0, "FMI %d: the step after the rest: %s", version, last_message);
    drop(I);
}

/* A wall that never comes to rest (a small elastic vibration, undamped) in one step of 2e4 s: the
 * step is refused once 1e4 s of motion have been walked, the bound in the message, in bounded time. */
static void test_step_of_endless_motion_is_refused_with_its_bound(int version)
{
    inst I = {version, NULL};
    const fmi2ValueReference vr_q1 = RW_VR_q1;
    const double q1 = 0.0005;
    double t0;
    int st;
    if (version == 2) {
        I.c = fmi2Instantiate("edge", fmi2CoSimulation, RW_GUID, "", &CB, fmi2False, fmi2False);
        fmi2SetReal(I.c, &vr_q1, 1, &q1);
        fmi2SetupExperiment(I.c, fmi2False, 0, 0, fmi2False, 0);
        fmi2EnterInitializationMode(I.c);
        fmi2ExitInitializationMode(I.c);
    } else {
        I.c = fmi3InstantiateCoSimulation("edge", RW_GUID, NULL, false, false, false, false, NULL, 0, NULL, logger3, NULL);
        fmi3SetFloat64(I.c, &vr_q1, 1, &q1, 1);
        fmi3EnterInitializationMode(I.c, false, 0, 0, false, 0);
        fmi3ExitInitializationMode(I.c);
    }
    t0 = cpu_seconds();
    n_errors = 0;
    st = do_step(I, 0.0, 2e4);
    printf("  FMI %d: a step of 2e4 s of motion: status %d after %.2f s of CPU\n", version, st, cpu_seconds() - t0);
    CHECK(st == 3 && n_errors == 1 && strstr(last_message, "at most 10000 s of motion"),
          "FMI %d: a step of 2e4 s of endless motion: status %d, log '%s'", version, st, last_message);
    drop(I);
}

/* A serialized state whose GUID field holds bytes that are not text (here: another FMU's, or
 * garbage with our magic number): the message must be printable ASCII, not the raw bytes. */
static void test_deserialize_of_a_wrong_guid_logs_printable_text(int version)
{
    static unsigned char buf[1 << 16];
    inst I = make(version, 0);
    void *st = NULL, *back = NULL;
    size_t n = 0, k;
    int status, printable = 1;
    if (version == 2) {
        fmi2GetFMUstate(I.c, &st);
        fmi2SerializedFMUstateSize(I.c, st, &n);
        fmi2SerializeFMUstate(I.c, st, (fmi2Byte *)buf, n);
    } else {
        fmi3GetFMUState(I.c, &st);
        fmi3SerializedFMUStateSize(I.c, st, &n);
        fmi3SerializeFMUState(I.c, st, buf, n);
    }
    for (k = 8; k < 8 + 64; k++) buf[k] = (unsigned char)(0x80 + k); /* the GUID field: no text */
    n_errors = 0;
    status = version == 2 ? (int)fmi2DeSerializeFMUstate(I.c, (fmi2Byte *)buf, n, &back)
                          : (int)fmi3DeserializeFMUState(I.c, buf, n, &back);
    for (k = 0; last_message[k]; k++) printable &= last_message[k] >= 0x20 && last_message[k] < 0x7f;
    CHECK(status == 3 && n_errors == 1, "FMI %d: a state of another GUID accepted (%d)", version, status);
    CHECK(printable, "FMI %d: the message carries raw bytes: '%s'", version, last_message);
    CHECK(strstr(last_message, "GUID") != NULL, "FMI %d: the message does not say what differs: '%s'", version, last_message);
    if (version == 2) fmi2FreeFMUstate(I.c, &st);
    else fmi3FreeFMUState(I.c, &st);
    drop(I);
}

int main(void)
{
    for (int version = 2; version <= 3; version++) {
        test_finite_input_with_non_finite_step_is_an_error(version);
        test_finite_input_with_non_finite_derivatives_is_an_error(version);
        test_step_to_1e300_is_refused_with_its_bound(version);
        test_long_step_at_rest_is_cheap(version);
        test_step_of_endless_motion_is_refused_with_its_bound(version);
        test_deserialize_of_a_wrong_guid_logs_printable_text(version);
    }
    printf("%d checks, %d failures\n", checks, failures);
    return failures ? 1 : 0;
}
