/* The FMI 2.0 API, Model Exchange and Co-Simulation, shared by every model of this repository:
 * the model supplies the callbacks of fmu_model.h (rw_model.c, diaphragm/diaphragm_model.c).
 * No global state: every instance owns its model data.
 *
 * This layer checks what the standard makes the importer's duty and reports every violation as
 * fmi2Error with a logged reason: the call sequence (state machines of sections 3.2.3 and 4.2.4),
 * NULL arguments, value references, types, settability, non-finite values, array sizes.
 * fmi2DoStep integrates the model with CVODE (cs_cvode.c). */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cs_cvode.h"
#include "fmi2Functions.h"
#include "fmu_model.h"

/* ---- instance ------------------------------------------------------------------------------ */

enum {
    ST_INSTANTIATED = 1 << 0,
    ST_INIT = 1 << 1,
    ST_EVENT = 1 << 2,      /* Model Exchange: event mode */
    ST_CONT = 1 << 3,       /* Model Exchange: continuous-time mode */
    ST_STEP = 1 << 4,       /* Co-Simulation: slave initialized, between steps */
    ST_TERMINATED = 1 << 5,
    ST_ERROR = 1 << 6
};
#define ST_ANY (ST_INSTANTIATED | ST_INIT | ST_EVENT | ST_CONT | ST_STEP | ST_TERMINATED | ST_ERROR)
#define ST_INITIALIZED (ST_EVENT | ST_CONT | ST_STEP)
#define ST_READABLE (ST_INIT | ST_INITIALIZED | ST_TERMINATED | ST_ERROR)

/* log categories (declared in modelDescription.xml) */
enum { LOG_EVENTS = 1 << 0, LOG_WARNING = 1 << 1, LOG_ERROR = 1 << 2 };
static const char *const CATEGORY_NAMES[] = {"logEvents", "logStatusWarning", "logStatusError"};
#define N_CATEGORIES 3

typedef struct {
    char *name;
    fmi2CallbackFunctions cb;
    fmi2Type type;
    int state;
    unsigned categories;
    void *M; /* the model's data (FMU_MODEL.data_size bytes) */
    double time;
    fmu_logger log;
    /* Co-Simulation */
    double rtol;
    cs_solver *cs;
    cs_input *inputs;      /* every Real input, value refreshed before each step */
    size_t n_inputs;
    int terminated;        /* the model ended the run (fmi2Terminated status) */
    double last_successful_time;
} Inst;

#define MODEL (&FMU_MODEL)

static const fmu_var *find_var(fmi2ValueReference vr)
{
    size_t i;
    for (i = 0; i < MODEL->nvars; i++)
        if (MODEL->vars[i].vr == vr) return &MODEL->vars[i];
    return NULL;
}

static const char *TYPE_NAMES[] = {"Real", "Integer", "Boolean"};

/* ---- memory -------------------------------------------------------------------------------- */

/* the importer's memory functions when it gives both, else the C library's */
static void *alloc(const fmi2CallbackFunctions *cb, size_t n, size_t size)
{
    return (cb->allocateMemory && cb->freeMemory) ? cb->allocateMemory(n, size) : calloc(n, size);
}

static void release(const fmi2CallbackFunctions *cb, void *p)
{
    if (!p) return;
    if (cb->allocateMemory && cb->freeMemory) cb->freeMemory(p);
    else free(p);
}

/* ---- logging ------------------------------------------------------------------------------- */

