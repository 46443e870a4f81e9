/* RockingWall exact event-driven engine: advances the model from event to event on the
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

/* an input linear over a step or segment: value at its start and slope */
typedef struct {
    double ag, ag_slope, u_top, u_slope;
} rw_linear_input;

/* error codes of rw_engine_run (0 = ok) */
/* The parapet (support 1) runs in Housner's small-rotation form, whose peaks stay within 1 % of the
 * nonlinear block's up to this b/h (docs/engine.md "The parapet"); stockier parapets are refused
 * (RW_ENGINE_UNSUPPORTED) and stay on CVODE. */
#define RW_ENGINE_PARAPET_MAX_B_OVER_H 0.1

enum {
    RW_ENGINE_OK = 0,
    RW_ENGINE_BAD_ARGUMENT = 1,   /* NULL pointer, bad record or grid, bad option */
    RW_ENGINE_BAD_PARAMETERS = 2, /* rw_params_validate refused them */
    RW_ENGINE_UNSUPPORTED = 3,    /* a parapet stockier than the small-rotation limit, or a region the engine cannot decompose */
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

/* ---- sweeps: many runs over one record in one call -------------------------------------------
 * Run i uses the parameters params[params_each ? i : 0] and the record's ag times scale[i] (scale
 * NULL: 1; u_top as given), over opt (which must not ask for an output grid). Each output array
 * holds n values and may be NULL. No Python (or other caller) work between runs, and no shared
 * state: separate calls can run on separate threads. */
typedef struct {
    double *peak_s1, *peak_s2; /* max |s1|, |s2| */
    int *collapsed;            /* 1 if the wall collapsed */
    double *t_collapse;        /* its time (NaN if standing) */
    long *impacts;             /* base impacts */
    int *code;                 /* the run's rw_engine_run code (0 ok, RW_ENGINE_ZENO: peaks so far) */
} rw_engine_batch;

/* Returns 0 when every run was made (each run's own code in out->code), or an error code for the
 * call itself (NULL pointers, an output grid, a non-finite scale, no memory) with msg filled. */
int rw_engine_run_many(size_t n, const rw_params *params, int params_each, const double *scale, const rw_record *rec,
                       const rw_engine_options *opt, const rw_engine_batch *out, char *msg, size_t msg_len);

/* ---- a stepper for callers that own the time loop (Co-Simulation) ---------------------------- */
/* The engine is opaque: its state is rw_engine_internal.h's, not part of this API. It holds no
 * pointer but to static data, so a byte copy of an engine (an FMU state) is the same engine. */
typedef struct rw_engine rw_engine;

/* A heap engine over p (NULL with msg filled if p is refused or the parapet). */
rw_engine *rw_engine_new(const rw_params *p, char *msg, size_t n);
void rw_engine_free(rw_engine *e);
/* Or in place, in rw_engine_size() bytes of memory aligned for a double (inside the FMU's
 * instance data, models/RockingWall/rw_model_data.h): 0, or 1 with msg filled. Nothing to free. */
size_t rw_engine_size(void);
int rw_engine_init(rw_engine *e, const rw_params *p, char *msg, size_t n);
/* The steps then report the energy the event maps take out (two energy evaluations per event). */
void rw_engine_track_dissipated(rw_engine *e);

/* what a step did */
typedef struct {
    long impacts;        /* base impacts applied */
    double t_reached;    /* t + h, or where the wall collapsed */
    int collapse_reason; /* RW_STANDING, or why it collapsed (rw_collapse_reason) */
    double dissipated;   /* energy the event maps took out (0 unless rw_engine_track_dissipated) */
    char message[256];   /* why it failed */
} rw_engine_step_report;

/* Advance x, m (initialised by the caller: rw_init_regime and the initial event iteration) from t
 * to t + h with the inputs linear over the step (value at t and slope). If the inputs jumped at t
 * since the previous step so that an indicator changed sign, the model's event iteration runs at
 * t first (an input can open a hinge at rest). Returns 0, 1 if the wall collapsed at
 * out->t_reached (<= t + h), or an error code + 1 (out->message filled). */
int rw_engine_step(rw_engine *e, rw_regime *m, double x[RW_NX], double t, double h, const rw_linear_input *in,
                   rw_engine_step_report *out);

/* ---- one linear region on its own (for tests of the closed form) ------------------------------
 * The 2DOF with open hinges on the region whose hinge moments are Q = c + J q: the exact motion of
 * M q'' + (K - J) q = pa ag + fu u_top (1, 1) + c from x0 over s (the input linear from its value at
 * s = 0), through the engine's own decomposition (the symmetric path when J is symmetric, the
 * general 2x2 path otherwise) and closed form. 0, or RW_ENGINE_UNSUPPORTED (complex or repeated
 * modes, or an engine that is not the 2DOF). */
int rw_engine_region_motion(rw_engine *e, const double J[2][2], const double c[2], const rw_linear_input *in,
                            const double x0[RW_NX], double s, double x[RW_NX]);

#endif
