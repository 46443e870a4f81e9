/* Model-Exchange simulation with CVODE (SUNDIALS 6): the FMI 2.0 call sequence, root-finding on
 * the event indicators, the event iteration, time and step events, and CSV output.
 *
 * Inputs are linear between their samples, so every sample time is a kink: CVODE is stopped there
 * (CVodeSetStopTime) instead of stepping across it. Besides accuracy this matters for models at
 * rest, whose right-hand side is zero: CVODE's step would otherwise grow past an input that
 * rises above a threshold and falls back within one step, and the root would be missed.
 *
 * CVODE runs in CV_ONE_STEP mode so that fmi2CompletedIntegratorStep follows every accepted step
 * and output rows on the regular grid are interpolated (CVodeGetDky) inside steps. After an event
 * CVODE is re-initialised when the FMU says states or nominals changed, and after every state
 * event: there CVODE has already stepped past the root with the pre-event right-hand side, so its
 * history is stale even when no state jumped.
 *
 * --solver erk runs ARKODE's ERKStep (explicit Runge-Kutta, its default 4th/3rd-order pair) in
 * the same loop: one step at a time, the same stop times, roots, dense output and re-initialisation
 * (the integrator layer below is the only place that knows which one runs). */
#include "simulate_me.h"
#include "fmu_inputs.h"

#include <arkode/arkode_erkstep.h>
#include <cvode/cvode.h>
#include <math.h>
#include <nvector/nvector_serial.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <time.h>

typedef struct {
    const model_description *md;
    const fmu_binary *fmu;
    const sim_options *opt;
    fmi2Component c;
    size_t nx, nz;
    fmu_inputs ins;          /* the input columns and the FMU variables they drive */
    const md_variable **out; /* outputs, XML order */
    size_t n_out;
    char *err;
    size_t errn;
    int failed;
    char cvode_msg[512];
} sim;

static int fail(sim *s, const char *fmt, ...)
{
    va_list ap;
    if (s->failed) return -1; /* keep the first, root-cause message */
    va_start(ap, fmt);
    vsnprintf(s->err, s->errn, fmt, ap);
    va_end(ap);
    s->failed = 1;
    return -1;
}

#define FMI(s, call, name) \
    do { if ((call) > fmi2Warning) return fail((s), "%s failed (see the FMU's log above)", (name)); } while (0)

/* the same, inside run() once solver memory exists: clean up on the way out */
#define FMI_DONE(s, call, name) \
    do { if ((call) > fmi2Warning) { fail((s), "%s failed (see the FMU's log above)", (name)); goto done; } } while (0)

static const char *status_name(fmi2Status st)
{
    static const char *n[] = {"OK", "Warning", "Discard", "Error", "Fatal", "Pending"};
    return st <= fmi2Pending ? n[st] : "?";
}

static void fmu_logger(fmi2ComponentEnvironment env, fmi2String instance, fmi2Status status,
                       fmi2String category, fmi2String message, ...)
{
    const int verbose = env ? *(const int *)env : 0;
    va_list ap;
    if (status < fmi2Warning && !verbose) return;
    fprintf(stderr, "fmi2sim: [%s] %s %s: ", status_name(status), instance ? instance : "",
            category ? category : "");
    va_start(ap, message);
    vfprintf(stderr, message, ap);
    va_end(ap);
    fputc('\n', stderr);
}

static void cvode_error_handler(int code, const char *module, const char *function, char *msg, void *user)
{
    sim *s = user;
    (void)code; (void)module;
    snprintf(s->cvode_msg, sizeof s->cvode_msg, "%s: %s", function, msg);
}

/* CVodeGetReturnFlagName returns a string allocated with malloc (SUNDIALS 6): free it. */
static void cvode_failed(sim *s, int flag, double t)
{
    char *name = CVodeGetReturnFlagName(flag);
    char inputs[768];
    fail(s, "CVODE failed at t = %.10g: %s (%s)%s", t, name ? name : "?", s->cvode_msg,
         fmu_inputs_describe(&s->ins, t, inputs, sizeof inputs));
    free(name);
}