static void vlog(Inst *S, fmi2Status status, unsigned cat, const char *fmt, va_list ap)
{
    char buf[1024];
    char *c;
    int idx = cat == LOG_EVENTS ? 0 : (cat == LOG_WARNING ? 1 : 2);
    if (!S || !S->cb.logger || !(S->categories & cat)) return;
    vsnprintf(buf, sizeof buf, fmt, ap);
    for (c = buf; *c; c++) /* importers may treat the message as a format string */
        if (*c == '%') *c = '_';
    S->cb.logger(S->cb.componentEnvironment, S->name, status, CATEGORY_NAMES[idx], buf);
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

/* log an error, enter the error state, return fmi2Error */
static fmi2Status fail(Inst *S, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vlog(S, fmi2Error, LOG_ERROR, fmt, ap);
    va_end(ap);
    S->state = ST_ERROR;
    return fmi2Error;
}

/* the model's messages */
static void model_event(void *ctx, const char *message) { log_event((Inst *)ctx, "%s", message); }
static void model_warning(void *ctx, const char *message) { log_warning((Inst *)ctx, "%s", message); }

#define CHECK_INSTANCE(c) \
    do { if (!(c)) return fmi2Error; } while (0)

static int allowed(Inst *S, const char *f, int mask)
{
    if (S->state & mask) return 1;
    fail(S, "%s: illegal call sequence (not allowed in the current state%s)", f,
         (S->type == fmi2CoSimulation && (mask & (ST_EVENT | ST_CONT)) && !(mask & ST_STEP))
             ? "; a Model Exchange function called on a Co-Simulation instance"
             : (S->type == fmi2ModelExchange && (mask & ST_STEP) && !(mask & (ST_EVENT | ST_CONT)))
                   ? "; a Co-Simulation function called on a Model Exchange instance"
                   : "");
    return 0;
}

#define ASSERT_STATE(S, F, MASK) \
    do { if (!allowed(S, F, MASK)) return fmi2Error; } while (0)
#define ASSERT_NOT_NULL(S, F, P) \
    do { if (!(P)) return fail(S, "%s: argument %s must not be NULL", F, #P); } while (0)
#define ASSERT_SIZE(S, F, N, EXPECTED, WHAT) \
    do { if ((N) != (size_t)(EXPECTED)) return fail(S, "%s: " WHAT " = %u, expected %d", F, (unsigned)(N), (EXPECTED)); } while (0)

static const fmu_var *lookup(Inst *S, const char *f, fmi2ValueReference vr, fmu_type type)
{
    const fmu_var *v = find_var(vr);
    if (!v) {
        fail(S, "%s: unknown value reference %u", f, (unsigned)vr);
        return NULL;
    }
    if (v->type != type) {
        fail(S, "%s: value reference %u (%s) is a %s, not a %s", f, (unsigned)vr, v->name, TYPE_NAMES[v->type],
             TYPE_NAMES[type]);
        return NULL;
    }
    return v;
}

/* may v be set now? (FMI 2.0 section 2.2.7) */
static int settable(Inst *S, const char *f, const fmu_var *v)
{
    const int before_init = (S->state & (ST_INSTANTIATED | ST_INIT)) != 0;
    if (!strcmp(v->causality, "input")) return 1;
    if (!strcmp(v->causality, "parameter") || !strcmp(v->initial, "exact")) {
        if (before_init) return 1;
        fail(S, "%s: %s %s can only be set before fmi2ExitInitializationMode%s", f,
             !strcmp(v->causality, "parameter") ? "parameter" : "start value of", v->name,
             !strcmp(v->causality, "parameter") ? "" : " (use fmi2SetContinuousStates)");
        return 0;
    }
    fail(S, "%s: variable %s (causality %s) cannot be set", f, v->name, v->causality);
    return 0;
}

static int initializing(const Inst *S) { return (S->state & (ST_INSTANTIATED | ST_INIT)) != 0; }

/* ---- inquiry, instantiation ---------------------------------------------------------------- */

const char *fmi2GetTypesPlatform(void) { return fmi2TypesPlatform; }
const char *fmi2GetVersion(void) { return fmi2Version; }

static void instantiate_error(const fmi2CallbackFunctions *f, fmi2String name, const char *msg)
{
    f->logger(f->componentEnvironment, name ? name : "?", fmi2Error, "logStatusError", msg);
}

fmi2Component fmi2Instantiate(fmi2String instanceName, fmi2Type fmuType, fmi2String fmuGUID,
                              fmi2String fmuResourceLocation, const fmi2CallbackFunctions *functions,
                              fmi2Boolean visible, fmi2Boolean loggingOn)
{
    Inst *S;
    char msg[512];
    size_t i;
    (void)fmuResourceLocation;
    (void)visible;
    if (!functions || !functions->logger) return NULL;
    if (!instanceName || !*instanceName) {
        instantiate_error(functions, instanceName, "fmi2Instantiate: instanceName must be a non-empty string");
        return NULL;
    }
    if (fmuType != fmi2ModelExchange && fmuType != fmi2CoSimulation) {
        instantiate_error(functions, instanceName,
                          "fmi2Instantiate: fmuType must be fmi2ModelExchange or fmi2CoSimulation");
        return NULL;
    }
    if (!fmuGUID || strcmp(fmuGUID, MODEL->guid) != 0) {
        char *c;
        snprintf(msg, sizeof msg, "fmi2Instantiate: wrong GUID \"%s\", this FMU has GUID %s",
                 fmuGUID ? fmuGUID : "(null)", MODEL->guid);
        for (c = msg; *c; c++)
            if (*c == '%') *c = '_';
        instantiate_error(functions, instanceName, msg);
        return NULL;
    }
    S = (Inst *)alloc(functions, 1, sizeof(Inst));
    if (!S) return NULL;
    memset(S, 0, sizeof *S);
    S->cb = *functions;
    if (!(functions->allocateMemory && functions->freeMemory)) S->cb.allocateMemory = NULL, S->cb.freeMemory = NULL;
    S->name = (char *)alloc(&S->cb, strlen(instanceName) + 1, 1);
    S->M = alloc(&S->cb, 1, MODEL->data_size);
    S->inputs = (cs_input *)alloc(&S->cb, MODEL->nvars + 1, sizeof(cs_input));
    if (!S->name || !S->M || !S->inputs) {
        fmi2FreeInstance(S);
        return NULL;
    }
    strcpy(S->name, instanceName);
    for (i = 0; i < MODEL->nvars; i++)
        if (MODEL->vars[i].type == FMU_REAL && !strcmp(MODEL->vars[i].causality, "input"))
            S->inputs[S->n_inputs++].vr = MODEL->vars[i].vr;
    S->type = fmuType;
    S->categories = LOG_ERROR | LOG_WARNING | (loggingOn ? LOG_EVENTS : 0);
    S->log.event = model_event;
    S->log.warning = model_warning;
    S->log.ctx = S;
    MODEL->reset(S->M);
    S->state = ST_INSTANTIATED;
    log_event(S, "fmi2Instantiate: %s instance created",
              fmuType == fmi2CoSimulation ? "Co-Simulation" : "Model Exchange");
    return S;
}

void fmi2FreeInstance(fmi2Component c)
{
    Inst *S = (Inst *)c;
    fmi2CallbackFunctions cb;
    if (!S) return;
    cb = S->cb;
    cs_free(S->cs);
    release(&cb, S->inputs);
    release(&cb, S->M);
    release(&cb, S->name);
    release(&cb, S);
}

fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean loggingOn, size_t nCategories,
                               const fmi2String categories[])
{
    Inst *S = (Inst *)c;
    size_t i;
    int k;
    CHECK_INSTANCE(S);
    ASSERT_STATE(S, "fmi2SetDebugLogging", ST_ANY);
    if (nCategories == 0) {
        S->categories = loggingOn ? (LOG_EVENTS | LOG_WARNING | LOG_ERROR) : (LOG_WARNING | LOG_ERROR);
        return fmi2OK;
    }
    ASSERT_NOT_NULL(S, "fmi2SetDebugLogging", categories);
    for (i = 0; i < nCategories; i++) {
        int found = 0;
        for (k = 0; k < N_CATEGORIES; k++) {
            if (categories[i] && !strcmp(categories[i], CATEGORY_NAMES[k])) {
                if (loggingOn) S->categories |= 1u << k;
                else S->categories &= ~(1u << k);
                found = 1;
            }
        }
        if (!found) return fail(S, "fmi2SetDebugLogging: unknown log category \"%s\"", categories[i] ? categories[i] : "(null)");
    }
    return fmi2OK;
}

/* ---- initialization ------------------------------------------------------------------------ */

fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean toleranceDefined, fmi2Real tolerance,
                               fmi2Real startTime, fmi2Boolean stopTimeDefined, fmi2Real stopTime)
{
    Inst *S = (Inst *)c;
    (void)stopTimeDefined;
    (void)stopTime;
    CHECK_INSTANCE(S);
    ASSERT_STATE(S, "fmi2SetupExperiment", ST_INSTANTIATED);
    if (!isfinite(startTime)) return fail(S, "fmi2SetupExperiment: startTime = %g is not finite", startTime);
    if (toleranceDefined && !(tolerance > 0 && tolerance < 1))
        return fail(S, "fmi2SetupExperiment: tolerance = %g must be in (0, 1)", tolerance);
    S->rtol = toleranceDefined ? tolerance : 0.0; /* only Co-Simulation uses it (CVODE inside) */
    S->time = startTime;
    return fmi2OK;
}

fmi2Status fmi2EnterInitializationMode(fmi2Component c)
{
    Inst *S = (Inst *)c;
    CHECK_INSTANCE(S);
    ASSERT_STATE(S, "fmi2EnterInitializationMode", ST_INSTANTIATED);
    S->state = ST_INIT;
    return fmi2OK;
}

fmi2Status fmi2ExitInitializationMode(fmi2Component c)
{
    Inst *S = (Inst *)c;
    char msg[512];
    CHECK_INSTANCE(S);
    ASSERT_STATE(S, "fmi2ExitInitializationMode", ST_INIT);
    if (MODEL->exit_init(S->M, S->time, &S->log, msg, sizeof msg))
        return fail(S, "fmi2ExitInitializationMode: %s", msg);
    if (S->type == fmi2CoSimulation) {
        int terminated = 0;
        S->cs = cs_new(MODEL, S->M, S->time, S->rtol, &S->log, &terminated, msg, sizeof msg);
        if (!S->cs) return fail(S, "fmi2ExitInitializationMode: %s", msg);
        S->terminated = terminated;
        S->last_successful_time = S->time;
        S->state = ST_STEP;
    } else {
        S->state = ST_EVENT;
    }
    return fmi2OK;
}

fmi2Status fmi2Terminate(fmi2Component c)
{
    Inst *S = (Inst *)c;
    CHECK_INSTANCE(S);
    ASSERT_STATE(S, "fmi2Terminate", ST_INITIALIZED);
    S->state = ST_TERMINATED;
    return fmi2OK;
}

fmi2Status fmi2Reset(fmi2Component c)
{
    Inst *S = (Inst *)c;
    CHECK_INSTANCE(S);
    ASSERT_STATE(S, "fmi2Reset", ST_ANY);
    cs_free(S->cs);
    S->cs = NULL;
    S->terminated = 0;
    S->time = 0.0;
    MODEL->reset(S->M);
    S->state = ST_INSTANTIATED;
    return fmi2OK;
}

/* ---- getters ------------------------------------------------------------------------------- */

/* common checks of a getter: state, NULL arrays, every value reference of the right type */
static int get_checks(Inst *S, const char *f, const fmi2ValueReference vr[], size_t nvr, const void *value,
                      fmu_type type)
{
    size_t i;
    if (!allowed(S, f, ST_READABLE)) return 0;
    if (nvr == 0) return 1;
    if (!vr) return fail(S, "%s: argument vr must not be NULL", f), 0;
    if (!value) return fail(S, "%s: argument value must not be NULL", f), 0;
    for (i = 0; i < nvr; i++)
        if (!lookup(S, f, vr[i], type)) return 0;
    return 1;
}

fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Real value[])
{
    Inst *S = (Inst *)c;
    CHECK_INSTANCE(S);
    if (!get_checks(S, "fmi2GetReal", vr, nvr, value, FMU_REAL)) return fmi2Error;
    if (nvr) MODEL->get_real(S->M, initializing(S), S->time, vr, nvr, value);
    return fmi2OK;
}

fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Integer value[])
{
    Inst *S = (Inst *)c;
    CHECK_INSTANCE(S);
    if (!get_checks(S, "fmi2GetInteger", vr, nvr, value, FMU_INTEGER)) return fmi2Error;
    if (nvr) MODEL->get_integer(S->M, initializing(S), vr, nvr, value);
    return fmi2OK;
}

fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Boolean value[])
{
    Inst *S = (Inst *)c;
    CHECK_INSTANCE(S);
    if (!get_checks(S, "fmi2GetBoolean", vr, nvr, value, FMU_BOOLEAN)) return fmi2Error;
    if (nvr) MODEL->get_boolean(S->M, vr, nvr, value); /* fmi2Boolean is int */
    return fmi2OK;
}

fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2String value[])
{
    Inst *S = (Inst *)c;
    (void)value;
    CHECK_INSTANCE(S);
    ASSERT_STATE(S, "fmi2GetString", ST_READABLE);
    if (nvr == 0) return fmi2OK;
    ASSERT_NOT_NULL(S, "fmi2GetString", vr);
    return fail(S, "fmi2GetString: unknown value reference %u (the model has no String variables)", (unsigned)vr[0]);
}

/* ---- setters ------------------------------------------------------------------------------- */

#define ST_SETTABLE (ST_INSTANTIATED | ST_INIT | ST_EVENT | ST_CONT | ST_STEP)

fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2Real value[])
{
    Inst *S = (Inst *)c;
    size_t i, k;
    char msg[256];
    CHECK_INSTANCE(S);
    ASSERT_STATE(S, "fmi2SetReal", ST_SETTABLE);
    if (nvr == 0) return fmi2OK;
    ASSERT_NOT_NULL(S, "fmi2SetReal", vr);
    ASSERT_NOT_NULL(S, "fmi2SetReal", value);
    for (i = 0; i < nvr; i++) {
        const fmu_var *v = lookup(S, "fmi2SetReal", vr[i], FMU_REAL);
        if (!v) return fmi2Error;
        if (!isfinite(value[i])) return fail(S, "fmi2SetReal: %s = %g is not a finite number", v->name, value[i]);
        if (!settable(S, "fmi2SetReal", v)) return fmi2Error;
        if (MODEL->set_real(S->M, vr[i], value[i], msg, sizeof msg)) return fail(S, "fmi2SetReal: %s", msg);
        for (k = 0; k < S->n_inputs; k++) /* a new value without a derivative is held over the step */
            if (S->inputs[k].vr == vr[i]) S->inputs[k].slope = 0.0;
    }
    return fmi2OK;
}

fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2Integer value[])
{
    Inst *S = (Inst *)c;
    size_t i;
    char msg[256];
    CHECK_INSTANCE(S);
    ASSERT_STATE(S, "fmi2SetInteger", ST_INSTANTIATED | ST_INIT | ST_EVENT | ST_STEP);
    if (nvr == 0) return fmi2OK;
    ASSERT_NOT_NULL(S, "fmi2SetInteger", vr);
    ASSERT_NOT_NULL(S, "fmi2SetInteger", value);
    for (i = 0; i < nvr; i++) {
        const fmu_var *v = lookup(S, "fmi2SetInteger", vr[i], FMU_INTEGER);
        if (!v || !settable(S, "fmi2SetInteger", v)) return fmi2Error;
        if (MODEL->set_integer(S->M, vr[i], value[i], msg, sizeof msg)) return fail(S, "fmi2SetInteger: %s", msg);
    }
    return fmi2OK;
}

fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2Boolean value[])
{
    Inst *S = (Inst *)c;
    size_t i;
    (void)value;
    CHECK_INSTANCE(S);
    ASSERT_STATE(S, "fmi2SetBoolean", ST_INSTANTIATED | ST_INIT | ST_EVENT | ST_STEP);
    if (nvr == 0) return fmi2OK;
    ASSERT_NOT_NULL(S, "fmi2SetBoolean", vr);
    for (i = 0; i < nvr; i++) {
        const fmu_var *v = lookup(S, "fmi2SetBoolean", vr[i], FMU_BOOLEAN);
        if (!v) return fmi2Error;
        /* no model of this repository has a settable Boolean */
        return fail(S, "fmi2SetBoolean: variable %s (causality %s) cannot be set", v->name, v->causality);
    }
    return fmi2OK;
}

fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2String value[])
{
    Inst *S = (Inst *)c;
    (void)value;
    CHECK_INSTANCE(S);
    ASSERT_STATE(S, "fmi2SetString", ST_INSTANTIATED | ST_INIT | ST_EVENT | ST_STEP);
    if (nvr == 0) return fmi2OK;
    ASSERT_NOT_NULL(S, "fmi2SetString", vr);
    return fail(S, "fmi2SetString: unknown value reference %u (the model has no String variables)", (unsigned)vr[0]);
}

/* ---- FMU state, directional derivatives: not supported ------------------------------------ */

static fmi2Status unsupported(fmi2Component c, const char *f)
{
    Inst *S = (Inst *)c;
    CHECK_INSTANCE(S);
    return fail(S, "%s is not supported by this FMU", f);
}

fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate *s) { (void)s; return unsupported(c, "fmi2GetFMUstate"); }
fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate s) { (void)s; return unsupported(c, "fmi2SetFMUstate"); }
fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate *s) { (void)s; return unsupported(c, "fmi2FreeFMUstate"); }
fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate s, size_t *n)
{
    (void)s; (void)n;
    return unsupported(c, "fmi2SerializedFMUstateSize");
}
fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate s, fmi2Byte b[], size_t n)
{
    (void)s; (void)b; (void)n;
    return unsupported(c, "fmi2SerializeFMUstate");
}
fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte b[], size_t n, fmi2FMUstate *s)
{
    (void)s; (void)b; (void)n;
    return unsupported(c, "fmi2DeSerializeFMUstate");
}
fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference u[], size_t nu,
                                        const fmi2ValueReference z[], size_t nz, const fmi2Real dv[], fmi2Real dz[])
{
    (void)u; (void)nu; (void)z; (void)nz; (void)dv; (void)dz;
    return unsupported(c, "fmi2GetDirectionalDerivative");
}

/* ---- Model Exchange ------------------------------------------------------------------------ */

