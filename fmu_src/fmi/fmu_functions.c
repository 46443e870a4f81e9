/* The work of the FMI functions both versions have, on a version-free instance (fmu_instance.h):
 * initialization, Event Mode, Model Exchange, the Co-Simulation step, the FMU state. The API
 * layers call these after ENTER and translate the status. */
#include "fmu_instance.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define PHASE(I, X) ((I)->core.co_simulation ? FMU_CS_##X : FMU_ME_##X)

/* ---- initialization, termination, reset ------------------------------------------- */

fmu_status fmu_setup(fmu_instance *I, int tolerance_defined, double tolerance, double start_time)
{
    if (!isfinite(start_time)) return fmu_fail(I, "startTime = %g is not finite", start_time);
    if (tolerance_defined && !(tolerance > 0 && tolerance < 1))
        return fmu_fail(I, "tolerance = %g must be in (0, 1)", tolerance);
    I->core.rtol = tolerance_defined ? tolerance : 0.0; /* only Co-Simulation uses it (CVODE inside) */
    I->core.time = start_time;
    return FMU_OK;
}

fmu_status fmu_exit_init(fmu_instance *I)
{
    fmu_core *const C = &I->core;
    char msg[512];
    if (C->model.exit_init(C->M, C->time, &I->log, msg, sizeof msg)) return fmu_fail(I, "%s", msg);
    I->states_changed = 0;
    if (!C->co_simulation) {
        C->initialized = 1;
        I->state = FMU_ME_EVENT; /* the initial event iteration */
        return FMU_OK;
    }
    C->cs = cs_new(&C->model, C->M, C->time, C->rtol, &I->log, &C->terminated, msg, sizeof msg);
    if (!C->cs) return fmu_fail(I, "%s", msg);
    C->last_successful_time = C->time;
    C->initialized = 1;
    I->state = I->event_mode_used ? FMU_CS_EVENT : FMU_CS_STEP;
    return FMU_OK;
}

fmu_status fmu_enter_event_mode(fmu_instance *I)
{
    if (I->core.co_simulation && !I->event_mode_used)
        return fmu_fail(I, "Event Mode of Co-Simulation needs eventModeUsed = true at %sInstantiateCoSimulation",
                        I->api->prefix);
    I->state = PHASE(I, EVENT);
    I->states_changed = 0;
    return FMU_OK;
}

void fmu_leave_event_mode(fmu_instance *I)
{
    I->state = I->core.co_simulation ? FMU_CS_STEP : FMU_ME_CONT;
    I->states_changed = 0;
}

void fmu_terminate(fmu_instance *I) { I->state = PHASE(I, TERMINATED); }

void fmu_reset(fmu_instance *I)
{
    cs_free(I->core.cs);
    I->core.cs = NULL;
    I->core.terminated = 0;
    I->core.initialized = 0;
    I->core.time = 0.0;
    I->core.model.reset(I->core.M);
    I->state = PHASE(I, INSTANTIATED);
}

/* ---- results that must be finite ----------------------------------------------------------- */

/* The first Real output, or else the first state, that is not finite: its name and value in msg,
 * 1; 0 when all are finite (or there is no memory to look). */
static int non_finite_result(fmu_instance *I, char *msg, size_t n)
{
    fmu_core *const C = &I->core;
    double *x, v;
    size_t i;
    int k;
    for (i = 0; i < C->model.nvars; i++) {
        const fmu_var *var = &C->model.vars[i];
        if (var->type != FMU_REAL || strcmp(var->causality, "output")) continue;
        C->model.get_real(C->M, 0, C->time, &var->vr, 1, &v);
        if (!isfinite(v)) return snprintf(msg, n, "%s = %g", var->name, v), 1;
    }
    x = (double *)I->alloc((size_t)C->model.nx + 1, sizeof(double));
    if (!x) return 0;
    C->model.get_states(C->M, 0, x);
    for (k = 0; k < C->model.nx; k++)
        if (!isfinite(x[k])) break;
    if (k < C->model.nx) snprintf(msg, n, "continuous state %d = %g", k, x[k]);
    I->release(x);
    return k < C->model.nx;
}

