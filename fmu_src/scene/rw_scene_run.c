/* A scene over a record with CVODE (rw_scene_run.h): root-finding on the walls' event indicators,
 * the walls' event rules at each root, and the energy balance's two work integrals as CVODE
 * quadratures (outside its error test). CVODE stops at every record sample (a kink of the
 * interpolated input) and every output time, and restarts after every event.
 *
 * The method: Adams, with fixed-point iteration, and with dense Newton from where the scene proves
 * stiff. The scene's fastest modes are lightly damped oscillations (a stiff tie, in-plane walls)
 * that a relative tolerance must resolve whatever the method; at the steps that resolve them Adams
 * (orders up to 12) takes fewer steps than BDF (up to 5) and damps them less, and fixed-point
 * iteration needs no Jacobian or linear solve. It fails to converge where a mode is fast against
 * the steps (a very stiff dashpot, a loose tolerance on a stiff tie): Newton converges there, and
 * Adams's orders 1 and 2 are A-stable. BDF with Newton throughout is kept on request (opt->bdf). */
#include "rw_scene_run.h"
#include "rw_scene_step_peaks.h"

#include <cvodes/cvodes.h>
#include <math.h>
#include <nvector/nvector_serial.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#define MAX_ROUNDS_PER_EVENT 100
#define MAX_STEPS 20000000L
/* the scene proves stiff when fixed-point iteration fails to converge on more than STIFF_SHARE of
 * STIFF_WINDOW steps (where it suits the scene it fails on hardly any) */
#define STIFF_WINDOW 200L
#define STIFF_SHARE 0.1

enum { ADAMS_FIXED_POINT, ADAMS_NEWTON, BDF_NEWTON };

typedef struct {
    rw_scene sc;
    const rw_scene_record *rec;
    const rw_scene_options *opt;
    rw_scene_result *res;
    size_t hint;     /* the record interval of the last look-up */
    size_t next_out; /* the next row of the output grid */
    double losses;   /* energy taken out at events */
    rw_step_end last_end; /* the peak quantities at the last step's end, after its events */
    SUNContext ctx;
    void *mem;
    int method;
    long window_steps, window_fails; /* fixed-point steps and convergence failures in this window */
    long fails_seen;                 /* CVODE's count of convergence failures since its last (re)start */
    N_Vector y, abstol, q;
    SUNMatrix A;
    SUNLinearSolver LS;
    SUNNonlinearSolver NLS;
    char cvode_msg[160];
} run;

/* the record at t: linear between samples, the end values held */
static double ground(run *r, double t)
{
    const rw_scene_record *rec = r->rec;
    size_t k = r->hint;
    if (t <= rec->t[0]) return rec->ag[0];
    if (t >= rec->t[rec->n - 1]) return rec->ag[rec->n - 1];
    while (k > 0 && rec->t[k] > t) k--;
    while (k + 2 < rec->n && rec->t[k + 1] <= t) k++;
    r->hint = k;
    return rec->ag[k] + (rec->ag[k + 1] - rec->ag[k]) * (t - rec->t[k]) / (rec->t[k + 1] - rec->t[k]);
}

static int rhs(sunrealtype t, N_Vector y, N_Vector ydot, void *user)
{
    run *r = (run *)user;
    rw_scene_derivatives(&r->sc, ground(r, t), N_VGetArrayPointer(y), N_VGetArrayPointer(ydot), NULL);
    return 0;
}

static int roots(sunrealtype t, N_Vector y, sunrealtype *g, void *user)
{
    run *r = (run *)user;
    rw_scene_indicators(&r->sc, ground(r, t), N_VGetArrayPointer(y), g);
    return 0;
}

/* the ground's work rate and the viscous dissipation rate, integrated by CVODE */
static int powers(sunrealtype t, N_Vector y, N_Vector qdot, void *user)
{
    run *r = (run *)user;
    double *w = N_VGetArrayPointer(qdot);
    rw_scene_powers(&r->sc, ground(r, t), N_VGetArrayPointer(y), &w[0], &w[1]);
    return 0;
}

static void cvode_error(int code, const char *module, const char *function, char *msg, void *user)
{
    run *r = (run *)user;
    (void)code;
    (void)module;
    snprintf(r->cvode_msg, sizeof r->cvode_msg, "%s: %s", function, msg);
}

