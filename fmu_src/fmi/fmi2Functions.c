/* The FMI 2.0 API, Model Exchange and Co-Simulation, shared by every model of this repository:
 * the model supplies the callbacks of fmu_model.h (rw_model.c, diaphragm/diaphragm_model.c).
 * No global state: every instance owns its model data.
 *
 * A thin layer: the FMI 2.0 types and signatures, the state machines of sections 3.2.3 and 4.2.4
 * (one mask per function below), the status codes, the importer's logger and memory functions.
 * Everything else (the instance, the checks with their logged reasons, the work of the functions
 * FMI 3.0 has too) is the version-free half, fmu_instance.c and fmu_functions.c, shared with the
 * FMI 3.0 layer fmi3Functions.c.
 *
 * Every function starts with ENTER(name), which checks the instance and the call sequence against
 * the function's mask and records the function's name for the messages, and ends with
 * LEAVE(status), which makes every fmi2Error leave the instance in the error state. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmi2Functions.h"
#include "fmu_instance.h"

/* ---- which calls each state allows ---------------------------------------------------------- */

#define ANY_STATE FMU_ANY_STATE
#define READABLE FMU_READABLE
#define ME_EVENT_OR_CONT (FMU_ME_EVENT | FMU_ME_CONT)
#define SETUP (FMU_ME_INSTANTIATED | FMU_CS_INSTANTIATED)
#define INIT (FMU_ME_INIT | FMU_CS_INIT)
#define ME_AFTER_INIT (FMU_ME_EVENT | FMU_ME_CONT | FMU_ME_TERMINATED | FMU_ME_ERROR)
#define CS_RESULTS (FMU_CS_STEP | FMU_CS_TERMINATED)

#define MASK_fmi2SetDebugLogging ANY_STATE
#define MASK_fmi2SetupExperiment SETUP
#define MASK_fmi2EnterInitializationMode SETUP
#define MASK_fmi2ExitInitializationMode INIT
#define MASK_fmi2Terminate (ME_EVENT_OR_CONT | FMU_CS_STEP)
#define MASK_fmi2Reset ANY_STATE
#define MASK_fmi2GetReal READABLE
#define MASK_fmi2GetInteger READABLE
#define MASK_fmi2GetBoolean READABLE
#define MASK_fmi2GetString READABLE
#define MASK_fmi2SetReal (FMU_WRITABLE & ~FMU_CS_EVENT)
#define MASK_fmi2SetInteger (SETUP | INIT | FMU_ME_EVENT | FMU_CS_STEP)
#define MASK_fmi2SetBoolean MASK_fmi2SetInteger
#define MASK_fmi2SetString MASK_fmi2SetInteger
#define MASK_fmi2GetFMUstate ANY_STATE
#define MASK_fmi2SetFMUstate ANY_STATE
#define MASK_fmi2FreeFMUstate ANY_STATE
#define MASK_fmi2SerializedFMUstateSize ANY_STATE
#define MASK_fmi2SerializeFMUstate ANY_STATE
#define MASK_fmi2DeSerializeFMUstate ANY_STATE
#define MASK_fmi2GetDirectionalDerivative ANY_STATE
/* Model Exchange only */
#define MASK_fmi2EnterEventMode ME_EVENT_OR_CONT
#define MASK_fmi2NewDiscreteStates FMU_ME_EVENT
#define MASK_fmi2EnterContinuousTimeMode FMU_ME_EVENT
#define MASK_fmi2CompletedIntegratorStep FMU_ME_CONT
#define MASK_fmi2SetTime ME_EVENT_OR_CONT
#define MASK_fmi2SetContinuousStates FMU_ME_CONT
#define MASK_fmi2GetDerivatives ME_AFTER_INIT
#define MASK_fmi2GetEventIndicators (FMU_ME_INIT | ME_AFTER_INIT)
#define MASK_fmi2GetContinuousStates (FMU_ME_INIT | ME_AFTER_INIT)
#define MASK_fmi2GetNominalsOfContinuousStates (FMU_ME_INSTANTIATED | ME_AFTER_INIT)
/* Co-Simulation only */
#define MASK_fmi2SetRealInputDerivatives (FMU_CS_INSTANTIATED | FMU_CS_INIT | FMU_CS_STEP)
#define MASK_fmi2GetRealOutputDerivatives FMU_CS_ANY
#define MASK_fmi2DoStep FMU_CS_STEP
#define MASK_fmi2CancelStep FMU_CS_ANY
#define MASK_fmi2GetStatus CS_RESULTS
#define MASK_fmi2GetRealStatus CS_RESULTS
#define MASK_fmi2GetIntegerStatus FMU_CS_ANY
#define MASK_fmi2GetBooleanStatus CS_RESULTS
#define MASK_fmi2GetStringStatus CS_RESULTS

