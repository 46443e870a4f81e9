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

/* ---- the engine's state (public so that it can live inside the FMU's instance data) ------------ */
/* a point of a span: its offset s from the span's start, the state and the indicators with their rates */
typedef struct {
    double s;
    double x[RW_NX];
    double z[RW_NZ], dz[RW_NZ];
} rw_engine_point;

/* One linear region in modal coordinates: q = P eta, eta = Pi q, and per mode
 * eta_i'' + lam_i eta_i = g0_i + ga_i ag + gu_i u_top; decompositions are cached by region (the
 * closed flags and J, or the 1DOF slope), with the Stumpff coefficients of the last two step
 * lengths. */
#define RW_CACHE_SIZE 48
typedef struct {
    double P[2][2], Pi[2][2], lam[2];
    double ga[2], gu[2];
    double fm[2][2]; /* modal forcing of a generalised force vector (2DOF open hinges) */
} rw_modes2;

/* The hinge moments of a region as Q = c + J q, where the region fixes them so: a law of q alone
 * (rw_hinge_law.q_only), or the rigid law (constant for the region's sides) */
typedef struct {
    int valid;
    double c[2], J[2][2];
} rw_affine_Q;

typedef struct {
    int used, closed_b, closed_m;
    double key[4]; /* J (2DOF) or the 1DOF slope */
    rw_modes2 E;
    double w[2];   /* sqrt(|lam|) of each mode */
    double col[2]; /* max |P[.][i]|: mode i's largest share of a rotation */
    double inv_lam[2];
    double h[2], C[2][2][4]; /* Stumpff coefficients of the last two step lengths */
    int h_valid[2], h_next;
} rw_cache_entry;

/* the indicator lines of the current regime as arrays (rw_indicator_line's fields), for the
 * vectorized evaluation of all of them at once */
typedef struct {
    double a0[RW_NZ], a1[RW_NZ], s[RW_NZ], t[RW_NZ], c[RW_NZ];
} rw_line_arrays;

typedef struct rw_engine { /* by value in the FMU's data; use the functions, not the fields */
    rw_params P;
    rw_derived D;
    const rw_hinge_law *law;
    int rigid;
    rw_cache_entry cache[RW_CACHE_SIZE];
    int cache_next;
    int cache_last; /* the entry found last: consecutive input segments mostly stay in one region */
    /* the region of the current motion (a cache index), kept from one input segment to the next
     * until an event */
    int region_valid, region;
    double region_g0[2];
    rw_affine_Q region_aq;
    rw_indicator_line lines[RW_NZ]; /* the indicators that are lines under the current regime */
    unsigned line_mask;
    rw_line_arrays line_arrays;
    rw_collapse_form collapse_form; /* the collapse indicator of the region (if region_aq.valid) */
    unsigned closed_mask;           /* the indicators of closed rigid hinges (rw_closed_hinge_mask) */
    rw_closed_form closed_form;     /* their moments, affine in the rotations and inputs */
    double collapse_radius;         /* |q| beyond which it cannot vanish (rw_engine.c collapse_cannot_vanish) */
    /* the end point of the last resolved span (time, state, indicators and their rates): the next
     * input segment starts there, and without an event in between only the closed hinges'
     * indicators, which depend on the input's rate, differ */
    int carry_valid;
    double carry_t;
    rw_engine_point carry;
    /* the end point of a segment that rw_engine_quiet_segment evaluated and found not quiet: the
     * first substep of resolve() over the same segment takes it (pending_t0: its start time) */
    int pending_valid;
    unsigned pending_suspects;
    double pending_t0;
    rw_engine_point pending;
    /* the same as carry for the slow part of a span with fast modes (rw_engine.c "fast modes"): the
     * slow point at the end of the last quiet substep, which ended at slow_carry_t in the state
     * slow_carry_x0, with the slow rotations' accelerations there */
    int slow_carry_valid;
    double slow_carry_t, slow_carry_x0[RW_NX];
    rw_engine_point slow_carry;
    double slow_carry_ddq[2];
    /* run bookkeeping */
    int mid_is_bookkeeping;     /* the mid-height switch changes nothing in the motion (region_lines) */
    int b[RW_NZ];               /* indicator states z > 0 */
    double b_sign[RW_NZ];       /* the same as +-1 */
    double peak_s1, peak_s2;
    long events, steps, impacts;
    double dissipated;          /* energy taken out by the event maps (impacts, closings), if track_dissipated */
    int track_dissipated;       /* set by the caller that reads `dissipated` (the FMU) */
    double s_coef[2][2];        /* s1, s2 = s_coef[.] . (q1, q2) */
    double floor_rate;          /* rw_engine.c rocking_rate: the slowest rate a substep resolves */
    int collapsed, reason;
    double t_collapse;
    double t_last_event;
    int same_instant, max_same_instant;
    const double *t_out;
    size_t n_out, i_out;
    double *x_out, *s1_out, *s2_out;
    double *impact_t, *impact_energy;
    size_t impact_cap;
    int b_valid;                /* b holds the indicator states of the last step's end */
    int b_stale;                /* an event changed the regime: b is set at the next span's start */
    int region_keep;            /* the event kept the region (rw_engine.c hinge_event_keeps_region) */
    char msg[256];
} rw_engine;

/* ---- a stepper for callers that own the time loop (Co-Simulation) ---------------------------- */
/* In place (e.g. inside the FMU's instance data): 0, or 1 with msg filled. */
int rw_engine_init(rw_engine *e, const rw_params *p, char *msg, size_t n);

/* A heap engine over p (NULL with msg filled if p is refused or the parapet). */
rw_engine *rw_engine_new(const rw_params *p, char *msg, size_t n);
void rw_engine_free(rw_engine *e);
/* Advance x, m (initialised by the caller: rw_init_regime and the initial event iteration) from t
 * to t + h with the inputs linear over the step (value at t and slope). If the inputs jumped at t
 * since the previous step so that an indicator changed sign, the model's event iteration runs at
 * t first (an input can open a hinge at rest). Impacts are added to *impacts. Returns 0, 1 if the
 * wall collapsed at *t_reached (<= t + h), or an error code + 1 (msg filled). */
int rw_engine_step(rw_engine *e, rw_regime *m, double x[RW_NX], double t, double h, const rw_linear_input *in,
                   long *impacts, double *t_reached, char *msg, size_t n);

/* ---- one linear region on its own (for tests of the closed form) ------------------------------
 * The 2DOF with open hinges on the region whose hinge moments are Q = c + J q: the exact motion of
 * M q'' + (K - J) q = pa ag + fu u_top (1, 1) + c from x0 over s (the input linear from its value at
 * s = 0), through the engine's own decomposition (the symmetric path when J is symmetric, the
 * general 2x2 path otherwise) and closed form. 0, or RW_ENGINE_UNSUPPORTED (complex or repeated
 * modes, or an engine that is not the 2DOF). */
int rw_engine_region_motion(rw_engine *e, const double J[2][2], const double c[2], const rw_linear_input *in,
                            const double x0[RW_NX], double s, double x[RW_NX]);

#endif
