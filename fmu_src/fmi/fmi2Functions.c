/* The FMI 2.0 API, Model Exchange and Co-Simulation, shared by every model of this repository:
 * the model supplies the callbacks of fmu_model.h (rw_model.c, diaphragm/diaphragm_model.c).
 * No global state: every instance owns its model data.
 *
 * This layer checks what the standard makes the importer's duty and reports every violation as
 * fmi2Error with a logged reason: the call sequence (state machines of sections 3.2.3 and 4.2.4),
 * NULL arguments, value references, types, settability, non-finite values, array sizes.
 * fmi2DoStep steps the model exactly where it can (its exact_step) or with CVODE (cs_cvode.c).
 * What does not depend on the FMI version (model defaults, variable lookup, the Co-Simulation
 * step, the FMU state) is fmu_core.c, shared with the FMI 3.0 layer fmi3Functions.c.
 *
 * Every function starts with ENTER(name), which checks the instance and the call sequence against
 * the function's mask below and records the function's name for the messages, and ends with
 * LEAVE(status), which makes every fmi2Error leave the instance in the error state. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cs_cvode.h"
#include "fmi2Functions.h"
#include "fmu_core.h"

/* ---- the state machines and which calls each state allows ---------------------------------- */

/* One bit per state of each interface type, so that one mask per function says both in which
 * states and for which interface type a call is allowed. */
enum {
    ME_INSTANTIATED = 1 << 0,
    ME_INIT = 1 << 1,
    ME_EVENT = 1 << 2,
    ME_CONT = 1 << 3,
    ME_TERMINATED = 1 << 4,
    ME_ERROR = 1 << 5,
    CS_INSTANTIATED = 1 << 6,
    CS_INIT = 1 << 7,
    CS_STEP = 1 << 8, /* slave initialized, between steps (stepComplete) */
    CS_TERMINATED = 1 << 9,
    CS_ERROR = 1 << 10
};
#define ME_ANY (ME_INSTANTIATED | ME_INIT | ME_EVENT | ME_CONT | ME_TERMINATED | ME_ERROR)
#define CS_ANY (CS_INSTANTIATED | CS_INIT | CS_STEP | CS_TERMINATED | CS_ERROR)
#define ANY_STATE (ME_ANY | CS_ANY)
#define BEFORE_INIT_END (ME_INSTANTIATED | ME_INIT | CS_INSTANTIATED | CS_INIT)
#define READABLE (ME_INIT | ME_EVENT | ME_CONT | ME_TERMINATED | ME_ERROR | CS_INIT | CS_STEP | CS_TERMINATED | CS_ERROR)

#define MASK_fmi2SetDebugLogging ANY_STATE
#define MASK_fmi2SetupExperiment (ME_INSTANTIATED | CS_INSTANTIATED)
#define MASK_fmi2EnterInitializationMode (ME_INSTANTIATED | CS_INSTANTIATED)
#define MASK_fmi2ExitInitializationMode (ME_INIT | CS_INIT)
#define MASK_fmi2Terminate (ME_EVENT | ME_CONT | CS_STEP)
#define MASK_fmi2Reset ANY_STATE
#define MASK_fmi2GetReal READABLE
#define MASK_fmi2GetInteger READABLE
#define MASK_fmi2GetBoolean READABLE
#define MASK_fmi2GetString READABLE
#define MASK_fmi2SetReal (ME_INSTANTIATED | ME_INIT | ME_EVENT | ME_CONT | CS_INSTANTIATED | CS_INIT | CS_STEP)
#define MASK_fmi2SetInteger (ME_INSTANTIATED | ME_INIT | ME_EVENT | CS_INSTANTIATED | CS_INIT | CS_STEP)
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
#define MASK_fmi2EnterEventMode (ME_EVENT | ME_CONT)
#define MASK_fmi2NewDiscreteStates ME_EVENT
#define MASK_fmi2EnterContinuousTimeMode ME_EVENT
#define MASK_fmi2CompletedIntegratorStep ME_CONT
#define MASK_fmi2SetTime (ME_EVENT | ME_CONT)
#define MASK_fmi2SetContinuousStates ME_CONT
#define MASK_fmi2GetDerivatives (ME_EVENT | ME_CONT | ME_TERMINATED | ME_ERROR)
#define MASK_fmi2GetEventIndicators (ME_INIT | ME_EVENT | ME_CONT | ME_TERMINATED | ME_ERROR)
#define MASK_fmi2GetContinuousStates (ME_INIT | ME_EVENT | ME_CONT | ME_TERMINATED | ME_ERROR)
#define MASK_fmi2GetNominalsOfContinuousStates (ME_INSTANTIATED | ME_EVENT | ME_CONT | ME_TERMINATED | ME_ERROR)
/* Co-Simulation only */
#define MASK_fmi2SetRealInputDerivatives (CS_INSTANTIATED | CS_INIT | CS_STEP)
#define MASK_fmi2GetRealOutputDerivatives CS_ANY
#define MASK_fmi2DoStep CS_STEP
#define MASK_fmi2CancelStep CS_ANY
#define MASK_fmi2GetStatus (CS_STEP | CS_TERMINATED)
#define MASK_fmi2GetRealStatus (CS_STEP | CS_TERMINATED)
#define MASK_fmi2GetIntegerStatus CS_ANY
#define MASK_fmi2GetBooleanStatus (CS_STEP | CS_TERMINATED)
#define MASK_fmi2GetStringStatus (CS_STEP | CS_TERMINATED)

