/* How the exact scene engine takes a record interval (the record linear over it): one slow step if
 * the modes' quiet test clears it, else its dyadic halves, down to the steps the exact series
 * converge over, each cleared by the quiet test on its table or examined on its series (which
 * stops at the first root and has the event handled); and, where it can, three intervals at once
 * under one quiet test (sx_window). docs/scenes.md says how. */
#include "rw_scene_exact_internal.h"

#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

static sx_region *current(sx_run *R) { return R->regions[R->cur]; }

/* the motion over a cleared step of its table: xa1 = exp(Aa h) xa0, the work integrals */
static void table_step(sx_run *R, const sx_region *r, const sx_step *st, const double xa0[], const double xa1[],
                       double t1)
{
    const double wd = sx_step_dissipation(r, st, xa0);
    double m0 = 0.0, m1 = 0.0;
    int k;
    for (k = 0; k < r->na; k++) {
        m0 += st->wg[k] * xa0[k];
        m1 += st->wg[r->na + k] * xa0[k];
    }
    R->work_ground -= xa0[r->n] * m0 + xa0[r->n + 1] * m1;
    R->work_damping += wd;
    sx_scatter(r, xa1, R->x);
    R->t = t1;
    R->res->steps++;
}

/* a Bouc-Wen fit that did not settle over a step of length L: the region's steps are halved from
 * here on (the rounds contract by about (1 - alpha) k h^2 / m_d: a light diaphragm on a soft
 * linear share, alpha k and the tie, whose own mode does not limit the steps); 1 where they are
 * already shorter than anything a record needs, and the run ends */
static int fit_failed(sx_run *R, sx_region *r, double L)
{
    if (L > SX_BW_HMIN) {
        r->hcap = 0.5 * L;
        return 0;
    }
    snprintf(R->res->message, sizeof R->res->message,
             "the Bouc-Wen diaphragms' fit did not settle at t = %.9g s over steps of %.3g s", R->t, L);
    R->error = RW_SCENE_SOLVER;
    return 1;
}

/* the first root over a piece of the exact series (u in (0, 1], or 2 if none), with the peaks up to
 * it: the quiet test on the piece's ends first (xa1: the end it finds), and the series only for what
 * it could not clear */
static double piece_root(sx_run *R, const sx_region *r, const sx_series *s, const double xa0[], double xa1[])
{
    sx_lopoly P[SX_MAX_F];
    sx_hermite_step hs;
    sx_suspects sus;
    sx_series_at(r, s, 1.0, xa1);
    if (!r->modes.valid || r->nz) return sx_watch_step(R, r, s, NULL);
    sx_hermite_step_of(r, s->L, &hs);
    sx_hermite_polys(r, &hs, xa0, xa1, P);
    if (sx_watch_suspects(R, r, P, &sus)) return sx_watch_step(R, r, s, &sus);
    sx_watch_peaks_at(R, r, xa1); /* (it may still hold a peak at its end) */
    return 2.0;
}

/* a piece [R->t, t1] on the exact series, in parts no longer than the region's limit; stops early
 * at an event (handled here) */
static int exact_piece(sx_run *R, double t1, double ta, double ag_a, double slope)
{
    while (R->t < t1) {
        sx_region *r = current(R);
        const int parts = sx_parts(r, t1 - R->t);
        const double L = (t1 - R->t) / parts;
        double xa0[SX_MAX_NA], xa[SX_MAX_NA], wg, wd, u;
        sx_series s;
        sx_gather(r, R->x, ag_a + slope * (R->t - ta), slope, xa0);
        if (r->nz && sx_bouc_wen_fit(R, r, NULL, L, xa0)) {
            if (fit_failed(R, r, L)) return -1;
            continue; /* again in shorter parts */
        }
        sx_series_of(r, xa0, L, &s);
        u = piece_root(R, r, &s, xa0, xa);
        sx_series_work(r, &s, fmin(u, 1.0), &wg, &wd);
        R->work_ground += wg;
        R->work_damping += wd;
        if (u < 1.0) sx_series_at(r, &s, u, xa); /* (else the end piece_root found) */
        if (r->nz) sx_bouc_wen_advance(R, r, xa0, fmin(u, 1.0), NULL, &s);
        sx_scatter(r, xa, R->x);
        R->res->steps++;
        if (u > 1.0) {
            R->t = parts > 1 ? R->t + L : t1;
            continue;
        }
        R->t = (u == 1.0 && parts <= 1) ? t1 : R->t + u * L;
        R->error = sx_handle_events(R);
        return R->error ? -1 : 1;
    }
    return 0;
}

