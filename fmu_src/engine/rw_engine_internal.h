/* What the exact engine's files share and its API (rw_engine.h) does not publish.
 * The engine's state, a span and the context of its resolution, the functions one file gives
 * another. */
#ifndef RW_ENGINE_INTERNAL_H
#define RW_ENGINE_INTERNAL_H

#include "rw_engine.h"

#define RW_PHASE_PER_SUBSTEP 1.0 /* rad of the fastest significant mode per bracketing substep */
#define RW_MAX_SUBSTEPS 2000000L

/* ---- the engine's state (rw_engine.h: opaque) ---------------------------------------------------- */
/* a point of a span: its offset s from the span's start, the state and the indicators with their rates */
typedef struct {
    double s;
    double x[RW_NX];
    double z[RW_NZ], dz[RW_NZ];
} rw_engine_point;
typedef rw_engine_point rw_point;

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
    double collapse_radius;         /* |q| beyond which it cannot vanish (rw_engine_band.c collapse_cannot_vanish) */
    /* the end point of the last resolved span (time, state, indicators and their rates): the next
     * input segment starts there, and without an event in between only the closed hinges'
     * indicators, which depend on the input's rate, differ */
    int carry_valid;
    double carry_t;
    rw_engine_point carry;
    /* the end point of a segment that rwe_quiet_segment evaluated and found not quiet: the first
     * substep of rwe_resolve over the same segment takes it (pending_t0: its start time) */
    int pending_valid;
    unsigned pending_suspects;
    double pending_t0;
    rw_engine_point pending;
    /* the same as carry for the slow part of a span with fast modes (rw_engine_band.c): the slow
     * point at the end of the last quiet substep, which ended at slow_carry_t in the state
     * slow_carry_x0, with the slow rotations' accelerations there */
    int slow_carry_valid;
    double slow_carry_t, slow_carry_x0[RW_NX];
    rw_engine_point slow_carry;
    double slow_carry_ddq[2];
    /* run bookkeeping */
    int mid_is_bookkeeping;     /* the mid-height switch changes nothing in the motion (rwe_region_lines) */
    int b[RW_NZ];               /* indicator states z > 0 */
    double b_sign[RW_NZ];       /* the same as +-1 */
    double peak_s1, peak_s2;
    long events, steps, impacts;
    double dissipated;          /* energy taken out by the event maps (impacts, closings), if track_dissipated */
    int track_dissipated;       /* set by the caller that reads `dissipated` (the FMU) */
    double s_coef[2][2];        /* s1, s2 = s_coef[.] . (q1, q2) */
    double floor_rate;          /* rw_engine_object.c rocking_rate: the slowest rate a substep resolves */
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
    int region_keep;            /* the event kept the region (rwe_hinge_event_keeps_region) */
    char msg[256];
};

/* ---- spans and their resolution --------------------------------------------------------------- */
/* a span: a region with a linear input, from a start state (rw_engine_span.h) */
typedef struct {
    const rw_cache_entry *R;
    double t0;
    double eta[2], v[2]; /* modal state at t0 */
    double f0[2], f1[2]; /* modal forcing at t0 and its rate */
    double ag0, ag1, u0, u1; /* the input at t0 and its rate */
    double x0[RW_NX];        /* the start state itself: the motion is x0 + P (eta(s) - eta(0)) */
    rw_affine_Q aq;          /* the region's hinge moments, if affine in q */
} rw_span;

/* The modes of a span, for bracketing: unstable modes always count; an oscillating mode counts
 * when its free oscillation about the quasi-static solution is larger than 1e-12 of the toppling
 * rotation (a stiff spring's mode driven quasi-statically is not), and it is `fast` when it turns
 * more than 4 times faster than every other counted rate (including the wall's rocking rate, see
 * rwe_substeps_for): its free oscillation is then a band around the slow motion
 * (rw_engine_band.c) instead of setting the substeps. At most one mode is fast (each would have to
 * turn 4 times faster than the other), so the band is dq_fast times a factor in [-1, 1]: the
 * mode's shape times its amplitude, with signs. */