/* log categories (declared in modelDescription.xml) */
enum { LOG_EVENTS = 1 << 0, LOG_WARNING = 1 << 1, LOG_ERROR = 1 << 2 };
static const char *const CATEGORY_NAMES[] = {"logEvents", "logStatusWarning", "logStatusError"};
#define N_CATEGORIES 3

/* ---- instance ------------------------------------------------------------------------------ */

/* The importer's callbacks, copied member by member: the FMI 2.0.0 headers declare the members
 * of fmi2CallbackFunctions const, so a copy of the struct could not be assigned. */
typedef struct {
    fmi2CallbackLogger logger;
    fmi2CallbackAllocateMemory allocate; /* both NULL: the C library's calloc and free */
    fmi2CallbackFreeMemory release;
    fmi2ComponentEnvironment env;
} callbacks;

typedef struct {
    char *name;
    callbacks cb;
    fmi2Type type;
    int state;
    const char *function; /* the FMI function running, for the messages */
    unsigned categories;
    fmu_logger log;
    fmu_core core;        /* the model, its data, time and Co-Simulation solver (fmu_core.h) */
} Inst;

static const char *TYPE_NAMES[] = {"Real", "Integer", "Boolean"};

/* the state of this instance's type: PHASE(S, INIT) is ME_INIT or CS_INIT */
#define PHASE(S, X) ((S)->type == fmi2CoSimulation ? CS_##X : ME_##X)

/* ---- memory -------------------------------------------------------------------------------- */

static void *alloc(const callbacks *cb, size_t n, size_t size)
{
    return cb->allocate ? cb->allocate(n, size) : calloc(n, size);
}

static void release(const callbacks *cb, void *p)
{
    if (!p) return;
    if (cb->release) cb->release(p);
    else free(p);
}

/* ---- logging ------------------------------------------------------------------------------- */

/* importers may treat the message as a format string */
static void defuse_percent(char *s)
{
    for (; *s; s++)
        if (*s == '%') *s = '_';
}

static void vlog(Inst *S, fmi2Status status, unsigned cat, const char *fmt, va_list ap)
{
    char text[1024], buf[1100];
    int idx = cat == LOG_EVENTS ? 0 : (cat == LOG_WARNING ? 1 : 2);
    if (!S->cb.logger || !(S->categories & cat)) return;
    vsnprintf(text, sizeof text, fmt, ap);
    if (S->function) snprintf(buf, sizeof buf, "%s: %s", S->function, text);
    else snprintf(buf, sizeof buf, "%s", text);
    defuse_percent(buf);
    S->cb.logger(S->cb.env, S->name, status, CATEGORY_NAMES[idx], buf);
}

static void log_event(Inst *S, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vlog(S, fmi2OK, LOG_EVENTS, fmt, ap);
    va_end(ap);
}

static void log_warning(Inst *S, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vlog(S, fmi2Warning, LOG_WARNING, fmt, ap);
    va_end(ap);
}

/* log an error (prefixed with the running function's name), enter the error state */
static fmi2Status fail(Inst *S, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vlog(S, fmi2Error, LOG_ERROR, fmt, ap);
    va_end(ap);
    S->state = PHASE(S, ERROR);
    return fmi2Error;
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
    case ME_INSTANTIATED: case CS_INSTANTIATED: return "instantiated";
    case ME_INIT: case CS_INIT: return "initializationMode";
    case ME_EVENT: return "eventMode";
    case ME_CONT: return "continuousTimeMode";
    case CS_STEP: return "stepComplete";
    case ME_TERMINATED: case CS_TERMINATED: return "terminated";
    default: return "error";
    }
}

/* Is the call allowed now? If not, log why and enter the error state. */
static int enter(Inst *S, const char *function, int mask)
{
    S->function = function;
    if (S->state & mask) return 1;
    if (S->type == fmi2CoSimulation && !(mask & CS_ANY))
        fail(S, "illegal call: a Model Exchange function called on a Co-Simulation instance");
    else if (S->type == fmi2ModelExchange && !(mask & ME_ANY))
        fail(S, "illegal call: a Co-Simulation function called on a Model Exchange instance");
    else
        fail(S, "illegal call sequence (not allowed in state %s)", state_name(S->state));
    return 0;
}

