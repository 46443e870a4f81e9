/* RockingWall: the FMI 2.0 Model Exchange API over the physics of rw_physics.c / rw_modes.c.
 * No global state: every instance owns its parameters, modes and states.
 * State machine: FMI 2.0 standard, section 3.2.3 (Model Exchange). */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmi2Functions.h"
#include "model_variables.h"
#include "rw_physics.h"

/* compile-time check: model_variables.h and rw_physics.h agree on the sizes */
typedef char rw_check_nx[(RW_NUMBER_OF_STATES == RW_NX) ? 1 : -1];
typedef char rw_check_nz[(RW_NUMBER_OF_EVENT_INDICATORS == RW_NZ) ? 1 : -1];

/* ---- instance ------------------------------------------------------------------------------ */

enum {
    ST_INSTANTIATED = 1 << 0,
    ST_INIT = 1 << 1,
    ST_EVENT = 1 << 2,
    ST_CONT = 1 << 3,
    ST_TERMINATED = 1 << 4,
    ST_ERROR = 1 << 5
};
#define ST_ANY (ST_INSTANTIATED | ST_INIT | ST_EVENT | ST_CONT | ST_TERMINATED | ST_ERROR)

/* log categories (declared in modelDescription.xml) */
enum { LOG_EVENTS = 1 << 0, LOG_WARNING = 1 << 1, LOG_ERROR = 1 << 2 };
static const char *const CATEGORY_NAMES[] = {"logEvents", "logStatusWarning", "logStatusError"};
#define N_CATEGORIES 3

/* time between the collapse event (where `collapsed` becomes true and is recorded) and the
 * time event that requests terminateSimulation */
#define RW_TERMINATE_DELAY 1e-6

typedef struct {
    char *name;
    fmi2CallbackFunctions cb;
    int state;
    unsigned categories;
    rw_params P;
    rw_derived D;
    rw_mode mode;
    rw_input in;
    double x[RW_NX];
    double time;
    int impacts;
    int collapsed;
    double terminate_time;
} Inst;

/* ---- variable table from model_variables.h ------------------------------------------------- */

enum { T_Real, T_Integer, T_Boolean };
typedef struct {
    fmi2ValueReference vr;
    int type;
    const char *name;
    const char *causality;
    const char *initial;
    double start;
} VarInfo;