static int cvode_ok(run *r, int flag, const char *call, double t)
{
    if (flag >= 0) return 1;
    snprintf(r->res->message, sizeof r->res->message, "%s failed at t = %.9g s: %s", call, t, r->cvode_msg);
    return 0;
}

/* absolute tolerances: rtol times each state's scale (rotations 0.01 rad, rates 0.1 rad/s,
 * displacements 0.01 m, velocities 0.1 m/s, Bouc-Wen variables 1, the springs' works 100 J/m) */
static void set_abstol(run *r, double rtol)
{
    static const double floor_scale[BD_STATES_PER_FLOOR] = {0.01, 0.1, 1.0, 0.01, 0.1, 1.0, 100.0, 100.0};
    double *a = N_VGetArrayPointer(r->abstol);
    const int N = r->sc.S.n_storeys;
    int i, k;
    for (i = 0; i < N; i++)
        for (k = 0; k < RW_NX; k++) a[RW_NX * i + k] = rtol * (k < 2 ? 0.01 : 0.1);
    for (i = 0; i < N * BD_STATES_PER_FLOOR; i++) a[RW_NX * N + i] = rtol * floor_scale[i % BD_STATES_PER_FLOOR];
}

static void free_solver(run *r)
{
    if (r->mem) CVodeFree(&r->mem);
    if (r->LS) SUNLinSolFree(r->LS);
    if (r->A) SUNMatDestroy(r->A);
    if (r->NLS) SUNNonlinSolFree(r->NLS);
    r->LS = NULL, r->A = NULL, r->NLS = NULL;
}

static void free_run(run *r)
{
    free_solver(r);
    if (r->y) N_VDestroy(r->y);
    if (r->abstol) N_VDestroy(r->abstol);
    if (r->q) N_VDestroy(r->q);
    if (r->ctx) SUNContext_Free(&r->ctx);
}

static int allocate_vectors(run *r)
{
    const int nx = r->sc.nx;
    if (SUNContext_Create(NULL, &r->ctx) != 0) return 0;
    r->y = N_VNew_Serial(nx, r->ctx);
    r->abstol = N_VNew_Serial(nx, r->ctx);
    r->q = N_VNew_Serial(2, r->ctx);
    return r->y && r->abstol && r->q;
}

/* CVODE's memory and iteration for a method (any former ones freed) */
static int allocate_solver(run *r, int method)
{
    const int nx = r->sc.nx;
    free_solver(r);
    r->method = method;
    r->mem = CVodeCreate(method == BDF_NEWTON ? CV_BDF : CV_ADAMS, r->ctx);
    if (method == ADAMS_FIXED_POINT) {
        r->NLS = SUNNonlinSol_FixedPoint(r->y, 0, r->ctx);
        return r->mem && r->NLS;
    }
    r->A = SUNDenseMatrix(nx, nx, r->ctx);
    r->LS = r->A ? SUNLinSol_Dense(r->y, r->A, r->ctx) : NULL;
    return r->mem && r->LS;
}

static int attach_iteration(run *r, double t0)
{
    if (r->method == ADAMS_FIXED_POINT)
        return cvode_ok(r, CVodeSetNonlinearSolver(r->mem, r->NLS), "CVodeSetNonlinearSolver", t0);
    return cvode_ok(r, CVodeSetLinearSolver(r->mem, r->LS, r->A), "CVodeSetLinearSolver", t0);
}

/* CVODE set up from (t0, y, q): at the start, and where the run goes on with Newton */
static int setup_cvode(run *r, double t0)
{
    const double rtol = r->opt->rtol > 0 ? r->opt->rtol : 1e-8;
    set_abstol(r, rtol);
    r->fails_seen = 0;
    return cvode_ok(r, CVodeSetErrHandlerFn(r->mem, cvode_error, r), "CVodeSetErrHandlerFn", t0) &&
           cvode_ok(r, CVodeInit(r->mem, rhs, t0, r->y), "CVodeInit", t0) &&
           cvode_ok(r, CVodeSetUserData(r->mem, r), "CVodeSetUserData", t0) &&
           cvode_ok(r, CVodeSVtolerances(r->mem, rtol, r->abstol), "CVodeSVtolerances", t0) &&
           attach_iteration(r, t0) &&
           cvode_ok(r, CVodeSetMaxNumSteps(r->mem, MAX_STEPS), "CVodeSetMaxNumSteps", t0) &&
           cvode_ok(r, CVodeSetNoInactiveRootWarn(r->mem), "CVodeSetNoInactiveRootWarn", t0) &&
           cvode_ok(r, CVodeRootInit(r->mem, RW_NZ * r->sc.S.n_storeys, roots), "CVodeRootInit", t0) &&
           cvode_ok(r, CVodeQuadInit(r->mem, powers, r->q), "CVodeQuadInit", t0);
}