/* every fmi2Error leaves the instance in the error state, whatever path produced it */
static fmi2Status leave(Inst *S, fmi2Status status)
{
    if (status >= fmi2Error && !(S->state & (ME_ERROR | CS_ERROR))) S->state = PHASE(S, ERROR);
    S->function = NULL;
    return status;
}

/* A NULL instance has no logger to reach: fmi2Error without a message. */
#define ENTER(F)                                   \
    Inst *const S = (Inst *)c;                     \
    if (!S) return fmi2Error;                      \
    if (!enter(S, #F, MASK_##F)) return leave(S, fmi2Error)
#define LEAVE(status) return leave(S, (status))

#define REQUIRE(cond, ...) \
    do { if (!(cond)) LEAVE(fail(S, __VA_ARGS__)); } while (0)
#define REQUIRE_NOT_NULL(P) REQUIRE((P) != NULL, "argument %s must not be NULL", #P)
#define REQUIRE_SIZE(N, EXPECTED, WHAT) \
    REQUIRE((N) == (size_t)(EXPECTED), WHAT " = %u, expected %d", (unsigned)(N), (int)(EXPECTED))

/* the nominals of the continuous states: the model's, or 1 where it gives none */
static void nominals(const Inst *S, double x[]) { fmu_core_nominals(&S->core, x); }

/* ---- variables ----------------------------------------------------------------------------- */

static const fmu_var *find_var(const Inst *S, fmi2ValueReference vr) { return fmu_find_var(&S->core.model, vr); }

static const fmu_var *lookup(Inst *S, fmi2ValueReference vr, fmu_type type)
{
    const fmu_var *v = find_var(S, vr);
    if (!v) {
        fail(S, "unknown value reference %u", (unsigned)vr);
        return NULL;
    }
    if (v->type != type) {
        fail(S, "value reference %u (%s) is a %s, not a %s", (unsigned)vr, v->name, TYPE_NAMES[v->type], TYPE_NAMES[type]);
        return NULL;
    }
    return v;
}

static int initializing(const Inst *S) { return (S->state & BEFORE_INIT_END) != 0; }

/* may v be set now? (FMI 2.0 section 2.2.7) */
static int settable(Inst *S, const fmu_var *v)
{
    const int parameter = !strcmp(v->causality, "parameter"), kind = fmu_var_kind(v);
    if (kind == FMU_SET_ALWAYS) return 1;
    if (kind == FMU_SET_BEFORE_INIT_END) {
        if (initializing(S)) return 1;
        fail(S, "%s %s can only be set before fmi2ExitInitializationMode%s", parameter ? "parameter" : "start value of",
             v->name, parameter ? "" : " (use fmi2SetContinuousStates)");
        return 0;
    }
    fail(S, "variable %s (causality %s) cannot be set", v->name, v->causality);
    return 0;
}

/* common checks of a getter or setter: NULL arrays, every value reference known and of the type */
static int vr_checks(Inst *S, const fmi2ValueReference vr[], size_t nvr, const void *value, fmu_type type)
{
    size_t i;
    if (nvr == 0) return 1;
    if (!vr) return fail(S, "argument vr must not be NULL"), 0;
    if (!value) return fail(S, "argument value must not be NULL"), 0;
    for (i = 0; i < nvr; i++)
        if (!lookup(S, vr[i], type)) return 0;
    return 1;
}

/* ---- inquiry, instantiation ---------------------------------------------------------------- */

const char *fmi2GetTypesPlatform(void) { return fmi2TypesPlatform; }
const char *fmi2GetVersion(void) { return fmi2Version; }

static void instantiate_error(const fmi2CallbackFunctions *f, fmi2String name, const char *msg)
{
    f->logger(f->componentEnvironment, name ? name : "?", fmi2Error, "logStatusError", msg);
}

/* the arguments of fmi2Instantiate, checked before there is an instance to log through */
static int instantiate_arguments_ok(fmi2String instanceName, fmi2Type fmuType, fmi2String fmuGUID,
                                    const fmi2CallbackFunctions *functions)
{
    char msg[512];
    if (!instanceName || !*instanceName) {
        instantiate_error(functions, instanceName, "fmi2Instantiate: instanceName must be a non-empty string");
        return 0;
    }
    if (fmuType != fmi2ModelExchange && fmuType != fmi2CoSimulation) {
        instantiate_error(functions, instanceName, "fmi2Instantiate: fmuType must be fmi2ModelExchange or fmi2CoSimulation");
        return 0;
    }
    if (!fmuGUID || strcmp(fmuGUID, FMU_MODEL.guid) != 0) {
        snprintf(msg, sizeof msg, "fmi2Instantiate: wrong GUID \"%s\", this FMU has GUID %s", fmuGUID ? fmuGUID : "(null)",
                 FMU_MODEL.guid);
        defuse_percent(msg);
        instantiate_error(functions, instanceName, msg);
        return 0;
    }
    return 1;
}

fmi2Component fmi2Instantiate(fmi2String instanceName, fmi2Type fmuType, fmi2String fmuGUID,
                              fmi2String fmuResourceLocation, const fmi2CallbackFunctions *functions,
                              fmi2Boolean visible, fmi2Boolean loggingOn)
{
    callbacks cb;
    Inst *S;
    (void)fmuResourceLocation; /* the FMUs have no resources */
    (void)visible;
    if (!functions || !functions->logger) return NULL;
    if (!instantiate_arguments_ok(instanceName, fmuType, fmuGUID, functions)) return NULL;
    cb.logger = functions->logger;
    cb.env = functions->componentEnvironment;
    /* the importer's memory functions only as a pair */
    cb.allocate = functions->freeMemory ? functions->allocateMemory : NULL;
    cb.release = functions->allocateMemory ? functions->freeMemory : NULL;
    S = (Inst *)alloc(&cb, 1, sizeof(Inst));
    if (!S) return NULL;
    memset(S, 0, sizeof *S);
    S->cb = cb;
    fmu_model_with_defaults(&S->core.model);
    S->name = (char *)alloc(&S->cb, strlen(instanceName) + 1, 1);
    S->core.M = alloc(&S->cb, 1, S->core.model.data_size);
    S->core.inputs = (cs_input *)alloc(&S->cb, S->core.model.nvars + 1, sizeof(cs_input));
    if (!S->name || !S->core.M || !S->core.inputs) {
        fmi2FreeInstance(S);
        return NULL;
    }
    strcpy(S->name, instanceName);
    fmu_core_inputs(&S->core);
    S->type = fmuType;
    S->core.co_simulation = fmuType == fmi2CoSimulation;
    S->categories = LOG_ERROR | LOG_WARNING | (loggingOn ? LOG_EVENTS : 0);
    S->log.event = model_event;
    S->log.warning = model_warning;
    S->log.ctx = S;
    S->core.model.reset(S->core.M);
    S->state = PHASE(S, INSTANTIATED);
    log_event(S, "fmi2Instantiate: %s instance created", fmuType == fmi2CoSimulation ? "Co-Simulation" : "Model Exchange");
    return S;
}

void fmi2FreeInstance(fmi2Component c)
{
    Inst *S = (Inst *)c;
    callbacks cb;
    if (!S) return;
    cb = S->cb;
    cs_free(S->core.cs);
    release(&cb, S->core.inputs);
    release(&cb, S->core.M);
    release(&cb, S->name);
    release(&cb, S);
}

/* the category bit of a name, 0 if unknown */
static unsigned category_bit(fmi2String name)
{
    int k;
    for (k = 0; name && k < N_CATEGORIES; k++)
        if (!strcmp(name, CATEGORY_NAMES[k])) return 1u << k;
    return 0;
}

fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean loggingOn, size_t nCategories, const fmi2String categories[])
{
    size_t i;
    ENTER(fmi2SetDebugLogging);
    if (nCategories == 0) {
        S->categories = loggingOn ? (LOG_EVENTS | LOG_WARNING | LOG_ERROR) : (LOG_WARNING | LOG_ERROR);
        LEAVE(fmi2OK);
    }
    REQUIRE_NOT_NULL(categories);
    for (i = 0; i < nCategories; i++) {
        const unsigned bit = category_bit(categories[i]);
        REQUIRE(bit, "unknown log category \"%s\"", categories[i] ? categories[i] : "(null)");
        if (loggingOn) S->categories |= bit;
        else S->categories &= ~bit;
    }
    LEAVE(fmi2OK);
}

/* ---- initialization ------------------------------------------------------------------------ */

fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean toleranceDefined, fmi2Real tolerance,
                               fmi2Real startTime, fmi2Boolean stopTimeDefined, fmi2Real stopTime)
{
    ENTER(fmi2SetupExperiment);
    (void)stopTimeDefined;
    (void)stopTime;
    REQUIRE(isfinite(startTime), "startTime = %g is not finite", startTime);
    REQUIRE(!toleranceDefined || (tolerance > 0 && tolerance < 1), "tolerance = %g must be in (0, 1)", tolerance);
    S->core.rtol = toleranceDefined ? tolerance : 0.0; /* only Co-Simulation uses it (CVODE inside) */
    S->core.time = startTime;
    LEAVE(fmi2OK);
}

