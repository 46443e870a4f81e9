/* The FMI 3.0 API, Model Exchange and Co-Simulation, over the same model callbacks (fmu_model.h)
 * and the same version-free core (fmu_core.c: model defaults, variable lookup, Co-Simulation
 * step, FMU state) as the FMI 2.0 layer fmi2Functions.c. No physics here, no global state.
 *
 * As in the FMI 2.0 layer, every function starts with ENTER(name), which checks the instance and
 * the call sequence against the function's mask below (the state machines of FMI 3.0 sections 3.2
 * and 4.2) and records the function's name for the messages, and ends with LEAVE(status), which
 * makes every fmi3Error leave the instance in the error state. Bad input (NULL, unknown value
 * references, wrong types or sizes, non-finite or out-of-range values) is fmi3Error with a logged
 * reason.
 *
 * What FMI 3.0 adds over the model's table: the independent variable `time` (value reference
 * FMI3_TIME_VR) and the event indicators as Float64 variables (fmu_model.z_vrs). The model has
 * no variables of the other FMI 3.0 types, no clocks and no structural parameters: those
 * functions fail with the reason logged. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmi3Functions.h"
#include "fmu_core.h"

/* the value reference of `time` (causality="independent"); scripts/gen_model_description.py
 * writes the same number, and no model table uses it */
#define FMI3_TIME_VR 0u

/* ---- the state machines and which calls each state allows ---------------------------------- */

enum {
    ME_INSTANTIATED = 1 << 0,
    ME_INIT = 1 << 1,
    ME_EVENT = 1 << 2,
    ME_CONT = 1 << 3,
    ME_TERMINATED = 1 << 4,
    ME_ERROR = 1 << 5,
    CS_INSTANTIATED = 1 << 6,
    CS_INIT = 1 << 7,
    CS_EVENT = 1 << 8, /* only with eventModeUsed */
    CS_STEP = 1 << 9,
    CS_TERMINATED = 1 << 10,
    CS_ERROR = 1 << 11
};
#define ME_ANY (ME_INSTANTIATED | ME_INIT | ME_EVENT | ME_CONT | ME_TERMINATED | ME_ERROR)
#define CS_ANY (CS_INSTANTIATED | CS_INIT | CS_EVENT | CS_STEP | CS_TERMINATED | CS_ERROR)
#define ANY_STATE (ME_ANY | CS_ANY)
#define BEFORE_INIT_END (ME_INSTANTIATED | ME_INIT | CS_INSTANTIATED | CS_INIT)
#define READABLE (ME_INIT | ME_EVENT | ME_CONT | ME_TERMINATED | ME_ERROR | CS_INIT | CS_EVENT | CS_STEP | CS_TERMINATED | CS_ERROR)
#define WRITABLE (ME_INSTANTIATED | ME_INIT | ME_EVENT | ME_CONT | CS_INSTANTIATED | CS_INIT | CS_EVENT | CS_STEP)

#define MASK_fmi3SetDebugLogging ANY_STATE
#define MASK_fmi3EnterInitializationMode (ME_INSTANTIATED | CS_INSTANTIATED)
#define MASK_fmi3ExitInitializationMode (ME_INIT | CS_INIT)
#define MASK_fmi3EnterEventMode (ME_EVENT | ME_CONT | CS_STEP)
#define MASK_fmi3Terminate (ME_EVENT | ME_CONT | CS_EVENT | CS_STEP)
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
#define MASK_fmi3EvaluateDiscreteStates (ME_EVENT | CS_EVENT)
#define MASK_fmi3UpdateDiscreteStates (ME_EVENT | CS_EVENT)
#define MASK_fmi3GetNumberOfEventIndicators ANY_STATE
#define MASK_fmi3GetNumberOfContinuousStates ANY_STATE
/* Model Exchange only */
#define MASK_fmi3EnterContinuousTimeMode ME_EVENT
#define MASK_fmi3CompletedIntegratorStep ME_CONT
#define MASK_fmi3SetTime (ME_EVENT | ME_CONT)
#define MASK_fmi3SetContinuousStates ME_CONT
#define MASK_fmi3GetContinuousStateDerivatives (ME_EVENT | ME_CONT | ME_TERMINATED | ME_ERROR)
#define MASK_fmi3GetEventIndicators (ME_INIT | ME_EVENT | ME_CONT | ME_TERMINATED | ME_ERROR)
#define MASK_fmi3GetContinuousStates (ME_INIT | ME_EVENT | ME_CONT | ME_TERMINATED | ME_ERROR)
#define MASK_fmi3GetNominalsOfContinuousStates (ME_INSTANTIATED | ME_EVENT | ME_CONT | ME_TERMINATED | ME_ERROR)
/* Co-Simulation only */
#define MASK_fmi3EnterStepMode CS_EVENT
#define MASK_fmi3GetOutputDerivatives (CS_STEP | CS_TERMINATED | CS_ERROR)
#define MASK_fmi3DoStep CS_STEP

enum { LOG_EVENTS = 1 << 0, LOG_WARNING = 1 << 1, LOG_ERROR = 1 << 2 };
static const char *const CATEGORY_NAMES[] = {"logEvents", "logStatusWarning", "logStatusError"};
#define N_CATEGORIES 3