static double energy(run *r, double t) { return rw_scene_energy(&r->sc, ground(r, t), N_VGetArrayPointer(r->y)); }

static void track(double *peak, double v)
{
    if (fabs(v) > *peak) *peak = fabs(v);
}

/* the peaks inside the step from the last step's end to `end` (before any event there) */
static void peaks_inside(run *r, const rw_step_end *end)
{
    double *peaks[RW_PEAK_KINDS] = {r->res->peak_s1, r->res->peak_s2, r->res->peak_diaphragm};
    rw_step_peaks_inside(&r->sc, &r->last_end, end, peaks);
}

/* the same before the events at t change the state */
static void peaks_inside_before_events(run *r, double t)
{
    const double *x = N_VGetArrayPointer(r->y);
    double dx[RW_SCENE_NX];
    rw_step_end end;
    rw_scene_derivatives(&r->sc, ground(r, t), x, dx, NULL);
    rw_step_end_at(&r->sc, t, x, dx, &end);
    peaks_inside(r, &end);
}

/* peaks, the output row due at t, and the energy balance, at a step's end; with peaks inside the
 * step unless events at t took them already */
static void observe(run *r, double t, int peaks_taken)
{
    rw_scene_result *res = r->res;
    const double *x = N_VGetArrayPointer(r->y);
    const double *W = N_VGetArrayPointer(r->q);
    const double ag = ground(r, t);
    double dx[RW_SCENE_NX], residual;
    rw_step_end end;
    rw_scene_aux aux;
    int i;
    rw_scene_derivatives(&r->sc, ag, x, dx, &aux);
    rw_step_end_at(&r->sc, t, x, dx, &end);
    if (!peaks_taken) peaks_inside(r, &end);
    r->last_end = end;
    for (i = 0; i < r->sc.S.n_storeys; i++) {
        const double s1 = end.value[RW_PEAK_S1][i], s2 = end.value[RW_PEAK_S2][i], dd = end.value[RW_PEAK_DIAPHRAGM][i];
        track(&res->peak_s1[i], s1);
        track(&res->peak_s2[i], s2);
        track(&res->peak_diaphragm[i], dd);
        track(&res->peak_base_acc[i], aux.a_base[i]);
        if (r->next_out < r->opt->n_out && t >= r->opt->t_out[r->next_out]) {
            const size_t row = r->next_out * RW_SCENE_MAX_STOREYS + (size_t)i;
            if (res->s1_out) res->s1_out[row] = s1;
            if (res->s2_out) res->s2_out[row] = s2;
            if (res->diaphragm_out) res->diaphragm_out[row] = dd;
            if (res->base_acc_out) res->base_acc_out[row] = aux.a_base[i];
            if (res->tie_out) res->tie_out[row] = aux.F_top[i];
        }
    }
    if (r->next_out < r->opt->n_out && t >= r->opt->t_out[r->next_out]) r->next_out++;
    residual = energy(r, t) - res->energy_start - W[0] + W[1] + r->losses;
    track(&res->max_residual, residual);
    track(&res->max_work, W[0]);
}