fmi2Status fmi2EnterInitializationMode(fmi2Component c)
{
    ENTER(fmi2EnterInitializationMode);
    S->state = PHASE(S, INIT);
    LEAVE(fmi2OK);
}

fmi2Status fmi2ExitInitializationMode(fmi2Component c)
{
    char msg[512];
    ENTER(fmi2ExitInitializationMode);
    REQUIRE(S->core.model.exit_init(S->core.M, S->core.time, &S->log, msg, sizeof msg) == 0, "%s", msg);
    if (S->type == fmi2ModelExchange) {
        S->core.initialized = 1;
        S->state = ME_EVENT;
        LEAVE(fmi2OK);
    }
    S->core.cs = cs_new(&S->core.model, S->core.M, S->core.time, S->core.rtol, &S->log, &S->core.terminated, msg, sizeof msg);
    REQUIRE(S->core.cs != NULL, "%s", msg);
    S->core.last_successful_time = S->core.time;
    S->core.initialized = 1;
    S->state = CS_STEP;
    LEAVE(fmi2OK);
}

fmi2Status fmi2Terminate(fmi2Component c)
{
    ENTER(fmi2Terminate);
    S->state = PHASE(S, TERMINATED);
    LEAVE(fmi2OK);
}

fmi2Status fmi2Reset(fmi2Component c)
{
    ENTER(fmi2Reset);
    cs_free(S->core.cs);
    S->core.cs = NULL;
    S->core.terminated = 0;
    S->core.initialized = 0;
    S->core.time = 0.0;
    S->core.model.reset(S->core.M);
    S->state = PHASE(S, INSTANTIATED);
    LEAVE(fmi2OK);
}