/* ---- the instance: the version-free one and the importer's logger --------------------------- */

typedef struct {
    fmu_instance base; /* first: an Inst is an fmu_instance */
    fmi2CallbackLogger logger;
    fmi2ComponentEnvironment env;
} Inst;

static const fmi2Status STATUS[] = {fmi2OK, fmi2Warning, fmi2Discard, fmi2Error, fmi2Fatal};
#define API_STATUS(s) STATUS[s]

static void emit(fmu_instance *I, fmu_status status, const char *category, const char *message)
{
    Inst *S = (Inst *)I;
    S->logger(S->env, I->name, STATUS[status], category, message);
}

static const fmu_api FMI2 = {
    .prefix = "fmi2",
    .state_names = {"instantiated", "initializationMode", "eventMode", "continuousTimeMode", "terminated", "error",
                    "instantiated", "initializationMode", "eventMode", "stepComplete", "terminated", "error"},
    .type_names = {"Real", "Integer", "Boolean"},
    .vr_argument = "vr",
    .values_argument = "value",
    .nx_argument = "nx",
    .nz_argument = "ni",
    .fmu_state = "FMUstate",
    .emit = emit,
};

/* ---- inquiry, instantiation ---------------------------------------------------------------- */

const char *fmi2GetTypesPlatform(void) { return fmi2TypesPlatform; }
const char *fmi2GetVersion(void) { return fmi2Version; }

/* the arguments of fmi2Instantiate, checked before there is an instance to log through */
static int instantiate_arguments_ok(fmi2String instanceName, fmi2Type fmuType, fmi2String fmuGUID,
                                    const fmi2CallbackFunctions *f)
{
    char msg[512];
    if (fmuType != fmi2ModelExchange && fmuType != fmi2CoSimulation && instanceName && *instanceName)
        snprintf(msg, sizeof msg, "fmi2Instantiate: fmuType must be fmi2ModelExchange or fmi2CoSimulation");
    else if (!fmu_instantiate_arguments("fmi2Instantiate", instanceName, "GUID", fmuGUID, msg, sizeof msg))
        return 1;
    f->logger(f->componentEnvironment, instanceName ? instanceName : "?", fmi2Error, "logStatusError", msg);
    return 0;
}

fmi2Component fmi2Instantiate(fmi2String instanceName, fmi2Type fmuType, fmi2String fmuGUID,
                              fmi2String fmuResourceLocation, const fmi2CallbackFunctions *functions,
                              fmi2Boolean visible, fmi2Boolean loggingOn)
{
    /* the importer's memory functions only as a pair */
    const int own_memory = functions && functions->allocateMemory && functions->freeMemory;
    void *(*const alloc)(size_t, size_t) = own_memory ? functions->allocateMemory : calloc;
    Inst *S;
    (void)fmuResourceLocation; /* the FMUs have no resources */
    (void)visible;
    if (!functions || !functions->logger) return NULL;
    if (!instantiate_arguments_ok(instanceName, fmuType, fmuGUID, functions)) return NULL;
    S = (Inst *)alloc(1, sizeof(Inst));
    if (!S) return NULL;
    memset(S, 0, sizeof *S);
    S->logger = functions->logger;
    S->env = functions->componentEnvironment;
    S->base.api = &FMI2;
    S->base.alloc = alloc;
    S->base.release = own_memory ? functions->freeMemory : free;
    if (fmu_instance_init(&S->base, instanceName, fmuType == fmi2CoSimulation, loggingOn)) {
        fmu_instance_free(&S->base);
        return NULL;
    }
    fmu_log_event(&S->base, "fmi2Instantiate: %s instance created",
                  fmuType == fmi2CoSimulation ? "Co-Simulation" : "Model Exchange");
    return S;
}