typedef struct {
    int fast[2], any_fast;
    double slow_rate, fast_rate;
    double dq_fast[2]; /* the fast mode's free oscillation at its extreme, in (q1, q2) */
} rw_rates;

/* What the functions along a span share: the engine (its region, lines and forms, the tracked
 * indicator states, peaks and counters), the regime (events change it), the span, what a new span
 * of the same region starts from (the region, its modal forcing g0, the input segment given at
 * t_in), the rates of its modes (the band of a fast mode) and the motion's state x, *t, which the
 * resolution advances. A quiet segment (rwe_quiet_segment) sets e, m and sp only. */
typedef struct {
    rw_engine *e;
    rw_regime *m;
    rw_span sp;
    rw_cache_entry *R;
    double g0[2];
    const rw_linear_input *in;
    double t_in;
    rw_rates r;
    double *x, *t;
} rw_span_ctx;

/* a bracket [lo, hi] of a root with the function's values at its ends */
typedef struct {
    double lo, flo, hi, fhi;
} rw_bracket;

/* an event located on a span: its offset s, its indicator k and the state x there */
typedef struct {
    double s;
    int k;
    double x[RW_NX];
} rw_root;

/* a function of the span's motion at s (rwe_find_switch): an indicator's rate, a peak's rate */
typedef double (*rw_scalar_fn)(const rw_span_ctx *sc, int k, double s);

/* min and max of finite values without libm's calls (fmin, fmax handle NaN, which never reaches here) */
static inline double rw_min2(double a, double b) { return a < b ? a : b; }
static inline double rw_max2(double a, double b) { return a > b ? a : b; }

/* Substeps: the counted rate turns by at most RW_PHASE_PER_SUBSTEP per substep (the caller bounds
 * that rate below by a quarter radian of the wall's own rocking rate, rw_engine.floor_rate). A span
 * longer than RW_MAX_SUBSTEPS substeps covers a part (*len shortened); the caller continues. */
static inline int rwe_substeps_for(double rate, double *len)
{
    const double turns = *len * rate / RW_PHASE_PER_SUBSTEP;
    int n;
    if (!(turns <= RW_MAX_SUBSTEPS)) {
        *len *= RW_MAX_SUBSTEPS / turns;
        return (int)RW_MAX_SUBSTEPS;
    }
    n = (int)turns; /* ceil, without libm's call */
    n += n < turns;
    return n < 1 ? 1 : n;
}

/* Does q alone fix the span's region? Under a law whose hinge moments depend on q alone, with the
 * region's affine Q. (The rigid law has an affine Q too, but its region also depends on which
 * hinges are closed.) */
static inline int rwe_q_fixes_region(const rw_engine *e, const rw_span *sp)
{
    return rw_moments_of_q_alone(&e->P) && sp->aq.valid;
}

/* ---- the functions one file gives another ------------------------------------------------------
 * Hidden in librwengine.so (direct calls, not through the PLT) and prefixed in the FMU binaries
 * (fmu_symbol.h), as rw_symbols.h does for the API. */