/* ---- getters ------------------------------------------------------------------------------- */

fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Real value[])
{
    ENTER(fmi2GetReal);
    if (!vr_checks(S, vr, nvr, value, FMU_REAL)) LEAVE(fmi2Error);
    if (nvr) S->core.model.get_real(S->core.M, initializing(S), S->core.time, vr, nvr, value);
    LEAVE(fmi2OK);
}

fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Integer value[])
{
    ENTER(fmi2GetInteger);
    if (!vr_checks(S, vr, nvr, value, FMU_INTEGER)) LEAVE(fmi2Error);
    if (nvr) S->core.model.get_integer(S->core.M, initializing(S), vr, nvr, value);
    LEAVE(fmi2OK);
}

fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Boolean value[])
{
    ENTER(fmi2GetBoolean);
    if (!vr_checks(S, vr, nvr, value, FMU_BOOLEAN)) LEAVE(fmi2Error);
    if (nvr) S->core.model.get_boolean(S->core.M, vr, nvr, value); /* fmi2Boolean is int */
    LEAVE(fmi2OK);
}

fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2String value[])
{
    ENTER(fmi2GetString);
    (void)value;
    if (nvr == 0) LEAVE(fmi2OK);
    REQUIRE_NOT_NULL(vr);
    LEAVE(fail(S, "unknown value reference %u (the model has no String variables)", (unsigned)vr[0]));
}

/* ---- setters ------------------------------------------------------------------------------- */

/* a new input value without a derivative is held over the next step */
static void hold_input(Inst *S, fmi2ValueReference vr)
{
    cs_input *in = fmu_core_find_input(&S->core, vr);
    if (in) in->slope = 0.0;
}

fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2Real value[])
{
    size_t i;
    char msg[256];
    ENTER(fmi2SetReal);
    if (!vr_checks(S, vr, nvr, value, FMU_REAL)) LEAVE(fmi2Error);
    for (i = 0; i < nvr; i++) {
        const fmu_var *v = find_var(S, vr[i]);
        REQUIRE(isfinite(value[i]), "%s = %g is not a finite number", v->name, value[i]);
        if (!settable(S, v)) LEAVE(fmi2Error);
        REQUIRE(S->core.model.set_real(S->core.M, vr[i], value[i], msg, sizeof msg) == 0, "%s", msg);
        hold_input(S, vr[i]);
    }
    LEAVE(fmi2OK);
}

fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2Integer value[])
{
    size_t i;
    char msg[256];
    ENTER(fmi2SetInteger);
    if (!vr_checks(S, vr, nvr, value, FMU_INTEGER)) LEAVE(fmi2Error);
    for (i = 0; i < nvr; i++) {
        if (!settable(S, find_var(S, vr[i]))) LEAVE(fmi2Error);
        REQUIRE(S->core.model.set_integer(S->core.M, vr[i], value[i], msg, sizeof msg) == 0, "%s", msg);
    }
    LEAVE(fmi2OK);
}

fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2Boolean value[])
{
    const fmu_var *v;
    ENTER(fmi2SetBoolean);
    (void)value;
    if (nvr == 0) LEAVE(fmi2OK);
    REQUIRE_NOT_NULL(vr);
    v = lookup(S, vr[0], FMU_BOOLEAN);
    if (!v) LEAVE(fmi2Error);
    /* no model of this repository has a settable Boolean */
    LEAVE(fail(S, "variable %s (causality %s) cannot be set", v->name, v->causality));
}

fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2String value[])
{
    ENTER(fmi2SetString);
    (void)value;
    if (nvr == 0) LEAVE(fmi2OK);
    REQUIRE_NOT_NULL(vr);
    LEAVE(fail(S, "unknown value reference %u (the model has no String variables)", (unsigned)vr[0]));
}

/* ---- FMU state (canGetAndSetFMUstate, canSerializeFMUstate): fmu_core.c -------------------- */

/* a block of n bytes for an FMU state, reusing *old when it has the size */
static unsigned char *state_block(Inst *S, fmi2FMUstate old, size_t n)
{
    if (old) {
        if (fmu_state_bytes(old) == n) return (unsigned char *)old;
        release(&S->cb, old);
    }
    return (unsigned char *)alloc(&S->cb, n, 1);
}

/* a state the master hands back, checked to be one of ours; if not, log why */
static int own_state(Inst *S, fmi2FMUstate state)
{
    char msg[256];
    if (fmu_state_is_ours(state, msg, sizeof msg)) return fail(S, "%s", msg), 0;
    return 1;
}

fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate *FMUstate)
{
    unsigned char *block;
    size_t n;
    ENTER(fmi2GetFMUstate);
    REQUIRE_NOT_NULL(FMUstate);
    if (*FMUstate && !own_state(S, *FMUstate)) LEAVE(fmi2Error);
    n = fmu_state_size(&S->core);
    block = state_block(S, *FMUstate, n);
    *FMUstate = block;
    REQUIRE(block != NULL, "out of memory for an FMU state of %u bytes", (unsigned)n);
    fmu_state_write(&S->core, block);
    LEAVE(fmi2OK);
}

fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate FMUstate)
{
    char msg[512];
    ENTER(fmi2SetFMUstate);
    if (!own_state(S, FMUstate)) LEAVE(fmi2Error);
    REQUIRE(fmu_state_read(&S->core, FMUstate, msg, sizeof msg) == 0, "%s", msg);
    LEAVE(fmi2OK);
}

fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate *FMUstate)
{
    ENTER(fmi2FreeFMUstate);
    REQUIRE_NOT_NULL(FMUstate);
    if (!*FMUstate) LEAVE(fmi2OK);
    if (!own_state(S, *FMUstate)) LEAVE(fmi2Error);
    release(&S->cb, *FMUstate);
    *FMUstate = NULL;
    LEAVE(fmi2OK);
}

fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate FMUstate, size_t *size)
{
    ENTER(fmi2SerializedFMUstateSize);
    REQUIRE_NOT_NULL(size);
    if (!own_state(S, FMUstate)) LEAVE(fmi2Error);
    *size = fmu_state_bytes(FMUstate);
    LEAVE(fmi2OK);
}

fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate FMUstate, fmi2Byte serializedState[], size_t size)
{
    ENTER(fmi2SerializeFMUstate);
    REQUIRE_NOT_NULL(serializedState);
    if (!own_state(S, FMUstate)) LEAVE(fmi2Error);
    REQUIRE(size == fmu_state_bytes(FMUstate), "size = %u, but the FMU state has %u bytes (fmi2SerializedFMUstateSize)",
            (unsigned)size, (unsigned)fmu_state_bytes(FMUstate));
    memcpy(serializedState, FMUstate, size);
    LEAVE(fmi2OK);
}

fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte serializedState[], size_t size, fmi2FMUstate *FMUstate)
{
    unsigned char *block;
    char msg[512];
    ENTER(fmi2DeSerializeFMUstate);
    REQUIRE_NOT_NULL(serializedState);
    REQUIRE_NOT_NULL(FMUstate);
    if (*FMUstate && !own_state(S, *FMUstate)) LEAVE(fmi2Error);
    REQUIRE(fmu_state_check(&S->core, serializedState, size, msg, sizeof msg) == 0, "%s", msg);
    block = state_block(S, *FMUstate, size);
    *FMUstate = block;
    REQUIRE(block != NULL, "out of memory for an FMU state of %u bytes", (unsigned)size);
    memcpy(block, serializedState, size);
    LEAVE(fmi2OK);
}

/* ---- directional derivatives: not supported ------------------------------------------------ */

fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference u[], size_t nu,
                                        const fmi2ValueReference z[], size_t nz, const fmi2Real dv[], fmi2Real dz[])
{
    ENTER(fmi2GetDirectionalDerivative);
    (void)u; (void)nu; (void)z; (void)nz; (void)dv; (void)dz;
    LEAVE(fail(S, "not supported by this FMU (providesDirectionalDerivative is false)"));
}

/* ---- Model Exchange ------------------------------------------------------------------------ */

fmi2Status fmi2EnterEventMode(fmi2Component c)
{
    ENTER(fmi2EnterEventMode);
    S->state = ME_EVENT;
    LEAVE(fmi2OK);
}

fmi2Status fmi2NewDiscreteStates(fmi2Component c, fmi2EventInfo *info)
{
    fmu_event_result r;
    ENTER(fmi2NewDiscreteStates);
    REQUIRE_NOT_NULL(info);
    S->core.model.event_update(S->core.M, S->core.time, &S->log, &r);
    info->newDiscreteStatesNeeded = r.more ? fmi2True : fmi2False;
    info->terminateSimulation = r.terminate ? fmi2True : fmi2False;
    info->nominalsOfContinuousStatesChanged = fmi2False; /* the nominals are constants */
    info->valuesOfContinuousStatesChanged = r.states_changed ? fmi2True : fmi2False;
    info->nextEventTimeDefined = r.next_time_defined ? fmi2True : fmi2False;
    info->nextEventTime = r.next_time_defined ? r.next_time : 0.0;
    LEAVE(fmi2OK);
}

fmi2Status fmi2EnterContinuousTimeMode(fmi2Component c)
{
    ENTER(fmi2EnterContinuousTimeMode);
    S->state = ME_CONT;
    LEAVE(fmi2OK);
}

fmi2Status fmi2CompletedIntegratorStep(fmi2Component c, fmi2Boolean noSetFMUStatePriorToCurrentPoint,
                                       fmi2Boolean *enterEventMode, fmi2Boolean *terminateSimulation)
{
    ENTER(fmi2CompletedIntegratorStep);
    (void)noSetFMUStatePriorToCurrentPoint;
    REQUIRE_NOT_NULL(enterEventMode);
    REQUIRE_NOT_NULL(terminateSimulation);
    *enterEventMode = fmi2False;
    *terminateSimulation = fmi2False;
    LEAVE(fmi2OK);
}

fmi2Status fmi2SetTime(fmi2Component c, fmi2Real time)
{
    ENTER(fmi2SetTime);
    REQUIRE(isfinite(time), "time = %g is not finite", time);
    S->core.time = time;
    LEAVE(fmi2OK);
}

fmi2Status fmi2SetContinuousStates(fmi2Component c, const fmi2Real x[], size_t nx)
{
    size_t i;
    ENTER(fmi2SetContinuousStates);
    REQUIRE_NOT_NULL(x);
    REQUIRE_SIZE(nx, S->core.model.nx, "nx");
    for (i = 0; i < nx; i++) REQUIRE(isfinite(x[i]), "state %u = %g is not finite", (unsigned)i, x[i]);
    S->core.model.set_states(S->core.M, x);
    LEAVE(fmi2OK);
}

fmi2Status fmi2GetDerivatives(fmi2Component c, fmi2Real dx[], size_t nx)
{
    size_t i;
    ENTER(fmi2GetDerivatives);
    REQUIRE_NOT_NULL(dx);
    REQUIRE_SIZE(nx, S->core.model.nx, "nx");
    S->core.model.derivatives(S->core.M, dx);
    for (i = 0; i < nx; i++) REQUIRE(isfinite(dx[i]), "derivative %u is not finite at t = %g", (unsigned)i, S->core.time);
    LEAVE(fmi2OK);
}

fmi2Status fmi2GetEventIndicators(fmi2Component c, fmi2Real z[], size_t nz)
{
    ENTER(fmi2GetEventIndicators);
    REQUIRE_NOT_NULL(z);
    REQUIRE_SIZE(nz, S->core.model.nz, "ni");
    S->core.model.event_indicators(S->core.M, initializing(S), z);
    LEAVE(fmi2OK);
}

fmi2Status fmi2GetContinuousStates(fmi2Component c, fmi2Real x[], size_t nx)
{
    ENTER(fmi2GetContinuousStates);
    REQUIRE_NOT_NULL(x);
    REQUIRE_SIZE(nx, S->core.model.nx, "nx");
    S->core.model.get_states(S->core.M, initializing(S), x);
    LEAVE(fmi2OK);
}

fmi2Status fmi2GetNominalsOfContinuousStates(fmi2Component c, fmi2Real x_nominal[], size_t nx)
{
    ENTER(fmi2GetNominalsOfContinuousStates);
    REQUIRE_NOT_NULL(x_nominal);
    REQUIRE_SIZE(nx, S->core.model.nx, "nx");
    nominals(S, x_nominal);
    LEAVE(fmi2OK);
}

