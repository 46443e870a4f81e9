/* Co-Simulation inside the FMU with CVODE (SUNDIALS 6, linked statically so that the FMU needs
 * nothing beyond the C library): see cs_cvode.h.
 *
 * Within a communication step the inputs are the master's values, held or ramped with the
 * derivative it gave. When they differ from where the previous step ended, the right-hand side
 * has a discontinuity at the communication point: the event indicators are checked there (an
 * input can open a hinge at rest) and CVODE restarts, as it does after every event, because its
 * history belongs to the old right-hand side. */
#include "cs_cvode.h"

#include <cvode/cvode.h>
#include <math.h>
#include <nvector/nvector_serial.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#define CS_MAX_EVENT_ROUNDS 1000
#define CS_MAX_STEPS 1000000L

struct cs_solver {
    const fmu_model *model;
    void *M;
    int nx, nz;
    SUNContext ctx;
    void *mem;
    N_Vector y, abstol;
    SUNMatrix A;
    SUNLinearSolver LS;
    double time;
    double *z_before, *z_after;
    /* inputs of the current step, and where the previous step left them */
    const cs_input *in;
    size_t n_in;
    double t_in;
    cs_input *prev_in;
    size_t n_prev_in;
    int next_time_defined;
    double next_time;
    int restart_pending; /* re-initialise CVODE at the next step (an FMU state was saved or restored) */
    char cvode_msg[256];
};

static void apply_inputs(cs_solver *s, double t)
{
    char unused[8];
    size_t i;
    if (s->model->set_time) s->model->set_time(s->M, t); /* inputs of the model's own (a record) first */
    for (i = 0; i < s->n_in; i++)
        s->model->set_real(s->M, s->in[i].vr, s->in[i].value + s->in[i].slope * (t - s->t_in), unused, sizeof unused);
}

static int rhs(sunrealtype t, N_Vector y, N_Vector ydot, void *user)
{
    cs_solver *s = (cs_solver *)user;
    apply_inputs(s, t);
    s->model->set_states(s->M, N_VGetArrayPointer(y));
    s->model->derivatives(s->M, N_VGetArrayPointer(ydot));
    return 0;
}

static int roots(sunrealtype t, N_Vector y, sunrealtype *g, void *user)
{
    cs_solver *s = (cs_solver *)user;
    apply_inputs(s, t);
    s->model->set_states(s->M, N_VGetArrayPointer(y));
    s->model->event_indicators(s->M, 0, g);
    return 0;
}

static void cvode_error(int code, const char *module, const char *function, char *msg, void *user)
{
    cs_solver *s = (cs_solver *)user;
    (void)code;
    (void)module;
    snprintf(s->cvode_msg, sizeof s->cvode_msg, "%s: %s", function, msg);
}

/* Did a CVODE call succeed (flags >= 0 are successes such as CV_ROOT_RETURN)? If not, msg says
 * which call, CVODE's name of the flag and CVODE's own message. */
static int cvode_ok(cs_solver *s, int flag, const char *call, double t, char *msg, size_t n)
{
    char *name;
    if (flag >= 0) return 1;
    name = CVodeGetReturnFlagName(flag); /* malloc'ed by CVODE */
    snprintf(msg, n, "%s failed at t = %.17g: %s (%s)", call, t, name ? name : "unknown flag", s->cvode_msg);
    free(name);
    return 0;
}

/* CVODE from the model's states at t. */
static int restart(cs_solver *s, double t, char *msg, size_t n)
{
    s->model->get_states(s->M, 0, N_VGetArrayPointer(s->y));
    if (!cvode_ok(s, CVodeReInit(s->mem, t, s->y), "CVodeReInit", t, msg, n)) return -1;
    s->time = t;
    return 0;
}

/* The event iteration at te (the model is at te); then CVODE restarts from the model's states. */
static int handle_event(cs_solver *s, double te, const fmu_logger *log, int *terminated, char *msg, size_t n)
{
    fmu_event_result r;
    int rounds = 0;
    *terminated = 0;
    s->next_time_defined = 0;
    do {
        s->model->event_update(s->M, te, log, &r);
        if (r.terminate) {
            *terminated = 1;
            return 0;
        }
        if (++rounds > CS_MAX_EVENT_ROUNDS) {
            snprintf(msg, n, "the event iteration at t = %.17g did not converge in %d rounds", te, CS_MAX_EVENT_ROUNDS);
            return -1;
        }
    } while (r.more);
    if (r.next_time_defined) {
        s->next_time_defined = 1;
        s->next_time = r.next_time;
    }
    return restart(s, te, msg, n);
}

void cs_free(cs_solver *s)
{
    if (!s) return;
    if (s->mem) CVodeFree(&s->mem);
    if (s->LS) SUNLinSolFree(s->LS);
    if (s->A) SUNMatDestroy(s->A);
    if (s->y) N_VDestroy(s->y);
    if (s->abstol) N_VDestroy(s->abstol);
    if (s->ctx) SUNContext_Free(&s->ctx);
    free(s->z_before);
    free(s->z_after);
    free(s->prev_in);
    free(s);
}