/* ---- instance ------------------------------------------------------------------------------ */

typedef struct {
    char *name;
    fmi3LogMessageCallback logger;
    fmi3InstanceEnvironment env;
    int state;
    const char *function; /* the FMI function running, for the messages */
    unsigned categories;
    int event_mode_used;  /* Co-Simulation: the importer enters Event Mode after initialization */
    fmu_logger log;
    fmu_core core;        /* the model, its data, time and Co-Simulation solver (fmu_core.h) */
} Inst;

static const char *TYPE_NAMES[] = {"Float64", "Int32", "Boolean"};

#define PHASE(S, X) ((S)->core.co_simulation ? CS_##X : ME_##X)

/* ---- logging ------------------------------------------------------------------------------- */

/* importers may treat the message as a format string */
static void defuse_percent(char *s)
{
    for (; *s; s++)
        if (*s == '%') *s = '_';
}

static void vlog(Inst *S, fmi3Status status, unsigned cat, const char *fmt, va_list ap)
{
    char text[1024], buf[1100];
    int idx = cat == LOG_EVENTS ? 0 : (cat == LOG_WARNING ? 1 : 2);
    if (!S->logger || !(S->categories & cat)) return;
    vsnprintf(text, sizeof text, fmt, ap);
    if (S->function) snprintf(buf, sizeof buf, "%s: %s: %s", S->name, S->function, text);
    else snprintf(buf, sizeof buf, "%s: %s", S->name, text);
    defuse_percent(buf);
    S->logger(S->env, status, CATEGORY_NAMES[idx], buf);
}

static void log_event(Inst *S, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vlog(S, fmi3OK, LOG_EVENTS, fmt, ap);
    va_end(ap);
}

static void log_warning(Inst *S, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vlog(S, fmi3Warning, LOG_WARNING, fmt, ap);
    va_end(ap);
}

/* log an error (prefixed with the running function's name), enter the error state */
static fmi3Status fail(Inst *S, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vlog(S, fmi3Error, LOG_ERROR, fmt, ap);
    va_end(ap);
    S->state = PHASE(S, ERROR);
    return fmi3Error;
}

/* the model's messages, without a function prefix: they say what happened at which time */
static void model_event(void *ctx, const char *message)
{
    Inst *S = (Inst *)ctx;
    const char *f = S->function;
    S->function = NULL;
    log_event(S, "%s", message);
    S->function = f;
}

static void model_warning(void *ctx, const char *message)
{
    Inst *S = (Inst *)ctx;
    const char *f = S->function;
    S->function = NULL;
    log_warning(S, "%s", message);
    S->function = f;
}

/* ---- entry and exit of every function ------------------------------------------------------ */

static const char *state_name(int state)
{
    switch (state) {
    case ME_INSTANTIATED: case CS_INSTANTIATED: return "Instantiated";
    case ME_INIT: case CS_INIT: return "InitializationMode";
    case ME_EVENT: case CS_EVENT: return "EventMode";
    case ME_CONT: return "ContinuousTimeMode";
    case CS_STEP: return "StepMode";
    case ME_TERMINATED: case CS_TERMINATED: return "Terminated";
    default: return "error";
    }
}

/* Is the call allowed now? If not, log why and enter the error state. */
static int enter(Inst *S, const char *function, int mask)
{
    S->function = function;
    if (S->state & mask) return 1;
    if (S->core.co_simulation && !(mask & CS_ANY))
        fail(S, "illegal call: a Model Exchange function called on a Co-Simulation instance");
    else if (!S->core.co_simulation && !(mask & ME_ANY))
        fail(S, "illegal call: a Co-Simulation function called on a Model Exchange instance");
    else
        fail(S, "illegal call sequence (not allowed in state %s)", state_name(S->state));
    return 0;
}

static fmi3Status leave(Inst *S, fmi3Status status)
{
    if (status >= fmi3Error && !(S->state & (ME_ERROR | CS_ERROR))) S->state = PHASE(S, ERROR);
    S->function = NULL;
    return status;
}

/* ENTER_AS(F, MASK): F's name in the messages, MASK the states it is allowed in */
#define ENTER_AS(F, MASK)                          \
    Inst *const S = (Inst *)instance;              \
    if (!S) return fmi3Error;                      \
    if (!enter(S, F, MASK)) return leave(S, fmi3Error)
#define ENTER(F) ENTER_AS(#F, MASK_##F)
#define LEAVE(status) return leave(S, (status))

#define REQUIRE(cond, ...) \
    do { if (!(cond)) LEAVE(fail(S, __VA_ARGS__)); } while (0)
#define REQUIRE_NOT_NULL(P) REQUIRE((P) != NULL, "argument %s must not be NULL", #P)
#define REQUIRE_SIZE(N, EXPECTED, WHAT) \
    REQUIRE((N) == (size_t)(EXPECTED), WHAT " = %u, expected %d", (unsigned)(N), (int)(EXPECTED))

static int initializing(const Inst *S) { return (S->state & BEFORE_INIT_END) != 0; }