void fmi2FreeInstance(fmi2Component instance)
{
    if (instance) fmu_instance_free((fmu_instance *)instance);
}

fmi2Status fmi2SetDebugLogging(fmi2Component instance, fmi2Boolean loggingOn, size_t nCategories,
                               const fmi2String categories[])
{
    ENTER(fmi2SetDebugLogging);
    LEAVE(fmu_set_debug_logging(S, loggingOn, nCategories, categories));
}

/* ---- initialization, termination, reset ---------------------------------------------------- */

fmi2Status fmi2SetupExperiment(fmi2Component instance, fmi2Boolean toleranceDefined, fmi2Real tolerance,
                               fmi2Real startTime, fmi2Boolean stopTimeDefined, fmi2Real stopTime)
{
    ENTER(fmi2SetupExperiment);
    (void)stopTimeDefined;
    (void)stopTime;
    LEAVE(fmu_setup(S, toleranceDefined, tolerance, startTime));
}

fmi2Status fmi2EnterInitializationMode(fmi2Component instance)
{
    ENTER(fmi2EnterInitializationMode);
    S->state = S->core.co_simulation ? FMU_CS_INIT : FMU_ME_INIT;
    LEAVE(FMU_OK);
}

fmi2Status fmi2ExitInitializationMode(fmi2Component instance)
{
    ENTER(fmi2ExitInitializationMode);
    LEAVE(fmu_exit_init(S));
}

fmi2Status fmi2Terminate(fmi2Component instance)
{
    ENTER(fmi2Terminate);
    fmu_terminate(S);
    LEAVE(FMU_OK);
}

fmi2Status fmi2Reset(fmi2Component instance)
{
    ENTER(fmi2Reset);
    fmu_reset(S);
    LEAVE(FMU_OK);
}

/* ---- getters and setters ------------------------------------------------------------------- */

fmi2Status fmi2GetReal(fmi2Component instance, const fmi2ValueReference vr[], size_t nvr, fmi2Real value[])
{
    ENTER(fmi2GetReal);
    REQUIRE_OK(fmu_check_vrs(S, vr, nvr, value, FMU_REAL));
    fmu_get_reals(S, vr, nvr, value);
    LEAVE(FMU_OK);
}

fmi2Status fmi2GetInteger(fmi2Component instance, const fmi2ValueReference vr[], size_t nvr, fmi2Integer value[])
{
    size_t i;
    ENTER(fmi2GetInteger);
    REQUIRE_OK(fmu_check_vrs(S, vr, nvr, value, FMU_INTEGER));
    for (i = 0; i < nvr; i++) value[i] = fmu_get_integer(S, vr[i]);
    LEAVE(FMU_OK);
}

fmi2Status fmi2GetBoolean(fmi2Component instance, const fmi2ValueReference vr[], size_t nvr, fmi2Boolean value[])
{
    size_t i;
    ENTER(fmi2GetBoolean);
    REQUIRE_OK(fmu_check_vrs(S, vr, nvr, value, FMU_BOOLEAN));
    for (i = 0; i < nvr; i++) value[i] = fmu_get_boolean(S, vr[i]) ? fmi2True : fmi2False;
    LEAVE(FMU_OK);
}

fmi2Status fmi2GetString(fmi2Component instance, const fmi2ValueReference vr[], size_t nvr, fmi2String value[])
{
    ENTER(fmi2GetString);
    (void)value;
    LEAVE(fmu_no_such_type(S, "String", vr, nvr));
}