/* The continuous inputs at time t into the FMU (Continuous-Time Mode: discrete inputs wait for
 * an event). */
static int apply_inputs(sim *s, double t)
{
    const char *call = "fmi2SetReal (input)";
    FMI(s, fmu_inputs_set_continuous(&s->ins, s->fmu, s->c, t, &call), call);
    return 0;
}

/* Every input at time t, the value from t on (Initialization and Event Mode). */
static int apply_all_inputs(sim *s, double t)
{
    const char *call = "fmi2SetReal (input)";
    FMI(s, fmu_inputs_set_all(&s->ins, s->fmu, s->c, t, &call), call);
    return 0;
}

static int set_point(sim *s, double t, const double *x)
{
    FMI(s, s->fmu->setTime(s->c, t), "fmi2SetTime");
    if (apply_inputs(s, t) != 0) return -1;
    if (s->nx) FMI(s, s->fmu->setContinuousStates(s->c, x, s->nx), "fmi2SetContinuousStates");
    return 0;
}

static int rhs(sunrealtype t, N_Vector y, N_Vector ydot, void *user)
{
    sim *s = user;
    if (set_point(s, t, N_VGetArrayPointer(y)) != 0) return -1;
    if (s->fmu->getDerivatives(s->c, N_VGetArrayPointer(ydot), s->nx) > fmi2Warning)
        return fail(s, "fmi2GetDerivatives failed at t = %.17g (see the FMU's log above)", t);
    return 0;
}

static int roots(sunrealtype t, N_Vector y, sunrealtype *gout, void *user)
{
    sim *s = user;
    if (set_point(s, t, N_VGetArrayPointer(y)) != 0) return -1;
    if (s->fmu->getEventIndicators(s->c, gout, s->nz) > fmi2Warning)
        return fail(s, "fmi2GetEventIndicators failed at t = %.17g (see the FMU's log above)", t);
    return 0;
}

/* --summary: fold the outputs as the FMU stands into max |value| and last value. */
static int track_outputs(sim *s)
{
    sim_summary *sum = s->opt->summary;
    for (size_t i = 0; sum && i < sum->n; i++) {
        const md_variable *v = sum->vars[i];
        fmi2Real r;
        fmi2Integer k;
        fmi2Boolean b;
        double x;
        if (v->type == MD_REAL) {
            FMI(s, s->fmu->getReal(s->c, &v->vr, 1, &r), "fmi2GetReal");
            x = r;
        } else if (v->type == MD_INTEGER || v->type == MD_ENUMERATION) {
            FMI(s, s->fmu->getInteger(s->c, &v->vr, 1, &k), "fmi2GetInteger");
            x = k;
        } else if (v->type == MD_BOOLEAN) {
            FMI(s, s->fmu->getBoolean(s->c, &v->vr, 1, &b), "fmi2GetBoolean");
            x = b ? 1.0 : 0.0;
        } else {
            continue; /* a String has no magnitude */
        }
        if (fabs(x) > sum->max_abs[i]) sum->max_abs[i] = fabs(x);
        sum->final[i] = x;
    }
    return 0;
}

/* A write to the CSV; a failed one (full disk, closed pipe) ends the run with the file's name. */
#define PUT(s, ...) \
    do { if (output_printf((s)->opt->output, __VA_ARGS__) != 0) return write_failed(s); } while (0)

static int write_failed(sim *s)
{
    return fail(s, "%s: write failed: %s", s->opt->output->name, strerror(s->opt->output->write_errno));
}