#define RW_VAR_INFO(ID, VR, NAME, TYPE, CAUS, VARIAB, INIT, START, UNIT, NOM, DER, DESC) \
    {VR, T_##TYPE, NAME, CAUS, INIT, START},
static const VarInfo VARS[] = {RW_VARIABLES(RW_VAR_INFO)};
#undef RW_VAR_INFO
#define N_VARS (sizeof VARS / sizeof VARS[0])

static const VarInfo *find_var(fmi2ValueReference vr)
{
    size_t i;
    for (i = 0; i < N_VARS; i++)
        if (VARS[i].vr == vr) return &VARS[i];
    return NULL;
}

static const char *TYPE_NAMES[] = {"Real", "Integer", "Boolean"};

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

static void physics_log(void *ctx, const char *message)
{
    Inst *S = (Inst *)ctx;
    log_event(S, "t = %.9g: %s", S->time, message);
}

#define CHECK_INSTANCE(c) \
    do { if (!(c)) return fmi2Error; } while (0)

static int allowed(Inst *S, const char *f, int mask)
{
    if (S->state & mask) return 1;
    fail(S, "%s: illegal call sequence (not allowed in the current state)", f);
    return 0;
}

#define ASSERT_STATE(S, F, MASK) \
    do { if (!allowed(S, F, MASK)) return fmi2Error; } while (0)
#define ASSERT_NOT_NULL(S, F, P) \
    do { if (!(P)) return fail(S, "%s: argument %s must not be NULL", F, #P); } while (0)

/* ---- helpers ------------------------------------------------------------------------------- */

static void reset_values(Inst *S)
{
    rw_params_default(&S->P);
    rw_derive(&S->P, &S->D);
    memset(&S->mode, 0, sizeof S->mode);
    S->mode.side_b = S->mode.side_m = 1;
    S->in.ag = 0.0;
    S->in.u_top = 0.0;
    memset(S->x, 0, sizeof S->x);
    S->time = 0.0;
    S->impacts = 0;
    S->collapsed = 0;
    S->terminate_time = 0.0;
}

/* modes and states as seen by getters: in initialization mode the modes are not decided yet, so
 * they are computed on copies from the start values */
static void view(Inst *S, rw_mode *m, double x[RW_NX])
{
    memcpy(x, S->x, sizeof S->x);
    *m = S->mode;
    if (S->state & (ST_INSTANTIATED | ST_INIT)) rw_init_modes(&S->P, &S->D, &S->in, x, m, NULL, NULL);
}

static double *real_param(rw_params *P, fmi2ValueReference vr)
{
    switch (vr) {
    case RW_VR_h: return &P->h;
    case RW_VR_b: return &P->b;
    case RW_VR_W: return &P->W;
    case RW_VR_psi: return &P->psi;
    case RW_VR_Kd: return &P->Kd;
    case RW_VR_er: return &P->er;
    case RW_VR_g: return &P->g;
    case RW_VR_delta1Ratio: return &P->delta1Ratio;
    case RW_VR_delta2A: return &P->delta2A;
    case RW_VR_delta2B: return &P->delta2B;
    case RW_VR_hingeSat: return &P->hingeSat;
    case RW_VR_restRate: return &P->restRate;
    default: return NULL;
    }
}

static int state_index(fmi2ValueReference vr)
{
    switch (vr) {
    case RW_VR_q1: return 0;
    case RW_VR_q2: return 1;
    case RW_VR_dq1: return 2;
    case RW_VR_dq2: return 3;
    default: return -1;
    }
}

static const VarInfo *lookup(Inst *S, const char *f, fmi2ValueReference vr, int type)
{
    const VarInfo *v = find_var(vr);
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
    (void)fmuResourceLocation;
    (void)visible;
    if (!functions || !functions->logger) return NULL;
    if (!instanceName || !*instanceName) {
        instantiate_error(functions, instanceName, "fmi2Instantiate: instanceName must be a non-empty string");
        return NULL;
    }
    if (fmuType != fmi2ModelExchange) {
        instantiate_error(functions, instanceName,
                          "fmi2Instantiate: only Model Exchange is supported (fmuType must be fmi2ModelExchange)");
        return NULL;
    }
    if (!fmuGUID || strcmp(fmuGUID, RW_GUID) != 0) {
        snprintf(msg, sizeof msg, "fmi2Instantiate: wrong GUID \"%s\", this FMU has GUID " RW_GUID,
                 fmuGUID ? fmuGUID : "(null)");
        for (char *c = msg; *c; c++)
            if (*c == '%') *c = '_';
        instantiate_error(functions, instanceName, msg);
        return NULL;
    }
    {   /* the importer's memory functions when it gives both, else the C library's */
        const int own = functions->allocateMemory && functions->freeMemory;
        S = own ? (Inst *)functions->allocateMemory(1, sizeof(Inst)) : (Inst *)calloc(1, sizeof(Inst));
        if (!S) return NULL;
        memset(S, 0, sizeof *S);
        S->cb = *functions;
        if (!own) S->cb.allocateMemory = NULL, S->cb.freeMemory = NULL;
        S->name = own ? (char *)functions->allocateMemory(strlen(instanceName) + 1, 1)
                      : (char *)calloc(strlen(instanceName) + 1, 1);
        if (!S->name) {
            if (own) functions->freeMemory(S); else free(S);
            return NULL;
        }
    }
    strcpy(S->name, instanceName);
    S->categories = LOG_ERROR | LOG_WARNING | (loggingOn ? LOG_EVENTS : 0);
    reset_values(S);
    S->state = ST_INSTANTIATED;
    log_event(S, "fmi2Instantiate: instance created");
    return S;
}

void fmi2FreeInstance(fmi2Component c)
{
    Inst *S = (Inst *)c;
    if (!S) return;
    if (S->cb.freeMemory && S->cb.allocateMemory) {
        S->cb.freeMemory(S->name);
        S->cb.freeMemory(S);
    } else {
        free(S->name);
        free(S);
    }
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
    (void)toleranceDefined;
    (void)tolerance;
    (void)stopTimeDefined;
    (void)stopTime;
    CHECK_INSTANCE(S);
    ASSERT_STATE(S, "fmi2SetupExperiment", ST_INSTANTIATED);
    if (!isfinite(startTime)) return fail(S, "fmi2SetupExperiment: startTime = %g is not finite", startTime);
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

static void check_collapse(Inst *S)
{
    if (S->collapsed || !rw_is_collapsed(&S->P, &S->D, &S->mode, &S->in, S->x)) return;
    S->collapsed = 1;
    S->terminate_time = S->time + RW_TERMINATE_DELAY;
    log_warning(S, "collapse at t = %.9g s: s1 = %.6g m, s2 = %.6g m (q1 = %.6g, q2 = %.6g rad): "
                   "the wall passed its instability point; terminating the simulation",
                S->time, rw_s1(&S->P, S->x), rw_s2(&S->P, S->x), S->x[0], S->x[1]);
}

fmi2Status fmi2ExitInitializationMode(fmi2Component c)
{
    Inst *S = (Inst *)c;
    char msg[512];
    CHECK_INSTANCE(S);
    ASSERT_STATE(S, "fmi2ExitInitializationMode", ST_INIT);
    if (rw_params_validate(&S->P, msg, sizeof msg)) return fail(S, "fmi2ExitInitializationMode: %s", msg);
    rw_derive(&S->P, &S->D);
    rw_init_modes(&S->P, &S->D, &S->in, S->x, &S->mode, physics_log, S);
    S->impacts = 0;
    S->collapsed = 0;
    check_collapse(S);
    S->state = ST_EVENT;
    return fmi2OK;
}

fmi2Status fmi2Terminate(fmi2Component c)
{
    Inst *S = (Inst *)c;
    CHECK_INSTANCE(S);
    ASSERT_STATE(S, "fmi2Terminate", ST_EVENT | ST_CONT);
    S->state = ST_TERMINATED;
    return fmi2OK;
}

fmi2Status fmi2Reset(fmi2Component c)
{
    Inst *S = (Inst *)c;
    CHECK_INSTANCE(S);
    ASSERT_STATE(S, "fmi2Reset", ST_ANY);
    reset_values(S);
    S->state = ST_INSTANTIATED;
    return fmi2OK;
}

/* ---- getters ------------------------------------------------------------------------------- */

fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Real value[])
{
    Inst *S = (Inst *)c;
    size_t i;
    rw_mode m;
    double x[RW_NX], dx[RW_NX];
    CHECK_INSTANCE(S);
    ASSERT_STATE(S, "fmi2GetReal", ST_INIT | ST_EVENT | ST_CONT | ST_TERMINATED | ST_ERROR);
    if (nvr == 0) return fmi2OK;
    ASSERT_NOT_NULL(S, "fmi2GetReal", vr);
    ASSERT_NOT_NULL(S, "fmi2GetReal", value);
    view(S, &m, x);
    rw_derivatives(&S->P, &S->D, &m, &S->in, x, dx);
    for (i = 0; i < nvr; i++) {
        const double *pp;
        int k;
        if (!lookup(S, "fmi2GetReal", vr[i], T_Real)) return fmi2Error;
        if ((pp = real_param(&S->P, vr[i])) != NULL) { value[i] = *pp; continue; }
        if ((k = state_index(vr[i])) >= 0) { value[i] = x[k]; continue; }
        switch (vr[i]) {
        case RW_VR_ag: value[i] = S->in.ag; break;
        case RW_VR_u_top: value[i] = S->in.u_top; break;
        case RW_VR_s1: value[i] = rw_s1(&S->P, x); break;
        case RW_VR_s2: value[i] = rw_s2(&S->P, x); break;
        case RW_VR_F_top: value[i] = rw_F_top(&S->P, &S->in, x); break;
        case RW_VR_energy: value[i] = rw_energy(&S->P, &S->D, &m, &S->in, x); break;
        case RW_VR_der_dq1: value[i] = dx[2]; break;
        case RW_VR_der_dq2: value[i] = dx[3]; break;
        default: return fail(S, "fmi2GetReal: value reference %u not handled", (unsigned)vr[i]);
        }
    }
    return fmi2OK;
}

fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Integer value[])
{
    Inst *S = (Inst *)c;
    size_t i;
    rw_mode m;
    double x[RW_NX];
    CHECK_INSTANCE(S);
    ASSERT_STATE(S, "fmi2GetInteger", ST_INIT | ST_EVENT | ST_CONT | ST_TERMINATED | ST_ERROR);
    if (nvr == 0) return fmi2OK;
    ASSERT_NOT_NULL(S, "fmi2GetInteger", vr);
    ASSERT_NOT_NULL(S, "fmi2GetInteger", value);
    view(S, &m, x);
    for (i = 0; i < nvr; i++) {
        if (!lookup(S, "fmi2GetInteger", vr[i], T_Integer)) return fmi2Error;
        switch (vr[i]) {
        case RW_VR_model: value[i] = S->P.model; break;
        case RW_VR_hingeLaw: value[i] = S->P.hingeLaw; break;
        case RW_VR_impacts: value[i] = S->impacts; break;
        case RW_VR_condition: value[i] = rw_condition(&S->P, &m); break;
        default: return fail(S, "fmi2GetInteger: value reference %u not handled", (unsigned)vr[i]);
        }
    }
    return fmi2OK;
}

fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Boolean value[])
{
    Inst *S = (Inst *)c;
    size_t i;
    CHECK_INSTANCE(S);
    ASSERT_STATE(S, "fmi2GetBoolean", ST_INIT | ST_EVENT | ST_CONT | ST_TERMINATED | ST_ERROR);
    if (nvr == 0) return fmi2OK;
    ASSERT_NOT_NULL(S, "fmi2GetBoolean", vr);
    ASSERT_NOT_NULL(S, "fmi2GetBoolean", value);
    for (i = 0; i < nvr; i++) {
        if (!lookup(S, "fmi2GetBoolean", vr[i], T_Boolean)) return fmi2Error;
        value[i] = S->collapsed ? fmi2True : fmi2False; /* the only Boolean */
    }
    return fmi2OK;
}

fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2String value[])
{
    Inst *S = (Inst *)c;
    (void)value;
    CHECK_INSTANCE(S);
    ASSERT_STATE(S, "fmi2GetString", ST_INIT | ST_EVENT | ST_CONT | ST_TERMINATED | ST_ERROR);
    if (nvr == 0) return fmi2OK;
    ASSERT_NOT_NULL(S, "fmi2GetString", vr);
    return fail(S, "fmi2GetString: unknown value reference %u (the model has no String variables)", (unsigned)vr[0]);
}