fmi2Status fmi2EnterEventMode(fmi2Component c)
{
    Inst *S = (Inst *)c;
    CHECK_INSTANCE(S);
    ASSERT_STATE(S, "fmi2EnterEventMode", ST_EVENT | ST_CONT);
    S->state = ST_EVENT;
    return fmi2OK;
}

fmi2Status fmi2NewDiscreteStates(fmi2Component c, fmi2EventInfo *info)
{
    Inst *S = (Inst *)c;
    fmu_event_result r;
    CHECK_INSTANCE(S);
    ASSERT_STATE(S, "fmi2NewDiscreteStates", ST_EVENT);
    ASSERT_NOT_NULL(S, "fmi2NewDiscreteStates", info);
    MODEL->event_update(S->M, S->time, &S->log, &r);
    info->newDiscreteStatesNeeded = r.more ? fmi2True : fmi2False;
    info->terminateSimulation = r.terminate ? fmi2True : fmi2False;
    info->nominalsOfContinuousStatesChanged = fmi2False; /* the nominals are constants */
    info->valuesOfContinuousStatesChanged = r.states_changed ? fmi2True : fmi2False;
    info->nextEventTimeDefined = r.next_time_defined ? fmi2True : fmi2False;
    info->nextEventTime = r.next_time_defined ? r.next_time : 0.0;
    return fmi2OK;
}

fmi2Status fmi2EnterContinuousTimeMode(fmi2Component c)
{
    Inst *S = (Inst *)c;
    CHECK_INSTANCE(S);
    ASSERT_STATE(S, "fmi2EnterContinuousTimeMode", ST_EVENT);
    S->state = ST_CONT;
    return fmi2OK;
}

fmi2Status fmi2CompletedIntegratorStep(fmi2Component c, fmi2Boolean noSetFMUStatePriorToCurrentPoint,
                                       fmi2Boolean *enterEventMode, fmi2Boolean *terminateSimulation)
{
    Inst *S = (Inst *)c;
    (void)noSetFMUStatePriorToCurrentPoint;
    CHECK_INSTANCE(S);
    ASSERT_STATE(S, "fmi2CompletedIntegratorStep", ST_CONT);
    ASSERT_NOT_NULL(S, "fmi2CompletedIntegratorStep", enterEventMode);
    ASSERT_NOT_NULL(S, "fmi2CompletedIntegratorStep", terminateSimulation);
    *enterEventMode = fmi2False;
    *terminateSimulation = fmi2False;
    return fmi2OK;
}

fmi2Status fmi2SetTime(fmi2Component c, fmi2Real time)
{
    Inst *S = (Inst *)c;
    CHECK_INSTANCE(S);
    ASSERT_STATE(S, "fmi2SetTime", ST_EVENT | ST_CONT);
    if (!isfinite(time)) return fail(S, "fmi2SetTime: time = %g is not finite", time);
    S->time = time;
    return fmi2OK;
}

fmi2Status fmi2SetContinuousStates(fmi2Component c, const fmi2Real x[], size_t nx)
{
    Inst *S = (Inst *)c;
    size_t i;
    CHECK_INSTANCE(S);
    ASSERT_STATE(S, "fmi2SetContinuousStates", ST_CONT);
    ASSERT_NOT_NULL(S, "fmi2SetContinuousStates", x);
    ASSERT_SIZE(S, "fmi2SetContinuousStates", nx, MODEL->nx, "nx");
    for (i = 0; i < nx; i++)
        if (!isfinite(x[i])) return fail(S, "fmi2SetContinuousStates: state %u = %g is not finite", (unsigned)i, x[i]);
    MODEL->set_states(S->M, x);
    return fmi2OK;
}

fmi2Status fmi2GetDerivatives(fmi2Component c, fmi2Real dx[], size_t nx)
{
    Inst *S = (Inst *)c;
    size_t i;
    CHECK_INSTANCE(S);
    ASSERT_STATE(S, "fmi2GetDerivatives", ST_EVENT | ST_CONT | ST_TERMINATED | ST_ERROR);
    ASSERT_NOT_NULL(S, "fmi2GetDerivatives", dx);
    ASSERT_SIZE(S, "fmi2GetDerivatives", nx, MODEL->nx, "nx");
    MODEL->derivatives(S->M, dx);
    for (i = 0; i < nx; i++)
        if (!isfinite(dx[i])) return fail(S, "fmi2GetDerivatives: derivative %u is not finite at t = %g", (unsigned)i, S->time);
    return fmi2OK;
}