/* the Real inputs' values, "ag = 1e+308, u_top = 0", for the messages */
static void describe_inputs(const fmu_instance *I, char *s, size_t n)
{
    size_t k, used = 0;
    s[0] = '\0';
    for (k = 0; k < I->core.n_inputs && used < n; k++) {
        const fmu_var *var = fmu_find_var(&I->core.model, I->core.inputs[k].vr);
        const int w = snprintf(s + used, n - used, "%s%s = %g", k ? ", " : "", var->name, I->core.inputs[k].value);
        if (w < 0) break;
        used += (size_t)w;
    }
}

/* ---- Event Mode ---------------------------------------------------------------------------- */

/* In Co-Simulation the step (exact engine or CVODE) iterates its events itself, so Event Mode only
 * lets the importer change inputs between steps: nothing is left to update. */
fmu_status fmu_update_discrete_states(fmu_instance *I, fmu_event_result *r)
{
    char what[128];
    memset(r, 0, sizeof *r);
    if (I->core.co_simulation) {
        r->terminate = I->core.terminated;
        return FMU_OK;
    }
    I->core.model.event_update(I->core.M, I->core.time, &I->log, r);
    /* An importer that keeps only the last call's flags (the FMU Compliance Checker) would
     * otherwise miss a jump reported by an earlier call and write the old states back. */
    I->states_changed |= r->states_changed;
    r->states_changed = I->states_changed;
    if (non_finite_result(I, what, sizeof what))
        return fmu_fail(I, "the event update at t = %.17g ended with %s, which is not finite", I->core.time, what);
    return FMU_OK;
}

/* ---- Model Exchange ------------------------------------------------------------------------ */

/* n, the size the importer gave for an array of `expected` values */
static fmu_status check_size(fmu_instance *I, size_t n, int expected, const char *what)
{
    if (n == (size_t)expected) return FMU_OK;
    return fmu_fail(I, "%s = %u, expected %d", what, (unsigned)n, expected);
}

fmu_status fmu_set_time(fmu_instance *I, double time)
{
    if (!isfinite(time)) return fmu_fail(I, "time = %g is not finite", time);
    I->core.time = time;
    return FMU_OK;
}

fmu_status fmu_set_states(fmu_instance *I, const double x[], size_t n)
{
    size_t i;
    if (check_size(I, n, I->core.model.nx, I->api->nx_argument)) return FMU_ERROR;
    for (i = 0; i < n; i++)
        if (!isfinite(x[i])) return fmu_fail(I, "state %u = %g is not finite", (unsigned)i, x[i]);
    I->core.model.set_states(I->core.M, x);
    return FMU_OK;
}

fmu_status fmu_get_derivatives(fmu_instance *I, double dx[], size_t n)
{
    size_t i;
    if (check_size(I, n, I->core.model.nx, I->api->nx_argument)) return FMU_ERROR;
    I->core.model.derivatives(I->core.M, dx);
    for (i = 0; i < n; i++)
        if (!isfinite(dx[i])) return fmu_fail(I, "derivative %u is not finite at t = %g", (unsigned)i, I->core.time);
    return FMU_OK;
}

fmu_status fmu_get_event_indicators(fmu_instance *I, double z[], size_t n)
{
    if (check_size(I, n, I->core.model.nz, I->api->nz_argument)) return FMU_ERROR;
    if (n > 0) I->core.model.event_indicators(I->core.M, fmu_initializing(I), z);
    return FMU_OK;
}

fmu_status fmu_get_states(fmu_instance *I, double x[], size_t n)
{
    if (check_size(I, n, I->core.model.nx, I->api->nx_argument)) return FMU_ERROR;
    I->core.model.get_states(I->core.M, fmu_initializing(I), x);
    return FMU_OK;
}

fmu_status fmu_get_nominals(fmu_instance *I, double x[], size_t n)
{
    if (check_size(I, n, I->core.model.nx, I->api->nx_argument)) return FMU_ERROR;
    fmu_core_nominals(&I->core, x);
    return FMU_OK;
}

/* ---- Co-Simulation ------------------------------------------------------------------------- */