#if defined(__GNUC__) && !defined(_WIN32)
#define RWE_INTERNAL __attribute__((visibility("hidden")))
#else
#define RWE_INTERNAL
#endif
#define rwe_region_of FMU_SYMBOL(rwe_region_of)
#define rwe_modes_open FMU_SYMBOL(rwe_modes_open)
#define rwe_modal_force FMU_SYMBOL(rwe_modal_force)
#define rwe_substep_coefficients FMU_SYMBOL(rwe_substep_coefficients)
#define rwe_region_lines FMU_SYMBOL(rwe_region_lines)
#define rwe_current_region FMU_SYMBOL(rwe_current_region)
#define rwe_region_indicators FMU_SYMBOL(rwe_region_indicators)
#define rwe_closed_hinge_values FMU_SYMBOL(rwe_closed_hinge_values)
#define rwe_find_switch FMU_SYMBOL(rwe_find_switch)
#define rwe_refine_root FMU_SYMBOL(rwe_refine_root)
#define rwe_first_event FMU_SYMBOL(rwe_first_event)
#define rwe_track_peak FMU_SYMBOL(rwe_track_peak)
#define rwe_peaks_on FMU_SYMBOL(rwe_peaks_on)
#define rwe_record_output FMU_SYMBOL(rwe_record_output)
#define rwe_outputs_on FMU_SYMBOL(rwe_outputs_on)
#define rwe_peak_possible FMU_SYMBOL(rwe_peak_possible)
#define rwe_peaks_under_band FMU_SYMBOL(rwe_peaks_under_band)
#define rwe_track_states FMU_SYMBOL(rwe_track_states)
#define rwe_set_indicator_states FMU_SYMBOL(rwe_set_indicator_states)
#define rwe_apply_event FMU_SYMBOL(rwe_apply_event)
#define rwe_hinge_event_keeps_region FMU_SYMBOL(rwe_hinge_event_keeps_region)
#define rwe_resolve FMU_SYMBOL(rwe_resolve)
#define rwe_fast_substep FMU_SYMBOL(rwe_fast_substep)
#define rwe_advance FMU_SYMBOL(rwe_advance)
#define rwe_quiet_segment FMU_SYMBOL(rwe_quiet_segment)
#define rwe_begin FMU_SYMBOL(rwe_begin)
#define rwe_fill_outputs FMU_SYMBOL(rwe_fill_outputs)
#define rwe_parapet_beyond_small_rotation FMU_SYMBOL(rwe_parapet_beyond_small_rotation)

/* ---- set-up (rw_engine_object.c) ---- */
/* 1 (msg filled) for a parapet stockier than RW_ENGINE_PARAPET_MAX_B_OVER_H, else 0 */
RWE_INTERNAL int rwe_parapet_beyond_small_rotation(const rw_params *p, char *msg, size_t n);

/* ---- regions (rw_engine_regions.c) ---- */
/* The region the state x (moving along dq_sel) is in, under the regime m: its cache entry, the
 * modal forcing g0 of its constant terms and, where the law allows it, its affine hinge moments
 * aq. NULL if the engine cannot decompose it (e->msg filled). */
RWE_INTERNAL rw_cache_entry *rwe_region_of(rw_engine *e, const rw_regime *m, const double x[RW_NX],
                                           const double dq_sel[2], double g0[2], rw_affine_Q *aq);
/* The 2DOF with open hinges on the region of Jacobian J (stiffness K - J): 0, or -1 (complex or
 * repeated modes) */
RWE_INTERNAL int rwe_modes_open(const rw_engine *e, const double J[2][2], rw_modes2 *E);
/* the modal forcing of a generalised force vector F */
RWE_INTERNAL void rwe_modal_force(const rw_modes2 *E, const double F[2], double out[2]);
/* the Stumpff coefficients of a substep of length h at time t (cached in the region) */
RWE_INTERNAL const double (*rwe_substep_coefficients(rw_cache_entry *c, double h, double t))[4];
/* the indicators that are lines of the rotations under the regime m, into e */
RWE_INTERNAL void rwe_region_lines(rw_engine *e, const rw_regime *m);
/* The region of the motion at (sc->x, t), with sc->g0 and sc->sp.aq; NULL if the engine cannot
 * decompose it (e->msg filled) */
RWE_INTERNAL rw_cache_entry *rwe_current_region(rw_span_ctx *sc, double t);

/* ---- indicators (rw_engine_indicators.c) ---- */
/* The indicators of `mask` at the state x of the span's motion (the input in) and, if xd is not
 * NULL, their rates dz along it */
RWE_INTERNAL void rwe_region_indicators(const rw_span_ctx *sc, const rw_input *in, const double x[RW_NX],
                                        const double xd[RW_NX], unsigned mask, double *restrict z, double *restrict dz);
/* the closed rigid hinges' indicators among `mask` from their affine form (in[0]: the input,
 * in[1]: its rate); those near zero as a bit each */
RWE_INTERNAL unsigned rwe_closed_hinge_values(const rw_engine *e, const rw_input in[2], const double x[RW_NX],
                                              const double *xd, unsigned mask, double *z, double *dz);

/* ---- the search of a substep (rw_engine_search.c) ---- */
/* the first s in the bracket where f's sign differs from its sign at lo (regula falsi) */
RWE_INTERNAL double rwe_find_switch(rw_scalar_fn f, const rw_span_ctx *sc, int k, const rw_bracket *br,
                                    double rel_tol, double guess);