fmi2Status fmi2SetReal(fmi2Component instance, const fmi2ValueReference vr[], size_t nvr, const fmi2Real value[])
{
    size_t i;
    ENTER(fmi2SetReal);
    REQUIRE_OK(fmu_check_vrs(S, vr, nvr, value, FMU_REAL));
    for (i = 0; i < nvr; i++) REQUIRE_OK(fmu_set_real(S, vr[i], value[i]));
    LEAVE(FMU_OK);
}

fmi2Status fmi2SetInteger(fmi2Component instance, const fmi2ValueReference vr[], size_t nvr, const fmi2Integer value[])
{
    size_t i;
    ENTER(fmi2SetInteger);
    REQUIRE_OK(fmu_check_vrs(S, vr, nvr, value, FMU_INTEGER));
    for (i = 0; i < nvr; i++) REQUIRE_OK(fmu_set_integer(S, vr[i], value[i]));
    LEAVE(FMU_OK);
}

fmi2Status fmi2SetBoolean(fmi2Component instance, const fmi2ValueReference vr[], size_t nvr, const fmi2Boolean value[])
{
    size_t i;
    ENTER(fmi2SetBoolean);
    REQUIRE_OK(fmu_check_vrs(S, vr, nvr, value, FMU_BOOLEAN));
    for (i = 0; i < nvr; i++) REQUIRE_OK(fmu_set_boolean(S, vr[i]));
    LEAVE(FMU_OK);
}

fmi2Status fmi2SetString(fmi2Component instance, const fmi2ValueReference vr[], size_t nvr, const fmi2String value[])
{
    ENTER(fmi2SetString);
    (void)value;
    LEAVE(fmu_no_such_type(S, "String", vr, nvr));
}

/* ---- FMU state (canGetAndSetFMUstate, canSerializeFMUstate) -------------------------------- */

fmi2Status fmi2GetFMUstate(fmi2Component instance, fmi2FMUstate *FMUstate)
{
    ENTER(fmi2GetFMUstate);
    LEAVE(fmu_get_fmu_state(S, FMUstate));
}

fmi2Status fmi2SetFMUstate(fmi2Component instance, fmi2FMUstate FMUstate)
{
    ENTER(fmi2SetFMUstate);
    LEAVE(fmu_set_fmu_state(S, FMUstate));
}

fmi2Status fmi2FreeFMUstate(fmi2Component instance, fmi2FMUstate *FMUstate)
{
    ENTER(fmi2FreeFMUstate);
    LEAVE(fmu_free_fmu_state(S, FMUstate));
}

fmi2Status fmi2SerializedFMUstateSize(fmi2Component instance, fmi2FMUstate FMUstate, size_t *size)
{
    ENTER(fmi2SerializedFMUstateSize);
    LEAVE(fmu_serialized_size(S, FMUstate, size));
}

fmi2Status fmi2SerializeFMUstate(fmi2Component instance, fmi2FMUstate FMUstate, fmi2Byte serializedState[], size_t size)
{
    ENTER(fmi2SerializeFMUstate);
    LEAVE(fmu_serialize(S, FMUstate, serializedState, size));
}

fmi2Status fmi2DeSerializeFMUstate(fmi2Component instance, const fmi2Byte serializedState[], size_t size,
                                   fmi2FMUstate *FMUstate)
{
    ENTER(fmi2DeSerializeFMUstate);
    LEAVE(fmu_deserialize(S, serializedState, size, FMUstate));
}

/* ---- directional derivatives: not supported ------------------------------------------------ */

fmi2Status fmi2GetDirectionalDerivative(fmi2Component instance, const fmi2ValueReference u[], size_t nu,
                                        const fmi2ValueReference z[], size_t nz, const fmi2Real dv[], fmi2Real dz[])
{
    ENTER(fmi2GetDirectionalDerivative);
    (void)u; (void)nu; (void)z; (void)nz; (void)dv; (void)dz;
    LEAVE(fmu_fail(S, "not supported by this FMU (providesDirectionalDerivative is false)"));
}

/* ---- Model Exchange ------------------------------------------------------------------------ */

fmi2Status fmi2EnterEventMode(fmi2Component instance)
{
    ENTER(fmi2EnterEventMode);
    LEAVE(fmu_enter_event_mode(S));
}

