/* The FMI 2.0 API, Model Exchange and Co-Simulation, shared by every model of this repository:
 * the model supplies the callbacks of fmu_model.h (rw_model.c, diaphragm/diaphragm_model.c).
 * No global state: every instance owns its model data.
 *
 * This layer checks what the standard makes the importer's duty and reports every violation as
 * fmi2Error with a logged reason: the call sequence (state machines of sections 3.2.3 and 4.2.4),
 * NULL arguments, value references, types, settability, non-finite values, array sizes.
 * fmi2DoStep integrates the model with CVODE (cs_cvode.c).
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
#include "fmu_model.h"

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
    fmu_model model;      /* FMU_MODEL with defaults for the callbacks it leaves out */
    void *M;              /* the model's data (model.data_size bytes) */
    double time;
    fmu_logger log;
    /* Co-Simulation */
    double rtol;
    cs_solver *cs;
    cs_input *inputs;     /* every Real input, value refreshed before each step */
    size_t n_inputs;
    unsigned *step_vrs;   /* the inputs' value references and slopes as fmu_model.exact_step takes */
    double *step_slopes;  /* them (allocated here: MSVC, which builds FMUs from sources, has no VLAs) */
    int terminated;       /* the model ended the run (fmi2Terminated status) */
    int initialized;      /* fmi2ExitInitializationMode succeeded (until fmi2Reset) */
    double last_successful_time;
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

/* ---- default model callbacks: a model writes only what it has ------------------------------ */

static void no_get_integer(void *M, int initializing, const unsigned vr[], size_t n, int v[])
{
    (void)M; (void)initializing; (void)vr;
    memset(v, 0, n * sizeof *v); /* unreachable: there is no Integer variable to look up */
}

static void no_get_boolean(void *M, const unsigned vr[], size_t n, int v[])
{
    (void)M; (void)vr;
    memset(v, 0, n * sizeof *v); /* unreachable: there is no Boolean variable to look up */
}

static int no_set_real(void *M, unsigned vr, double v, char *msg, size_t n)
{
    (void)M; (void)v;
    snprintf(msg, n, "value reference %u cannot be set", vr);
    return 1;
}

static int no_set_integer(void *M, unsigned vr, int v, char *msg, size_t n)
{
    (void)M; (void)v;
    snprintf(msg, n, "value reference %u cannot be set", vr);
    return 1;
}

static int no_checks_at_exit_init(void *M, double time, const fmu_logger *log, char *msg, size_t n)
{
    (void)M; (void)time; (void)log; (void)msg; (void)n;
    return 0;
}

static void no_event_indicators(void *M, int initializing, double z[]) { (void)M; (void)initializing; (void)z; }

static void keep_nominals(double x[]) { (void)x; } /* the caller filled in 1 for every state */

static void no_events(void *M, double time, const fmu_logger *log, fmu_event_result *r)
{
    (void)M; (void)time; (void)log;
    memset(r, 0, sizeof *r);
}

static void model_with_defaults(fmu_model *m)
{
    *m = FMU_MODEL;
    if (!m->get_integer) m->get_integer = no_get_integer;
    if (!m->get_boolean) m->get_boolean = no_get_boolean;
    if (!m->set_real) m->set_real = no_set_real;
    if (!m->set_integer) m->set_integer = no_set_integer;
    if (!m->exit_init) m->exit_init = no_checks_at_exit_init;
    if (!m->event_indicators) m->event_indicators = no_event_indicators;
    if (!m->nominals) m->nominals = keep_nominals;
    if (!m->event_update) m->event_update = no_events;
}

/* the nominals of the continuous states: the model's, or 1 where it gives none */
static void nominals(const Inst *S, double x[])
{
    int i;
    for (i = 0; i < S->model.nx; i++) x[i] = 1.0;
    S->model.nominals(x);
}

/* ---- variables ----------------------------------------------------------------------------- */