/* ---- variables ----------------------------------------------------------------------------- */

/* the index of vr among the event indicators, -1 if it is none */
static int event_indicator_index(const Inst *S, fmi3ValueReference vr)
{
    int k;
    for (k = 0; S->core.model.z_vrs && k < S->core.model.nz; k++)
        if (S->core.model.z_vrs[k] == vr) return k;
    return -1;
}

/* Is vr a variable of this type? The FMI 3.0 additions (time, event indicators) are Float64. */
static int known_as(Inst *S, fmi3ValueReference vr, fmu_type type)
{
    const fmu_var *v = fmu_find_var(&S->core.model, vr);
    const int extra = vr == FMI3_TIME_VR || event_indicator_index(S, vr) >= 0;
    if (!v && !extra) return fail(S, "unknown value reference %u", (unsigned)vr), 0;
    if (extra && type != FMU_REAL)
        return fail(S, "value reference %u is a Float64, not a %s", (unsigned)vr, TYPE_NAMES[type]), 0;
    if (v && v->type != type)
        return fail(S, "value reference %u (%s) is a %s, not a %s", (unsigned)vr, v->name, TYPE_NAMES[v->type],
                    TYPE_NAMES[type]), 0;
    return 1;
}

/* common checks of a getter or setter of scalars: NULL arrays, nValues, every value reference
 * known and of the type */
static int vr_checks(Inst *S, const fmi3ValueReference vr[], size_t nvr, const void *values, size_t nValues,
                     fmu_type type)
{
    size_t i;
    if (nvr == 0 && nValues == 0) return 1;
    if (!vr) return fail(S, "argument valueReferences must not be NULL"), 0;
    if (!values) return fail(S, "argument values must not be NULL"), 0;
    if (nValues != nvr)
        return fail(S, "nValues = %u, expected %u (every variable of this FMU is a scalar)", (unsigned)nValues,
                    (unsigned)nvr), 0;
    for (i = 0; i < nvr; i++)
        if (!known_as(S, vr[i], type)) return 0;
    return 1;
}

/* may v be set now? (FMI 3.0 section 2.4.7.4: parameters and initial="exact" until
 * fmi3ExitInitializationMode, inputs always) */
static int settable(Inst *S, fmi3ValueReference vr)
{
    const fmu_var *v = fmu_find_var(&S->core.model, vr);
    int kind;
    if (!v) return fail(S, "%s (value reference %u) is computed by the FMU and cannot be set",
                        vr == FMI3_TIME_VR ? "time" : "an event indicator", (unsigned)vr), 0;
    kind = fmu_var_kind(v);
    if (kind == FMU_SET_ALWAYS) return 1;
    if (kind == FMU_SET_BEFORE_INIT_END) {
        const int parameter = !strcmp(v->causality, "parameter");
        if (initializing(S)) return 1;
        return fail(S, "%s %s can only be set before fmi3ExitInitializationMode%s", parameter ? "parameter" : "start value of",
                    v->name, parameter ? "" : " (use fmi3SetContinuousStates)"), 0;
    }
    return fail(S, "variable %s (causality %s) cannot be set", v->name, v->causality), 0;
}

/* ---- inquiry, instantiation ---------------------------------------------------------------- */

const char *fmi3GetVersion(void) { return fmi3Version; }

/* the arguments of an instantiation, checked before there is an instance to log through */
static int instantiate_arguments_ok(fmi3String name, fmi3String token, fmi3InstanceEnvironment env,
                                    fmi3LogMessageCallback logger)
{
    char msg[512];
    if (!name || !*name) {
        logger(env, fmi3Error, "logStatusError", "fmi3Instantiate: instanceName must be a non-empty string");
        return 0;
    }
    if (!token || strcmp(token, FMU_MODEL.guid) != 0) {
        snprintf(msg, sizeof msg, "%s: fmi3Instantiate: wrong instantiationToken \"%s\", this FMU has %s", name,
                 token ? token : "(null)", FMU_MODEL.guid);
        defuse_percent(msg);
        logger(env, fmi3Error, "logStatusError", msg);
        return 0;
    }
    return 1;
}

static Inst *instantiate(fmi3String name, fmi3String token, int co_simulation, fmi3Boolean loggingOn,
                         fmi3InstanceEnvironment env, fmi3LogMessageCallback logger)
{
    Inst *S;
    if (!logger) return NULL; /* nothing to report through */
    if (!instantiate_arguments_ok(name, token, env, logger)) return NULL;
    S = (Inst *)calloc(1, sizeof(Inst));
    if (!S) return NULL;
    S->logger = logger;
    S->env = env;
    fmu_model_with_defaults(&S->core.model);
    S->name = (char *)calloc(strlen(name) + 1, 1);
    S->core.M = calloc(1, S->core.model.data_size);
    S->core.inputs = (cs_input *)calloc(S->core.model.nvars + 1, sizeof(cs_input));
    if (!S->name || !S->core.M || !S->core.inputs) {
        fmi3FreeInstance(S);
        return NULL;
    }
    strcpy(S->name, name);
    fmu_core_inputs(&S->core);
    S->core.co_simulation = co_simulation;
    S->categories = LOG_ERROR | LOG_WARNING | (loggingOn ? LOG_EVENTS : 0);
    S->log.event = model_event;
    S->log.warning = model_warning;
    S->log.ctx = S;
    S->core.model.reset(S->core.M);
    S->state = PHASE(S, INSTANTIATED);
    log_event(S, "%s instance created", co_simulation ? "Co-Simulation" : "Model Exchange");
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
    if (S) S->event_mode_used = eventModeUsed ? 1 : 0;
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
    Inst *S = (Inst *)instance;
    if (!S) return;
    cs_free(S->core.cs);
    free(S->core.inputs);
    free(S->core.M);
    free(S->name);
    free(S);
}