fmi2Status fmi2NewDiscreteStates(fmi2Component instance, fmi2EventInfo *info)
{
    fmu_event_result r;
    ENTER(fmi2NewDiscreteStates);
    REQUIRE_NOT_NULL(info);
    REQUIRE_OK(fmu_update_discrete_states(S, &r));
    info->newDiscreteStatesNeeded = r.more ? fmi2True : fmi2False;
    info->terminateSimulation = r.terminate ? fmi2True : fmi2False;
    info->nominalsOfContinuousStatesChanged = fmi2False; /* the nominals are constants */
    info->valuesOfContinuousStatesChanged = r.states_changed ? fmi2True : fmi2False;
    info->nextEventTimeDefined = r.next_time_defined ? fmi2True : fmi2False;
    info->nextEventTime = r.next_time_defined ? r.next_time : 0.0;
    LEAVE(FMU_OK);
}

fmi2Status fmi2EnterContinuousTimeMode(fmi2Component instance)
{
    ENTER(fmi2EnterContinuousTimeMode);
    fmu_leave_event_mode(S);
    LEAVE(FMU_OK);
}

fmi2Status fmi2CompletedIntegratorStep(fmi2Component instance, fmi2Boolean noSetFMUStatePriorToCurrentPoint,
                                       fmi2Boolean *enterEventMode, fmi2Boolean *terminateSimulation)
{
    ENTER(fmi2CompletedIntegratorStep);
    (void)noSetFMUStatePriorToCurrentPoint;
    REQUIRE_NOT_NULL(enterEventMode);
    REQUIRE_NOT_NULL(terminateSimulation);
    *enterEventMode = fmi2False;
    *terminateSimulation = fmi2False;
    LEAVE(FMU_OK);
}

fmi2Status fmi2SetTime(fmi2Component instance, fmi2Real time)
{
    ENTER(fmi2SetTime);
    LEAVE(fmu_set_time(S, time));
}

fmi2Status fmi2SetContinuousStates(fmi2Component instance, const fmi2Real x[], size_t nx)
{
    ENTER(fmi2SetContinuousStates);
    REQUIRE_NOT_NULL(x);
    LEAVE(fmu_set_states(S, x, nx));
}

fmi2Status fmi2GetDerivatives(fmi2Component instance, fmi2Real dx[], size_t nx)
{
    ENTER(fmi2GetDerivatives);
    REQUIRE_NOT_NULL(dx);
    LEAVE(fmu_get_derivatives(S, dx, nx));
}

fmi2Status fmi2GetEventIndicators(fmi2Component instance, fmi2Real z[], size_t ni)
{
    ENTER(fmi2GetEventIndicators);
    REQUIRE(z || ni == 0, "argument z must not be NULL");
    LEAVE(fmu_get_event_indicators(S, z, ni));
}

fmi2Status fmi2GetContinuousStates(fmi2Component instance, fmi2Real x[], size_t nx)
{
    ENTER(fmi2GetContinuousStates);
    REQUIRE_NOT_NULL(x);
    LEAVE(fmu_get_states(S, x, nx));
}

fmi2Status fmi2GetNominalsOfContinuousStates(fmi2Component instance, fmi2Real x_nominal[], size_t nx)
{
    ENTER(fmi2GetNominalsOfContinuousStates);
    REQUIRE_NOT_NULL(x_nominal);
    LEAVE(fmu_get_nominals(S, x_nominal, nx));
}

/* ---- Co-Simulation ------------------------------------------------------------------------- */

