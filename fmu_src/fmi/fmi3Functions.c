/* The FMI 3.0 API, Model Exchange and Co-Simulation, over the same model callbacks (fmu_model.h)
 * and the same version-free half (fmu_instance.c, fmu_functions.c: the instance, the checks with
 * their logged reasons, the work of the functions FMI 2.0 has too) as the FMI 2.0 layer
 * fmi2Functions.c. No physics here, no global state.
 *
 * A thin layer: the FMI 3.0 types and signatures, the state machines of sections 3.2 and 4.2 (one
 * mask per function below), the status codes and the importer's logger. As in the FMI 2.0 layer,
 * every function starts with ENTER(name), which checks the instance and the call sequence against
 * the function's mask and records the function's name for the messages, and ends with
 * LEAVE(status), which makes every fmi3Error leave the instance in the error state.
 *
 * What FMI 3.0 adds over the model's table: the independent variable `time` (value reference
 * FMU_TIME_VR) and the event indicators as Float64 variables (fmu_model.z_vrs). The model has
 * no variables of the other FMI 3.0 types, no clocks and no structural parameters: those
 * functions fail with the reason logged. Memory: FMI 3.0 has no memory callbacks (calloc, free). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmi3Functions.h"
#include "fmu_instance.h"

/* ---- which calls each state allows ---------------------------------------------------------- */

#define ANY_STATE FMU_ANY_STATE
#define READABLE FMU_READABLE
#define WRITABLE FMU_WRITABLE
#define EVENT (FMU_ME_EVENT | FMU_CS_EVENT)
#define ME_AFTER_INIT (FMU_ME_EVENT | FMU_ME_CONT | FMU_ME_TERMINATED | FMU_ME_ERROR)

#define MASK_fmi3SetDebugLogging ANY_STATE
#define MASK_fmi3EnterInitializationMode (FMU_ME_INSTANTIATED | FMU_CS_INSTANTIATED)
#define MASK_fmi3ExitInitializationMode (FMU_ME_INIT | FMU_CS_INIT)
#define MASK_fmi3EnterEventMode (FMU_ME_EVENT | FMU_ME_CONT | FMU_CS_STEP)
#define MASK_fmi3Terminate (FMU_ME_EVENT | FMU_ME_CONT | FMU_CS_EVENT | FMU_CS_STEP)
#define MASK_fmi3Reset ANY_STATE
#define MASK_fmi3GetFloat64 READABLE
#define MASK_fmi3GetInt32 READABLE
#define MASK_fmi3GetBoolean READABLE
#define MASK_fmi3GetOtherType READABLE
#define MASK_fmi3SetFloat64 WRITABLE
#define MASK_fmi3SetInt32 WRITABLE
#define MASK_fmi3SetBoolean WRITABLE
#define MASK_fmi3SetOtherType WRITABLE
#define MASK_fmi3Unsupported ANY_STATE
#define MASK_fmi3GetFMUState ANY_STATE
#define MASK_fmi3SetFMUState ANY_STATE
#define MASK_fmi3FreeFMUState ANY_STATE
#define MASK_fmi3SerializedFMUStateSize ANY_STATE
#define MASK_fmi3SerializeFMUState ANY_STATE
#define MASK_fmi3DeserializeFMUState ANY_STATE
#define MASK_fmi3EvaluateDiscreteStates EVENT
#define MASK_fmi3UpdateDiscreteStates EVENT
#define MASK_fmi3GetNumberOfEventIndicators ANY_STATE
#define MASK_fmi3GetNumberOfContinuousStates ANY_STATE
/* Model Exchange only */
#define MASK_fmi3EnterContinuousTimeMode FMU_ME_EVENT
#define MASK_fmi3CompletedIntegratorStep FMU_ME_CONT
#define MASK_fmi3SetTime (FMU_ME_EVENT | FMU_ME_CONT)
#define MASK_fmi3SetContinuousStates FMU_ME_CONT
#define MASK_fmi3GetContinuousStateDerivatives ME_AFTER_INIT
#define MASK_fmi3GetEventIndicators (FMU_ME_INIT | ME_AFTER_INIT)
#define MASK_fmi3GetContinuousStates (FMU_ME_INIT | ME_AFTER_INIT)
#define MASK_fmi3GetNominalsOfContinuousStates (FMU_ME_INSTANTIATED | ME_AFTER_INIT)
/* Co-Simulation only */
#define MASK_fmi3EnterStepMode FMU_CS_EVENT
#define MASK_fmi3GetOutputDerivatives (FMU_CS_STEP | FMU_CS_TERMINATED | FMU_CS_ERROR)
#define MASK_fmi3DoStep FMU_CS_STEP