fmi2Status fmi2GetEventIndicators(fmi2Component c, fmi2Real z[], size_t nz)
{
    Inst *S = (Inst *)c;
    CHECK_INSTANCE(S);
    ASSERT_STATE(S, "fmi2GetEventIndicators", ST_INIT | ST_EVENT | ST_CONT | ST_TERMINATED | ST_ERROR);
    ASSERT_NOT_NULL(S, "fmi2GetEventIndicators", z);
    ASSERT_SIZE(S, "fmi2GetEventIndicators", nz, MODEL->nz, "ni");
    MODEL->event_indicators(S->M, initializing(S), z);
    return fmi2OK;
}

fmi2Status fmi2GetContinuousStates(fmi2Component c, fmi2Real x[], size_t nx)
{
    Inst *S = (Inst *)c;
    CHECK_INSTANCE(S);
    ASSERT_STATE(S, "fmi2GetContinuousStates", ST_INIT | ST_EVENT | ST_CONT | ST_TERMINATED | ST_ERROR);
    ASSERT_NOT_NULL(S, "fmi2GetContinuousStates", x);
    ASSERT_SIZE(S, "fmi2GetContinuousStates", nx, MODEL->nx, "nx");
    MODEL->get_states(S->M, initializing(S), x);
    return fmi2OK;
}

fmi2Status fmi2GetNominalsOfContinuousStates(fmi2Component c, fmi2Real x_nominal[], size_t nx)
{
    Inst *S = (Inst *)c;
    CHECK_INSTANCE(S);
    ASSERT_STATE(S, "fmi2GetNominalsOfContinuousStates",
                 ST_INSTANTIATED | ST_EVENT | ST_CONT | ST_TERMINATED | ST_ERROR);
    ASSERT_NOT_NULL(S, "fmi2GetNominalsOfContinuousStates", x_nominal);
    ASSERT_SIZE(S, "fmi2GetNominalsOfContinuousStates", nx, MODEL->nx, "nx");
    MODEL->nominals(x_nominal);
    return fmi2OK;
}

/* ---- Co-Simulation ------------------------------------------------------------------------- */

/* First derivatives of Real inputs ramp them over the next step (canInterpolateInputs). */
fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                                       const fmi2Integer order[], const fmi2Real value[])
{
    Inst *S = (Inst *)c;
    size_t i, k;
    CHECK_INSTANCE(S);
    ASSERT_STATE(S, "fmi2SetRealInputDerivatives", ST_INSTANTIATED | ST_INIT | ST_STEP);
    if (nvr == 0) return fmi2OK;
    ASSERT_NOT_NULL(S, "fmi2SetRealInputDerivatives", vr);
    ASSERT_NOT_NULL(S, "fmi2SetRealInputDerivatives", order);
    ASSERT_NOT_NULL(S, "fmi2SetRealInputDerivatives", value);
    for (i = 0; i < nvr; i++) {
        const fmu_var *v = lookup(S, "fmi2SetRealInputDerivatives", vr[i], FMU_REAL);
        if (!v) return fmi2Error;
        for (k = 0; k < S->n_inputs && S->inputs[k].vr != vr[i]; k++) {}
        if (k == S->n_inputs) return fail(S, "fmi2SetRealInputDerivatives: %s is not an input", v->name);
        if (order[i] != 1)
            return fail(S, "fmi2SetRealInputDerivatives: order %d of %s (only first derivatives are used, "
                           "maxInputDerivativeOrder would be exceeded)", (int)order[i], v->name);
        if (!isfinite(value[i]))
            return fail(S, "fmi2SetRealInputDerivatives: der(%s) = %g is not a finite number", v->name, value[i]);
        S->inputs[k].slope = value[i];
    }
    return fmi2OK;
}

fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                                        const fmi2Integer order[], fmi2Real value[])
{
    (void)vr; (void)nvr; (void)order; (void)value;
    return unsupported(c, "fmi2GetRealOutputDerivatives (maxOutputDerivativeOrder is 0)");
}

