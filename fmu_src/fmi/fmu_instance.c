/* The version-free half of the FMI 2.0 and 3.0 layers: one FMU instance, its messages and its
 * checks (see fmu_instance.h). */
#include "fmu_instance.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

static const char *const CATEGORY_NAMES[] = {"logEvents", "logStatusWarning", "logStatusError"};
#define N_CATEGORIES 3

/* the state of this instance's interface type: PHASE(I, INIT) is FMU_ME_INIT or FMU_CS_INIT */
#define PHASE(I, X) ((I)->core.co_simulation ? FMU_CS_##X : FMU_ME_##X)

/* ---- logging ------------------------------------------------------------------------------- */

void fmu_defuse_percent(char *s)
{
    for (; *s; s++)
        if (*s == '%') *s = '_';
}

static void vlog(fmu_instance *I, fmu_status status, unsigned cat, const char *fmt, va_list ap)
{
    char text[1024], buf[1100];
    const int idx = cat == FMU_LOG_EVENTS ? 0 : (cat == FMU_LOG_WARNING ? 1 : 2);
    const char *name = I->api->name_in_message ? I->name : NULL;
    if (!(I->categories & cat)) return;
    vsnprintf(text, sizeof text, fmt, ap);
    if (name && I->function) snprintf(buf, sizeof buf, "%s: %s: %s", name, I->function, text);
    else if (name || I->function) snprintf(buf, sizeof buf, "%s: %s", name ? name : I->function, text);
    else snprintf(buf, sizeof buf, "%s", text);
    fmu_defuse_percent(buf);
    I->api->emit(I, status, CATEGORY_NAMES[idx], buf);
}

void fmu_log_event(fmu_instance *I, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vlog(I, FMU_OK, FMU_LOG_EVENTS, fmt, ap);
    va_end(ap);
}

fmu_status fmu_fail(fmu_instance *I, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vlog(I, FMU_ERROR, FMU_LOG_ERROR, fmt, ap);
    va_end(ap);
    I->state = PHASE(I, ERROR);
    return FMU_ERROR;
}

/* the category bit of a name, 0 if unknown */
static unsigned category_bit(const char *name)
{
    unsigned k;
    for (k = 0; name && k < N_CATEGORIES; k++)
        if (!strcmp(name, CATEGORY_NAMES[k])) return 1u << k;
    return 0;
}

fmu_status fmu_set_debug_logging(fmu_instance *I, int logging_on, size_t n, const char *const categories[])
{
    size_t i;
    if (n == 0) {
        I->categories = FMU_LOG_WARNING | FMU_LOG_ERROR | (logging_on ? FMU_LOG_EVENTS : 0);
        return FMU_OK;
    }
    if (!categories) return fmu_fail(I, "argument categories must not be NULL");
    for (i = 0; i < n; i++) {
        const unsigned bit = category_bit(categories[i]);
        if (!bit) return fmu_fail(I, "unknown log category \"%s\"", categories[i] ? categories[i] : "(null)");
        if (logging_on) I->categories |= bit;
        else I->categories &= ~bit;
    }
    return FMU_OK;
}

/* the model's messages, without a function prefix: they say what happened at which time */
static void model_message(fmu_instance *I, fmu_status status, unsigned cat, const char *message, ...)
{
    const char *f = I->function;
    va_list ap;
    I->function = NULL;
    va_start(ap, message);
    vlog(I, status, cat, message, ap);
    va_end(ap);
    I->function = f;
}

static void model_event(void *ctx, const char *message)
{
    model_message((fmu_instance *)ctx, FMU_OK, FMU_LOG_EVENTS, "%s", message);
}

static void model_warning(void *ctx, const char *message)
{
    model_message((fmu_instance *)ctx, FMU_WARNING, FMU_LOG_WARNING, "%s", message);
}

/* ---- instantiation ------------------------------------------------------------------------- */

int fmu_instantiate_arguments(const char *function, const char *name, const char *token_name, const char *token,
                              char *msg, size_t n)
{
    if (!name || !*name) return snprintf(msg, n, "%s: instanceName must be a non-empty string", function), 1;
    if (token && strcmp(token, FMU_MODEL.guid) == 0) return 0;
    snprintf(msg, n, "%s: wrong %s \"%s\", this FMU has %s", function, token_name, token ? token : "(null)",
             FMU_MODEL.guid);
    fmu_defuse_percent(msg);
    return 1;
}