fmu_status fmu_do_step(fmu_instance *I, double t, double h, int *ended)
{
    fmu_core *const C = &I->core;
    char msg[512], what[128];
    int rc;
    *ended = 0;
    if (!(isfinite(t) && isfinite(h) && h > 0))
        return fmu_fail(I, "communication point %g and step size %g must be finite, step size > 0", t, h);
    if (fabs(t - C->time) > 1e-9 * fmax(1.0, fabs(t)))
        return fmu_fail(I, "currentCommunicationPoint = %.17g, but the FMU is at t = %.17g", t, C->time);
    if (!(t + h <= FMU_MAX_TIME))
        return fmu_fail(I, "the step would end at t = %g, after the last time this FMU simulates, %g s", t + h,
                        FMU_MAX_TIME);
    if (t + h == t) return fmu_fail(I, "step size %g is below the resolution of the time %.17g", h, t);
    if (C->terminated) {
        fmu_log_event(I, "the model terminated at t = %.17g; no further steps", C->time);
        return FMU_DISCARD;
    }
    rc = fmu_core_step(C, h, &I->log, msg, sizeof msg);
    if (rc < 0) return fmu_fail(I, "%s", msg);
    if (non_finite_result(I, what, sizeof what)) {
        describe_inputs(I, msg, sizeof msg);
        return fmu_fail(I, "the step from t = %.17g to %.17g ended with %s, which is not finite (inputs: %s)", t, t + h,
                        what, msg);
    }
    *ended = rc == 1;
    if (*ended) fmu_log_event(I, "the model terminated the simulation at t = %.17g", C->time);
    return FMU_OK;
}

/* ---- FMU state ----------------------------------------------------------------------------- */

/* a block of n bytes for an FMU state, reusing old when it has the size */
static void *state_block(fmu_instance *I, void *old, size_t n)
{
    if (old) {
        if (fmu_state_bytes(old) == n) return old;
        I->release(old);
    }
    return I->alloc(n, 1);
}

/* a state the importer hands back, checked to be one of ours; if not, log why */
static fmu_status own_state(fmu_instance *I, const void *state)
{
    char msg[256];
    if (fmu_state_is_ours(state, msg, sizeof msg)) return fmu_fail(I, "%s", msg);
    return FMU_OK;
}

/* the argument that receives a state: not NULL, and what it holds NULL or one of ours */
static fmu_status state_argument(fmu_instance *I, void **state)
{
    if (!state) return fmu_fail(I, "argument %s must not be NULL", I->api->fmu_state);
    return *state ? own_state(I, *state) : FMU_OK;
}

fmu_status fmu_get_fmu_state(fmu_instance *I, void **state)
{
    const size_t n = fmu_state_size(&I->core);
    if (state_argument(I, state)) return FMU_ERROR;
    *state = state_block(I, *state, n);
    if (!*state) return fmu_fail(I, "out of memory for an FMU state of %u bytes", (unsigned)n);
    fmu_state_write(&I->core, *state);
    return FMU_OK;
}

fmu_status fmu_set_fmu_state(fmu_instance *I, void *state)
{
    char msg[512];
    if (own_state(I, state)) return FMU_ERROR;
    if (fmu_state_read(&I->core, state, msg, sizeof msg)) return fmu_fail(I, "%s", msg);
    return FMU_OK;
}

fmu_status fmu_free_fmu_state(fmu_instance *I, void **state)
{
    if (state_argument(I, state)) return FMU_ERROR;
    if (*state) I->release(*state);
    *state = NULL;
    return FMU_OK;
}

fmu_status fmu_serialized_size(fmu_instance *I, void *state, size_t *size)
{
    if (!size) return fmu_fail(I, "argument size must not be NULL");
    if (own_state(I, state)) return FMU_ERROR;
    *size = fmu_state_bytes(state);
    return FMU_OK;
}

fmu_status fmu_serialize(fmu_instance *I, void *state, void *bytes, size_t size)
{
    if (!bytes) return fmu_fail(I, "argument serializedState must not be NULL");
    if (own_state(I, state)) return FMU_ERROR;
    if (size != fmu_state_bytes(state))
        return fmu_fail(I, "size = %u, but the FMU state has %u bytes (%sSerialized%sSize)", (unsigned)size,
                        (unsigned)fmu_state_bytes(state), I->api->prefix, I->api->fmu_state);
    memcpy(bytes, state, size);
    return FMU_OK;
}

fmu_status fmu_deserialize(fmu_instance *I, const void *bytes, size_t size, void **state)
{
    char msg[512];
    if (!bytes) return fmu_fail(I, "argument serializedState must not be NULL");
    if (state_argument(I, state)) return FMU_ERROR;
    if (fmu_state_check(&I->core, bytes, size, msg, sizeof msg)) return fmu_fail(I, "%s", msg);
    *state = state_block(I, *state, size);
    if (!*state) return fmu_fail(I, "out of memory for an FMU state of %u bytes", (unsigned)size);
    memcpy(*state, bytes, size);
    return FMU_OK;
}