/* One output value of the FMU as it stands, as CSV text. */
static int put_value(sim *s, const md_variable *v)
{
    fmi2Real r;
    fmi2Integer k;
    fmi2Boolean b;
    fmi2String str;
    switch (v->type) {
    case MD_REAL:
        FMI(s, s->fmu->getReal(s->c, &v->vr, 1, &r), "fmi2GetReal");
        PUT(s, ",%.12g", r);
        break;
    case MD_INTEGER:
    case MD_ENUMERATION:
        FMI(s, s->fmu->getInteger(s->c, &v->vr, 1, &k), "fmi2GetInteger");
        PUT(s, ",%d", k);
        break;
    case MD_BOOLEAN:
        FMI(s, s->fmu->getBoolean(s->c, &v->vr, 1, &b), "fmi2GetBoolean");
        PUT(s, ",%d", b ? 1 : 0);
        break;
    case MD_STRING:
        FMI(s, s->fmu->getString(s->c, &v->vr, 1, &str), "fmi2GetString");
        PUT(s, ",\"%s\"", str ? str : "");
        break;
    }
    return 0;
}

/* One CSV row: time and every output, read from the FMU as it stands; with --summary also folded
 * into the peaks. Without a CSV file only the summary is kept. */
static int write_row(sim *s, double t)
{
    if (track_outputs(s) != 0) return -1;
    if (!s->opt->output) return 0;
    PUT(s, "%.15g", t);
    for (size_t i = 0; i < s->n_out; i++)
        if (put_value(s, s->out[i]) != 0) return -1;
    PUT(s, "\n");
    return 0;
}

/* Start values given with --set, converted to the variable's type (already checked in main). */
static int apply_start_values(sim *s)
{
    for (size_t i = 0; i < s->opt->n_start_values; i++) {
        const start_value *sv = &s->opt->start_values[i];
        const md_variable *v = md_find(s->md, sv->name);
        if (!v) return fail(s, "--set %s: no such variable", sv->name);
        if (v->type == MD_REAL) {
            double r = strtod(sv->value, NULL);
            FMI(s, s->fmu->setReal(s->c, &v->vr, 1, &r), "fmi2SetReal (--set)");
        } else if (v->type == MD_INTEGER || v->type == MD_ENUMERATION) {
            int k = (int)strtol(sv->value, NULL, 10);
            FMI(s, s->fmu->setInteger(s->c, &v->vr, 1, &k), "fmi2SetInteger (--set)");
        } else if (v->type == MD_BOOLEAN) {
            fmi2Boolean b = (strcmp(sv->value, "true") == 0 || strcmp(sv->value, "1") == 0);
            FMI(s, s->fmu->setBoolean(s->c, &v->vr, 1, &b), "fmi2SetBoolean (--set)");
        } else {
            fmi2String str = sv->value;
            FMI(s, s->fmu->setString(s->c, &v->vr, 1, &str), "fmi2SetString (--set)");
        }
    }
    return 0;
}

/* The FMI 2.0 event iteration; the FMU is in event mode. */
static int event_iteration(sim *s, fmi2EventInfo *info, int *values_changed, int *nominals_changed)
{
    int rounds = 0;
    *values_changed = *nominals_changed = 0;
    do {
        memset(info, 0, sizeof *info);
        FMI(s, s->fmu->newDiscreteStates(s->c, info), "fmi2NewDiscreteStates");
        *values_changed |= info->valuesOfContinuousStatesChanged == fmi2True;
        *nominals_changed |= info->nominalsOfContinuousStatesChanged == fmi2True;
        if (info->terminateSimulation) break;
        if (++rounds > 10000) return fail(s, "the event iteration did not converge (10000 rounds)");
    } while (info->newDiscreteStatesNeeded);
    return 0;
}

/* --atol must lie in [ATOL_MIN, ATOL_MAX] x the nominal of every state: far below, CVODE
 * chases round-off near zero; above, an error of 1 % of a state's scale passes unnoticed (at
 * --atol 1e300 a wall that collapses stands). */
#define ATOL_MIN 1e-16
#define ATOL_MAX 1e-2

/* ---- the integrator: CVODE (BDF or Adams) or ARKODE ERKStep, behind one small interface ---- */
typedef struct {
    int erk;
    void *mem;
    SUNMatrix A;
    SUNLinearSolver LS;
} integrator;