/* indicator k's root in the bracket, refined on the exact motion (the state there in x_hi if
 * *x_valid) */
RWE_INTERNAL double rwe_refine_root(const rw_span_ctx *sc, int k, int was, const rw_bracket *br, double guess,
                                    double x_hi[RW_NX], int *x_valid);
/* the earliest event in (a->s, b->s] among the suspects: 1 with *ev, or 0 */
RWE_INTERNAL int rwe_first_event(const rw_span_ctx *sc, const rw_point *a, const rw_point *b, unsigned suspects,
                                 rw_root *ev);

/* ---- peaks and outputs (rw_engine_peaks.c) ---- */
RWE_INTERNAL void rwe_track_peak(rw_engine *e, int which, double value);
RWE_INTERNAL void rwe_peaks_on(const rw_span_ctx *sc, const double xa[RW_NX], double sa, const double xb[RW_NX],
                               double sb);
RWE_INTERNAL void rwe_record_output(rw_engine *e, const double x[RW_NX]);
RWE_INTERNAL void rwe_outputs_on(const rw_span_ctx *sc, double sb);
RWE_INTERNAL int rwe_peak_possible(const rw_span_ctx *sc, int which, const double xa[RW_NX], const double xb[RW_NX],
                                   double L, double *reach, double *slow_max);
RWE_INTERNAL void rwe_peaks_under_band(const rw_span_ctx *sc, double u, const double xu[RW_NX], double v,
                                       const double xv[RW_NX], int depth);

/* ---- events (rw_engine_events.c) ---- */
RWE_INTERNAL void rwe_track_states(rw_engine *e, const double z[RW_NZ]);
RWE_INTERNAL void rwe_set_indicator_states(rw_engine *e, const rw_regime *m, const rw_input *in,
                                           const double x[RW_NX]);
/* the model's event iteration at t, then its collapse test: 0, 1 on collapse, or an error code + 1 */
RWE_INTERNAL int rwe_apply_event(rw_engine *e, rw_regime *m, double x[RW_NX], double t, const rw_input *in);
RWE_INTERNAL int rwe_hinge_event_keeps_region(const rw_engine *e, const rw_span *sp, int k_event,
                                              const double x[RW_NX]);

/* ---- resolution (rw_engine_resolve.c, rw_engine_band.c) ---- */
/* The span resolved in full over [0, len] in n pieces (C: their Stumpff coefficients, NULL:
 * computed): 0 (len reached), -1 (an event ends the span), or a collapse / error code */
RWE_INTERNAL int rwe_resolve(rw_span_ctx *sc, double len, int n, const double (*C)[4]);
/* A substep of a span with a fast mode, to t_to: returns as rwe_resolve */
RWE_INTERNAL int rwe_fast_substep(rw_span_ctx *sc, double t_to, const double (*C)[4], int depth);

/* ---- the stepper (rw_engine_stepper.c) ---- */
/* Advance over [*t, t_end] with the input linear (in, given at t_in): 0, 1 on collapse, or an
 * error code + 1 */
RWE_INTERNAL int rwe_advance(rw_engine *e, rw_regime *m, double x[RW_NX], double *t, double t_end,
                             const rw_linear_input *in, double t_in);
/* The segment [*t, t_end] when it is quiet: 1 (x, *t at its end), else 0 with nothing changed, for
 * rwe_advance */
RWE_INTERNAL int rwe_quiet_segment(rw_engine *e, rw_regime *m, double x[RW_NX], double *t, double t_end,
                                   const rw_linear_input *in, double t_in);

/* ---- the run (rw_engine_object.c), for rw_engine_batch.c ---- */
/* The start at t0 from x (regime, the initial event iteration, the collapse test): 0, 1 if
 * collapsed, or an error code + 1 */
RWE_INTERNAL int rwe_begin(rw_engine *e, rw_regime *m, double x[RW_NX], double t0, const rw_input *in);
/* the output grid's rows past where the run stopped: NaN */
RWE_INTERNAL void rwe_fill_outputs(rw_engine *e);

#endif