static unsigned category_bit(fmi3String name)
{
    int k;
    for (k = 0; name && k < N_CATEGORIES; k++)
        if (!strcmp(name, CATEGORY_NAMES[k])) return 1u << k;
    return 0;
}

fmi3Status fmi3SetDebugLogging(fmi3Instance instance, fmi3Boolean loggingOn, size_t nCategories,
                               const fmi3String categories[])
{
    size_t i;
    ENTER(fmi3SetDebugLogging);
    if (nCategories == 0) {
        S->categories = loggingOn ? (LOG_EVENTS | LOG_WARNING | LOG_ERROR) : (LOG_WARNING | LOG_ERROR);
        LEAVE(fmi3OK);
    }
    REQUIRE_NOT_NULL(categories);
    for (i = 0; i < nCategories; i++) {
        const unsigned bit = category_bit(categories[i]);
        REQUIRE(bit, "unknown log category \"%s\"", categories[i] ? categories[i] : "(null)");
        if (loggingOn) S->categories |= bit;
        else S->categories &= ~bit;
    }
    LEAVE(fmi3OK);
}

/* ---- initialization, termination, reset ---------------------------------------------------- */

fmi3Status fmi3EnterInitializationMode(fmi3Instance instance, fmi3Boolean toleranceDefined, fmi3Float64 tolerance,
                                       fmi3Float64 startTime, fmi3Boolean stopTimeDefined, fmi3Float64 stopTime)
{
    ENTER(fmi3EnterInitializationMode);
    (void)stopTimeDefined;
    (void)stopTime;
    REQUIRE(isfinite(startTime), "startTime = %g is not finite", startTime);
    REQUIRE(!toleranceDefined || (tolerance > 0 && tolerance < 1), "tolerance = %g must be in (0, 1)", tolerance);
    S->core.rtol = toleranceDefined ? tolerance : 0.0; /* only Co-Simulation uses it (CVODE inside) */
    S->core.time = startTime;
    S->state = PHASE(S, INIT);
    LEAVE(fmi3OK);
}

fmi3Status fmi3ExitInitializationMode(fmi3Instance instance)
{
    char msg[512];
    ENTER(fmi3ExitInitializationMode);
    REQUIRE(S->core.model.exit_init(S->core.M, S->core.time, &S->log, msg, sizeof msg) == 0, "%s", msg);
    if (!S->core.co_simulation) {
        S->core.initialized = 1;
        S->state = ME_EVENT; /* FMI 3.0: Model Exchange leaves initialization into Event Mode */
        LEAVE(fmi3OK);
    }
    S->core.cs = cs_new(&S->core.model, S->core.M, S->core.time, S->core.rtol, &S->log, &S->core.terminated, msg, sizeof msg);
    REQUIRE(S->core.cs != NULL, "%s", msg);
    S->core.last_successful_time = S->core.time;
    S->core.initialized = 1;
    S->state = S->event_mode_used ? CS_EVENT : CS_STEP;
    LEAVE(fmi3OK);
}

fmi3Status fmi3EnterEventMode(fmi3Instance instance)
{
    ENTER(fmi3EnterEventMode);
    REQUIRE(!S->core.co_simulation || S->event_mode_used,
            "Event Mode of Co-Simulation needs eventModeUsed = true at fmi3InstantiateCoSimulation");
    S->state = PHASE(S, EVENT);
    LEAVE(fmi3OK);
}

fmi3Status fmi3Terminate(fmi3Instance instance)
{
    ENTER(fmi3Terminate);
    S->state = PHASE(S, TERMINATED);
    LEAVE(fmi3OK);
}

fmi3Status fmi3Reset(fmi3Instance instance)
{
    ENTER(fmi3Reset);
    cs_free(S->core.cs);
    S->core.cs = NULL;
    S->core.terminated = 0;
    S->core.initialized = 0;
    S->core.time = 0.0;
    S->core.model.reset(S->core.M);
    S->state = PHASE(S, INSTANTIATED);
    LEAVE(fmi3OK);
}

/* ---- getters ------------------------------------------------------------------------------- */

/* one Float64: time, an event indicator or a Real of the model's table (checked before) */
static double get_float64(Inst *S, fmi3ValueReference vr)
{
    double v, z[S->core.model.nz + 1];
    int k;
    if (vr == FMI3_TIME_VR) return S->core.time;
    k = event_indicator_index(S, vr);
    if (k >= 0) {
        S->core.model.event_indicators(S->core.M, initializing(S), z);
        return z[k];
    }
    S->core.model.get_real(S->core.M, initializing(S), S->core.time, &vr, 1, &v);
    return v;
}

