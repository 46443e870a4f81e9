/* Internal to the exact engine (rw_engine.c, rw_engine_regions.c, rw_engine_batch.c): not part of
 * its C API (rw_engine.h). */
#ifndef RW_ENGINE_INTERNAL_H
#define RW_ENGINE_INTERNAL_H

#include "rw_engine.h"

/* ---- the engine's state (rw_engine.h: opaque) ---------------------------------------------------- */
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

struct rw_engine { /* plain data: no pointer but to static data or the batch run's outputs */
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
};

/* min and max of finite values without libm's calls (fmin, fmax handle NaN, which never reaches here) */
static inline double rw_min2(double a, double b) { return a < b ? a : b; }
static inline double rw_max2(double a, double b) { return a > b ? a : b; }

/* ---- regions (rw_engine_regions.c) ---- */
/* The region the state x (moving along dq_sel) is in, under the regime m: its cache entry, the
 * modal forcing g0 of its constant terms and, where the law allows it, its affine hinge moments
 * aq. NULL if the engine cannot decompose it (e->msg filled). */
rw_cache_entry *rw_engine_region_of(rw_engine *e, const rw_regime *m, const double x[RW_NX], const double dq_sel[2],
                                    double g0[2], rw_affine_Q *aq);
/* The 2DOF with open hinges on the region of Jacobian J (stiffness K - J): 0, or -1 (complex or
 * repeated modes) */
int rw_engine_modes_open(const rw_engine *e, const double J[2][2], rw_modes2 *E);
/* the modal forcing of a generalised force vector F */
void rw_engine_modal_force(const rw_modes2 *E, const double F[2], double out[2]);

/* ---- the run (rw_engine.c), for rw_engine_batch.c ---- */
/* The start at t0 from x (regime, the initial event iteration, the collapse test): 0, 1 if
 * collapsed, or an error code + 1 */
int rw_engine_begin(rw_engine *e, rw_regime *m, double x[RW_NX], double t0, const rw_input *in);
/* Advance over [*t, t_end] with the input linear (in, given at t_in): 0, 1 on collapse, or an
 * error code + 1 */
int rw_engine_advance(rw_engine *e, rw_regime *m, double x[RW_NX], double *t, double t_end, const rw_linear_input *in,
                      double t_in);
/* The segment [*t, t_end] when it is quiet (rw_engine.c): 1 (x, *t at its end), else 0 with
 * nothing changed, for rw_engine_advance */
int rw_engine_quiet_segment(rw_engine *e, rw_regime *m, double x[RW_NX], double *t, double t_end,
                            const rw_linear_input *in, double t_in);
/* the output grid's rows past where the run stopped: NaN */
void rw_engine_fill_outputs(rw_engine *e);

#endif