static int set_tolerances(sim *s, const integrator *I, N_Vector abstol)
{
    double *a = N_VGetArrayPointer(abstol);
    FMI(s, s->fmu->getNominalsOfContinuousStates(s->c, a, s->nx), "fmi2GetNominalsOfContinuousStates");
    for (size_t i = 0; i < s->nx; i++) {
        const double nominal = a[i] > 0 && isfinite(a[i]) ? a[i] : 1.0;
        const double atol = s->opt->atol > 0 ? s->opt->atol : s->opt->rtol * nominal;
        if (!(atol >= ATOL_MIN * nominal && atol <= ATOL_MAX * nominal))
            return fail(s, "--atol %g is out of range for state %zu (nominal %g): it must lie in [%g, %g] x the "
                        "state's nominal, here [%g, %g]", atol, i + 1, nominal, ATOL_MIN, ATOL_MAX,
                        ATOL_MIN * nominal, ATOL_MAX * nominal);
        a[i] = atol;
    }
    if (I->erk) ERKStepSVtolerances(I->mem, s->opt->rtol, abstol);
    else CVodeSVtolerances(I->mem, s->opt->rtol, abstol);
    return 0;
}

/* The counts of the model description must be the binary's: numberOfEventIndicators="0" for a
 * model that has indicators would switch root-finding off, and a missing state would freeze.
 * A binary that checks its sizes, as FMI 2.0 asks, refuses a wrong count here. */
static int check_counts(sim *s)
{
    double *buf = calloc((s->nx > s->nz ? s->nx : s->nz) + 1, sizeof *buf);
    fmi2Status states, indicators;
    if (!buf) return fail(s, "out of memory");
    states = s->fmu->getContinuousStates(s->c, buf, s->nx);
    indicators = s->fmu->getEventIndicators(s->c, buf, s->nz);
    free(buf);
    if (states > fmi2Warning)
        return fail(s, "the binary refuses %zu continuous states, the number of Derivatives in the model "
                    "description: they do not match (see the FMU's log above)", s->nx);
    if (indicators > fmi2Warning)
        return fail(s, "the binary refuses %zu event indicators, the model description's "
                    "numberOfEventIndicators: they do not match (see the FMU's log above)", s->nz);
    return 0;
}

static int integrator_create(sim *s, integrator *I, double t0, N_Vector y, N_Vector abstol, SUNContext ctx)
{
    const sim_options *o = s->opt;
    I->erk = o->erk;
    if (I->erk) {
        I->mem = ERKStepCreate(rhs, t0, y, ctx);
        if (!I->mem) return fail(s, "ERKStepCreate failed");
        ERKStepSetErrHandlerFn(I->mem, cvode_error_handler, s);
        ERKStepSetUserData(I->mem, s);
        if (set_tolerances(s, I, abstol) != 0) return -1;
        if (o->max_step > 0) ERKStepSetMaxStep(I->mem, o->max_step);
        if (s->nz) ERKStepRootInit(I->mem, (int)s->nz, roots);
        ERKStepSetNoInactiveRootWarn(I->mem);
        return 0;
    }
    I->mem = CVodeCreate(o->adams ? CV_ADAMS : CV_BDF, ctx);
    if (!I->mem) return fail(s, "CVodeCreate failed");
    CVodeSetErrHandlerFn(I->mem, cvode_error_handler, s);
    if (CVodeInit(I->mem, rhs, t0, y) != CV_SUCCESS) return fail(s, "CVodeInit: %s", s->cvode_msg);
    CVodeSetUserData(I->mem, s);
    if (set_tolerances(s, I, abstol) != 0) return -1;
    I->A = SUNDenseMatrix((sunindextype)s->nx, (sunindextype)s->nx, ctx);
    I->LS = SUNLinSol_Dense(y, I->A, ctx);
    CVodeSetLinearSolver(I->mem, I->LS, I->A);
    if (o->max_step > 0) CVodeSetMaxStep(I->mem, o->max_step);
    if (s->nz) CVodeRootInit(I->mem, (int)s->nz, roots);
    CVodeSetNoInactiveRootWarn(I->mem);
    return 0;
}