fmi2Status fmi2DoStep(fmi2Component c, fmi2Real currentCommunicationPoint, fmi2Real communicationStepSize,
                      fmi2Boolean noSetFMUStatePriorToCurrentCommunicationPoint)
{
    Inst *S = (Inst *)c;
    const double t = currentCommunicationPoint, h = communicationStepSize;
    double t_reached, u;
    char msg[512];
    size_t k;
    int rc;
    (void)noSetFMUStatePriorToCurrentCommunicationPoint;
    CHECK_INSTANCE(S);
    ASSERT_STATE(S, "fmi2DoStep", ST_STEP);
    if (!isfinite(t) || !isfinite(h) || h <= 0)
        return fail(S, "fmi2DoStep: communication point %g and step size %g must be finite, step size > 0", t, h);
    if (fabs(t - S->time) > 1e-9 * fmax(1.0, fabs(t)))
        return fail(S, "fmi2DoStep: currentCommunicationPoint = %.17g, but the FMU is at t = %.17g", t, S->time);
    if (S->terminated) {
        log_event(S, "fmi2DoStep: the model terminated at t = %.17g; no further steps", S->time);
        return fmi2Discard;
    }
    for (k = 0; k < S->n_inputs; k++) { /* the values the master set, read back from the model */
        MODEL->get_real(S->M, 0, S->time, &S->inputs[k].vr, 1, &u);
        S->inputs[k].value = u;
    }
    rc = FMU_NOT_EXACT; /* exact step where the model offers one (RockingWall: cs_exact.c), else CVODE */
    if (MODEL->exact_step) {
        unsigned vr[S->n_inputs + 1];
        double slope[S->n_inputs + 1];
        for (k = 0; k < S->n_inputs; k++) vr[k] = S->inputs[k].vr, slope[k] = S->inputs[k].slope;
        rc = MODEL->exact_step(S->M, S->time, h, vr, slope, S->n_inputs, &S->log, &t_reached, msg, sizeof msg);
    }
    if (rc == FMU_NOT_EXACT) rc = cs_step(S->cs, S->time, h, S->inputs, S->n_inputs, &S->log, &t_reached, msg, sizeof msg);
    for (k = 0; k < S->n_inputs; k++) S->inputs[k].slope = 0.0; /* derivatives hold for one step */
    if (rc < 0) return fail(S, "fmi2DoStep: %s", msg);
    S->time = t_reached;
    S->last_successful_time = t_reached;
    if (rc == 1) {
        S->terminated = 1;
        log_event(S, "fmi2DoStep: the model terminated the simulation at t = %.17g", t_reached);
        return fmi2Discard;
    }
    return fmi2OK;
}

fmi2Status fmi2CancelStep(fmi2Component c)
{
    return unsupported(c, "fmi2CancelStep (fmi2DoStep never returns fmi2Pending)");
}

fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind s, fmi2Status *v)
{
    Inst *S = (Inst *)c;
    CHECK_INSTANCE(S);
    ASSERT_STATE(S, "fmi2GetStatus", ST_STEP | ST_TERMINATED);
    ASSERT_NOT_NULL(S, "fmi2GetStatus", v);
    if (s != fmi2DoStepStatus) return fail(S, "fmi2GetStatus: status kind %d is not a fmi2Status", (int)s);
    *v = S->terminated ? fmi2Discard : fmi2OK; /* steps are synchronous: never pending */
    return fmi2OK;
}

fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind s, fmi2Real *v)
{
    Inst *S = (Inst *)c;
    CHECK_INSTANCE(S);
    ASSERT_STATE(S, "fmi2GetRealStatus", ST_STEP | ST_TERMINATED);
    ASSERT_NOT_NULL(S, "fmi2GetRealStatus", v);
    if (s != fmi2LastSuccessfulTime) return fail(S, "fmi2GetRealStatus: status kind %d is not a Real", (int)s);
    *v = S->last_successful_time;
    return fmi2OK;
}

fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind s, fmi2Integer *v)
{
    (void)s; (void)v;
    return unsupported(c, "fmi2GetIntegerStatus (no Integer status kinds in FMI 2.0)");
}

fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind s, fmi2Boolean *v)
{
    Inst *S = (Inst *)c;
    CHECK_INSTANCE(S);
    ASSERT_STATE(S, "fmi2GetBooleanStatus", ST_STEP | ST_TERMINATED);
    ASSERT_NOT_NULL(S, "fmi2GetBooleanStatus", v);
    if (s != fmi2Terminated) return fail(S, "fmi2GetBooleanStatus: status kind %d is not a Boolean", (int)s);
    *v = S->terminated ? fmi2True : fmi2False;
    return fmi2OK;
}

fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind s, fmi2String *v)
{
    Inst *S = (Inst *)c;
    CHECK_INSTANCE(S);
    ASSERT_STATE(S, "fmi2GetStringStatus", ST_STEP | ST_TERMINATED);
    ASSERT_NOT_NULL(S, "fmi2GetStringStatus", v);
    if (s != fmi2PendingStatus) return fail(S, "fmi2GetStringStatus: status kind %d is not a String", (int)s);
    *v = "";
    return fmi2OK;
}