/* ---- the instance: the version-free one and the importer's logger --------------------------- */

typedef struct {
    fmu_instance base; /* first: an Inst is an fmu_instance */
    fmi3LogMessageCallback logger;
    fmi3InstanceEnvironment env;
} Inst;

static const fmi3Status STATUS[] = {fmi3OK, fmi3Warning, fmi3Discard, fmi3Error, fmi3Fatal};
#define API_STATUS(s) STATUS[s]

static void emit(fmu_instance *I, fmu_status status, const char *category, const char *message)
{
    Inst *S = (Inst *)I;
    S->logger(S->env, STATUS[status], category, message);
}

static const fmu_api FMI3 = {
    .prefix = "fmi3",
    .state_names = {"Instantiated", "InitializationMode", "EventMode", "ContinuousTimeMode", "Terminated", "error",
                    "Instantiated", "InitializationMode", "EventMode", "StepMode", "Terminated", "error"},
    .type_names = {"Float64", "Int32", "Boolean"},
    .vr_argument = "valueReferences",
    .values_argument = "values",
    .nx_argument = "nContinuousStates",
    .nz_argument = "nEventIndicators",
    .fmu_state = "FMUState",
    .name_in_message = 1,
    .time_and_indicators_are_variables = 1,
    .emit = emit,
};

/* ---- inquiry, instantiation ---------------------------------------------------------------- */

const char *fmi3GetVersion(void) { return fmi3Version; }

static Inst *instantiate(fmi3String name, fmi3String token, int co_simulation, fmi3Boolean loggingOn,
                         fmi3InstanceEnvironment env, fmi3LogMessageCallback logger)
{
    char msg[512], named[600];
    Inst *S;
    if (!logger) return NULL; /* nothing to report through */
    if (fmu_instantiate_arguments("fmi3Instantiate", name, "instantiationToken", token, msg, sizeof msg)) {
        snprintf(named, sizeof named, "%s%s%s", name && *name ? name : "", name && *name ? ": " : "", msg);
        logger(env, fmi3Error, "logStatusError", named);
        return NULL;
    }
    S = (Inst *)calloc(1, sizeof(Inst));
    if (!S) return NULL;
    S->logger = logger;
    S->env = env;
    S->base.api = &FMI3;
    S->base.alloc = calloc;
    S->base.release = free;
    if (fmu_instance_init(&S->base, name, co_simulation, loggingOn)) {
        fmu_instance_free(&S->base);
        return NULL;
    }
    fmu_log_event(&S->base, "%s instance created", co_simulation ? "Co-Simulation" : "Model Exchange");
    return S;
}

fmi3Instance fmi3InstantiateModelExchange(fmi3String instanceName, fmi3String instantiationToken,
                                          fmi3String resourcePath, fmi3Boolean visible, fmi3Boolean loggingOn,
                                          fmi3InstanceEnvironment instanceEnvironment, fmi3LogMessageCallback logMessage)
{
    (void)resourcePath; /* the FMUs have no resources */
    (void)visible;
    return instantiate(instanceName, instantiationToken, 0, loggingOn, instanceEnvironment, logMessage);
}

fmi3Instance fmi3InstantiateCoSimulation(fmi3String instanceName, fmi3String instantiationToken,
                                         fmi3String resourcePath, fmi3Boolean visible, fmi3Boolean loggingOn,
                                         fmi3Boolean eventModeUsed, fmi3Boolean earlyReturnAllowed,
                                         const fmi3ValueReference requiredIntermediateVariables[],
                                         size_t nRequiredIntermediateVariables,
                                         fmi3InstanceEnvironment instanceEnvironment, fmi3LogMessageCallback logMessage,
                                         fmi3IntermediateUpdateCallback intermediateUpdate)
{
    Inst *S;
    (void)resourcePath;
    (void)visible;
    (void)earlyReturnAllowed; /* steps never return early */
    (void)requiredIntermediateVariables; /* providesIntermediateUpdate is false */
    (void)nRequiredIntermediateVariables;
    (void)intermediateUpdate;
    S = instantiate(instanceName, instantiationToken, 1, loggingOn, instanceEnvironment, logMessage);
    if (S) S->base.event_mode_used = eventModeUsed ? 1 : 0;
    return S;
}