/* One step toward t_stop (never past it). Returns <0 on failure (message set), 1 at a root, else 0. */
static int integrator_step(sim *s, const integrator *I, double t_stop, N_Vector y, double *tret)
{
    int flag;
    if (I->erk) {
        ERKStepSetStopTime(I->mem, t_stop);
        flag = ERKStepEvolve(I->mem, t_stop, y, tret, ARK_ONE_STEP);
        if (flag < 0) {
            char *name = ERKStepGetReturnFlagName(flag); /* malloc'ed, like CVODE's */
            char inputs[768];
            fail(s, "ARKODE ERKStep failed at t = %.10g: %s (%s)%s", *tret, name ? name : "?", s->cvode_msg,
                 fmu_inputs_describe(&s->ins, *tret, inputs, sizeof inputs));
            free(name);
            return -1;
        }
        return flag == ARK_ROOT_RETURN;
    }
    CVodeSetStopTime(I->mem, t_stop);
    flag = CVode(I->mem, t_stop, y, tret, CV_ONE_STEP);
    if (flag < 0) {
        cvode_failed(s, flag, *tret);
        return -1;
    }
    return flag == CV_ROOT_RETURN;
}

static void integrator_dky(const integrator *I, double t, N_Vector out)
{
    if (I->erk) ERKStepGetDky(I->mem, t, 0, out);
    else CVodeGetDky(I->mem, t, 0, out);
}

/* The counters restart at every re-initialisation: add them up before each one and at the end. */
static void add_counters(const integrator *I, sim_stats *st)
{
    long steps = 0, rhs_evals = 0, root_evals = 0;
    if (I->erk) {
        ERKStepGetNumSteps(I->mem, &steps);
        ERKStepGetNumRhsEvals(I->mem, &rhs_evals);
        ERKStepGetNumGEvals(I->mem, &root_evals);
    } else {
        CVodeGetNumSteps(I->mem, &steps);
        CVodeGetNumRhsEvals(I->mem, &rhs_evals);
        CVodeGetNumGEvals(I->mem, &root_evals);
    }
    st->steps += steps;
    st->rhs_evals += rhs_evals;
    st->root_evals += root_evals;
}

static void integrator_reinit(const integrator *I, double t, N_Vector y)
{
    if (I->erk) ERKStepReInit(I->mem, rhs, t, y);
    else CVodeReInit(I->mem, t, y);
}

static void integrator_free(integrator *I)
{
    if (I->mem) {
        if (I->erk) ERKStepFree(&I->mem);
        else CVodeFree(&I->mem);
    }
    if (I->LS) SUNLinSolFree(I->LS);
    if (I->A) SUNMatDestroy(I->A);
}

static int setup_io(sim *s)
{
    const model_description *md = s->md;
    s->out = calloc(md->n_vars + 1, sizeof *s->out);
    if (!s->out || fmu_inputs_setup(&s->ins, md, s->opt->inputs, s->opt->n_inputs) != 0) return fail(s, "out of memory");
    for (size_t i = 0; i < md->n_vars; i++)
        if (strcmp(md->vars[i].causality, "output") == 0) s->out[s->n_out++] = &md->vars[i];
    if (s->opt->summary) {
        sim_summary *sum = s->opt->summary;
        sum->n = s->n_out;
        sum->vars = calloc(s->n_out + 1, sizeof *sum->vars);
        sum->max_abs = calloc(s->n_out + 1, sizeof *sum->max_abs);
        sum->final = calloc(s->n_out + 1, sizeof *sum->final);
        if (!sum->vars || !sum->max_abs || !sum->final) return fail(s, "out of memory");
        for (size_t i = 0; i < s->n_out; i++) {
            sum->vars[i] = s->out[i];
            sum->final[i] = NAN;
            if (s->out[i]->type == MD_STRING) sum->max_abs[i] = NAN;
        }
    }
    if (!s->opt->output) return 0;
    PUT(s, "time");
    for (size_t i = 0; i < s->n_out; i++) PUT(s, ",%s", s->out[i]->name);
    PUT(s, "\n");
    return 0;
}