static const fmu_var *find_var(const Inst *S, fmi2ValueReference vr)
{
    size_t i;
    for (i = 0; i < S->model.nvars; i++)
        if (S->model.vars[i].vr == vr) return &S->model.vars[i];
    return NULL;
}

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
    const int parameter = !strcmp(v->causality, "parameter");
    if (!strcmp(v->causality, "input")) return 1;
    if (parameter || !strcmp(v->initial, "exact")) {
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
    size_t i;
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
    model_with_defaults(&S->model);
    S->name = (char *)alloc(&S->cb, strlen(instanceName) + 1, 1);
    S->M = alloc(&S->cb, 1, S->model.data_size);
    S->inputs = (cs_input *)alloc(&S->cb, S->model.nvars + 1, sizeof(cs_input));
    S->step_vrs = (unsigned *)alloc(&S->cb, S->model.nvars + 1, sizeof(unsigned));
    S->step_slopes = (double *)alloc(&S->cb, S->model.nvars + 1, sizeof(double));
    if (!S->name || !S->M || !S->inputs || !S->step_vrs || !S->step_slopes) {
        fmi2FreeInstance(S);
        return NULL;
    }
    strcpy(S->name, instanceName);
    for (i = 0; i < S->model.nvars; i++)
        if (S->model.vars[i].type == FMU_REAL && !strcmp(S->model.vars[i].causality, "input"))
            S->inputs[S->n_inputs++].vr = S->model.vars[i].vr;
    S->type = fmuType;
    S->categories = LOG_ERROR | LOG_WARNING | (loggingOn ? LOG_EVENTS : 0);
    S->log.event = model_event;
    S->log.warning = model_warning;
    S->log.ctx = S;
    S->model.reset(S->M);
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
    cs_free(S->cs);
    release(&cb, S->inputs);
    release(&cb, S->step_vrs);
    release(&cb, S->step_slopes);
    release(&cb, S->M);
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
    S->rtol = toleranceDefined ? tolerance : 0.0; /* only Co-Simulation uses it (CVODE inside) */
    S->time = startTime;
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
    REQUIRE(S->model.exit_init(S->M, S->time, &S->log, msg, sizeof msg) == 0, "%s", msg);
    if (S->type == fmi2ModelExchange) {
        S->initialized = 1;
        S->state = ME_EVENT;
        LEAVE(fmi2OK);
    }
    S->cs = cs_new(&S->model, S->M, S->time, S->rtol, &S->log, &S->terminated, msg, sizeof msg);
    REQUIRE(S->cs != NULL, "%s", msg);
    S->last_successful_time = S->time;
    S->initialized = 1;
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
    cs_free(S->cs);
    S->cs = NULL;
    S->terminated = 0;
    S->initialized = 0;
    S->time = 0.0;
    S->model.reset(S->M);
    S->state = PHASE(S, INSTANTIATED);
    LEAVE(fmi2OK);
}

/* ---- getters ------------------------------------------------------------------------------- */

fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Real value[])
{
    ENTER(fmi2GetReal);
    if (!vr_checks(S, vr, nvr, value, FMU_REAL)) LEAVE(fmi2Error);
    if (nvr) S->model.get_real(S->M, initializing(S), S->time, vr, nvr, value);
    LEAVE(fmi2OK);
}

fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Integer value[])
{
    ENTER(fmi2GetInteger);
    if (!vr_checks(S, vr, nvr, value, FMU_INTEGER)) LEAVE(fmi2Error);
    if (nvr) S->model.get_integer(S->M, initializing(S), vr, nvr, value);
    LEAVE(fmi2OK);
}

fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Boolean value[])
{
    ENTER(fmi2GetBoolean);
    if (!vr_checks(S, vr, nvr, value, FMU_BOOLEAN)) LEAVE(fmi2Error);
    if (nvr) S->model.get_boolean(S->M, vr, nvr, value); /* fmi2Boolean is int */
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
    size_t k;
    for (k = 0; k < S->n_inputs; k++)
        if (S->inputs[k].vr == vr) S->inputs[k].slope = 0.0;
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
        REQUIRE(S->model.set_real(S->M, vr[i], value[i], msg, sizeof msg) == 0, "%s", msg);
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
        REQUIRE(S->model.set_integer(S->M, vr[i], value[i], msg, sizeof msg) == 0, "%s", msg);
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

/* ---- FMU state (canGetAndSetFMUstate, canSerializeFMUstate) -------------------------------- */

/* An FMU state is kept in its serialized form: one block of bytes, a header and then the model's
 * data (a byte copy: fmu_model.h asks for plain data), the Real inputs' slopes and, in
 * Co-Simulation after initialization, what re-creates the integrator exactly (cs_get_state).
 * fmi2SerializeFMUstate is a copy; fmi2DeSerializeFMUstate checks everything before copying.
 * The call-sequence state of the instance is not part of it: the master is in charge of that. */
#define STATE_MAGIC "RWFMUS1" /* 8 bytes with the terminating zero; the last digit is the format */

typedef struct {
    char magic[8];
    char guid[64];
    unsigned long long size; /* of the whole block */
    int type;                /* fmi2ModelExchange or fmi2CoSimulation */
    int initialized;         /* taken after fmi2ExitInitializationMode */
    int terminated;
    double time, rtol, last_successful_time;
    unsigned long long data_size, n_inputs, solver_size;
} state_header;

static size_t state_size(const state_header *h)
{
    return sizeof *h + (size_t)h->data_size + (size_t)h->n_inputs * sizeof(double) + (size_t)h->solver_size;
}

static void make_header(const Inst *S, state_header *h)
{
    memset(h, 0, sizeof *h);
    memcpy(h->magic, STATE_MAGIC, sizeof h->magic);
    snprintf(h->guid, sizeof h->guid, "%s", S->model.guid);
    h->type = (int)S->type;
    h->initialized = S->initialized;
    h->terminated = S->terminated;
    h->time = S->time;
    h->rtol = S->rtol;
    h->last_successful_time = S->last_successful_time;
    h->data_size = S->model.data_size;
    h->n_inputs = S->n_inputs;
    h->solver_size = S->cs ? cs_state_size(S->cs) : 0;
    h->size = state_size(h);
}

/* the instance's state into `block` (h->size bytes) */
static void write_state(Inst *S, const state_header *h, unsigned char *block)
{
    unsigned char *p = block + sizeof *h;
    size_t k;
    memcpy(block, h, sizeof *h);
    memcpy(p, S->M, S->model.data_size);
    p += S->model.data_size;
    for (k = 0; k < S->n_inputs; k++, p += sizeof(double)) memcpy(p, &S->inputs[k].slope, sizeof(double));
    if (S->cs) cs_get_state(S->cs, p);
}

/* Is `block` (n bytes) an FMU state of this FMU and this binary? If not, log why. */
static int compatible_state(Inst *S, const void *block, size_t n, state_header *h)
{
    state_header mine;
    if (n < sizeof *h) return fail(S, "the FMU state has %u bytes, fewer than its header (%u)", (unsigned)n, (unsigned)sizeof *h), 0;
    memcpy(h, block, sizeof *h);
    if (memcmp(h->magic, STATE_MAGIC, sizeof h->magic) != 0) return fail(S, "not an FMU state of this FMU (bad magic number)"), 0;
    h->guid[sizeof h->guid - 1] = '\0';
    if (strcmp(h->guid, S->model.guid) != 0)
        return fail(S, "the FMU state belongs to the FMU with GUID %s, this FMU has GUID %s", h->guid, S->model.guid), 0;
    if (h->size != n) return fail(S, "the FMU state says it has %llu bytes, but %u were given", h->size, (unsigned)n), 0;
    make_header(S, &mine);
    if (h->data_size != mine.data_size || h->n_inputs != mine.n_inputs || state_size(h) != n)
        return fail(S, "the FMU state's sizes (model data %llu, inputs %llu, total %llu) do not match this binary's "
                       "(%llu, %llu)", h->data_size, h->n_inputs, h->size, mine.data_size, mine.n_inputs), 0;
    return 1;
}

/* Can the instance take this compatible state now (same interface type, same phase)? */
static int applicable_state(Inst *S, const state_header *h)
{
    state_header mine;
    make_header(S, &mine);
    if (h->type != mine.type)
        return fail(S, "the FMU state is of a %s instance, this is a %s instance",
                    h->type == fmi2CoSimulation ? "Co-Simulation" : "Model Exchange",
                    mine.type == fmi2CoSimulation ? "Co-Simulation" : "Model Exchange"), 0;
    if (h->initialized != mine.initialized)
        return fail(S, "the FMU state was taken %s fmi2ExitInitializationMode, the instance is %s it",
                    h->initialized ? "after" : "before", mine.initialized ? "past" : "before"), 0;
    if (h->solver_size != mine.solver_size)
        return fail(S, "the FMU state's integrator part has %llu bytes, expected %llu", h->solver_size, mine.solver_size), 0;
    return 1;
}

/* a checked state block into the instance */
static int read_state(Inst *S, const state_header *h, const unsigned char *block)
{
    const unsigned char *p = block + sizeof *h;
    char msg[256];
    size_t k;
    if (S->cs && cs_set_state(S->cs, p + h->data_size + h->n_inputs * sizeof(double), (size_t)h->solver_size, msg, sizeof msg))
        return fail(S, "%s", msg), 0;
    memcpy(S->M, p, S->model.data_size);
    p += S->model.data_size;
    for (k = 0; k < S->n_inputs; k++, p += sizeof(double)) memcpy(&S->inputs[k].slope, p, sizeof(double));
    S->time = h->time;
    S->rtol = h->rtol;
    S->terminated = h->terminated;
    S->last_successful_time = h->last_successful_time;
    return 1;
}

/* a block of n bytes for an FMU state, reusing *old when it has the size */
static unsigned char *state_block(Inst *S, fmi2FMUstate old, size_t n)
{
    state_header h;
    if (old) {
        memcpy(&h, old, sizeof h);
        if (h.size == n) return (unsigned char *)old;
        release(&S->cb, old);
    }
    return (unsigned char *)alloc(&S->cb, n, 1);
}

/* the header of a state the master hands back, checked to be one of ours */
static int own_state(Inst *S, fmi2FMUstate state, state_header *h)
{
    if (!state) return fail(S, "argument FMUstate must not be NULL"), 0;
    memcpy(h, state, sizeof *h);
    if (memcmp(h->magic, STATE_MAGIC, sizeof h->magic) != 0) return fail(S, "not an FMU state of this FMU (bad magic number)"), 0;
    return 1;
}

fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate *FMUstate)
{
    state_header h;
    unsigned char *block;
    ENTER(fmi2GetFMUstate);
    REQUIRE_NOT_NULL(FMUstate);
    if (*FMUstate && !own_state(S, *FMUstate, &h)) LEAVE(fmi2Error);
    make_header(S, &h);
    block = state_block(S, *FMUstate, (size_t)h.size);
    *FMUstate = block;
    REQUIRE(block != NULL, "out of memory for an FMU state of %llu bytes", h.size);
    write_state(S, &h, block);
    LEAVE(fmi2OK);
}

fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate FMUstate)
{
    state_header h;
    ENTER(fmi2SetFMUstate);
    if (!own_state(S, FMUstate, &h)) LEAVE(fmi2Error);
    if (!compatible_state(S, FMUstate, (size_t)h.size, &h) || !applicable_state(S, &h) ||
        !read_state(S, &h, (const unsigned char *)FMUstate))
        LEAVE(fmi2Error);
    LEAVE(fmi2OK);
}

fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate *FMUstate)
{
    state_header h;
    ENTER(fmi2FreeFMUstate);
    REQUIRE_NOT_NULL(FMUstate);
    if (!*FMUstate) LEAVE(fmi2OK);
    if (!own_state(S, *FMUstate, &h)) LEAVE(fmi2Error);
    release(&S->cb, *FMUstate);
    *FMUstate = NULL;
    LEAVE(fmi2OK);
}

fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate FMUstate, size_t *size)
{
    state_header h;
    ENTER(fmi2SerializedFMUstateSize);
    REQUIRE_NOT_NULL(size);
    if (!own_state(S, FMUstate, &h)) LEAVE(fmi2Error);
    *size = (size_t)h.size;
    LEAVE(fmi2OK);
}

fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate FMUstate, fmi2Byte serializedState[], size_t size)
{
    state_header h;
    ENTER(fmi2SerializeFMUstate);
    REQUIRE_NOT_NULL(serializedState);
    if (!own_state(S, FMUstate, &h)) LEAVE(fmi2Error);
    REQUIRE(size == h.size, "size = %u, but the FMU state has %llu bytes (fmi2SerializedFMUstateSize)", (unsigned)size, h.size);
    memcpy(serializedState, FMUstate, size);
    LEAVE(fmi2OK);
}

fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte serializedState[], size_t size, fmi2FMUstate *FMUstate)
{
    state_header h;
    unsigned char *block;
    ENTER(fmi2DeSerializeFMUstate);
    REQUIRE_NOT_NULL(serializedState);
    REQUIRE_NOT_NULL(FMUstate);
    if (*FMUstate && !own_state(S, *FMUstate, &h)) LEAVE(fmi2Error);
    if (!compatible_state(S, serializedState, size, &h)) LEAVE(fmi2Error);
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
    S->model.event_update(S->M, S->time, &S->log, &r);
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
    S->time = time;
    LEAVE(fmi2OK);
}

fmi2Status fmi2SetContinuousStates(fmi2Component c, const fmi2Real x[], size_t nx)
{
    size_t i;
    ENTER(fmi2SetContinuousStates);
    REQUIRE_NOT_NULL(x);
    REQUIRE_SIZE(nx, S->model.nx, "nx");
    for (i = 0; i < nx; i++) REQUIRE(isfinite(x[i]), "state %u = %g is not finite", (unsigned)i, x[i]);
    S->model.set_states(S->M, x);
    LEAVE(fmi2OK);
}

fmi2Status fmi2GetDerivatives(fmi2Component c, fmi2Real dx[], size_t nx)
{
    size_t i;
    ENTER(fmi2GetDerivatives);
    REQUIRE_NOT_NULL(dx);
    REQUIRE_SIZE(nx, S->model.nx, "nx");
    S->model.derivatives(S->M, dx);
    for (i = 0; i < nx; i++) REQUIRE(isfinite(dx[i]), "derivative %u is not finite at t = %g", (unsigned)i, S->time);
    LEAVE(fmi2OK);
}

fmi2Status fmi2GetEventIndicators(fmi2Component c, fmi2Real z[], size_t nz)
{
    ENTER(fmi2GetEventIndicators);
    REQUIRE_NOT_NULL(z);
    REQUIRE_SIZE(nz, S->model.nz, "ni");
    S->model.event_indicators(S->M, initializing(S), z);
    LEAVE(fmi2OK);
}

fmi2Status fmi2GetContinuousStates(fmi2Component c, fmi2Real x[], size_t nx)
{
    ENTER(fmi2GetContinuousStates);
    REQUIRE_NOT_NULL(x);
    REQUIRE_SIZE(nx, S->model.nx, "nx");
    S->model.get_states(S->M, initializing(S), x);
    LEAVE(fmi2OK);
}