/* one step of the grid on its table: 1 if the quiet test cleared it (then taken), 0 if not */
static int quiet_step(sx_run *R, double h, double t1, double ag0, double slope)
{
    sx_region *r = current(R);
    double xa0[SX_MAX_NA], xa1[SX_MAX_NA];
    sx_step *st;
    int quiet;
    if (h > sx_hmax(r) * (1.0 + 1e-12)) return 0;
    st = sx_step_of(r, h, SX_TIME_TOL(t1), ++R->stamp);
    if (!st || (st->is_long && !r->modes.valid)) return 0; /* no memory, or a length at the limit, doubled: no
                                                              polynomial rows (the modes bound without them) */
    sx_gather(r, R->x, ag0, slope, xa0);
    if (r->nz && sx_bouc_wen_fit(R, r, st, h, xa0)) return 0; /* not settled: the series tries, in
                                                                  shorter parts if it must */
    st->used = LONG_MAX; /* kept while in use: doubts settled inside the test (their store full) build tables */
    quiet = sx_watch_quiet(R, r, st, xa0, xa1);
    st->used = R->stamp;
    if (!quiet) return 0;
    if (r->nz) sx_bouc_wen_advance(R, r, xa0, 1.0, st, NULL);
    table_step(R, r, st, xa0, xa1, t1);
    return 1;
}

/* [R->t, t1] in the grid of equal steps no longer than the region allows (the steps the exact
 * series converge over): each cleared by the quiet test on its table, or examined on its series
 * (after an event the series takes the motion to the next grid point). failed: the quiet test has
 * just failed on the whole of [R->t, t1] in this region, so a grid of one step goes to the series
 * at once (the same test on the same table would fail again: 2 % of the house's instructions). */
static int exact_steps(sx_run *R, double t1, double ta, double ag_a, double slope, int failed)
{
    const double t0 = R->t;
    const int steps = sx_parts(current(R), t1 - t0);
    const double h = (t1 - t0) / steps;
    int k = 0;
    while (R->t < t1) {
        const double end = k + 1 >= steps ? t1 : t0 + (k + 1) * h;
        const int known = failed && steps == 1 && k == 0;
        if (!known && R->t == (k == 0 ? t0 : t0 + k * h) && quiet_step(R, h, end, ag_a + slope * (R->t - ta), slope)) {
            k++;
            continue;
        }
        if (exact_piece(R, end, ta, ag_a, slope) < 0) return 1;
        if (R->t >= end) k++;
    }
    return 0;
}

/* the quiet test of a step of table st from xa0 to its exact end xa1 (the region's modes valid), and
 * the step taken where it clears: 0, else why not */
static int cleared_step(sx_run *R, const sx_region *r, sx_step *st, const double xa0[], const double xa1[], double t1)
{
    int why;
    st->used = LONG_MAX; /* kept while in use: doubts settled inside the test (their store full) build tables */
    why = sx_quiet_ends(R, r, &st->herm, xa0, xa1);
    st->used = R->stamp;
    if (!why) table_step(R, r, st, xa0, xa1, t1);
    return why;
}

/* a slow step [R->t, t1] cleared by the quiet test on its (long) table: 0 if taken, else why not
 * (SX_MAY_CROSS, SX_MAY_PEAK, or -1: no modes, or no memory for the table). in_failed: the step is
 * a piece of one that failed, so a line that surely crosses over it is looked for first (over a
 * whole record interval that would cost more than it saves: few of them hold a crossing) */
static int slow_step(sx_run *R, double t1, double ta, double ag_a, double slope, int in_failed)
{
    sx_region *r = current(R);
    const double h = t1 - R->t;
    double xa0[SX_MAX_NA], xa1[SX_MAX_NA];
    sx_step *st;
    if (!r->modes.valid) return -1;
    if (!(st = sx_step_of(r, h, SX_TIME_TOL(t1), ++R->stamp))) return -1; /* no memory for it: the dyadic
                                    pieces end on the exact series */
    sx_gather(r, R->x, ag_a + slope * (R->t - ta), slope, xa0);
    sx_step_propagate(r, st, xa0, xa1);
    if (in_failed && sx_watch_sure_cross(R, r, xa0, xa1)) return SX_MAY_CROSS;
    return cleared_step(R, r, st, xa0, xa1, t1);
}

/* The dyadic piece `index` of `level` of the interval [ta, ta + L] (its `pieces` = 2^level): one slow
 * step if the modes' test clears it, else its two halves, down to the exact steps (docs/scenes.md).
 * (L / pieces is exact, as ldexp's would be, without a call into the library at every interval.) */
static int dyadic(sx_run *R, double ta, double L, int level, double pieces, double index, double ag_a, double slope);

/* that piece once its slow step has failed for why: its exact steps, or its two halves */
static int halves(sx_run *R, double ta, double L, int level, double pieces, double index, double ag_a, double slope,
                  int why)
{
    const double h = L / pieces, t1 = index + 1.0 >= pieces ? ta + L : ta + (index + 1.0) * h;
    if (h <= 2.0 * sx_hmax(current(R))) return exact_steps(R, t1, ta, ag_a, slope, why > 0);
    if (dyadic(R, ta, L, level + 1, 2.0 * pieces, 2.0 * index, ag_a, slope)) return 1;
    return dyadic(R, ta, L, level + 1, 2.0 * pieces, 2.0 * index + 1.0, ag_a, slope);
}