/* the walls' event rules at t until nothing changes, then CVODE from the new states */
static int handle_events(run *r, double t)
{
    const double ag = ground(r, t);
    double *x = N_VGetArrayPointer(r->y);
    int rounds = 0, flags;
    do {
        const double before = energy(r, t);
        flags = rw_scene_event_update(&r->sc, t, ag, x, NULL);
        r->losses += before - energy(r, t);
        r->res->events++;
        if (++rounds > MAX_ROUNDS_PER_EVENT) {
            snprintf(r->res->message, sizeof r->res->message,
                     "the walls' event iteration at t = %.9g s did not settle in %d rounds", t, MAX_ROUNDS_PER_EVENT);
            return RW_SCENE_ZENO;
        }
    } while (flags & 3);
    r->fails_seen = 0;
    if (!cvode_ok(r, CVodeReInit(r->mem, t, r->y), "CVodeReInit", t) ||
        !cvode_ok(r, CVodeQuadReInit(r->mem, r->q), "CVodeQuadReInit", t))
        return RW_SCENE_SOLVER;
    return RW_SCENE_OK;
}

/* where CVODE must stop next: the next record sample, output time or the end */
static double next_stop(const run *r, double t)
{
    const rw_scene_record *rec = r->rec;
    double stop = r->opt->t_end;
    size_t k = r->hint;
    while (k < rec->n && rec->t[k] <= t) k++;
    if (k < rec->n && rec->t[k] < stop) stop = rec->t[k];
    if (r->next_out < r->opt->n_out && r->opt->t_out[r->next_out] < stop) stop = r->opt->t_out[r->next_out];
    return stop;
}

/* The run goes on with Newton iteration from (t, y, q) */
static int switch_to_newton(run *r, double t)
{
    if (!allocate_solver(r, ADAMS_NEWTON)) {
        snprintf(r->res->message, sizeof r->res->message, "out of memory setting up Newton at t = %.9g s", t);
        return RW_SCENE_NO_MEMORY;
    }
    r->res->t_newton = t;
    return setup_cvode(r, t) ? RW_SCENE_OK : RW_SCENE_SOLVER;
}

/* fixed-point iteration failed to converge on too many of the last window's steps (CVODE counts
 * its failures from its last restart, so the window keeps its own count) */
static int proves_stiff(run *r)
{
    long fails = 0;
    int stiff;
    if (r->method != ADAMS_FIXED_POINT) return 0;
    CVodeGetNumNonlinSolvConvFails(r->mem, &fails);
    r->window_fails += fails - r->fails_seen;
    r->fails_seen = fails;
    if (++r->window_steps < STIFF_WINDOW) return 0;
    stiff = r->window_fails > STIFF_SHARE * (double)r->window_steps;
    r->window_steps = r->window_fails = 0;
    return stiff;
}

static int integrate(run *r, double t)
{
    const double t_end = r->opt->t_end;
    while (t < t_end) {
        const double stop = next_stop(r, t);
        int flag, code = RW_SCENE_OK;
        if (!cvode_ok(r, CVodeSetStopTime(r->mem, stop), "CVodeSetStopTime", t)) return RW_SCENE_SOLVER;
        flag = CVode(r->mem, stop, r->y, &t, CV_ONE_STEP);
        if (flag < 0 && r->method == ADAMS_FIXED_POINT) { /* y is left at the last step taken */
            code = cvode_ok(r, CVodeGetQuad(r->mem, &t, r->q), "CVodeGetQuad", t) ? switch_to_newton(r, t)
                                                                                  : RW_SCENE_SOLVER;
            if (code) return code;
            continue;
        }
        if (!cvode_ok(r, flag, "CVode", t)) return RW_SCENE_SOLVER;
        if (!cvode_ok(r, CVodeGetQuad(r->mem, &t, r->q), "CVodeGetQuad", t)) return RW_SCENE_SOLVER;
        r->res->steps++;
        if (flag == CV_ROOT_RETURN) {
            peaks_inside_before_events(r, t);
            code = handle_events(r, t);
        } else if (proves_stiff(r)) {
            code = switch_to_newton(r, t);
        }
        if (code) return code;
        observe(r, t, flag == CV_ROOT_RETURN);
        r->res->t_reached = t;
    }
    return RW_SCENE_OK;
}

void rw_scene_result_start(rw_scene_result *res)
{
    double *out[5];
    out[0] = res->s1_out, out[1] = res->s2_out, out[2] = res->diaphragm_out, out[3] = res->base_acc_out;
    out[4] = res->tie_out;
    memset(res, 0, sizeof *res);
    res->s1_out = out[0], res->s2_out = out[1], res->diaphragm_out = out[2], res->base_acc_out = out[3];
    res->tie_out = out[4];
}