/* ---- setters ------------------------------------------------------------------------------- */

fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2Real value[])
{
    Inst *S = (Inst *)c;
    size_t i;
    char msg[256];
    CHECK_INSTANCE(S);
    ASSERT_STATE(S, "fmi2SetReal", ST_INSTANTIATED | ST_INIT | ST_EVENT | ST_CONT);
    if (nvr == 0) return fmi2OK;
    ASSERT_NOT_NULL(S, "fmi2SetReal", vr);
    ASSERT_NOT_NULL(S, "fmi2SetReal", value);
    for (i = 0; i < nvr; i++) {
        const VarInfo *v = lookup(S, "fmi2SetReal", vr[i], T_Real);
        double *pp;
        int k;
        if (!v) return fmi2Error;
        if (!isfinite(value[i]))
            return fail(S, "fmi2SetReal: %s = %g is not a finite number", v->name, value[i]);
        if ((pp = real_param(&S->P, vr[i])) != NULL) {
            if (!(S->state & (ST_INSTANTIATED | ST_INIT)))
                return fail(S, "fmi2SetReal: parameter %s can only be set before fmi2ExitInitializationMode", v->name);
            if (rw_check_real_param(v->name, value[i], msg, sizeof msg)) return fail(S, "fmi2SetReal: %s", msg);
            *pp = value[i];
            rw_derive(&S->P, &S->D);
        } else if ((k = state_index(vr[i])) >= 0) {
            if (!(S->state & (ST_INSTANTIATED | ST_INIT)))
                return fail(S, "fmi2SetReal: start value of state %s can only be set before fmi2ExitInitializationMode "
                               "(use fmi2SetContinuousStates)", v->name);
            S->x[k] = value[i];
        } else if (vr[i] == RW_VR_ag) {
            S->in.ag = value[i];
        } else if (vr[i] == RW_VR_u_top) {
            S->in.u_top = value[i];
        } else {
            return fail(S, "fmi2SetReal: variable %s (causality %s) cannot be set", v->name, v->causality);
        }
    }
    return fmi2OK;
}

fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2Integer value[])
{
    Inst *S = (Inst *)c;
    size_t i;
    char msg[256];
    CHECK_INSTANCE(S);
    ASSERT_STATE(S, "fmi2SetInteger", ST_INSTANTIATED | ST_INIT | ST_EVENT);
    if (nvr == 0) return fmi2OK;
    ASSERT_NOT_NULL(S, "fmi2SetInteger", vr);
    ASSERT_NOT_NULL(S, "fmi2SetInteger", value);
    for (i = 0; i < nvr; i++) {
        const VarInfo *v = lookup(S, "fmi2SetInteger", vr[i], T_Integer);
        if (!v) return fmi2Error;
        if (vr[i] != RW_VR_model && vr[i] != RW_VR_hingeLaw)
            return fail(S, "fmi2SetInteger: variable %s (causality %s) cannot be set", v->name, v->causality);
        if (!(S->state & (ST_INSTANTIATED | ST_INIT)))
            return fail(S, "fmi2SetInteger: parameter %s can only be set before fmi2ExitInitializationMode", v->name);
        if (rw_check_int_param(v->name, value[i], msg, sizeof msg)) return fail(S, "fmi2SetInteger: %s", msg);
        if (vr[i] == RW_VR_model) S->P.model = value[i];
        else S->P.hingeLaw = value[i];
        rw_derive(&S->P, &S->D);
    }
    return fmi2OK;
}

fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2Boolean value[])
{
    Inst *S = (Inst *)c;
    size_t i;
    (void)value;
    CHECK_INSTANCE(S);
    ASSERT_STATE(S, "fmi2SetBoolean", ST_INSTANTIATED | ST_INIT | ST_EVENT);
    if (nvr == 0) return fmi2OK;
    ASSERT_NOT_NULL(S, "fmi2SetBoolean", vr);
    for (i = 0; i < nvr; i++) {
        const VarInfo *v = lookup(S, "fmi2SetBoolean", vr[i], T_Boolean);
        if (!v) return fmi2Error;
        return fail(S, "fmi2SetBoolean: variable %s (causality %s) cannot be set", v->name, v->causality);
    }
    return fmi2OK;
}

fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2String value[])
{
    Inst *S = (Inst *)c;
    (void)value;
    CHECK_INSTANCE(S);
    ASSERT_STATE(S, "fmi2SetString", ST_INSTANTIATED | ST_INIT | ST_EVENT);
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
    rw_event_result r;
    CHECK_INSTANCE(S);
    ASSERT_STATE(S, "fmi2NewDiscreteStates", ST_EVENT);
    ASSERT_NOT_NULL(S, "fmi2NewDiscreteStates", info);
    info->newDiscreteStatesNeeded = fmi2False;
    info->terminateSimulation = fmi2False;
    info->nominalsOfContinuousStatesChanged = fmi2False;
    info->valuesOfContinuousStatesChanged = fmi2False;
    info->nextEventTimeDefined = fmi2False;
    info->nextEventTime = 0.0;
    if (S->collapsed) {
        /* `collapsed` became true at the collapse event (so importers record it); the time event
         * RW_TERMINATE_DELAY later ends the run */
        if (S->time >= S->terminate_time - 1e-12 * fmax(1.0, fabs(S->time))) {
            info->terminateSimulation = fmi2True;
            log_event(S, "t = %.9g: terminateSimulation after collapse", S->time);
        } else {
            info->nextEventTimeDefined = fmi2True;
            info->nextEventTime = S->terminate_time;
        }
        return fmi2OK;
    }
    rw_event_update(&S->P, &S->D, &S->mode, &S->in, S->x, &r, physics_log, S);
    S->impacts += r.impacts;
    if (r.states_changed) info->valuesOfContinuousStatesChanged = fmi2True;
    if (r.modes_changed || r.states_changed) info->newDiscreteStatesNeeded = fmi2True; /* confirm */
    check_collapse(S);
    if (S->collapsed) {
        info->newDiscreteStatesNeeded = fmi2False;
        info->nextEventTimeDefined = fmi2True;
        info->nextEventTime = S->terminate_time;
    }
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
    if (nx != RW_NX) return fail(S, "fmi2SetContinuousStates: nx = %u, expected %d", (unsigned)nx, RW_NX);
    for (i = 0; i < nx; i++)
        if (!isfinite(x[i])) return fail(S, "fmi2SetContinuousStates: state %u = %g is not finite", (unsigned)i, x[i]);
    memcpy(S->x, x, sizeof S->x);
    return fmi2OK;
}

fmi2Status fmi2GetDerivatives(fmi2Component c, fmi2Real dx[], size_t nx)
{
    Inst *S = (Inst *)c;
    size_t i;
    CHECK_INSTANCE(S);
    ASSERT_STATE(S, "fmi2GetDerivatives", ST_EVENT | ST_CONT | ST_TERMINATED | ST_ERROR);
    ASSERT_NOT_NULL(S, "fmi2GetDerivatives", dx);
    if (nx != RW_NX) return fail(S, "fmi2GetDerivatives: nx = %u, expected %d", (unsigned)nx, RW_NX);
    rw_derivatives(&S->P, &S->D, &S->mode, &S->in, S->x, dx);
    for (i = 0; i < nx; i++)
        if (!isfinite(dx[i])) return fail(S, "fmi2GetDerivatives: derivative %u is not finite at t = %g", (unsigned)i, S->time);
    return fmi2OK;
}

