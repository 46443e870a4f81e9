/* RockingWall as an FMU model: the callbacks of fmu_model.h over the wall's physics (rw_physics.h,
 * fmu_src/wall/). Holds the instance data (parameters, contact regime, inputs, states, counters); the FMI 2.0
 * API itself is the shared fmi2Functions.c. */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmu_model.h"
#include "model_variables.h"
#include "rw_physics.h"
#include "rw_model_data.h"

/* compile-time check: model_variables.h and rw_physics.h agree on the sizes */
typedef char rw_check_nx[(RW_NUMBER_OF_STATES == RW_NX) ? 1 : -1];
typedef char rw_check_nz[(RW_NUMBER_OF_EVENT_INDICATORS == RW_NZ) ? 1 : -1];


#define FMU_Real FMU_REAL
#define FMU_Integer FMU_INTEGER
#define FMU_Boolean FMU_BOOLEAN
#define FMU_String FMU_STRING
#define RW_PARAM_VAR(ID, VR, TYPE, UNIT, DEF, LO, HI, DESC) {VR, FMU_##TYPE, #ID, "parameter", "exact"},
#define RW_VAR(ID, VR, NAME, TYPE, CAUS, VARIAB, INIT, START, UNIT, NOM, DER, DESC) \
    {VR, FMU_##TYPE, NAME, CAUS, INIT},
static const fmu_var VARS[] = {RW_PARAMETERS(RW_PARAM_VAR) RW_VARIABLES(RW_VAR)};
#undef RW_VAR
#undef RW_PARAM_VAR

#define RW_Z_VR(ID, VR, DESC) VR,
static const unsigned Z_VRS[] = {RW_EVENT_INDICATORS(RW_Z_VR)};
#undef RW_Z_VR
typedef char rw_check_z_vrs[(sizeof Z_VRS / sizeof Z_VRS[0] == RW_NZ) ? 1 : -1];

static void physics_log(void *ctx, const char *message)
{
    rw_data *S = (rw_data *)ctx;
    char buf[768];
    if (!S->log || !S->log->event) return;
    snprintf(buf, sizeof buf, "t = %.9g: %s", S->time, message);
    S->log->event(S->log->ctx, buf);
}

static void reset(void *M)
{
    rw_data *S = (rw_data *)M;
    memset(S, 0, sizeof *S);
    rw_params_default(&S->P);
    rw_derive(&S->P, &S->D);
    S->regime.side_b = S->regime.side_m = 1;
    S->ag_scale = 1.0;
}

/* the record the instance read, at reset and free (the FMI layer calls it) */
static void release(void *M)
{
    rw_data *S = (rw_data *)M;
    if (!S->record) return;
    rw_gm_free(S->record);
    free(S->record);
    S->record = NULL;
}

/* in.ag: the input plus the record at S->time */
static void update_ground(rw_data *S)
{
    double slope, t_next;
    S->in.ag = S->ag_input + (S->record ? rw_gm_at(S->record, S->time, &slope, &t_next) : 0.0);
}

static void set_time(void *M, double time)
{
    rw_data *S = (rw_data *)M;
    S->time = time;
    update_ground(S);
}

/* regime and states as seen by getters: before initialization ends the regime is not decided, so
 * they are computed on copies from the start values */
static void view(rw_data *S, int initializing, rw_regime *m, double x[RW_NX])
{
    memcpy(x, S->x, sizeof S->x);
    *m = S->regime;
    if (initializing) rw_init_regime(&S->P, &S->D, &S->in, x, m, NULL, NULL);
}

static int state_index(unsigned vr)
{
    switch (vr) {
    case RW_VR_q1: return 0;
    case RW_VR_q2: return 1;
    case RW_VR_dq1: return 2;
    case RW_VR_dq2: return 3;
    default: return -1;
    }
}

static void get_real(void *M, int initializing, double time, const unsigned vr[], size_t n, double v[])
{
    rw_data *S = (rw_data *)M;
    rw_regime m;
    double x[RW_NX], dx[RW_NX], F_top;
    size_t i;
    (void)time;
    view(S, initializing, &m, x);
    rw_derivatives(&S->P, &S->D, &m, &S->in, x, dx);
    F_top = rw_tie_force(&S->P, &S->D, &m, &S->in, x);
    for (i = 0; i < n; i++) {
        const rw_param_info *param = rw_param_by_vr(vr[i]);
        const int k = state_index(vr[i]);
        if (param) { v[i] = rw_param_get(&S->P, param); continue; }
        if (k >= 0) { v[i] = x[k]; continue; }
        switch (vr[i]) {
        case RW_VR_ag: v[i] = S->ag_input; break;
        case RW_VR_agScale: v[i] = S->ag_scale; break;
        case RW_VR_u_top: v[i] = S->in.u_top; break;
        case RW_VR_s1: v[i] = rw_s1(&S->P, x); break;
        case RW_VR_s2: v[i] = m.tie_held ? F_top / S->P.Kd : rw_s2(&S->P, x); break; /* held: the tie's deflection */
        case RW_VR_F_top: v[i] = F_top; break;
        case RW_VR_F_base: v[i] = rw_F_base_given_top(&S->P, &S->D, &m, &S->in, x, dx, F_top); break;
        case RW_VR_energy: v[i] = rw_energy(&S->P, &S->D, &m, &S->in, x); break;
        case RW_VR_P_ground: v[i] = rw_ground_power(&S->P, &S->D, &m, &S->in, x); break;
        case RW_VR_dissipated: v[i] = S->dissipated; break;
        case RW_VR_der_dq1: v[i] = dx[2]; break;
        case RW_VR_der_dq2: v[i] = dx[3]; break;
        default: v[i] = NAN; break; /* every Real of the table is handled above */
        }
    }
}

static void get_integer(void *M, int initializing, const unsigned vr[], size_t n, int v[])
{
    rw_data *S = (rw_data *)M;
    rw_regime m;
    double x[RW_NX];
    size_t i;
    view(S, initializing, &m, x);
    for (i = 0; i < n; i++) {
        const rw_param_info *param = rw_param_by_vr(vr[i]);
        if (param) v[i] = (int)rw_param_get(&S->P, param);
        else if (vr[i] == RW_VR_impacts) v[i] = S->impacts;
        else v[i] = rw_condition(&S->P, &m); /* RW_VR_condition */
    }
}

static void get_boolean(void *M, const unsigned vr[], size_t n, int v[])
{
    size_t i;
    (void)vr;
    for (i = 0; i < n; i++) v[i] = ((rw_data *)M)->collapsed; /* the only Boolean */
}

static int set_real(void *M, unsigned vr, double value, char *msg, size_t n)
{
    rw_data *S = (rw_data *)M;
    const rw_param_info *param = rw_param_by_vr(vr);
    int k;
    if (param) {
        if (rw_param_set(&S->P, param, value, msg, n)) return 1;
        rw_derive(&S->P, &S->D);
    } else if ((k = state_index(vr)) >= 0) {
        S->x[k] = value;
    } else if (vr == RW_VR_ag) {
        S->ag_input = value;
        update_ground(S);
    } else if (vr == RW_VR_agScale) {
        S->ag_scale = value;
    } else { /* RW_VR_u_top, the only other settable Real */
        S->in.u_top = value;
        if (value != 0.0 && S->regime.tie_held) {
            S->regime.tie_held = 0;
            physics_log(S, "u_top is driven: the tie is no longer held rigid, its own mode is integrated");
        }
    }
    return 0;
}

static int set_integer(void *M, unsigned vr, int value, char *msg, size_t n)
{
    rw_data *S = (rw_data *)M;
    if (rw_param_set(&S->P, rw_param_by_vr(vr), value, msg, n)) return 1; /* the only settable Integers */
    rw_derive(&S->P, &S->D);
    return 0;
}

static const char *get_string(void *M, unsigned vr)
{
    (void)vr; /* RW_VR_agFile, the only String */
    return ((rw_data *)M)->ag_file;
}

static int set_string(void *M, unsigned vr, const char *value, char *msg, size_t n)
{
    rw_data *S = (rw_data *)M;
    (void)vr; /* RW_VR_agFile, the only String */
    if (strlen(value) >= sizeof S->ag_file)
        return snprintf(msg, n, "agFile: a path of %lu characters, longer than the %d this FMU takes",
                        (unsigned long)strlen(value), RW_AG_FILE_MAX - 1), 1;
    strcpy(S->ag_file, value);
    return 0;
}

/* The record of agFile (none if empty), read at the end of initialization. 0 = ok, else msg. */
static int read_record(rw_data *S, char *msg, size_t n)
{
    char err[768];
    release(S);
    if (!S->ag_file[0]) return 0;
    S->record = (rw_ground_motion *)malloc(sizeof *S->record);
    if (!S->record) return snprintf(msg, n, "agFile: out of memory"), 1;
    if (rw_gm_read(S->ag_file, S->P.g, S->ag_scale, S->record, err, sizeof err)) {
        free(S->record);
        S->record = NULL;
        return snprintf(msg, n, "agFile: %s", err), 1;
    }
    if (S->log && S->log->event) {
        snprintf(err, sizeof err, "agFile: read %lu samples from %.9g to %.9g s of %.600s (scaled by %g)",
                 (unsigned long)S->record->n, S->record->t[0], S->record->t[S->record->n - 1], S->ag_file,
                 S->ag_scale);
        S->log->event(S->log->ctx, err);
    }
    return 0;
}

/* An FMU state restored into an initialized instance must have been taken with the record the
 * instance read (the record is the instance's, not the state's). */
static int state_fits(const void *M, const void *state_data, char *msg, size_t n)
{
    const rw_data *now = (const rw_data *)M;
    const rw_data *then = (const rw_data *)state_data;
    char file[RW_AG_FILE_MAX];
    if (!now->initialized) return 0;
    memcpy(file, then->ag_file, sizeof file);
    file[sizeof file - 1] = '\0';
    if (strcmp(file, now->ag_file) || then->ag_scale != now->ag_scale || (now->ag_file[0] && then->P.g != now->P.g))
        return snprintf(msg, n, "the FMU state was taken with agFile \"%.200s\" (agScale %g), this instance read \"%.200s\" "
                        "(agScale %g)", file, then->ag_scale, now->ag_file, now->ag_scale), 1;
    return 0;
}

static void check_collapse(rw_data *S)
{
    char buf[512];
    int reason;
    if (S->collapsed) return;
    reason = rw_collapse_reason(&S->P, &S->D, &S->regime, &S->in, S->x);
    if (reason == RW_STANDING) return;
    S->collapsed = 1;
    S->terminate_time = S->time + RW_TERMINATE_DELAY;
    if (!S->log || !S->log->warning) return;
    snprintf(buf, sizeof buf,
             "collapse at t = %.9g s: s1 = %.6g m, s2 = %.6g m (q1 = %.6g, q2 = %.6g rad): %s; terminating the simulation",
             S->time, rw_s1(&S->P, S->x), rw_s2(&S->P, S->x), S->x[0], S->x[1],
             reason == RW_PAST_INSTABILITY ? "the wall passed its instability point"
                                           : "a body turned past its toppling limit 2b/h");
    S->log->warning(S->log->ctx, buf);
}

/* A tie far stiffer than the wall is held rigid (rw_rigid_tie.c) from the end of initialization
 * until u_top is set nonzero (the far end then drives the tie): say so, with the ratio */
static void hold_stiff_tie(rw_data *S)
{
    char buf[512];
    if (!rw_hold_tie(&S->P, &S->D, &S->regime, &S->in, S->x, physics_log, S)) return;
    snprintf(buf, sizeof buf, "the tie (Kd = %g N/m per m) is held rigid (q2 = -q1, F_top its reaction): the wall's "
             "stiffest mode has %.3g of its omega^2, below %g; the answer differs by about that ratio and the tie's "
             "oscillation is not integrated", S->P.Kd, rw_tie_stiffness_ratio(&S->P, &S->D), RW_RIGID_TIE_RATIO);
    physics_log(S, buf);
}

static int exit_init(void *M, double time, const fmu_logger *log, char *msg, size_t n)
{
    rw_data *S = (rw_data *)M;
    if (rw_params_validate(&S->P, msg, n)) return 1;
    S->log = log;
    S->time = time;
    if (read_record(S, msg, n)) return 1;
    S->initialized = 1;
    update_ground(S);
    rw_derive(&S->P, &S->D);
    rw_init_regime(&S->P, &S->D, &S->in, S->x, &S->regime, physics_log, S);
    hold_stiff_tie(S);
    S->impacts = 0;
    S->collapsed = 0;
    S->dissipated = 0.0;
    check_collapse(S);
    return 0;
}

static void get_states(void *M, int initializing, double x[])
{
    rw_regime m;
    view((rw_data *)M, initializing, &m, x);
}

static void set_states(void *M, const double x[])
{
    memcpy(((rw_data *)M)->x, x, sizeof(double) * RW_NX);
}

static void derivatives(void *M, double dx[])
{
    rw_data *S = (rw_data *)M;
    rw_derivatives(&S->P, &S->D, &S->regime, &S->in, S->x, dx);
}

static void event_indicators(void *M, int initializing, double z[])
{
    rw_data *S = (rw_data *)M;
    rw_regime m;
    double x[RW_NX];
    view(S, initializing, &m, x);
    rw_event_indicators(&S->P, &S->D, &m, &S->in, x, z);
}

static void nominals(double x[])
{
    x[0] = x[1] = 0.01; /* rotations of a rocking wall are of the order of 0.01 rad */
    x[2] = x[3] = 0.1;
}

static void event_update(void *M, double time, const fmu_logger *log, fmu_event_result *r)
{
    rw_data *S = (rw_data *)M;
    rw_event_result e;
    double energy_before;
    memset(r, 0, sizeof *r);
    S->log = log;
    S->time = time;
    if (S->collapsed) {
        /* `collapsed` became true at the collapse event (so importers record it); the time event
         * RW_TERMINATE_DELAY later ends the run */
        if (time >= S->terminate_time - 1e-12 * fmax(1.0, fabs(time))) {
            r->terminate = 1;
            physics_log(S, "terminateSimulation after collapse");
        } else {
            r->next_time_defined = 1;
            r->next_time = S->terminate_time;
        }
        return;
    }
    energy_before = rw_energy(&S->P, &S->D, &S->regime, &S->in, S->x);
    rw_event_update(&S->P, &S->D, &S->regime, &S->in, S->x, &e, physics_log, S);
    S->impacts += e.impacts;
    if (e.states_changed) {
        r->states_changed = 1;
        S->dissipated += energy_before - rw_energy(&S->P, &S->D, &S->regime, &S->in, S->x);
    }
    r->more = e.regime_changed || e.states_changed; /* confirm at the same instant */
    check_collapse(S);
    if (S->collapsed) {
        r->more = 0;
        r->next_time_defined = 1;
        r->next_time = S->terminate_time;
    }
}

const fmu_model FMU_MODEL = {
    .identifier = RW_MODEL_IDENTIFIER,
    .guid = RW_GUID,
    .nx = RW_NX,
    .nz = RW_NZ,
    .vars = VARS,
    .nvars = sizeof VARS / sizeof VARS[0],
    .z_vrs = Z_VRS,
    .data_size = sizeof(rw_data),
    .data_tail_size = rw_engine_size, /* the exact engine after the data (rw_model_data.h) */
    .reset = reset,
    .get_real = get_real,
    .get_integer = get_integer,
    .get_boolean = get_boolean,
    .set_real = set_real,
    .set_integer = set_integer,
    .get_string = get_string,
    .set_string = set_string,
    .exit_init = exit_init,
    .get_states = get_states,
    .set_states = set_states,
    .derivatives = derivatives,
    .event_indicators = event_indicators,
    .nominals = nominals,
    .event_update = event_update,
    .set_time = set_time,
    .instance_offset = offsetof(rw_data, record),
    .instance_size = sizeof(rw_ground_motion *),
    .release = release,
    .state_fits = state_fits,
    .exact_step = rw_exact_step, /* Co-Simulation through the exact engine (cs_exact.c) */
};