int rw_scene_check_arguments(const rw_scene_record *rec, const rw_scene_options *opt, char *msg, size_t n)
{
    size_t k;
    if (rec->n < 2 || !rec->t || !rec->ag) return snprintf(msg, n, "the record needs 2 or more samples"), 1;
    for (k = 0; k < rec->n; k++) {
        if (!isfinite(rec->t[k]) || !isfinite(rec->ag[k]) || (k > 0 && !(rec->t[k] > rec->t[k - 1])))
            return snprintf(msg, n, "record sample %zu: times must increase and values be finite", k), 1;
    }
    if (opt->x0)
        for (k = 0; k < RW_SCENE_NX; k++)
            if (!isfinite(opt->x0[k])) return snprintf(msg, n, "start state %zu is not finite", k), 1;
    if (!(opt->t_end > rec->t[0]) || !isfinite(opt->t_end))
        return snprintf(msg, n, "t_end = %g must be finite and after the record's start %g", opt->t_end, rec->t[0]), 1;
    for (k = 0; k < opt->n_out; k++) {
        const double tk = opt->t_out[k];
        if (!(tk >= rec->t[0] && tk <= opt->t_end) || (k > 0 && !(tk > opt->t_out[k - 1])))
            return snprintf(msg, n, "output time %zu (%g) outside [t0, t_end] or not increasing", k, tk), 1;
    }
    return 0;
}

static void collect(const run *r, rw_scene_result *res)
{
    int i;
    for (i = 0; i < r->sc.S.n_storeys; i++) {
        res->collapsed[i] = r->sc.collapsed[i];
        res->collapse_reason[i] = r->sc.reason[i];
        res->t_collapse[i] = r->sc.t_collapse[i];
        res->impacts[i] = r->sc.impacts[i];
    }
    res->work_ground = N_VGetArrayPointer(r->q)[0];
    res->work_damping = N_VGetArrayPointer(r->q)[1];
    res->event_losses = r->losses;
}

int rw_scene_run(const rw_scene_spec *spec, const rw_scene_record *rec, const rw_scene_options *opt,
                 rw_scene_result *res)
{
    double x[RW_SCENE_NX];
    run *r;
    int code;
    if (!spec || !rec || !opt || !res) return RW_SCENE_BAD_ARGUMENT;
    rw_scene_result_start(res);
    res->t_newton = NAN;
    if (rw_scene_check_arguments(rec, opt, res->message, sizeof res->message)) return RW_SCENE_BAD_ARGUMENT;
    if (rw_scene_validate(spec, res->message, sizeof res->message)) return RW_SCENE_BAD_SPEC;
    r = (run *)calloc(1, sizeof *r);
    if (!r) return snprintf(res->message, sizeof res->message, "out of memory"), RW_SCENE_NO_MEMORY;
    r->rec = rec;
    r->opt = opt;
    r->res = res;
    rw_scene_start_state(spec, opt->x0, x);
    rw_scene_init(&r->sc, spec, rec->ag[0], x);
    if (!allocate_vectors(r) || !allocate_solver(r, opt->bdf ? BDF_NEWTON : ADAMS_FIXED_POINT)) {
        free_run(r);
        free(r);
        return snprintf(res->message, sizeof res->message, "out of memory setting up CVODE"), RW_SCENE_NO_MEMORY;
    }
    memcpy(N_VGetArrayPointer(r->y), x, sizeof(double) * (size_t)r->sc.nx);
    N_VConst(0.0, r->q);
    if (opt->bdf) res->t_newton = rec->t[0];
    res->energy_start = energy(r, rec->t[0]);
    code = setup_cvode(r, rec->t[0]) ? handle_events(r, rec->t[0]) : RW_SCENE_SOLVER;
    if (code == RW_SCENE_OK) {
        observe(r, rec->t[0], 1);
        code = integrate(r, rec->t[0]);
    }
    collect(r, res);
    res->energy_end = energy(r, res->t_reached);
    free_run(r);
    free(r);
    return code;
}

/* the sizes of the structs a binding mirrors (rockingwall's ctypes twins check theirs against them) */
const size_t RW_SCENE_STRUCT_SIZES[3] = {sizeof(rw_scene_spec), sizeof(rw_scene_result), sizeof(bd_params)};