int fmu_instance_init(fmu_instance *I, const char *name, int co_simulation, int logging_on)
{
    fmu_model_with_defaults(&I->core.model);
    I->name = (char *)I->alloc(strlen(name) + 1, 1);
    I->core.M = I->alloc(1, I->core.model.data_size);
    I->core.inputs = (cs_input *)I->alloc(I->core.model.nvars + 1, sizeof(cs_input));
    if (!I->name || !I->core.M || !I->core.inputs) return 1;
    strcpy(I->name, name);
    fmu_core_inputs(&I->core);
    I->core.co_simulation = co_simulation;
    I->categories = FMU_LOG_ERROR | FMU_LOG_WARNING | (logging_on ? FMU_LOG_EVENTS : 0);
    I->log.event = model_event;
    I->log.warning = model_warning;
    I->log.ctx = I;
    I->core.model.reset(I->core.M);
    I->state = PHASE(I, INSTANTIATED);
    return 0;
}

static void release(fmu_instance *I, void *p)
{
    if (p) I->release(p);
}

void fmu_instance_free(fmu_instance *I)
{
    cs_free(I->core.cs);
    release(I, I->core.inputs);
    release(I, I->core.M);
    release(I, I->name);
    I->release(I);
}

/* ---- entry and exit of every function ------------------------------------------------------ */

static const char *state_name(const fmu_instance *I)
{
    int k;
    for (k = 0; k < FMU_N_STATES; k++)
        if (I->state == 1 << k) return I->api->state_names[k];
    return "error";
}

int fmu_enter(fmu_instance *I, const char *function, int mask)
{
    I->function = function;
    if (I->state & mask) return 1;
    if (I->core.co_simulation && !(mask & FMU_CS_ANY))
        fmu_fail(I, "illegal call: a Model Exchange function called on a Co-Simulation instance");
    else if (!I->core.co_simulation && !(mask & FMU_ME_ANY))
        fmu_fail(I, "illegal call: a Co-Simulation function called on a Model Exchange instance");
    else
        fmu_fail(I, "illegal call sequence (not allowed in state %s)", state_name(I));
    return 0;
}

fmu_status fmu_leave(fmu_instance *I, fmu_status status)
{
    if (status >= FMU_ERROR && !(I->state & (FMU_ME_ERROR | FMU_CS_ERROR))) I->state = PHASE(I, ERROR);
    I->function = NULL;
    return status;
}

/* ---- variables ----------------------------------------------------------------------------- */

int fmu_initializing(const fmu_instance *I) { return (I->state & FMU_BEFORE_INIT_END) != 0; }

/* the index of vr among the event indicators when they are variables (FMI 3.0), else -1 */
static int indicator_index(const fmu_instance *I, unsigned vr)
{
    int k;
    if (!I->api->time_and_indicators_are_variables || !I->core.model.z_vrs) return -1;
    for (k = 0; k < I->core.model.nz; k++)
        if (I->core.model.z_vrs[k] == vr) return k;
    return -1;
}

/* Is vr a Real the FMI version adds to the model's table (FMI 3.0: time, the event indicators)? */
static int added_real(const fmu_instance *I, unsigned vr)
{
    return (I->api->time_and_indicators_are_variables && vr == FMU_TIME_VR) || indicator_index(I, vr) >= 0;
}

/* Is vr a variable of this type? */
static fmu_status known_as(fmu_instance *I, unsigned vr, fmu_type type)
{
    const fmu_var *v = fmu_find_var(&I->core.model, vr);
    const char *const *T = I->api->type_names;
    if (!v && !added_real(I, vr)) return fmu_fail(I, "unknown value reference %u", vr);
    if (!v && type != FMU_REAL) return fmu_fail(I, "value reference %u is a %s, not a %s", vr, T[FMU_REAL], T[type]);
    if (v && v->type != type)
        return fmu_fail(I, "value reference %u (%s) is a %s, not a %s", vr, v->name, T[v->type], T[type]);
    return FMU_OK;
}

fmu_status fmu_check_vrs(fmu_instance *I, const unsigned vr[], size_t nvr, const void *values, fmu_type type)
{
    size_t i;
    if (nvr == 0) return FMU_OK;
    if (!vr) return fmu_fail(I, "argument %s must not be NULL", I->api->vr_argument);
    if (!values) return fmu_fail(I, "argument %s must not be NULL", I->api->values_argument);
    for (i = 0; i < nvr; i++)
        if (known_as(I, vr[i], type) != FMU_OK) return FMU_ERROR;
    return FMU_OK;
}

