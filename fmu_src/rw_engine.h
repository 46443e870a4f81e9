/* RockingWall exact event-driven engine (issue 12): advances the model from event to event on the
 * closed-form solution of each linear region, over a piecewise-linear input record. No FMI types.
 *
 * Between two events every piecewise-linear hinge law gives M q'' + (K - J) q = p(ag) + f_u(u_top)
 * + (Q - J q) with constant coefficients (rw_hinge_laws.c), the 1DOF and the closed rigid states
 * are linear too, and the input is linear between samples. So each region decouples into two
 * scalar modes eta'' + lam eta = f0 + f1 s whose solution is exact for any lam (Stumpff
 * functions: cos/cosh/polynomial). Events are located on that exact solution with the model's own
 * event indicators and applied with the model's own event update (rw_event_update): one copy of
 * the event rules. The parapet (Housner's nonlinear block) is not covered: it stays on CVODE.
 */
#ifndef RW_ENGINE_H
#define RW_ENGINE_H

#include <stddef.h>

#include "rw_physics.h"

/* error codes of rw_engine_run (0 = ok) */
enum {
    RW_ENGINE_OK = 0,
    RW_ENGINE_BAD_ARGUMENT = 1,   /* NULL pointer, bad record or grid, bad option */
    RW_ENGINE_BAD_PARAMETERS = 2, /* rw_params_validate refused them */
    RW_ENGINE_UNSUPPORTED = 3,    /* the parapet, or a region the engine cannot decompose */
    RW_ENGINE_ZENO = 4,           /* too many events at one instant (result holds the run so far) */
    RW_ENGINE_NO_MEMORY = 5
};

/* A piecewise-linear input record: n >= 1 samples at strictly increasing times t, linear between
 * samples, end values held outside [t[0], t[n-1]] (as fmi2sim and the reference solver read an
 * input table). u_top may be NULL (zero). */
typedef struct {
    size_t n;
    const double *t;
    const double *ag;    /* ground acceleration [m/s2], + toward +x */
    const double *u_top; /* diaphragm displacement [m], NULL = 0 */
} rw_record;

typedef struct {
    double t_start, t_end;       /* run interval (t_end > t_start) */
    const double *x0;            /* start states (q1, q2, dq1, dq2); NULL = at rest */
    size_t n_out;                /* optional output grid: n_out increasing times in [t_start, t_end] */
    const double *t_out;
    int max_events_per_instant;  /* Zeno guard; <= 0 means 100 */
} rw_engine_options;

typedef struct {
    double peak_s1, peak_s2; /* max |s1|, |s2| over the run (exact, interior maxima located) */
    int collapsed;           /* a collapse reason was reached (rw_collapse_reason) */
    int collapse_reason;     /* RW_STANDING, RW_PAST_INSTABILITY, RW_PAST_TOPPLING_LIMIT */
    double t_collapse;       /* time of the collapse event (NaN if none) */
    long impacts;            /* base impacts applied */
    long events;             /* located events (every indicator root) */
    long steps;              /* closed-form propagation steps */
    double t_reached;        /* t_end, or the collapse time, or where a Zeno stop happened */
    double x_end[RW_NX];     /* states at t_reached */
    /* optional time history on the grid, caller-allocated (n_out each) or NULL */
    double *x_out;           /* n_out rows of RW_NX states (right limits at events) */
    double *s1_out, *s2_out;
    /* optional impact log, caller-allocated (impact_cap entries each) or NULL: the time of each
     * impact and the energy (rw_energy) just before it */
    double *impact_t, *impact_energy;
    size_t impact_cap;
    char message[256];       /* why a run failed or stopped early */
} rw_engine_result;

/* Runs the model from opt->t_start to opt->t_end (or collapse). Returns an error code (0 = ok)
 * and fills res->message when not 0. */
int rw_engine_run(const rw_params *p, const rw_record *rec, const rw_engine_options *opt, rw_engine_result *res);

/* ---- a stepper for callers that own the time loop (Co-Simulation) ---------------------------- */
typedef struct rw_engine rw_engine;

/* After the modes are initialised by the caller (rw_init_modes): the engine over p from x, m at t. */
rw_engine *rw_engine_new(const rw_params *p, char *msg, size_t n);
void rw_engine_free(rw_engine *e);
/* Advance x, m from t to t + h with the inputs linear over the step (value at t and slope).
 * Event updates are the model's; impacts are added to *impacts. Returns 0, 1 if the wall
 * collapsed at *t_reached (<= t + h), or an error code + 1 (msg filled). */
typedef struct {
    double ag, ag_slope, u_top, u_slope;
} rw_linear_input;
int rw_engine_step(rw_engine *e, rw_mode *m, double x[RW_NX], double t, double h, const rw_linear_input *in,
                   long *impacts, double *t_reached, char *msg, size_t n);

#endif
