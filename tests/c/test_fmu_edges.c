/* RockingWall's edges, through both FMI layers (fmi2Functions.c and fmi3Functions.c linked
 * statically), each a finding measured on the code and named here:
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
    for (int version = 2; version <= 3; version++) test_deserialize_of_a_wrong_guid_logs_printable_text(version);
    printf("%d checks, %d failures\n", checks, failures);
    return failures ? 1 : 0;
}