static int run(sim *s, sim_stats *st, SUNContext ctx)
{
    const sim_options *o = s->opt;
    const double t0 = o->start_time, tend = o->stop_time, dt = o->output_interval;
    const double eps = 1e-12 * fmax(1.0, fabs(tend));
    fmi2CallbackFunctions cb = {fmu_logger, calloc, free, NULL, (fmi2ComponentEnvironment)&o->logging};
    fmi2EventInfo info;
    int values_changed, nominals_changed;
    N_Vector y = NULL, abstol = NULL, ytmp = NULL;
    integrator I;
    double t = t0, next_event = INFINITY;
    long k_out = 1;
    int rc = -1;

    memset(&I, 0, sizeof I);
    s->c = s->fmu->instantiate(s->md->model_identifier, fmi2ModelExchange, s->md->guid, o->resource_uri,
                               &cb, fmi2False, o->logging ? fmi2True : fmi2False);
    if (!s->c) return fail(s, "fmi2Instantiate returned NULL: the binary refused the FMU "
                              "(wrong GUID %s? see its log above)", s->md->guid);
    if (setup_io(s) != 0 || apply_start_values(s) != 0) return -1;
    FMI(s, s->fmu->setupExperiment(s->c, fmi2False, 0.0, t0, fmi2True, tend), "fmi2SetupExperiment");
    FMI(s, s->fmu->enterInitializationMode(s->c), "fmi2EnterInitializationMode");
    if (apply_all_inputs(s, t0) != 0) return -1;
    FMI(s, s->fmu->exitInitializationMode(s->c), "fmi2ExitInitializationMode");
    if (event_iteration(s, &info, &values_changed, &nominals_changed) != 0) return -1;
    if (info.terminateSimulation) { st->terminated_by_model = 1; return write_row(s, t0); }
    if (info.nextEventTimeDefined) next_event = info.nextEventTime;
    FMI(s, s->fmu->enterContinuousTimeMode(s->c), "fmi2EnterContinuousTimeMode");
    if (check_counts(s) != 0) return -1;

    y = N_VNew_Serial((sunindextype)(s->nx ? s->nx : 1), ctx);
    ytmp = N_VClone(y);
    abstol = N_VClone(y);
    if (s->nx) {
        FMI_DONE(s, s->fmu->getContinuousStates(s->c, N_VGetArrayPointer(y), s->nx), "fmi2GetContinuousStates");
        if (integrator_create(s, &I, t0, y, abstol, ctx) != 0) goto done;
    }
    if (write_row(s, t0) != 0) goto done;

    while (t < tend - eps) {
        const double t_stop = fmin(fmin(tend, next_event), fmu_inputs_next_time(&s->ins, t + eps));
        double tret;
        int state_event = 0, time_event, step_event = 0, input_event;
        fmi2Boolean enter_event = fmi2False, terminate = fmi2False;
        if (s->nx) {
            const int flag = integrator_step(s, &I, t_stop, y, &tret);
            if (s->failed || flag < 0) goto done;
            state_event = flag == 1;
        } else {
            tret = fmin(t_stop, t0 + (double)k_out * dt);
        }
        /* regular output rows strictly inside this step, from CVODE's interpolant */
        for (double to = t0 + (double)k_out * dt; to < tret - eps && to <= tend + eps; to = t0 + (double)++k_out * dt) {
            if (s->nx) integrator_dky(&I, to, ytmp);
            if (set_point(s, to, N_VGetArrayPointer(ytmp)) != 0 || write_row(s, to) != 0) goto done;
        }
        if (set_point(s, tret, N_VGetArrayPointer(y)) != 0 || track_outputs(s) != 0) goto done;
        if (s->md->needs_completed_integrator_step) {
            FMI_DONE(s, s->fmu->completedIntegratorStep(s->c, fmi2True, &enter_event, &terminate), "fmi2CompletedIntegratorStep");
            if (terminate) { st->terminated_by_model = 1; if (write_row(s, tret) != 0) goto done; t = tret; break; }
            step_event = enter_event == fmi2True;
        }
        time_event = tret >= next_event - eps;
        /* CVODE stops at every sample: one where a discrete input changes or a continuous one steps
         * is an event, at which the new values are set */
        input_event = fabs(tret - t_stop) <= eps && fmu_inputs_event_at(&s->ins, t_stop);
        if (input_event) tret = t_stop;
        if (fabs(tret - (t0 + (double)k_out * dt)) <= eps) { /* a grid point: its row, before any event */
            if (write_row(s, tret) != 0) goto done;
            k_out++;
        } else if (state_event || time_event || step_event || input_event) {
            if (write_row(s, tret) != 0) goto done; /* the row before the event */
        }
        t = tret;
        if (!(state_event || time_event || step_event || input_event)) continue;

        st->events++;
        st->state_events += state_event;
        st->time_events += time_event || input_event;
        st->step_events += step_event;
        FMI_DONE(s, s->fmu->enterEventMode(s->c), "fmi2EnterEventMode");
        if (apply_all_inputs(s, t) != 0) goto done;
        if (event_iteration(s, &info, &values_changed, &nominals_changed) != 0) goto done;
        if (info.terminateSimulation) { st->terminated_by_model = 1; if (write_row(s, t) != 0) goto done; break; }
        next_event = info.nextEventTimeDefined ? info.nextEventTime : INFINITY;
        FMI_DONE(s, s->fmu->enterContinuousTimeMode(s->c), "fmi2EnterContinuousTimeMode");
        if (s->nx) FMI_DONE(s, s->fmu->getContinuousStates(s->c, N_VGetArrayPointer(y), s->nx), "fmi2GetContinuousStates");
        if (write_row(s, t) != 0) goto done; /* the row after the event */
        if (s->nx && (values_changed || nominals_changed || state_event || input_event)) {
            if (nominals_changed && set_tolerances(s, &I, abstol) != 0) goto done;
            add_counters(&I, st);
            integrator_reinit(&I, t, y);
            st->reinits++;
        }
    }
    st->end_time = t;
    rc = 0;
done:
    if (I.mem) add_counters(&I, st);
    integrator_free(&I);
    if (y) N_VDestroy(y);
    if (ytmp) N_VDestroy(ytmp);
    if (abstol) N_VDestroy(abstol);
    return rc;
}

int simulate_me(const model_description *md, const fmu_binary *fmu, const sim_options *opt,
                sim_stats *stats, char *err, size_t n)
{
    sim s;
    SUNContext ctx;
    clock_t c0 = clock();
    int rc;
    memset(&s, 0, sizeof s);
    memset(stats, 0, sizeof *stats);
    s.md = md; s.fmu = fmu; s.opt = opt; s.err = err; s.errn = n;
    s.nx = (size_t)md->n_states;
    s.nz = (size_t)md->n_event_indicators;
    if (SUNContext_Create(NULL, &ctx) != 0) { snprintf(err, n, "SUNContext_Create failed"); return -1; }
    rc = run(&s, stats, ctx);
    if (s.c) {
        if (rc == 0) fmu->terminate(s.c);
        fmu->freeInstance(s.c);
    }
    fmu_inputs_free(&s.ins);
    free(s.out);
    SUNContext_Free(&ctx);
    stats->cpu_seconds = (double)(clock() - c0) / CLOCKS_PER_SEC;
    return rc == 0 && !s.failed ? 0 : -1;
}