fmi3Instance fmi3InstantiateScheduledExecution(fmi3String instanceName, fmi3String instantiationToken,
                                               fmi3String resourcePath, fmi3Boolean visible, fmi3Boolean loggingOn,
                                               fmi3InstanceEnvironment instanceEnvironment,
                                               fmi3LogMessageCallback logMessage, fmi3ClockUpdateCallback clockUpdate,
                                               fmi3LockPreemptionCallback lockPreemption,
                                               fmi3UnlockPreemptionCallback unlockPreemption)
{
    (void)resourcePath; (void)visible; (void)loggingOn; (void)clockUpdate; (void)lockPreemption; (void)unlockPreemption;
    if (logMessage)
        logMessage(instanceEnvironment, fmi3Error, "logStatusError",
                   "fmi3InstantiateScheduledExecution: this FMU does not offer Scheduled Execution");
    (void)instanceName;
    (void)instantiationToken;
    return NULL;
}

void fmi3FreeInstance(fmi3Instance instance)
{
    if (instance) fmu_instance_free((fmu_instance *)instance);
}

fmi3Status fmi3SetDebugLogging(fmi3Instance instance, fmi3Boolean loggingOn, size_t nCategories,
                               const fmi3String categories[])
{
    ENTER(fmi3SetDebugLogging);
    LEAVE(fmu_set_debug_logging(S, loggingOn, nCategories, categories));
}

/* ---- initialization, termination, reset ---------------------------------------------------- */

fmi3Status fmi3EnterInitializationMode(fmi3Instance instance, fmi3Boolean toleranceDefined, fmi3Float64 tolerance,
                                       fmi3Float64 startTime, fmi3Boolean stopTimeDefined, fmi3Float64 stopTime)
{
    ENTER(fmi3EnterInitializationMode);
    (void)stopTimeDefined;
    (void)stopTime;
    REQUIRE_OK(fmu_setup(S, toleranceDefined, tolerance, startTime));
    S->state = S->core.co_simulation ? FMU_CS_INIT : FMU_ME_INIT;
    LEAVE(FMU_OK);
}

/* FMI 3.0: Model Exchange leaves initialization into Event Mode, Co-Simulation into Step Mode (or
 * Event Mode with eventModeUsed) */
fmi3Status fmi3ExitInitializationMode(fmi3Instance instance)
{
    ENTER(fmi3ExitInitializationMode);
    LEAVE(fmu_exit_init(S));
}

fmi3Status fmi3EnterEventMode(fmi3Instance instance)
{
    ENTER(fmi3EnterEventMode);
    LEAVE(fmu_enter_event_mode(S));
}

fmi3Status fmi3Terminate(fmi3Instance instance)
{
    ENTER(fmi3Terminate);
    fmu_terminate(S);
    LEAVE(FMU_OK);
}

fmi3Status fmi3Reset(fmi3Instance instance)
{
    ENTER(fmi3Reset);
    fmu_reset(S);
    LEAVE(FMU_OK);
}

/* ---- getters and setters ------------------------------------------------------------------- */

/* the checks of a getter or setter of scalars: every variable of this FMU is a scalar */
static fmu_status scalars(fmu_instance *S, const fmi3ValueReference vr[], size_t nvr, const void *values,
                          size_t nValues, fmu_type type)
{
    if (nvr == 0 && nValues == 0) return FMU_OK;
    if (!vr) return fmu_fail(S, "argument valueReferences must not be NULL");
    if (!values) return fmu_fail(S, "argument values must not be NULL");
    if (nValues != nvr)
        return fmu_fail(S, "nValues = %u, expected %u (every variable of this FMU is a scalar)", (unsigned)nValues,
                        (unsigned)nvr);
    return fmu_check_vrs(S, vr, nvr, values, type);
}