static int dyadic(sx_run *R, double ta, double L, int level, double pieces, double index, double ag_a, double slope)
{
    const double h = L / pieces, t1 = index + 1.0 >= pieces ? ta + L : ta + (index + 1.0) * h;
    int why;
    if (R->t >= t1) return 0;
    if (R->t > ta + index * h || !current(R)->modes.valid || level >= 30) return exact_steps(R, t1, ta, ag_a, slope, 0);
    why = slow_step(R, t1, ta, ag_a, slope, level > 0);
    return why == 0 ? 0 : halves(R, ta, L, level, pieces, index, ag_a, slope, why);
}

/* After a window the quiet test did not clear, the record intervals taken one by one before the next
 * is tried: WINDOW_WAIT times a back-off that doubles at each failure in a row, up to WINDOW_BACKOFF
 * (failures come in runs, a peak rising or a wall near its lines, and a failed window's test is
 * spent). The house's instructions were least with these (scripts/bench_scenes.py's house: windows of
 * 3 steps, waits of 2 up to 16). */
#ifndef WINDOW_BACKOFF
#define WINDOW_BACKOFF 8
#endif
#ifndef WINDOW_WAIT
#define WINDOW_WAIT 2
#endif

/* can the current region (its modes valid) take a window (linear, its modes without blocks, no band so fast that the
 * ends' data come from the modes' own coordinates)? */
static int window_region(const sx_run *R, const sx_region *r, const sx_step *st)
{
    int i;
    if (r->modes.blocks || r->nz || st->herm_w.modal) return 0;
    for (i = 0; i < R->sc.S.n_storeys; i++)
        if (R->ndlines[i]) return 0;
    return 1;
}

/* Record intervals of the same table at once: each step propagated exactly as one by one, and one
 * quiet test over the window they make (the record kinks at the samples inside it:
 * rw_scene_exact_hermite.c bounds what that adds). Where it clears, the steps are taken as sx_advance
 * takes them, to the bit; where not, the first interval is taken as sx_advance takes it, its slow
 * step's test on the ends already propagated (and its halves where that fails too). */
int sx_window(sx_run *R, const double t[], int n)
{
    sx_region *r = current(R);
    double x[RW_SCENE_NX], ag[SX_WINDOW + 1], xa[SX_WINDOW][SX_MAX_NA], xe[SX_WINDOW][SX_MAX_NA];
    sx_step *st;
    int j, why;
    if (R->window_wait > 0) return R->window_wait--, 0;
    if (n != SX_WINDOW || !r->modes.valid || !(st = sx_step_of(r, t[1] - t[0], SX_TIME_TOL(t[1]), ++R->stamp))) return 0;
    if (!window_region(R, r, st)) return 0;
    for (j = 1; j < n; j++) /* (asking for their tables instead could take st's slot for another length) */
        if (!sx_step_fits(st, t[j + 1] - t[j], SX_TIME_TOL(t[j + 1]))) return 0;
    memcpy(x, R->x, sizeof x);
    for (j = 0; j <= n; j++) ag[j] = sx_ground(R, t[j]);
    for (j = 0; j < n; j++) { /* (each start as sx_advance gathers it) */
        if (j) sx_scatter(r, xe[j - 1], x);
        sx_gather(r, x, ag[j], (ag[j + 1] - ag[j]) / (t[j + 1] - t[j]), xa[j]);
        sx_step_propagate(r, st, xa[j], xe[j]);
    }
    if (sx_quiet_window(R, r, st, n, xa, xe[n - 1]) == 0) {
        R->window_backoff = 1;
        for (j = 0; j < n; j++) {
            if (j) sx_observe(R);
            table_step(R, r, st, xa[j], xe[j], t[j + 1]);
        }
        return n;
    }
    R->window_wait = R->window_backoff * WINDOW_WAIT;
    if (R->window_backoff < WINDOW_BACKOFF) R->window_backoff *= 2;
    if ((why = cleared_step(R, r, st, xa[0], xe[0], t[1])) == 0) return 1;
    return halves(R, t[0], t[1] - t[0], 0, 1.0, 0.0, ag[0], xa[0][r->n + 1], why) ? -1 : 1;
}

/* the interval [R->t, tb], the record linear over it */
int sx_advance(sx_run *R, double tb)
{
    const double ta = R->t, ag_a = sx_ground(R, ta), slope = (sx_ground(R, tb) - ag_a) / (tb - ta);
    return dyadic(R, ta, tb - ta, 0, 1.0, 0.0, ag_a, slope);
}