/* absolute tolerances: rtol times each state's nominal */
static void set_abstol(cs_solver *s, double rtol)
{
    double *a = N_VGetArrayPointer(s->abstol);
    int i;
    for (i = 0; i < s->nx; i++) a[i] = 1.0;
    s->model->nominals(a);
    for (i = 0; i < s->nx; i++) a[i] = rtol * (a[i] > 0 ? a[i] : 1.0);
}

/* CVODE (BDF, dense Newton, root-finding) from the model's states at t_start: every call checked */
static int setup_cvode(cs_solver *s, double t_start, double rtol, char *msg, size_t n)
{
    s->model->get_states(s->M, 0, N_VGetArrayPointer(s->y));
    set_abstol(s, rtol);
    if (!cvode_ok(s, CVodeSetErrHandlerFn(s->mem, cvode_error, s), "CVodeSetErrHandlerFn", t_start, msg, n) ||
        !cvode_ok(s, CVodeInit(s->mem, rhs, t_start, s->y), "CVodeInit", t_start, msg, n) ||
        !cvode_ok(s, CVodeSetUserData(s->mem, s), "CVodeSetUserData", t_start, msg, n) ||
        !cvode_ok(s, CVodeSVtolerances(s->mem, rtol, s->abstol), "CVodeSVtolerances", t_start, msg, n) ||
        !cvode_ok(s, CVodeSetLinearSolver(s->mem, s->LS, s->A), "CVodeSetLinearSolver", t_start, msg, n) ||
        !cvode_ok(s, CVodeSetMaxNumSteps(s->mem, CS_MAX_STEPS), "CVodeSetMaxNumSteps", t_start, msg, n) ||
        !cvode_ok(s, CVodeSetNoInactiveRootWarn(s->mem), "CVodeSetNoInactiveRootWarn", t_start, msg, n))
        return -1;
    if (s->nz > 0 && !cvode_ok(s, CVodeRootInit(s->mem, s->nz, roots), "CVodeRootInit", t_start, msg, n)) return -1;
    return 0;
}

/* the solver's memory; NULL when out of memory */
static cs_solver *allocate_solver(const fmu_model *model, void *M, double t_start)
{
    cs_solver *s = (cs_solver *)calloc(1, sizeof *s);
    if (!s) return NULL;
    s->model = model;
    s->M = M;
    s->nx = model->nx;
    s->nz = model->nz;
    s->time = t_start;
    s->z_before = (double *)calloc((size_t)s->nz + 1, sizeof(double));
    s->z_after = (double *)calloc((size_t)s->nz + 1, sizeof(double));
    s->prev_in = (cs_input *)calloc(model->nvars + 1, sizeof(cs_input));
    if (s->z_before && s->z_after && s->prev_in && SUNContext_Create(NULL, &s->ctx) == 0) {
        s->y = N_VNew_Serial(s->nx, s->ctx);
        s->abstol = N_VNew_Serial(s->nx, s->ctx);
        s->mem = CVodeCreate(CV_BDF, s->ctx);
        s->A = SUNDenseMatrix(s->nx, s->nx, s->ctx);
        s->LS = (s->y && s->A) ? SUNLinSol_Dense(s->y, s->A, s->ctx) : NULL;
    }
    if (!s->y || !s->abstol || !s->mem || !s->LS) {
        cs_free(s);
        return NULL;
    }
    return s;
}

cs_solver *cs_new(const fmu_model *model, void *M, double t_start, double rtol, const fmu_logger *log,
                  int *terminated, char *msg, size_t n)
{
    cs_solver *s = allocate_solver(model, M, t_start);
    *terminated = 0;
    if (!s) {
        snprintf(msg, n, "out of memory setting up CVODE");
        return NULL;
    }
    /* then the initial event iteration a Model-Exchange master would run after initialization */
    if (setup_cvode(s, t_start, rtol > 0 ? rtol : 1e-6, msg, n) != 0 ||
        handle_event(s, t_start, log, terminated, msg, n) != 0) {
        cs_free(s);
        return NULL;
    }
    model->event_indicators(M, 0, s->z_before);
    return s;
}

/* Did the master move the inputs away from where the previous step left them? */
static int inputs_jumped(cs_solver *s, const cs_input *in, size_t n_in, double t)
{
    size_t i, k;
    if (n_in != s->n_prev_in) return 1;
    for (i = 0; i < n_in; i++) {
        for (k = 0; k < s->n_prev_in && s->prev_in[k].vr != in[i].vr; k++) {}
        if (k == s->n_prev_in) return 1;
        if (in[i].slope != s->prev_in[k].slope ||
            in[i].value != s->prev_in[k].value + s->prev_in[k].slope * (t - s->t_in))
            return 1;
    }
    return 0;
}