/* First derivatives of Real inputs ramp them over the next step (canInterpolateInputs). */
fmi2Status fmi2SetRealInputDerivatives(fmi2Component instance, const fmi2ValueReference vr[], size_t nvr,
                                       const fmi2Integer order[], const fmi2Real value[])
{
    size_t i;
    ENTER(fmi2SetRealInputDerivatives);
    if (nvr == 0) LEAVE(FMU_OK);
    REQUIRE_NOT_NULL(order);
    REQUIRE_OK(fmu_check_vrs(S, vr, nvr, value, FMU_REAL));
    for (i = 0; i < nvr; i++) {
        const fmu_var *v = fmu_find_var(&S->core.model, vr[i]);
        cs_input *in = fmu_core_find_input(&S->core, vr[i]);
        REQUIRE(in != NULL, "%s is not an input", v->name);
        REQUIRE(order[i] == 1, "order %d of %s (only first derivatives are used, maxInputDerivativeOrder would be exceeded)",
                (int)order[i], v->name);
        REQUIRE(isfinite(value[i]), "der(%s) = %g is not a finite number", v->name, value[i]);
        in->slope = value[i];
    }
    LEAVE(FMU_OK);
}

fmi2Status fmi2GetRealOutputDerivatives(fmi2Component instance, const fmi2ValueReference vr[], size_t nvr,
                                        const fmi2Integer order[], fmi2Real value[])
{
    ENTER(fmi2GetRealOutputDerivatives);
    (void)vr; (void)nvr; (void)order; (void)value;
    LEAVE(fmu_fail(S, "not supported by this FMU (maxOutputDerivativeOrder is 0)"));
}

/* A step in which the model ends the run is fmi2Discard (fmi2GetBooleanStatus: fmi2Terminated). */
fmi2Status fmi2DoStep(fmi2Component instance, fmi2Real currentCommunicationPoint, fmi2Real communicationStepSize,
                      fmi2Boolean noSetFMUStatePriorToCurrentCommunicationPoint)
{
    int ended;
    fmu_status st;
    ENTER(fmi2DoStep);
    (void)noSetFMUStatePriorToCurrentCommunicationPoint;
    st = fmu_do_step(S, currentCommunicationPoint, communicationStepSize, &ended);
    LEAVE(st == FMU_OK && ended ? FMU_DISCARD : st);
}

fmi2Status fmi2CancelStep(fmi2Component instance)
{
    ENTER(fmi2CancelStep);
    LEAVE(fmu_fail(S, "not supported (fmi2DoStep never returns fmi2Pending)"));
}

fmi2Status fmi2GetStatus(fmi2Component instance, const fmi2StatusKind s, fmi2Status *v)
{
    ENTER(fmi2GetStatus);
    REQUIRE_NOT_NULL(v);
    REQUIRE(s == fmi2DoStepStatus, "status kind %d is not a fmi2Status", (int)s);
    *v = S->core.terminated ? fmi2Discard : fmi2OK; /* steps are synchronous: never pending */
    LEAVE(FMU_OK);
}

fmi2Status fmi2GetRealStatus(fmi2Component instance, const fmi2StatusKind s, fmi2Real *v)
{
    ENTER(fmi2GetRealStatus);
    REQUIRE_NOT_NULL(v);
    REQUIRE(s == fmi2LastSuccessfulTime, "status kind %d is not a Real", (int)s);
    *v = S->core.last_successful_time;
    LEAVE(FMU_OK);
}

fmi2Status fmi2GetIntegerStatus(fmi2Component instance, const fmi2StatusKind s, fmi2Integer *v)
{
    ENTER(fmi2GetIntegerStatus);
    (void)s; (void)v;
    LEAVE(fmu_fail(S, "not supported (no Integer status kinds in FMI 2.0)"));
}

fmi2Status fmi2GetBooleanStatus(fmi2Component instance, const fmi2StatusKind s, fmi2Boolean *v)
{
    ENTER(fmi2GetBooleanStatus);
    REQUIRE_NOT_NULL(v);
    REQUIRE(s == fmi2Terminated, "status kind %d is not a Boolean", (int)s);
    *v = S->core.terminated ? fmi2True : fmi2False;
    LEAVE(FMU_OK);
}

fmi2Status fmi2GetStringStatus(fmi2Component instance, const fmi2StatusKind s, fmi2String *v)
{
    ENTER(fmi2GetStringStatus);
    REQUIRE_NOT_NULL(v);
    REQUIRE(s == fmi2PendingStatus, "status kind %d is not a String", (int)s);
    *v = "";
    LEAVE(FMU_OK);
}
