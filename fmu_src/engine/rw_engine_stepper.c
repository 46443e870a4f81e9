/* An input segment advanced: the spans of the current region, resolved in turn.
 * The rates of each span's modes set its substeps; quiet and at-rest segments need no span. */
#include "rw_engine_hermite.h"
#include "rw_engine_span.h"

#include <float.h>
#include <math.h>
#include <string.h>

/* the squared amplitude of mode i's free oscillation about its quasi-static solution */
static double mode_amplitude2(const rw_span *sp, int i)
{
    const double il = sp->R->inv_lam[i];
    const double a = sp->eta[i] - sp->f0[i] * il, b = sp->v[i] - sp->f1[i] * il;
    return a * a + b * b * il;
}

/* the span's modes as rw_rates describes them: which count, the fast one if any, and the rate its
 * substeps follow (at least floor_rate) */
static void span_rates(const rw_engine *e, const rw_span *sp, double floor_rate, rw_rates *r)
{
    const rw_cache_entry *R = sp->R;
    const double small = 1e-12 * e->D.q_topple;
    double w[2] = {0.0, 0.0}, amp2[2];
    int i;
    memset(r, 0, sizeof *r);
    for (i = 0; i < 2; i++) {
        amp2[i] = mode_amplitude2(sp, i);
        if (R->E.lam[i] <= 0.0 || amp2[i] * R->col[i] * R->col[i] > small * small) w[i] = R->w[i];
    }
    r->slow_rate = floor_rate;
    for (i = 0; i < 2; i++) {
        const double other = rw_max2(floor_rate, w[1 - i]);
        if (R->E.lam[i] > 0.0 && w[i] > 4.0 * other) {
            const double amp = sqrt(amp2[i]); /* rotations of a standing wall: no overflow */
            r->fast[i] = r->any_fast = 1;
            r->fast_rate = rw_max2(r->fast_rate, w[i]);
            r->dq_fast[0] = amp * R->E.P[0][i];
            r->dq_fast[1] = amp * R->E.P[1][i];
        } else {
            r->slow_rate = rw_max2(r->slow_rate, w[i]);
        }
    }
}

/* Does one substep cover a span of length len in region R, whatever modes count: does every mode,
 * and the rocking rate that bounds the polynomial motions, turn by at most RW_PHASE_PER_SUBSTEP? */
static int one_substep_covers(const rw_engine *e, const rw_cache_entry *R, double len)
{
    return rw_max2(e->floor_rate, rw_max2(R->w[0], R->w[1])) * len <= RW_PHASE_PER_SUBSTEP;
}

/* The indicator states after an event: at the start point of the span that follows, which is kept
 * for rwe_resolve() (the region's own evaluation: the lines and the collapse form as the physics gives
 * them, so the same signs as rw_event_indicators) */
static void refresh_indicator_states(const rw_span_ctx *sc)
{
    rw_point pt;
    eval_point(sc, 0.0, NULL, &pt);
    rwe_track_states(sc->e, pt.z);
    sc->e->b_stale = 0;
    carry_point(sc->e, &pt, sc->sp.t0);
}

/* Right after an event under a stiff spring the next one often follows within microseconds (the
 * base and the mid-height hinge of a wall held at its top switch nearly together, under the laws
 * whose moments take the sides: the rigid law, semiRigidPaper). Left to the
 * band (rwe_fast_substep), it costs a band test of the rest of the segment before it and another after.
 * So when an indicator of the span's start point (the carried point) heads for zero, linearly,
 * within the piece over which the fast mode turns by RW_PHASE_PER_SUBSTEP, rwe_advance() resolves that
 * piece in full first: every mode turns little over it, as rwe_resolve() needs. */
static int event_ahead(const rw_engine *e, double piece)
{
    int k;
    for (k = 0; k < RW_NZ; k++)
        if (e->b_sign[k] * (e->carry.z[k] + e->carry.dz[k] * piece) < 0.0) return 1;
    return 0;
}

/* Advance over [t, t_end] with the input linear (in, given at t_in). Returns 0, 1 on collapse
 * (x, t at the collapse), or an error code + 1. */
int rwe_advance(rw_engine *e, rw_regime *m, double x[RW_NX], double *t, double t_end, const rw_linear_input *in,
                double t_in)
{
    rw_span_ctx sc;
    sc.e = e;
    sc.m = m;
    sc.in = in;
    sc.t_in = t_in;
    sc.x = x;
    sc.t = t;
    while (*t < t_end) {
        double span_len, h, span_end;
        int n, j, rc = 0, after_event;
        sc.R = rwe_current_region(&sc, *t);
        if (!sc.R) return RW_ENGINE_UNSUPPORTED + 1;
        restart_span(&sc, *t, x);
        after_event = e->b_stale; /* the indicator states are taken again at an event's state */
        if (after_event) refresh_indicator_states(&sc);
        span_len = t_end - *t;
        if (one_substep_covers(e, sc.R, span_len)) {
            sc.r.any_fast = 0;
            n = 1;
            h = span_len;
            span_end = t_end;
        } else {
            span_rates(e, &sc.sp, e->floor_rate, &sc.r);
            n = rwe_substeps_for(sc.r.slow_rate, &span_len);
            h = span_len / n;
            span_end = n * h < t_end - *t ? *t + span_len : t_end;
        }
        if (sc.r.any_fast || n != 1) e->pending_valid = 0;
        if (sc.r.any_fast && after_event) {
            const double piece = RW_PHASE_PER_SUBSTEP / sc.r.fast_rate;
            if (piece < span_len && event_ahead(e, piece)) {
                rc = rwe_resolve(&sc, piece, 1, NULL);
                if (rc > 0) return rc;
                continue; /* from the next event, or from the piece's end */
            }
        }
        if (!sc.r.any_fast) {
            rc = rwe_resolve(&sc, span_end - *t, n, rwe_substep_coefficients(sc.R, h, span_end));
            if (rc > 0) return rc;
            continue;
        }
        for (j = 0; j < n && rc == 0; j++) {
            const double t_to = j == n - 1 ? span_end : sc.sp.t0 + h;
            /* the last piece differs from h by rounding at most: the same coefficients */
            const int same = fabs((t_to - sc.sp.t0) - h) <= 4.0 * DBL_EPSILON * (fabs(t_to) + h);
            rc = rwe_fast_substep(&sc, t_to, same ? rwe_substep_coefficients(sc.R, h, t_to) : NULL, 0);
            if (rc > 0) return rc;
            if (rc == 0 && j < n - 1) restart_span(&sc, *t, x);
        }
    }
    return 0;
}