int cs_step(cs_solver *s, double t, double h, const cs_input *in, size_t n_in, const fmu_logger *log,
            double *t_reached, char *msg, size_t n)
{
    const double t_end = t + h;
    const double eps = 1e-12 * fmax(1.0, fabs(t_end));
    int terminated = 0, i;
    *t_reached = t;
    if (s->restart_pending) /* the states of a saved or restored FMU state, not CVODE's */
        s->model->get_states(s->M, 0, N_VGetArrayPointer(s->y));
    if (inputs_jumped(s, in, n_in, t)) {
        int crossed = 0;
        s->in = in;
        s->n_in = n_in;
        s->t_in = t;
        apply_inputs(s, t);
        s->model->set_states(s->M, N_VGetArrayPointer(s->y));
        s->model->event_indicators(s->M, 0, s->z_after);
        for (i = 0; i < s->nz; i++)
            crossed |= (s->z_before[i] > 0) != (s->z_after[i] > 0);
        if (crossed) {
            if (handle_event(s, t, log, &terminated, msg, n) != 0) return -1;
            if (terminated) return 1;
        } else if (restart(s, t, msg, n) != 0) {
            return -1;
        }
    } else if (s->restart_pending && restart(s, t, msg, n) != 0) {
        return -1;
    }
    s->restart_pending = 0;
    s->in = in;
    s->n_in = n_in;
    s->t_in = t;
    memcpy(s->prev_in, in, n_in * sizeof *in);
    s->n_prev_in = n_in;
    while (s->time < t_end - eps) {
        double t_stop = t_end, tret = s->time;
        int flag, time_event;
        if (s->next_time_defined && s->next_time < t_stop) t_stop = fmax(s->next_time, s->time);
        if (!cvode_ok(s, CVodeSetStopTime(s->mem, t_stop), "CVodeSetStopTime", s->time, msg, n)) return -1;
        flag = t_stop > s->time ? CVode(s->mem, t_stop, s->y, &tret, CV_NORMAL) : CV_TSTOP_RETURN;
        if (!cvode_ok(s, flag, "CVode", tret, msg, n)) return -1;
        s->time = tret;
        apply_inputs(s, tret);
        s->model->set_states(s->M, N_VGetArrayPointer(s->y));
        time_event = s->next_time_defined && tret >= s->next_time - eps;
        if (flag == CV_ROOT_RETURN || time_event) {
            if (handle_event(s, tret, log, &terminated, msg, n) != 0) return -1;
            *t_reached = tret;
            if (terminated) return 1;
        }
    }
    s->time = t_end;
    *t_reached = t_end;
    s->model->event_indicators(s->M, 0, s->z_before);
    return 0;
}

/* ---- FMU state ----------------------------------------------------------------------------- */

/* the scalars of the solver's part of an FMU state; then prev_in (nvars + 1 entries), z_before (nz) */
typedef struct {
    double time, t_in, next_time;
    int next_time_defined;
    unsigned n_prev_in;
} cs_saved;

static size_t n_prev_slots(const cs_solver *s) { return s->model->nvars + 1; }

size_t cs_state_size(const cs_solver *s)
{
    return sizeof(cs_saved) + n_prev_slots(s) * sizeof(cs_input) + (size_t)s->nz * sizeof(double);
}

void cs_get_state(cs_solver *s, void *buf)
{
    unsigned char *p = (unsigned char *)buf;
    cs_saved v;
    memset(&v, 0, sizeof v);
    v.time = s->time;
    v.t_in = s->t_in;
    v.next_time = s->next_time;
    v.next_time_defined = s->next_time_defined;
    v.n_prev_in = (unsigned)s->n_prev_in;
    memcpy(p, &v, sizeof v);
    memcpy(p + sizeof v, s->prev_in, n_prev_slots(s) * sizeof(cs_input));
    memcpy(p + sizeof v + n_prev_slots(s) * sizeof(cs_input), s->z_before, (size_t)s->nz * sizeof(double));
    s->restart_pending = 1; /* the step from here must not depend on CVODE's history */
}

int cs_set_state(cs_solver *s, const void *buf, size_t n, char *msg, size_t msg_n)
{
    const unsigned char *p = (const unsigned char *)buf;
    cs_saved v;
    if (n != cs_state_size(s)) {
        snprintf(msg, msg_n, "the integrator part of the FMU state has %u bytes, expected %u", (unsigned)n,
                 (unsigned)cs_state_size(s));
        return -1;
    }
    memcpy(&v, p, sizeof v);
    if (v.n_prev_in > n_prev_slots(s) || !isfinite(v.time) || !isfinite(v.t_in)) {
        snprintf(msg, msg_n, "the integrator part of the FMU state is corrupt");
        return -1;
    }
    s->time = v.time;
    s->t_in = v.t_in;
    s->next_time = v.next_time;
    s->next_time_defined = v.next_time_defined;
    s->n_prev_in = v.n_prev_in;
    memcpy(s->prev_in, p + sizeof v, n_prev_slots(s) * sizeof(cs_input));
    memcpy(s->z_before, p + sizeof v + n_prev_slots(s) * sizeof(cs_input), (size_t)s->nz * sizeof(double));
    s->restart_pending = 1; /* CVODE from the restored model states at the next step */
    return 0;
}