fmi3Status fmi3GetFloat64(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences,
                          fmi3Float64 values[], size_t nValues)
{
    ENTER(fmi3GetFloat64);
    REQUIRE_OK(scalars(S, valueReferences, nValueReferences, values, nValues, FMU_REAL));
    fmu_get_reals(S, valueReferences, nValueReferences, values);
    LEAVE(FMU_OK);
}

fmi3Status fmi3GetInt32(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences,
                        fmi3Int32 values[], size_t nValues)
{
    size_t i;
    ENTER(fmi3GetInt32);
    REQUIRE_OK(scalars(S, valueReferences, nValueReferences, values, nValues, FMU_INTEGER));
    for (i = 0; i < nValueReferences; i++) values[i] = (fmi3Int32)fmu_get_integer(S, valueReferences[i]);
    LEAVE(FMU_OK);
}

fmi3Status fmi3GetBoolean(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences,
                          fmi3Boolean values[], size_t nValues)
{
    size_t i;
    ENTER(fmi3GetBoolean);
    REQUIRE_OK(scalars(S, valueReferences, nValueReferences, values, nValues, FMU_BOOLEAN));
    for (i = 0; i < nValueReferences; i++) values[i] = fmu_get_boolean(S, valueReferences[i]) != 0;
    LEAVE(FMU_OK);
}

fmi3Status fmi3SetFloat64(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences,
                          const fmi3Float64 values[], size_t nValues)
{
    size_t i;
    ENTER(fmi3SetFloat64);
    REQUIRE_OK(scalars(S, valueReferences, nValueReferences, values, nValues, FMU_REAL));
    for (i = 0; i < nValueReferences; i++) REQUIRE_OK(fmu_set_real(S, valueReferences[i], values[i]));
    LEAVE(FMU_OK);
}

fmi3Status fmi3SetInt32(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences,
                        const fmi3Int32 values[], size_t nValues)
{
    size_t i;
    ENTER(fmi3SetInt32);
    REQUIRE_OK(scalars(S, valueReferences, nValueReferences, values, nValues, FMU_INTEGER));
    for (i = 0; i < nValueReferences; i++) REQUIRE_OK(fmu_set_integer(S, valueReferences[i], (int)values[i]));
    LEAVE(FMU_OK);
}

fmi3Status fmi3SetBoolean(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences,
                          const fmi3Boolean values[], size_t nValues)
{
    size_t i;
    ENTER(fmi3SetBoolean);
    REQUIRE_OK(scalars(S, valueReferences, nValueReferences, values, nValues, FMU_BOOLEAN));
    for (i = 0; i < nValueReferences; i++) REQUIRE_OK(fmu_set_boolean(S, valueReferences[i]));
    LEAVE(FMU_OK);
}

/* ---- the types, clocks and features the models do not have -------------------------------- */

/* A getter or setter of a type no variable of this FMU has: every value reference is unknown for
 * it (or of another type): fmu_no_such_type says why. */