fmi3Status fmi3GetFloat64(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences,
                          fmi3Float64 values[], size_t nValues)
{
    size_t i;
    ENTER(fmi3GetFloat64);
    if (!vr_checks(S, valueReferences, nValueReferences, values, nValues, FMU_REAL)) LEAVE(fmi3Error);
    for (i = 0; i < nValueReferences; i++) values[i] = get_float64(S, valueReferences[i]);
    LEAVE(fmi3OK);
}

fmi3Status fmi3GetInt32(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences,
                        fmi3Int32 values[], size_t nValues)
{
    size_t i;
    ENTER(fmi3GetInt32);
    if (!vr_checks(S, valueReferences, nValueReferences, values, nValues, FMU_INTEGER)) LEAVE(fmi3Error);
    for (i = 0; i < nValueReferences; i++) {
        int v;
        S->core.model.get_integer(S->core.M, initializing(S), &valueReferences[i], 1, &v);
        values[i] = (fmi3Int32)v;
    }
    LEAVE(fmi3OK);
}

fmi3Status fmi3GetBoolean(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences,
                          fmi3Boolean values[], size_t nValues)
{
    size_t i;
    ENTER(fmi3GetBoolean);
    if (!vr_checks(S, valueReferences, nValueReferences, values, nValues, FMU_BOOLEAN)) LEAVE(fmi3Error);
    for (i = 0; i < nValueReferences; i++) {
        int v;
        S->core.model.get_boolean(S->core.M, &valueReferences[i], 1, &v);
        values[i] = v != 0; /* fmi3Boolean is bool, the model's int */
    }
    LEAVE(fmi3OK);
}

/* ---- setters ------------------------------------------------------------------------------- */

/* a new input value without a derivative is held over the next step */
static void hold_input(Inst *S, fmi3ValueReference vr)
{
    cs_input *in = fmu_core_find_input(&S->core, vr);
    if (in) in->slope = 0.0;
}

fmi3Status fmi3SetFloat64(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences,
                          const fmi3Float64 values[], size_t nValues)
{
    size_t i;
    char msg[256];
    ENTER(fmi3SetFloat64);
    if (!vr_checks(S, valueReferences, nValueReferences, values, nValues, FMU_REAL)) LEAVE(fmi3Error);
    for (i = 0; i < nValueReferences; i++) {
        const fmi3ValueReference vr = valueReferences[i];
        const fmu_var *v = fmu_find_var(&S->core.model, vr);
        if (!settable(S, vr)) LEAVE(fmi3Error);
        REQUIRE(isfinite(values[i]), "%s = %g is not a finite number", v->name, values[i]);
        REQUIRE(S->core.model.set_real(S->core.M, vr, values[i], msg, sizeof msg) == 0, "%s", msg);
        hold_input(S, vr);
    }
    LEAVE(fmi3OK);
}

fmi3Status fmi3SetInt32(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences,
                        const fmi3Int32 values[], size_t nValues)
{
    size_t i;
    char msg[256];
    ENTER(fmi3SetInt32);
    if (!vr_checks(S, valueReferences, nValueReferences, values, nValues, FMU_INTEGER)) LEAVE(fmi3Error);
    for (i = 0; i < nValueReferences; i++) {
        if (!settable(S, valueReferences[i])) LEAVE(fmi3Error);
        REQUIRE(S->core.model.set_integer(S->core.M, valueReferences[i], (int)values[i], msg, sizeof msg) == 0, "%s", msg);
    }
    LEAVE(fmi3OK);
}

fmi3Status fmi3SetBoolean(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences,
                          const fmi3Boolean values[], size_t nValues)
{
    ENTER(fmi3SetBoolean);
    if (!vr_checks(S, valueReferences, nValueReferences, values, nValues, FMU_BOOLEAN)) LEAVE(fmi3Error);
    if (nValueReferences == 0) LEAVE(fmi3OK);
    /* no model of this repository has a settable Boolean: settable() says why */
    if (!settable(S, valueReferences[0])) LEAVE(fmi3Error);
    LEAVE(fail(S, "no Boolean of this FMU can be set"));
}

/* ---- the types, clocks and features the models do not have -------------------------------- */

/* A getter or setter of a type no variable of this FMU has: every value reference is unknown for
 * it (or of another type). */
static fmi3Status no_such_type(Inst *S, const char *type, const fmi3ValueReference vr[], size_t nvr)
{
    const fmu_var *v;
    if (nvr == 0) return fmi3OK;
    if (!vr) return fail(S, "argument valueReferences must not be NULL");
    v = fmu_find_var(&S->core.model, vr[0]);
    if (v) return fail(S, "value reference %u (%s) is a %s, not a %s", (unsigned)vr[0], v->name, TYPE_NAMES[v->type], type);
    if (vr[0] == FMI3_TIME_VR || event_indicator_index(S, vr[0]) >= 0)
        return fail(S, "value reference %u is a Float64, not a %s", (unsigned)vr[0], type);
    return fail(S, "unknown value reference %u (this FMU has no %s variables)", (unsigned)vr[0], type);
}