/* ---- a segment at rest ---------------------------------------------------------------------------
 * With both rigid hinges closed (or the simply supported wall's closed) the wall stands still: only
 * the closed hinges' indicators vary, through the input. 1 - |f|/cap + eps_f with f affine in the
 * input, which is linear over a segment, is concave there: when it holds (> 0) at both ends it holds
 * throughout. Such a segment needs its end values alone. */
static int at_rest(const rw_engine *e, const rw_regime *m)
{
    return e->rigid && m->closed_b && (m->closed_m || e->P.support != RW_FLEXIBLE_TOP);
}

/* 1 when the segment to t_end holds every closed hinge (x and the carried point stay, with the
 * closed hinges' values at the end; their rates are taken again at the next segment's start,
 * carried_start), else 0: an end near or past zero, for the general test */
static int rest_holds(rw_engine *e, double t_end, const rw_linear_input *in, double t_in)
{
    /* the input at the end (its rate is not needed: no rates are taken) */
    const rw_input end[2] = {{in->ag + in->ag_slope * (t_end - t_in), in->u_top + in->u_slope * (t_end - t_in)},
                             {0.0, 0.0}};
    /* only the closed hinges' entries are written and read: z is zeroed because gcc cannot see that
     * (-Wmaybe-uninitialized) */
    double z[RW_NZ] = {0.0}, dz[RW_NZ];
    int k;
    if (rwe_closed_hinge_values(e, end, e->carry.x, NULL, e->closed_mask, z, dz)) return 0;
    for (k = 0; k < RW_NZ; k++)
        if (((e->closed_mask >> k) & 1u) && !(e->b[k] && e->carry.z[k] > 0.0 && z[k] > 0.0)) return 0;
    for (k = 0; k < RW_NZ; k++)
        if ((e->closed_mask >> k) & 1u) e->carry.z[k] = z[k]; /* the next segment's start */
    return 1;
}

/* ---- a quiet segment: the common case without the general machinery --------------------------
 * Most input segments of a run hold no event: the region, its lines and the end point of the
 * segment before (rw_engine.carry) are known, one substep covers the segment (every mode turns by
 * at most RW_PHASE_PER_SUBSTEP), and the quick test clears every indicator. Such a segment is taken
 * here with the same evaluations as rwe_resolve() (so the same numbers), without its set-up; any other
 * segment is left untouched to rwe_advance. */
int rwe_quiet_segment(rw_engine *e, rw_regime *m, double x[RW_NX], double *t, double t_end,
                      const rw_linear_input *in, double t_in)
{
    const double len = t_end - *t;
    rw_cache_entry *R;
    rw_span_ctx sc;
    rw_point b, buf;
    const rw_point *a;
    unsigned suspects;
    if (!e->region_valid || !e->carry_valid || e->b_stale || e->carry_t != *t) return 0;
    if (e->i_out < e->n_out && e->t_out[e->i_out] <= t_end) return 0;
    R = &e->cache[e->region];
    if (!one_substep_covers(e, R, len)) return 0;
    if (memcmp(e->carry.x, x, sizeof e->carry.x) != 0) return 0;
    if (at_rest(e, m) && rest_holds(e, t_end, in, t_in)) {
        e->steps++;
        *t = e->carry_t = t_end;
        return 1;
    }
    sc.e = e;
    sc.m = m;
    sc.sp.aq = e->region_aq;
    span_start(&sc.sp, R, e->region_g0, *t, x, in, t_in);
    a = carried_start(&sc, &buf);
    eval_point(&sc, len, rwe_substep_coefficients(R, len, t_end), &b);
    suspects = suspects_of(e, a->z, a->dz, b.z, b.dz, len);
    if (suspects) { /* its end point and suspects, for rwe_resolve() (rw_engine.pending) */
        e->pending = b;
        e->pending_t0 = *t;
        e->pending_suspects = suspects;
        e->pending_valid = 1;
        return 0;
    }
    e->steps++;
    rwe_peaks_on(&sc, e->carry.x, 0.0, b.x, len);
    memcpy(x, b.x, sizeof b.x);
    *t = t_end;
    carry_point(e, &b, t_end);
    return 1;
}