#define NO_SUCH_GETTER(T, CT)                                                                                    \
    fmi3Status fmi3Get##T(fmi3Instance instance, const fmi3ValueReference valueReferences[],                  \
                          size_t nValueReferences, CT values[], size_t nValues)                                 \
    {                                                                                                            \
        ENTER_AS("fmi3Get" #T, MASK_fmi3GetOtherType);                                                           \
        (void)values; (void)nValues;                                                                             \
        LEAVE(fmu_no_such_type(S, #T, valueReferences, nValueReferences));                                           \
    }
#define NO_SUCH_SETTER(T, CT)                                                                                    \
    fmi3Status fmi3Set##T(fmi3Instance instance, const fmi3ValueReference valueReferences[],                  \
                          size_t nValueReferences, const CT values[], size_t nValues)                           \
    {                                                                                                            \
        ENTER_AS("fmi3Set" #T, MASK_fmi3SetOtherType);                                                           \
        (void)values; (void)nValues;                                                                             \
        LEAVE(fmu_no_such_type(S, #T, valueReferences, nValueReferences));                                           \
    }
NO_SUCH_GETTER(Float32, fmi3Float32)
NO_SUCH_GETTER(Int8, fmi3Int8)
NO_SUCH_GETTER(UInt8, fmi3UInt8)
NO_SUCH_GETTER(Int16, fmi3Int16)
NO_SUCH_GETTER(UInt16, fmi3UInt16)
NO_SUCH_GETTER(UInt32, fmi3UInt32)
NO_SUCH_GETTER(Int64, fmi3Int64)
NO_SUCH_GETTER(UInt64, fmi3UInt64)
NO_SUCH_GETTER(String, fmi3String)
NO_SUCH_SETTER(Float32, fmi3Float32)
NO_SUCH_SETTER(Int8, fmi3Int8)
NO_SUCH_SETTER(UInt8, fmi3UInt8)
NO_SUCH_SETTER(Int16, fmi3Int16)
NO_SUCH_SETTER(UInt16, fmi3UInt16)
NO_SUCH_SETTER(UInt32, fmi3UInt32)
NO_SUCH_SETTER(Int64, fmi3Int64)
NO_SUCH_SETTER(UInt64, fmi3UInt64)
NO_SUCH_SETTER(String, fmi3String)

fmi3Status fmi3GetBinary(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences,
                         size_t valueSizes[], fmi3Binary values[], size_t nValues)
{
    ENTER_AS("fmi3GetBinary", MASK_fmi3GetOtherType);
    (void)valueSizes; (void)values; (void)nValues;
    LEAVE(fmu_no_such_type(S, "Binary", valueReferences, nValueReferences));
}

fmi3Status fmi3SetBinary(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences,
                         const size_t valueSizes[], const fmi3Binary values[], size_t nValues)
{
    ENTER_AS("fmi3SetBinary", MASK_fmi3SetOtherType);
    (void)valueSizes; (void)values; (void)nValues;
    LEAVE(fmu_no_such_type(S, "Binary", valueReferences, nValueReferences));
}

fmi3Status fmi3GetClock(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences,
                        fmi3Clock values[])
{
    ENTER_AS("fmi3GetClock", MASK_fmi3Unsupported);
    (void)values;
    LEAVE(fmu_no_such_type(S, "Clock", valueReferences, nValueReferences));
}

fmi3Status fmi3SetClock(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences,
                        const fmi3Clock values[])
{
    ENTER_AS("fmi3SetClock", MASK_fmi3Unsupported);
    (void)values;
    LEAVE(fmu_no_such_type(S, "Clock", valueReferences, nValueReferences));
}

/* a function for a feature modelDescription.xml does not declare */
#define UNSUPPORTED(F, WHY) ENTER_AS(#F, MASK_fmi3Unsupported); LEAVE(fmu_fail(S, "not supported by this FMU (%s)", WHY))

fmi3Status fmi3GetNumberOfVariableDependencies(fmi3Instance instance, fmi3ValueReference valueReference,
                                               size_t *nDependencies)
{
    (void)valueReference; (void)nDependencies;
    UNSUPPORTED(fmi3GetNumberOfVariableDependencies, "providesPerElementDependencies is false");
}

fmi3Status fmi3GetVariableDependencies(fmi3Instance instance, fmi3ValueReference dependent,
                                       size_t elementIndicesOfDependent[], fmi3ValueReference independents[],
                                       size_t elementIndicesOfIndependents[], fmi3DependencyKind dependencyKinds[],
                                       size_t nDependencies)
{
    (void)dependent; (void)elementIndicesOfDependent; (void)independents; (void)elementIndicesOfIndependents;
    (void)dependencyKinds; (void)nDependencies;
    UNSUPPORTED(fmi3GetVariableDependencies, "providesPerElementDependencies is false");
}

fmi3Status fmi3GetDirectionalDerivative(fmi3Instance instance, const fmi3ValueReference unknowns[], size_t nUnknowns,
                                        const fmi3ValueReference knowns[], size_t nKnowns, const fmi3Float64 seed[],
                                        size_t nSeed, fmi3Float64 sensitivity[], size_t nSensitivity)
{
    (void)unknowns; (void)nUnknowns; (void)knowns; (void)nKnowns; (void)seed; (void)nSeed; (void)sensitivity;
    (void)nSensitivity;
    UNSUPPORTED(fmi3GetDirectionalDerivative, "providesDirectionalDerivatives is false");
}

fmi3Status fmi3GetAdjointDerivative(fmi3Instance instance, const fmi3ValueReference unknowns[], size_t nUnknowns,
                                    const fmi3ValueReference knowns[], size_t nKnowns, const fmi3Float64 seed[],
                                    size_t nSeed, fmi3Float64 sensitivity[], size_t nSensitivity)
{
    (void)unknowns; (void)nUnknowns; (void)knowns; (void)nKnowns; (void)seed; (void)nSeed; (void)sensitivity;
    (void)nSensitivity;
    UNSUPPORTED(fmi3GetAdjointDerivative, "providesAdjointDerivatives is false");
}

fmi3Status fmi3EnterConfigurationMode(fmi3Instance instance)
{
    UNSUPPORTED(fmi3EnterConfigurationMode, "no structural parameters");
}

fmi3Status fmi3ExitConfigurationMode(fmi3Instance instance)
{
    UNSUPPORTED(fmi3ExitConfigurationMode, "no structural parameters");
}

fmi3Status fmi3GetIntervalDecimal(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                                  size_t nValueReferences, fmi3Float64 intervals[], fmi3IntervalQualifier qualifiers[])
{
    (void)valueReferences; (void)nValueReferences; (void)intervals; (void)qualifiers;
    UNSUPPORTED(fmi3GetIntervalDecimal, "no clocks");
}

fmi3Status fmi3GetIntervalFraction(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                                   size_t nValueReferences, fmi3UInt64 counters[], fmi3UInt64 resolutions[],
                                   fmi3IntervalQualifier qualifiers[])
{
    (void)valueReferences; (void)nValueReferences; (void)counters; (void)resolutions; (void)qualifiers;
    UNSUPPORTED(fmi3GetIntervalFraction, "no clocks");
}

fmi3Status fmi3GetShiftDecimal(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                               size_t nValueReferences, fmi3Float64 shifts[])
{
    (void)valueReferences; (void)nValueReferences; (void)shifts;
    UNSUPPORTED(fmi3GetShiftDecimal, "no clocks");
}

fmi3Status fmi3GetShiftFraction(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                                size_t nValueReferences, fmi3UInt64 counters[], fmi3UInt64 resolutions[])
{
    (void)valueReferences; (void)nValueReferences; (void)counters; (void)resolutions;
    UNSUPPORTED(fmi3GetShiftFraction, "no clocks");
}

fmi3Status fmi3SetIntervalDecimal(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                                  size_t nValueReferences, const fmi3Float64 intervals[])
{
    (void)valueReferences; (void)nValueReferences; (void)intervals;
    UNSUPPORTED(fmi3SetIntervalDecimal, "no clocks");
}

fmi3Status fmi3SetIntervalFraction(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                                   size_t nValueReferences, const fmi3UInt64 counters[], const fmi3UInt64 resolutions[])
{
    (void)valueReferences; (void)nValueReferences; (void)counters; (void)resolutions;
    UNSUPPORTED(fmi3SetIntervalFraction, "no clocks");
}

fmi3Status fmi3SetShiftDecimal(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                               size_t nValueReferences, const fmi3Float64 shifts[])
{
    (void)valueReferences; (void)nValueReferences; (void)shifts;
    UNSUPPORTED(fmi3SetShiftDecimal, "no clocks");
}

fmi3Status fmi3SetShiftFraction(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                                size_t nValueReferences, const fmi3UInt64 counters[], const fmi3UInt64 resolutions[])
{
    (void)valueReferences; (void)nValueReferences; (void)counters; (void)resolutions;
    UNSUPPORTED(fmi3SetShiftFraction, "no clocks");
}

fmi3Status fmi3ActivateModelPartition(fmi3Instance instance, fmi3ValueReference clockReference,
                                      fmi3Float64 activationTime)
{
    (void)clockReference; (void)activationTime;
    UNSUPPORTED(fmi3ActivateModelPartition, "no Scheduled Execution");
}

/* ---- FMU state (canGetAndSetFMUState, canSerializeFMUState) -------------------------------- */

fmi3Status fmi3GetFMUState(fmi3Instance instance, fmi3FMUState *FMUState)
{
    ENTER(fmi3GetFMUState);
    LEAVE(fmu_get_fmu_state(S, FMUState));
}

fmi3Status fmi3SetFMUState(fmi3Instance instance, fmi3FMUState FMUState)
{
    ENTER(fmi3SetFMUState);
    LEAVE(fmu_set_fmu_state(S, FMUState));
}

fmi3Status fmi3FreeFMUState(fmi3Instance instance, fmi3FMUState *FMUState)
{
    ENTER(fmi3FreeFMUState);
    LEAVE(fmu_free_fmu_state(S, FMUState));
}

fmi3Status fmi3SerializedFMUStateSize(fmi3Instance instance, fmi3FMUState FMUState, size_t *size)
{
    ENTER(fmi3SerializedFMUStateSize);
    LEAVE(fmu_serialized_size(S, FMUState, size));
}

fmi3Status fmi3SerializeFMUState(fmi3Instance instance, fmi3FMUState FMUState, fmi3Byte serializedState[], size_t size)
{
    ENTER(fmi3SerializeFMUState);
    LEAVE(fmu_serialize(S, FMUState, serializedState, size));
}

fmi3Status fmi3DeserializeFMUState(fmi3Instance instance, const fmi3Byte serializedState[], size_t size,
                                   fmi3FMUState *FMUState)
{
    ENTER(fmi3DeserializeFMUState);
    LEAVE(fmu_deserialize(S, serializedState, size, FMUState));
}

/* ---- Event Mode (Model Exchange, and Co-Simulation with eventModeUsed) --------------------- */

fmi3Status fmi3EvaluateDiscreteStates(fmi3Instance instance)
{
    ENTER(fmi3EvaluateDiscreteStates);
    LEAVE(FMU_OK); /* the discrete states change only in fmi3UpdateDiscreteStates */
}

fmi3Status fmi3UpdateDiscreteStates(fmi3Instance instance, fmi3Boolean *discreteStatesNeedUpdate,
                                    fmi3Boolean *terminateSimulation, fmi3Boolean *nominalsOfContinuousStatesChanged,
                                    fmi3Boolean *valuesOfContinuousStatesChanged, fmi3Boolean *nextEventTimeDefined,
                                    fmi3Float64 *nextEventTime)
{
    fmu_event_result r;
    ENTER(fmi3UpdateDiscreteStates);
    REQUIRE_NOT_NULL(discreteStatesNeedUpdate);
    REQUIRE_NOT_NULL(terminateSimulation);
    REQUIRE_NOT_NULL(nominalsOfContinuousStatesChanged);
    REQUIRE_NOT_NULL(valuesOfContinuousStatesChanged);
    REQUIRE_NOT_NULL(nextEventTimeDefined);
    REQUIRE_NOT_NULL(nextEventTime);
    REQUIRE_OK(fmu_update_discrete_states(S, &r));
    *discreteStatesNeedUpdate = r.more != 0;
    *terminateSimulation = r.terminate != 0;
    *nominalsOfContinuousStatesChanged = false; /* the nominals are constants */
    *valuesOfContinuousStatesChanged = r.states_changed != 0;
    *nextEventTimeDefined = r.next_time_defined != 0;
    *nextEventTime = r.next_time_defined ? r.next_time : 0.0;
    LEAVE(FMU_OK);
}

/* ---- Model Exchange ------------------------------------------------------------------------ */

fmi3Status fmi3EnterContinuousTimeMode(fmi3Instance instance)
{
    ENTER(fmi3EnterContinuousTimeMode);
    fmu_leave_event_mode(S);
    LEAVE(FMU_OK);
}

fmi3Status fmi3CompletedIntegratorStep(fmi3Instance instance, fmi3Boolean noSetFMUStatePriorToCurrentPoint,
                                       fmi3Boolean *enterEventMode, fmi3Boolean *terminateSimulation)
{
    ENTER(fmi3CompletedIntegratorStep);
    (void)noSetFMUStatePriorToCurrentPoint;
    REQUIRE_NOT_NULL(enterEventMode);
    REQUIRE_NOT_NULL(terminateSimulation);
    *enterEventMode = false;
    *terminateSimulation = false;
    LEAVE(FMU_OK);
}

fmi3Status fmi3SetTime(fmi3Instance instance, fmi3Float64 time)
{
    ENTER(fmi3SetTime);
    LEAVE(fmu_set_time(S, time));
}

fmi3Status fmi3SetContinuousStates(fmi3Instance instance, const fmi3Float64 continuousStates[], size_t nContinuousStates)
{
    ENTER(fmi3SetContinuousStates);
    REQUIRE_NOT_NULL(continuousStates);
    LEAVE(fmu_set_states(S, continuousStates, nContinuousStates));
}

fmi3Status fmi3GetContinuousStateDerivatives(fmi3Instance instance, fmi3Float64 derivatives[], size_t nContinuousStates)
{
    ENTER(fmi3GetContinuousStateDerivatives);
    REQUIRE_NOT_NULL(derivatives);
    LEAVE(fmu_get_derivatives(S, derivatives, nContinuousStates));
}

fmi3Status fmi3GetEventIndicators(fmi3Instance instance, fmi3Float64 eventIndicators[], size_t nEventIndicators)
{
    ENTER(fmi3GetEventIndicators);
    REQUIRE(eventIndicators || nEventIndicators == 0, "argument eventIndicators must not be NULL");
    LEAVE(fmu_get_event_indicators(S, eventIndicators, nEventIndicators));
}

fmi3Status fmi3GetContinuousStates(fmi3Instance instance, fmi3Float64 continuousStates[], size_t nContinuousStates)
{
    ENTER(fmi3GetContinuousStates);
    REQUIRE_NOT_NULL(continuousStates);
    LEAVE(fmu_get_states(S, continuousStates, nContinuousStates));
}

fmi3Status fmi3GetNominalsOfContinuousStates(fmi3Instance instance, fmi3Float64 nominals[], size_t nContinuousStates)
{
    ENTER(fmi3GetNominalsOfContinuousStates);
    REQUIRE_NOT_NULL(nominals);
    LEAVE(fmu_get_nominals(S, nominals, nContinuousStates));
}

fmi3Status fmi3GetNumberOfEventIndicators(fmi3Instance instance, size_t *nEventIndicators)
{
    ENTER(fmi3GetNumberOfEventIndicators);
    REQUIRE_NOT_NULL(nEventIndicators);
    *nEventIndicators = (size_t)S->core.model.nz;
    LEAVE(FMU_OK);
}

fmi3Status fmi3GetNumberOfContinuousStates(fmi3Instance instance, size_t *nContinuousStates)
{
    ENTER(fmi3GetNumberOfContinuousStates);
    REQUIRE_NOT_NULL(nContinuousStates);
    *nContinuousStates = (size_t)S->core.model.nx;
    LEAVE(FMU_OK);
}

/* ---- Co-Simulation ------------------------------------------------------------------------- */

fmi3Status fmi3EnterStepMode(fmi3Instance instance)
{
    ENTER(fmi3EnterStepMode);
    fmu_leave_event_mode(S);
    LEAVE(FMU_OK);
}

fmi3Status fmi3GetOutputDerivatives(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                                    size_t nValueReferences, const fmi3Int32 orders[], fmi3Float64 values[],
                                    size_t nValues)
{
    (void)valueReferences; (void)nValueReferences; (void)orders; (void)values; (void)nValues;
    ENTER(fmi3GetOutputDerivatives);
    LEAVE(fmu_fail(S, "not supported by this FMU (maxOutputDerivativeOrder is 0)"));
}

/* A step in which the model ends the run is fmi3OK with terminateSimulation; a step after it is
 * fmi3Discard. The step handles its events itself, and returns early only at termination. */
fmi3Status fmi3DoStep(fmi3Instance instance, fmi3Float64 currentCommunicationPoint, fmi3Float64 communicationStepSize,
                      fmi3Boolean noSetFMUStatePriorToCurrentPoint, fmi3Boolean *eventHandlingNeeded,
                      fmi3Boolean *terminateSimulation, fmi3Boolean *earlyReturn, fmi3Float64 *lastSuccessfulTime)
{
    int ended;
    fmu_status st;
    ENTER(fmi3DoStep);
    (void)noSetFMUStatePriorToCurrentPoint;
    REQUIRE_NOT_NULL(eventHandlingNeeded);
    REQUIRE_NOT_NULL(terminateSimulation);
    REQUIRE_NOT_NULL(earlyReturn);
    REQUIRE_NOT_NULL(lastSuccessfulTime);
    st = fmu_do_step(S, currentCommunicationPoint, communicationStepSize, &ended);
    *eventHandlingNeeded = false;
    *terminateSimulation = S->core.terminated != 0;
    *earlyReturn = false; /* earlyReturnAllowed is never used */
    *lastSuccessfulTime = S->core.time;
    LEAVE(st);
}