#define NO_SUCH_GETTER(T, CT)                                                                                    \
    fmi3Status fmi3Get##T(fmi3Instance instance, const fmi3ValueReference valueReferences[],                  \
                          size_t nValueReferences, CT values[], size_t nValues)                                 \
    {                                                                                                            \
        ENTER_AS("fmi3Get" #T, MASK_fmi3GetOtherType);                                                           \
        (void)values; (void)nValues;                                                                             \
        LEAVE(no_such_type(S, #T, valueReferences, nValueReferences));                                           \
    }
#define NO_SUCH_SETTER(T, CT)                                                                                    \
    fmi3Status fmi3Set##T(fmi3Instance instance, const fmi3ValueReference valueReferences[],                  \
                          size_t nValueReferences, const CT values[], size_t nValues)                           \
    {                                                                                                            \
        ENTER_AS("fmi3Set" #T, MASK_fmi3SetOtherType);                                                           \
        (void)values; (void)nValues;                                                                             \
        LEAVE(no_such_type(S, #T, valueReferences, nValueReferences));                                           \
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
    LEAVE(no_such_type(S, "Binary", valueReferences, nValueReferences));
}

fmi3Status fmi3SetBinary(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences,
                         const size_t valueSizes[], const fmi3Binary values[], size_t nValues)
{
    ENTER_AS("fmi3SetBinary", MASK_fmi3SetOtherType);
    (void)valueSizes; (void)values; (void)nValues;
    LEAVE(no_such_type(S, "Binary", valueReferences, nValueReferences));
}

fmi3Status fmi3GetClock(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences,
                        fmi3Clock values[])
{
    ENTER_AS("fmi3GetClock", MASK_fmi3Unsupported);
    (void)values;
    LEAVE(no_such_type(S, "Clock", valueReferences, nValueReferences));
}

fmi3Status fmi3SetClock(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences,
                        const fmi3Clock values[])
{
    ENTER_AS("fmi3SetClock", MASK_fmi3Unsupported);
    (void)values;
    LEAVE(no_such_type(S, "Clock", valueReferences, nValueReferences));
}

/* a function for a feature modelDescription.xml does not declare */
#define UNSUPPORTED(F, WHY) ENTER_AS(#F, MASK_fmi3Unsupported); LEAVE(fail(S, "not supported by this FMU (%s)", WHY))

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

/* ---- FMU state (canGetAndSetFMUState, canSerializeFMUState): fmu_core.c -------------------- */

/* a block of n bytes for an FMU state, reusing *old when it has the size */
static unsigned char *state_block(fmi3FMUState old, size_t n)
{
    if (old) {
        if (fmu_state_bytes(old) == n) return (unsigned char *)old;
        free(old);
    }
    return (unsigned char *)calloc(n, 1);
}

/* a state the importer hands back, checked to be one of ours; if not, log why */
static int own_state(Inst *S, fmi3FMUState state)
{
    char msg[256];
    if (fmu_state_is_ours(state, msg, sizeof msg)) return fail(S, "%s", msg), 0;
    return 1;
}

fmi3Status fmi3GetFMUState(fmi3Instance instance, fmi3FMUState *FMUState)
{
    unsigned char *block;
    size_t n;
    ENTER(fmi3GetFMUState);
    REQUIRE_NOT_NULL(FMUState);
    if (*FMUState && !own_state(S, *FMUState)) LEAVE(fmi3Error);
    n = fmu_state_size(&S->core);
    block = state_block(*FMUState, n);
    *FMUState = block;
    REQUIRE(block != NULL, "out of memory for an FMU state of %u bytes", (unsigned)n);
    fmu_state_write(&S->core, block);
    LEAVE(fmi3OK);
}

fmi3Status fmi3SetFMUState(fmi3Instance instance, fmi3FMUState FMUState)
{
    char msg[512];
    ENTER(fmi3SetFMUState);
    if (!own_state(S, FMUState)) LEAVE(fmi3Error);
    REQUIRE(fmu_state_read(&S->core, FMUState, msg, sizeof msg) == 0, "%s", msg);
    LEAVE(fmi3OK);
}

fmi3Status fmi3FreeFMUState(fmi3Instance instance, fmi3FMUState *FMUState)
{
    ENTER(fmi3FreeFMUState);
    REQUIRE_NOT_NULL(FMUState);
    if (!*FMUState) LEAVE(fmi3OK);
    if (!own_state(S, *FMUState)) LEAVE(fmi3Error);
    free(*FMUState);
    *FMUState = NULL;
    LEAVE(fmi3OK);
}

fmi3Status fmi3SerializedFMUStateSize(fmi3Instance instance, fmi3FMUState FMUState, size_t *size)
{
    ENTER(fmi3SerializedFMUStateSize);
    REQUIRE_NOT_NULL(size);
    if (!own_state(S, FMUState)) LEAVE(fmi3Error);
    *size = fmu_state_bytes(FMUState);
    LEAVE(fmi3OK);
}

fmi3Status fmi3SerializeFMUState(fmi3Instance instance, fmi3FMUState FMUState, fmi3Byte serializedState[], size_t size)
{
    ENTER(fmi3SerializeFMUState);
    REQUIRE_NOT_NULL(serializedState);
    if (!own_state(S, FMUState)) LEAVE(fmi3Error);
    REQUIRE(size == fmu_state_bytes(FMUState), "size = %u, but the FMU state has %u bytes (fmi3SerializedFMUStateSize)",
            (unsigned)size, (unsigned)fmu_state_bytes(FMUState));
    memcpy(serializedState, FMUState, size);
    LEAVE(fmi3OK);
}

fmi3Status fmi3DeserializeFMUState(fmi3Instance instance, const fmi3Byte serializedState[], size_t size,
                                   fmi3FMUState *FMUState)
{
    unsigned char *block;
    char msg[512];
    ENTER(fmi3DeserializeFMUState);
    REQUIRE_NOT_NULL(serializedState);
    REQUIRE_NOT_NULL(FMUState);
    if (*FMUState && !own_state(S, *FMUState)) LEAVE(fmi3Error);
    REQUIRE(fmu_state_check(&S->core, serializedState, size, msg, sizeof msg) == 0, "%s", msg);
    block = state_block(*FMUState, size);
    *FMUState = block;
    REQUIRE(block != NULL, "out of memory for an FMU state of %u bytes", (unsigned)size);
    memcpy(block, serializedState, size);
    LEAVE(fmi3OK);
}

/* ---- Event Mode (Model Exchange, and Co-Simulation with eventModeUsed) --------------------- */

fmi3Status fmi3EvaluateDiscreteStates(fmi3Instance instance)
{
    ENTER(fmi3EvaluateDiscreteStates);
    LEAVE(fmi3OK); /* the discrete states change only in fmi3UpdateDiscreteStates */
}

/* In Co-Simulation the step (exact engine or CVODE) iterates its events itself, so Event Mode
 * only lets the importer change inputs between steps: nothing is left to update. */
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
    memset(&r, 0, sizeof r);
    if (!S->core.co_simulation) S->core.model.event_update(S->core.M, S->core.time, &S->log, &r);
    else r.terminate = S->core.terminated;
    *discreteStatesNeedUpdate = r.more != 0;
    *terminateSimulation = r.terminate != 0;
    *nominalsOfContinuousStatesChanged = false; /* the nominals are constants */
    *valuesOfContinuousStatesChanged = r.states_changed != 0;
    *nextEventTimeDefined = r.next_time_defined != 0;
    *nextEventTime = r.next_time_defined ? r.next_time : 0.0;
    LEAVE(fmi3OK);
}

/* ---- Model Exchange ------------------------------------------------------------------------ */

fmi3Status fmi3EnterContinuousTimeMode(fmi3Instance instance)
{
    ENTER(fmi3EnterContinuousTimeMode);
    S->state = ME_CONT;
    LEAVE(fmi3OK);
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
    LEAVE(fmi3OK);
}

fmi3Status fmi3SetTime(fmi3Instance instance, fmi3Float64 time)
{
    ENTER(fmi3SetTime);
    REQUIRE(isfinite(time), "time = %g is not finite", time);
    S->core.time = time;
    LEAVE(fmi3OK);
}

fmi3Status fmi3SetContinuousStates(fmi3Instance instance, const fmi3Float64 continuousStates[], size_t nContinuousStates)
{
    size_t i;
    ENTER(fmi3SetContinuousStates);
    REQUIRE_NOT_NULL(continuousStates);
    REQUIRE_SIZE(nContinuousStates, S->core.model.nx, "nContinuousStates");
    for (i = 0; i < nContinuousStates; i++)
        REQUIRE(isfinite(continuousStates[i]), "state %u = %g is not finite", (unsigned)i, continuousStates[i]);
    S->core.model.set_states(S->core.M, continuousStates);
    LEAVE(fmi3OK);
}

fmi3Status fmi3GetContinuousStateDerivatives(fmi3Instance instance, fmi3Float64 derivatives[], size_t nContinuousStates)
{
    size_t i;
    ENTER(fmi3GetContinuousStateDerivatives);
    REQUIRE_NOT_NULL(derivatives);
    REQUIRE_SIZE(nContinuousStates, S->core.model.nx, "nContinuousStates");
    S->core.model.derivatives(S->core.M, derivatives);
    for (i = 0; i < nContinuousStates; i++)
        REQUIRE(isfinite(derivatives[i]), "derivative %u is not finite at t = %g", (unsigned)i, S->core.time);
    LEAVE(fmi3OK);
}

fmi3Status fmi3GetEventIndicators(fmi3Instance instance, fmi3Float64 eventIndicators[], size_t nEventIndicators)
{
    ENTER(fmi3GetEventIndicators);
    REQUIRE_SIZE(nEventIndicators, S->core.model.nz, "nEventIndicators");
    if (nEventIndicators == 0) LEAVE(fmi3OK);
    REQUIRE_NOT_NULL(eventIndicators);
    S->core.model.event_indicators(S->core.M, initializing(S), eventIndicators);
    LEAVE(fmi3OK);
}

fmi3Status fmi3GetContinuousStates(fmi3Instance instance, fmi3Float64 continuousStates[], size_t nContinuousStates)
{
    ENTER(fmi3GetContinuousStates);
    REQUIRE_NOT_NULL(continuousStates);
    REQUIRE_SIZE(nContinuousStates, S->core.model.nx, "nContinuousStates");
    S->core.model.get_states(S->core.M, initializing(S), continuousStates);
    LEAVE(fmi3OK);
}

fmi3Status fmi3GetNominalsOfContinuousStates(fmi3Instance instance, fmi3Float64 nominals[], size_t nContinuousStates)
{
    ENTER(fmi3GetNominalsOfContinuousStates);
    REQUIRE_NOT_NULL(nominals);
    REQUIRE_SIZE(nContinuousStates, S->core.model.nx, "nContinuousStates");
    fmu_core_nominals(&S->core, nominals);
    LEAVE(fmi3OK);
}

fmi3Status fmi3GetNumberOfEventIndicators(fmi3Instance instance, size_t *nEventIndicators)
{
    ENTER(fmi3GetNumberOfEventIndicators);
    REQUIRE_NOT_NULL(nEventIndicators);
    *nEventIndicators = (size_t)S->core.model.nz;
    LEAVE(fmi3OK);
}

fmi3Status fmi3GetNumberOfContinuousStates(fmi3Instance instance, size_t *nContinuousStates)
{
    ENTER(fmi3GetNumberOfContinuousStates);
    REQUIRE_NOT_NULL(nContinuousStates);
    *nContinuousStates = (size_t)S->core.model.nx;
    LEAVE(fmi3OK);
}

/* ---- Co-Simulation ------------------------------------------------------------------------- */

fmi3Status fmi3EnterStepMode(fmi3Instance instance)
{
    ENTER(fmi3EnterStepMode);
    S->state = CS_STEP;
    LEAVE(fmi3OK);
}

fmi3Status fmi3GetOutputDerivatives(fmi3Instance instance, const fmi3ValueReference valueReferences[],
                                    size_t nValueReferences, const fmi3Int32 orders[], fmi3Float64 values[],
                                    size_t nValues)
{
    (void)valueReferences; (void)nValueReferences; (void)orders; (void)values; (void)nValues;
    ENTER(fmi3GetOutputDerivatives);
    LEAVE(fail(S, "not supported by this FMU (maxOutputDerivativeOrder is 0)"));
}

/* the outputs of fmi3DoStep for a step that ended at the FMU's time */
static void step_result(Inst *S, fmi3Boolean *eventHandlingNeeded, fmi3Boolean *terminateSimulation,
                        fmi3Boolean *earlyReturn, fmi3Float64 *lastSuccessfulTime)
{
    *eventHandlingNeeded = false; /* the step handled its events itself */
    *terminateSimulation = S->core.terminated != 0;
    *earlyReturn = false;         /* earlyReturnAllowed is never used: a step ends early only at termination */
    *lastSuccessfulTime = S->core.time;
}

fmi3Status fmi3DoStep(fmi3Instance instance, fmi3Float64 currentCommunicationPoint, fmi3Float64 communicationStepSize,
                      fmi3Boolean noSetFMUStatePriorToCurrentPoint, fmi3Boolean *eventHandlingNeeded,
                      fmi3Boolean *terminateSimulation, fmi3Boolean *earlyReturn, fmi3Float64 *lastSuccessfulTime)
{
    const double t = currentCommunicationPoint, h = communicationStepSize;
    char msg[512];
    int rc;
    ENTER(fmi3DoStep);
    (void)noSetFMUStatePriorToCurrentPoint;
    REQUIRE_NOT_NULL(eventHandlingNeeded);
    REQUIRE_NOT_NULL(terminateSimulation);
    REQUIRE_NOT_NULL(earlyReturn);
    REQUIRE_NOT_NULL(lastSuccessfulTime);
    REQUIRE(isfinite(t) && isfinite(h) && h > 0,
            "communication point %g and step size %g must be finite, step size > 0", t, h);
    REQUIRE(fabs(t - S->core.time) <= 1e-9 * fmax(1.0, fabs(t)),
            "currentCommunicationPoint = %.17g, but the FMU is at t = %.17g", t, S->core.time);
    if (S->core.terminated) {
        step_result(S, eventHandlingNeeded, terminateSimulation, earlyReturn, lastSuccessfulTime);
        log_event(S, "the model terminated at t = %.17g; no further steps", S->core.time);
        LEAVE(fmi3Discard);
    }
    rc = fmu_core_step(&S->core, h, &S->log, msg, sizeof msg);
    REQUIRE(rc >= 0, "%s", msg);
    step_result(S, eventHandlingNeeded, terminateSimulation, earlyReturn, lastSuccessfulTime);
    if (rc == 1) log_event(S, "the model terminated the simulation at t = %.17g", S->core.time);
    LEAVE(fmi3OK);
}