fmu_status fmu_no_such_type(fmu_instance *I, const char *type, const unsigned vr[], size_t nvr)
{
    const fmu_var *v;
    if (nvr == 0) return FMU_OK;
    if (!vr) return fmu_fail(I, "argument %s must not be NULL", I->api->vr_argument);
    v = fmu_find_var(&I->core.model, vr[0]);
    if (v)
        return fmu_fail(I, "value reference %u (%s) is a %s, not a %s", vr[0], v->name, I->api->type_names[v->type], type);
    if (added_real(I, vr[0]))
        return fmu_fail(I, "value reference %u is a %s, not a %s", vr[0], I->api->type_names[FMU_REAL], type);
    return fmu_fail(I, "unknown value reference %u (this FMU has no %s variables)", vr[0], type);
}

/* one event indicator of the model (FMI 3.0 reads them as variables); NaN without memory */
static double event_indicator(fmu_instance *I, int k)
{
    double *z = (double *)I->alloc((size_t)I->core.model.nz, sizeof(double)), v;
    if (!z) return NAN;
    I->core.model.event_indicators(I->core.M, fmu_initializing(I), z);
    v = z[k];
    I->release(z);
    return v;
}

void fmu_get_reals(fmu_instance *I, const unsigned vr[], size_t n, double v[])
{
    size_t i;
    if (n == 0) return;
    if (!I->api->time_and_indicators_are_variables) { /* the model's own, all at once */
        I->core.model.get_real(I->core.M, fmu_initializing(I), I->core.time, vr, n, v);
        return;
    }
    for (i = 0; i < n; i++) {
        const int k = indicator_index(I, vr[i]);
        if (vr[i] == FMU_TIME_VR) v[i] = I->core.time;
        else if (k >= 0) v[i] = event_indicator(I, k);
        else I->core.model.get_real(I->core.M, fmu_initializing(I), I->core.time, &vr[i], 1, &v[i]);
    }
}

int fmu_get_integer(fmu_instance *I, unsigned vr)
{
    int v;
    I->core.model.get_integer(I->core.M, fmu_initializing(I), &vr, 1, &v);
    return v;
}

int fmu_get_boolean(fmu_instance *I, unsigned vr)
{
    int v;
    I->core.model.get_boolean(I->core.M, &vr, 1, &v);
    return v;
}

/* May vr be set now? Inputs always; parameters and start values (initial="exact") until
 * initialization mode is left; nothing else (FMI 2.0 section 2.2.7, FMI 3.0 section 2.4.7.4). */
static fmu_status settable(fmu_instance *I, unsigned vr)
{
    const fmu_var *v = fmu_find_var(&I->core.model, vr);
    const char *const fmi = I->api->prefix;
    int kind, parameter;
    if (!v)
        return fmu_fail(I, "%s (value reference %u) is computed by the FMU and cannot be set",
                        vr == FMU_TIME_VR ? "time" : "an event indicator", vr);
    kind = fmu_var_kind(v);
    parameter = !strcmp(v->causality, "parameter");
    if (kind == FMU_SET_ALWAYS || (kind == FMU_SET_BEFORE_INIT_END && fmu_initializing(I))) return FMU_OK;
    if (kind == FMU_SET_NEVER) return fmu_fail(I, "variable %s (causality %s) cannot be set", v->name, v->causality);
    if (parameter) return fmu_fail(I, "parameter %s can only be set before %sExitInitializationMode", v->name, fmi);
    return fmu_fail(I, "start value of %s can only be set before %sExitInitializationMode (use %sSetContinuousStates)",
                    v->name, fmi, fmi);
}

/* a new input value without a derivative is held over the next step */
static void hold_input(fmu_instance *I, unsigned vr)
{
    cs_input *in = fmu_core_find_input(&I->core, vr);
    if (in) in->slope = 0.0;
}

fmu_status fmu_set_real(fmu_instance *I, unsigned vr, double v)
{
    char msg[256];
    if (settable(I, vr) != FMU_OK) return FMU_ERROR;
    if (!isfinite(v)) return fmu_fail(I, "%s = %g is not a finite number", fmu_find_var(&I->core.model, vr)->name, v);
    if (I->core.model.set_real(I->core.M, vr, v, msg, sizeof msg)) return fmu_fail(I, "%s", msg);
    hold_input(I, vr);
    return FMU_OK;
}

fmu_status fmu_set_integer(fmu_instance *I, unsigned vr, int v)
{
    char msg[256];
    if (settable(I, vr) != FMU_OK) return FMU_ERROR;
    if (I->core.model.set_integer(I->core.M, vr, v, msg, sizeof msg)) return fmu_fail(I, "%s", msg);
    return FMU_OK;
}

fmu_status fmu_set_boolean(fmu_instance *I, unsigned vr)
{
    if (settable(I, vr) != FMU_OK) return FMU_ERROR;
    return fmu_fail(I, "no Boolean of this FMU can be set"); /* no model of this repository has one */
}