fmi2Status fmi2GetNominalsOfContinuousStates(fmi2Component c, fmi2Real x_nominal[], size_t nx)
{
    ENTER(fmi2GetNominalsOfContinuousStates);
    REQUIRE_NOT_NULL(x_nominal);
    REQUIRE_SIZE(nx, S->model.nx, "nx");
    nominals(S, x_nominal);
    LEAVE(fmi2OK);
}

/* ---- Co-Simulation ------------------------------------------------------------------------- */

static cs_input *find_input(Inst *S, fmi2ValueReference vr)
{
    size_t k;
    for (k = 0; k < S->n_inputs; k++)
        if (S->inputs[k].vr == vr) return &S->inputs[k];
    return NULL;
}

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
        cs_input *in = find_input(S, vr[i]);
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

/* the values the master set, read back from the model, as the held values over the next step */
static void refresh_inputs(Inst *S)
{
    size_t k;
    for (k = 0; k < S->n_inputs; k++) S->model.get_real(S->M, 0, S->time, &S->inputs[k].vr, 1, &S->inputs[k].value);
}

fmi2Status fmi2DoStep(fmi2Component c, fmi2Real currentCommunicationPoint, fmi2Real communicationStepSize,
                      fmi2Boolean noSetFMUStatePriorToCurrentCommunicationPoint)
{
    const double t = currentCommunicationPoint, h = communicationStepSize;
    double t_reached;
    char msg[512];
    size_t k;
    int rc;
    ENTER(fmi2DoStep);
    (void)noSetFMUStatePriorToCurrentCommunicationPoint;
    REQUIRE(isfinite(t) && isfinite(h) && h > 0,
            "communication point %g and step size %g must be finite, step size > 0", t, h);
    REQUIRE(fabs(t - S->time) <= 1e-9 * fmax(1.0, fabs(t)),
            "currentCommunicationPoint = %.17g, but the FMU is at t = %.17g", t, S->time);
    if (S->terminated) {
        log_event(S, "the model terminated at t = %.17g; no further steps", S->time);
        LEAVE(fmi2Discard);
    }
    refresh_inputs(S);
    msg[0] = '\0'; /* the exact step may leave its reason for declining here (cs_none.c reports it) */
    rc = FMU_NOT_EXACT; /* exact step where the model offers one (RockingWall: cs_exact.c), else CVODE */
    if (S->model.exact_step) {
        for (k = 0; k < S->n_inputs; k++) S->step_vrs[k] = S->inputs[k].vr, S->step_slopes[k] = S->inputs[k].slope;
        rc = S->model.exact_step(S->M, S->time, h, S->step_vrs, S->step_slopes, S->n_inputs, &S->log, &t_reached, msg,
                                 sizeof msg);
    }
    if (rc == FMU_NOT_EXACT) rc = cs_step(S->cs, S->time, h, S->inputs, S->n_inputs, &S->log, &t_reached, msg, sizeof msg);
    for (k = 0; k < S->n_inputs; k++) S->inputs[k].slope = 0.0; /* derivatives hold for one step */
    REQUIRE(rc >= 0, "%s", msg);
    S->time = t_reached;
    S->last_successful_time = t_reached;
    if (rc == 1) {
        S->terminated = 1;
        log_event(S, "the model terminated the simulation at t = %.17g", t_reached);
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
    *v = S->terminated ? fmi2Discard : fmi2OK; /* steps are synchronous: never pending */
    LEAVE(fmi2OK);
}

fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind s, fmi2Real *v)
{
    ENTER(fmi2GetRealStatus);
    REQUIRE_NOT_NULL(v);
    REQUIRE(s == fmi2LastSuccessfulTime, "status kind %d is not a Real", (int)s);
    *v = S->last_successful_time;
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
    *v = S->terminated ? fmi2True : fmi2False;
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