/* ---- Co-Simulation ------------------------------------------------------------------------- */

/* First derivatives of Real inputs ramp them over the next step (canInterpolateInputs). */
fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                                       const fmi2Integer order[], const fmi2Real value[])
{
    size_t i;
    ENTER(fmi2SetRealInputDerivatives);
    if (nvr == 0) LEAVE(fmi2OK);
    REQUIRE_NOT_NULL(order);
    if (!vr_checks(S, vr, nvr, value, FMU_REAL)) LEAVE(fmi2Error);
    for (i = 0; i < nvr; i++) {
        const fmu_var *v = find_var(S, vr[i]);
        cs_input *in = fmu_core_find_input(&S->core, vr[i]);
        REQUIRE(in != NULL, "%s is not an input", v->name);
        REQUIRE(order[i] == 1, "order %d of %s (only first derivatives are used, maxInputDerivativeOrder would be exceeded)",
                (int)order[i], v->name);
        REQUIRE(isfinite(value[i]), "der(%s) = %g is not a finite number", v->name, value[i]);
        in->slope = value[i];
    }
    LEAVE(fmi2OK);
}

fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                                        const fmi2Integer order[], fmi2Real value[])
{
    ENTER(fmi2GetRealOutputDerivatives);
    (void)vr; (void)nvr; (void)order; (void)value;
    LEAVE(fail(S, "not supported by this FMU (maxOutputDerivativeOrder is 0)"));
}

fmi2Status fmi2DoStep(fmi2Component c, fmi2Real currentCommunicationPoint, fmi2Real communicationStepSize,
                      fmi2Boolean noSetFMUStatePriorToCurrentCommunicationPoint)
{
    const double t = currentCommunicationPoint, h = communicationStepSize;
    char msg[512];
    int rc;
    ENTER(fmi2DoStep);
    (void)noSetFMUStatePriorToCurrentCommunicationPoint;
    REQUIRE(isfinite(t) && isfinite(h) && h > 0,
            "communication point %g and step size %g must be finite, step size > 0", t, h);
    REQUIRE(fabs(t - S->core.time) <= 1e-9 * fmax(1.0, fabs(t)),
            "currentCommunicationPoint = %.17g, but the FMU is at t = %.17g", t, S->core.time);
    if (S->core.terminated) {
        log_event(S, "the model terminated at t = %.17g; no further steps", S->core.time);
        LEAVE(fmi2Discard);
    }
    rc = fmu_core_step(&S->core, h, &S->log, msg, sizeof msg);
    REQUIRE(rc >= 0, "%s", msg);
    if (rc == 1) {
        log_event(S, "the model terminated the simulation at t = %.17g", S->core.time);
        LEAVE(fmi2Discard);
    }
    LEAVE(fmi2OK);
}

fmi2Status fmi2CancelStep(fmi2Component c)
{
    ENTER(fmi2CancelStep);
    LEAVE(fail(S, "not supported (fmi2DoStep never returns fmi2Pending)"));
}

fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind s, fmi2Status *v)
{
    ENTER(fmi2GetStatus);
    REQUIRE_NOT_NULL(v);
    REQUIRE(s == fmi2DoStepStatus, "status kind %d is not a fmi2Status", (int)s);
    *v = S->core.terminated ? fmi2Discard : fmi2OK; /* steps are synchronous: never pending */
    LEAVE(fmi2OK);
}

fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind s, fmi2Real *v)
{
    ENTER(fmi2GetRealStatus);
    REQUIRE_NOT_NULL(v);
    REQUIRE(s == fmi2LastSuccessfulTime, "status kind %d is not a Real", (int)s);
    *v = S->core.last_successful_time;
    LEAVE(fmi2OK);
}

fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind s, fmi2Integer *v)
{
    ENTER(fmi2GetIntegerStatus);
    (void)s; (void)v;
    LEAVE(fail(S, "not supported (no Integer status kinds in FMI 2.0)"));
}

fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind s, fmi2Boolean *v)
{
    ENTER(fmi2GetBooleanStatus);
    REQUIRE_NOT_NULL(v);
    REQUIRE(s == fmi2Terminated, "status kind %d is not a Boolean", (int)s);
    *v = S->core.terminated ? fmi2True : fmi2False;
    LEAVE(fmi2OK);
}

fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind s, fmi2String *v)
{
    ENTER(fmi2GetStringStatus);
    REQUIRE_NOT_NULL(v);
    REQUIRE(s == fmi2PendingStatus, "status kind %d is not a String", (int)s);
    *v = "";
    LEAVE(fmi2OK);
}