fmi2Status fmi2GetEventIndicators(fmi2Component c, fmi2Real z[], size_t nz)
{
    Inst *S = (Inst *)c;
    rw_mode m;
    double x[RW_NX];
    CHECK_INSTANCE(S);
    ASSERT_STATE(S, "fmi2GetEventIndicators", ST_INIT | ST_EVENT | ST_CONT | ST_TERMINATED | ST_ERROR);
    ASSERT_NOT_NULL(S, "fmi2GetEventIndicators", z);
    if (nz != RW_NZ) return fail(S, "fmi2GetEventIndicators: ni = %u, expected %d", (unsigned)nz, RW_NZ);
    view(S, &m, x);
    rw_event_indicators(&S->P, &S->D, &m, &S->in, x, z);
    return fmi2OK;
}

fmi2Status fmi2GetContinuousStates(fmi2Component c, fmi2Real x[], size_t nx)
{
    Inst *S = (Inst *)c;
    rw_mode m;
    CHECK_INSTANCE(S);
    ASSERT_STATE(S, "fmi2GetContinuousStates", ST_INIT | ST_EVENT | ST_CONT | ST_TERMINATED | ST_ERROR);
    ASSERT_NOT_NULL(S, "fmi2GetContinuousStates", x);
    if (nx != RW_NX) return fail(S, "fmi2GetContinuousStates: nx = %u, expected %d", (unsigned)nx, RW_NX);
    view(S, &m, x);
    return fmi2OK;
}

fmi2Status fmi2GetNominalsOfContinuousStates(fmi2Component c, fmi2Real x_nominal[], size_t nx)
{
    Inst *S = (Inst *)c;
    CHECK_INSTANCE(S);
    ASSERT_STATE(S, "fmi2GetNominalsOfContinuousStates",
                 ST_INSTANTIATED | ST_EVENT | ST_CONT | ST_TERMINATED | ST_ERROR);
    ASSERT_NOT_NULL(S, "fmi2GetNominalsOfContinuousStates", x_nominal);
    if (nx != RW_NX) return fail(S, "fmi2GetNominalsOfContinuousStates: nx = %u, expected %d", (unsigned)nx, RW_NX);
    x_nominal[0] = x_nominal[1] = 0.01;
    x_nominal[2] = x_nominal[3] = 0.1;
    return fmi2OK;
}

/* ---- Co-Simulation: not supported (yet) ---------------------------------------------------- */

fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                                       const fmi2Integer order[], const fmi2Real value[])
{
    (void)vr; (void)nvr; (void)order; (void)value;
    return unsupported(c, "fmi2SetRealInputDerivatives (Co-Simulation)");
}
fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                                        const fmi2Integer order[], fmi2Real value[])
{
    (void)vr; (void)nvr; (void)order; (void)value;
    return unsupported(c, "fmi2GetRealOutputDerivatives (Co-Simulation)");
}
fmi2Status fmi2DoStep(fmi2Component c, fmi2Real t, fmi2Real h, fmi2Boolean noSetPrior)
{
    (void)t; (void)h; (void)noSetPrior;
    return unsupported(c, "fmi2DoStep (Co-Simulation)");
}
fmi2Status fmi2CancelStep(fmi2Component c) { return unsupported(c, "fmi2CancelStep (Co-Simulation)"); }
fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind s, fmi2Status *v)
{
    (void)s; (void)v;
    return unsupported(c, "fmi2GetStatus (Co-Simulation)");
}
fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind s, fmi2Real *v)
{
    (void)s; (void)v;
    return unsupported(c, "fmi2GetRealStatus (Co-Simulation)");
}
fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind s, fmi2Integer *v)
{
    (void)s; (void)v;
    return unsupported(c, "fmi2GetIntegerStatus (Co-Simulation)");
}
fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind s, fmi2Boolean *v)
{
    (void)s; (void)v;
    return unsupported(c, "fmi2GetBooleanStatus (Co-Simulation)");
}
fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind s, fmi2String *v)
{
    (void)s; (void)v;
    return unsupported(c, "fmi2GetStringStatus (Co-Simulation)");
}
