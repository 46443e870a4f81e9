/* Spans with a fast mode: the band around the slow motion, and the substeps it cannot settle.
 * Lines that cross the band once are located on the full motion; other substeps are halved down to
 * the fast rate. */
#include "rw_engine_hermite.h"
#include "rw_engine_span.h"

#include <float.h>
#include <math.h>
#include <string.h>

/* A stiff mode (a stiff spring: up to 1e5 rad/s) would set substeps of microseconds. Its free
 * oscillation is a sinusoid of constant amplitude (dq_fast) about its exact quasi-static solution, so
 * over a substep of the slow modes the motion is the slow part (span_eval_part) within that band.
 * A substep can hold no event when every indicator of the slow part stays farther from zero than
 * what the band can change it by (evaluated at +-dq_fast, doubled), and no new peak when |s1|, |s2|
 * of the slow part plus the band stay below the peaks so far; otherwise the substep is resolved at
 * the fast rate. The slow part between the substep's ends is bounded by its cubic Hermite
 * interpolant with the margin of hermite_keeps_sign. */

/* is an indicator in the state `state` clear of zero over a range [lo, hi] widened by the band? */
static int indicator_clear(int state, double lo, double hi, double band)
{
    return state ? lo > band : hi < -band;
}

/* The slow part's ends of a substep [0, L]: the points (indicators with their rates) and the
 * rotations' accelerations there, with which line_crossing bounds a line's slow rate */
typedef struct {
    rw_point a, b;
    double ddq_a[2], ddq_b[2];
} rw_slow_ends;

/* the slow point at s (the fast modes' slow part: sc->r.fast) and, if x_full is not NULL, the full
 * state there */
static void eval_slow_point(const rw_span_ctx *sc, double s, const double (*C)[4], rw_point *pt, double ddq[2],
                            double *x_full)
{
    double xd[RW_NX];
    rw_input in = span_input(&sc->sp, s);
    pt->s = s;
    if (x_full) span_eval_slow_and_full(&sc->sp, s, C, sc->r.fast, pt->x, xd, x_full);
    else span_eval_part(&sc->sp, s, C, sc->r.fast, pt->x, xd);
    rwe_region_indicators(sc, &in, pt->x, xd, RW_Z_ALL, pt->z, pt->dz);
    ddq[0] = xd[2];
    ddq[1] = xd[3];
}

/* The band of the indicators of `mask` near the slow point a, evaluated: twice the larger change
 * of each at a +- dq_fast */
static void band_by_evaluation(const rw_span_ctx *sc, const rw_point *a, unsigned mask, double band[RW_NZ])
{
    const rw_rates *r = &sc->r;
    double xp[RW_NX], xm[RW_NX], zp[RW_NZ], zm[RW_NZ];
    const rw_input in = span_input(&sc->sp, a->s);
    int k;
    memcpy(xp, a->x, sizeof xp);
    memcpy(xm, a->x, sizeof xm);
    xp[0] += r->dq_fast[0], xp[1] += r->dq_fast[1];
    xm[0] -= r->dq_fast[0], xm[1] -= r->dq_fast[1];
    rwe_region_indicators(sc, &in, xp, NULL, mask, zp, NULL);
    rwe_region_indicators(sc, &in, xm, NULL, mask, zm, NULL);
    for (k = 0; k < RW_NZ; k++)
        if ((mask >> k) & 1u) band[k] = 2.0 * rw_max2(fabs(zp[k] - a->z[k]), fabs(zm[k] - a->z[k]));
}

/* How much the band can change each indicator near the slow point a, doubled: for a line
 * c + s|w| + t w of w = a.q, at most (|s| + |t|) |a.dq_fast|; for the toppling indicator,
 * max |dq_fast|/q_topple; the closed hinges' evaluated (band_by_evaluation). The collapse
 * indicator's is evaluated only where substep_suspects needs it. */
static void band_of(const rw_span_ctx *sc, const rw_point *a, double band[RW_NZ])
{
    const rw_engine *e = sc->e;
    const double d0 = sc->r.dq_fast[0], d1 = sc->r.dq_fast[1];
    const rw_line_arrays *A = &e->line_arrays;
    unsigned rest = RW_Z_ALL & ~e->line_mask & ~(1u << RW_Z_COLLAPSE);
    int k;
    for (k = 0; k < RW_NZ; k++) /* on arrays, which the compiler vectorizes; overwritten below for the rest */
        band[k] = 2.0 * (fabs(A->s[k]) + fabs(A->t[k])) * fabs(A->a0[k] * d0 + A->a1[k] * d1);
    if ((rest & (1u << RW_Z_TOPPLE)) && e->P.support == RW_FLEXIBLE_TOP) {
        band[RW_Z_TOPPLE] = 2.0 * rw_max2(fabs(d0), fabs(d1)) * e->D.inv_q_topple;
        rest &= ~(1u << RW_Z_TOPPLE);
    }
    if (rest) band_by_evaluation(sc, a, rest, band);
}

/* The collapse indicator under the band. Near q = 0 the band turns the direction of q and so
 * moves the scale-free indicator by much, but there it cannot vanish at all on a region whose
 * form G = q.A q - c.q has a positive definite symmetric part (least eigenvalue lam_min > 0):
 * G >= lam_min |q|^2 - |c| |q| > 0 for |q| > |c|/lam_min (collapse_radius, 0 when c is zero to
 * rounding, as in an elastic range). So the wall stands over the substep when the full motion
 * stays beyond that radius: each rotation's slow range, widened by the band, bounds |q| below. */
static int collapse_cannot_vanish(const rw_span_ctx *sc, const rw_point *a, const rw_point *b, double L)
{
    const rw_engine *e = sc->e;
    double q_min = 0.0, lo, hi;
    int j;
    if (!sc->sp.aq.valid || !e->b[RW_Z_COLLAPSE] || !(e->collapse_radius < INFINITY)) return 0;
    if (e->collapse_radius == 0.0) return 1;
    for (j = 0; j < 2; j++) {
        hermite_range(a->x[j], a->x[2 + j], b->x[j], b->x[2 + j], L, &lo, &hi);
        q_min = rw_max2(q_min, rw_max2(lo - fabs(sc->r.dq_fast[j]), -hi - fabs(sc->r.dq_fast[j])));
    }
    return q_min > e->collapse_radius;
}

#define RW_PEAKS_SUSPECT (1u << RW_NZ) /* substep_suspects: a new peak is possible under a band that matters */

/* The indicators (a bit each) that the band test does not clear over the substep [0, L] of the
 * span, and RW_PEAKS_SUSPECT when a new peak is possible under a band that is not negligible: 0
 * when the substep is quiet. Then *peaks_full says whether a new peak is possible there: the band
 * is then negligible (below 1e-9 of the peak) and the peaks are taken on the full motion at the
 * substep's resolution. ends: the slow part's ends; x_end: the full state at the end. */
static unsigned substep_suspects(const rw_span_ctx *sc, double L, const double (*C)[4], int *peaks_full,
                                 rw_slow_ends *ends, double x_end[RW_NX])
{
    const rw_engine *e = sc->e;
    const rw_span *sp = &sc->sp;
    const unsigned collapse = 1u << RW_Z_COLLAPSE;
    const rw_point *a = &ends->a, *b = &ends->b;
    double band[RW_NZ], lo, hi;
    unsigned suspects;
    int k, w, stands;
    *peaks_full = 0;
    if (e->slow_carry_valid && e->slow_carry_t == sp->t0 && memcmp(e->slow_carry_x0, sp->x0, sizeof sp->x0) == 0) {
        ends->a = e->slow_carry; /* the slow end of the quiet substep before (equal to rounding) */
        memcpy(ends->ddq_a, e->slow_carry_ddq, sizeof ends->ddq_a);
    } else {
        eval_slow_point(sc, 0.0, NULL, &ends->a, ends->ddq_a, NULL);
    }
    eval_slow_point(sc, L, C, &ends->b, ends->ddq_b, x_end);
    band_of(sc, a, band);
    stands = collapse_cannot_vanish(sc, a, b, L);
    if (stands) band[RW_Z_COLLAPSE] = 0.0;
    else band_by_evaluation(sc, a, collapse, band);
    /* the quick test, then the exact range of the slow part's interpolant for what it leaves */
    suspects = clearance_suspects(e, a->z, a->dz, b->z, b->dz, band, L) & ~(stands ? collapse : 0u);
    for (k = 0; suspects >> k; k++) {
        if (!((suspects >> k) & 1u)) continue;
        hermite_range(a->z[k], a->dz[k], b->z[k], b->dz[k], L, &lo, &hi);
        if (indicator_clear(e->b[k], lo, hi, band[k])) suspects &= ~(1u << k);
    }
    for (w = 0; w < 2; w++) {
        double reach, slow_max;
        if (!rwe_peak_possible(sc, w, a->x, b->x, L, &reach, &slow_max)) continue;
        if (reach > 1e-9 * slow_max) suspects |= RW_PEAKS_SUSPECT;
        else *peaks_full = 1;
    }
    return suspects;
}

/* ---- one crossing through the band ----------------------------------------------------------
 * Near an event the band test fails for the indicator that crosses, and resolving the substep at
 * the fast rate costs many full steps. An indicator that is a line of the rotations, z = c +
 * s|w| + t w with w = a.q, is monotone on the full motion where its slow rate outruns the fastest
 * the band can move it: |a.dq_slow| > w_fast |a.dq_fast| over the whole substep (the slow rate's
 * range from its cubic Hermite interpolant, with that interpolant's margin), with a breakpoint
 * (s != 0) kept on one side of its kink w = 0 (the slow w's range clear of the band). Then it
 * crosses at most once, and the full motion's values at the ends decide: no crossing, or one.
 * Returns -1 (undecided: the caller resolves at the fast rate), 0 (no crossing) or 1 (a crossing,
 * with the line's full values at the ends, z[0] and z[1], and *guess: the slow part's crossing,
 * within the band's width over the slow rate of the full one; NaN when the slow part does not
 * cross). */
static int line_crossing(const rw_span_ctx *sc, int k, double L, const rw_slow_ends *ends, const double x_end[RW_NX],
                         double z[2], double *guess)
{
    const rw_engine *e = sc->e;
    const rw_rates *r = &sc->r;
    const rw_indicator_line *line = &e->lines[k];
    const double a0 = line->a[0], a1 = line->a[1];
    const double w_band = fabs(a0 * r->dq_fast[0] + a1 * r->dq_fast[1]);
    const double *xa = ends->a.x, *xb = ends->b.x;
    const double za = ends->a.z[k], zb = ends->b.z[k];
    double lo, hi, slope;
    if (!((e->line_mask >> k) & 1u)) return -1;
    slope = line->t;
    if (line->s != 0.0) { /* a breakpoint: one side of w = 0 throughout */
        hermite_range(a0 * xa[0] + a1 * xa[1], a0 * xa[2] + a1 * xa[3], a0 * xb[0] + a1 * xb[1], a0 * xb[2] + a1 * xb[3],
                      L, &lo, &hi);
        if (!(lo > w_band || hi < -w_band)) return -1;
        slope += lo > w_band ? line->s : -line->s;
    }
    if (slope == 0.0) return -1;
    hermite_range(a0 * xa[2] + a1 * xa[3], a0 * ends->ddq_a[0] + a1 * ends->ddq_a[1], a0 * xb[2] + a1 * xb[3],
                  a0 * ends->ddq_b[0] + a1 * ends->ddq_b[1], L, &lo, &hi);
    if (!(lo > r->fast_rate * w_band || hi < -r->fast_rate * w_band)) return -1; /* not monotone */
    z[0] = rw_line_value(line, sc->sp.x0, NULL, NULL);
    if ((z[0] > 0.0) != e->b[k]) return -1; /* the start is not on the tracked side: let the fast rate decide */
    z[1] = rw_line_value(line, x_end, NULL, NULL);
    if ((z[1] > 0.0) == e->b[k]) return 0;
    *guess = (za > 0.0) != (zb > 0.0) ? L * hermite_root(za, ends->a.dz[k], zb, ends->b.dz[k], L) : NAN;
    return 1;
}

/* The suspects of a substep settled by line_crossing when every one is a line: 1 with the first
 * crossing (*ev) or 0 with none, or -1 if one is undecided. The crossings are refined the earliest
 * guess first; a later line is monotone over the substep, so one still on its tracked side at the
 * first root crosses after it and needs no refinement. */
static int crossings_through_band(const rw_span_ctx *sc, unsigned suspects, double L, const rw_slow_ends *ends,
                                  const double x_end[RW_NX], rw_root *ev)
{
    const rw_engine *e = sc->e;
    int order[RW_NZ], n = 0, i, found = 0;
    double guess[RW_NZ], z_ends[RW_NZ][2];
    if (suspects & ~e->line_mask) return -1; /* a new peak, the collapse or the toppling indicator */
    for (i = 0; suspects >> i; i++) {
        int rc;
        if (!((suspects >> i) & 1u)) continue;
        rc = line_crossing(sc, i, L, ends, x_end, z_ends[i], &guess[i]);
        if (rc < 0) return -1;
        if (rc == 1) n = insert_by_guess(order, n, guess, i);
    }
    for (i = 0; i < n; i++) {
        const int k = order[i];
        const rw_indicator_line *line = &e->lines[k];
        const rw_bracket br = {0.0, z_ends[k][0], L, z_ends[k][1]};
        double s_k, x_k[RW_NX];
        int valid;
        if (found && (rw_line_value(line, ev->x, NULL, NULL) > 0.0) == e->b[k]) continue; /* crosses later */
        s_k = rwe_refine_root(sc, k, e->b[k], &br, guess[k], x_k, &valid);
        if (!valid) span_eval(&sc->sp, s_k, NULL, x_k, NULL);
        if (!found || s_k < ev->s) {
            found = 1;
            ev->s = s_k;
            ev->k = k;
            memcpy(ev->x, x_k, sizeof x_k);
        }
    }
    return found;
}

/* The substep [0, L] of the span taken whole (quiet, or quiet but for indicators without a
 * crossing): the motion's x, *t at its end x_end, the slow end point carried to the next substep. */
static void accept_substep(rw_span_ctx *sc, double L, const double x_end[RW_NX], int peaks_full,
                           const rw_slow_ends *ends, double t_to)
{
    rw_engine *e = sc->e;
    double *x = sc->x;
    e->steps++;
    if (peaks_full) rwe_peaks_on(sc, x, 0.0, x_end, L);
    memcpy(x, x_end, sizeof(double) * RW_NX);
    rwe_outputs_on(sc, L);
    *sc->t = t_to;
    e->slow_carry = ends->b;
    e->slow_carry.s = 0.0; /* the next substep starts here */
    memcpy(e->slow_carry_ddq, ends->ddq_b, sizeof e->slow_carry_ddq);
    e->slow_carry_t = t_to;
    memcpy(e->slow_carry_x0, x, sizeof e->slow_carry_x0);
    e->slow_carry_valid = 1;
}

/* A substep of a span with fast modes, from the span's start to t_to: accepted when quiet or when
 * its suspects are lines that cross at most once (crossings_through_band), else halved until its
 * halves are or are short enough (8 pieces at the fast rate) to be resolved in full, so that only
 * the neighbourhood of an event that the band cannot settle, or of a new peak, is resolved at the
 * fast rate. Returns as rwe_resolve(). */
int rwe_fast_substep(rw_span_ctx *sc, double t_to, const double (*C)[4], int depth)
{
    rw_engine *e = sc->e;
    const rw_span *sp = &sc->sp;
    double *x = sc->x;
    const double L = t_to - sp->t0;
    int peaks_full, nf, rc;
    double len = L, x_end[RW_NX];
    rw_root ev; /* set by crossings_through_band when it finds one */
    rw_slow_ends ends;
    const unsigned suspects = substep_suspects(sc, L, C, &peaks_full, &ends, x_end);
    if (suspects == 0) {
        accept_substep(sc, L, x_end, peaks_full, &ends, t_to);
        return 0;
    }
    e->slow_carry_valid = 0;
    ev.s = 0.0;
    ev.k = 0;
    rc = suspects & ~RW_PEAKS_SUSPECT ? crossings_through_band(sc, suspects & ~RW_PEAKS_SUSPECT, L, &ends, x_end, &ev)
                                      : 0;
    if (rc == 0) {
        if (suspects & RW_PEAKS_SUSPECT) rwe_peaks_under_band(sc, 0.0, ends.a.x, L, ends.b.x, 0);
        accept_substep(sc, L, x_end, peaks_full, &ends, t_to);
        return 0;
    }
    if (rc == 1) { /* the event, as rwe_resolve() applies it */
        const rw_input ie = span_input(sp, ev.s);
        e->steps++;
        if (suspects & RW_PEAKS_SUSPECT) {
            double x_slow[RW_NX];
            span_eval_part(sp, ev.s, NULL, sc->r.fast, x_slow, NULL);
            rwe_peaks_under_band(sc, 0.0, ends.a.x, ev.s, x_slow, 0);
        }
        if (peaks_full) rwe_peaks_on(sc, x, 0.0, ev.x, ev.s);
        rwe_outputs_on(sc, ev.s);
        memcpy(x, ev.x, sizeof ev.x);
        *sc->t = sp->t0 + ev.s;
        rc = rwe_apply_event(e, sc->m, x, *sc->t, &ie);
        if (rc == 0 && rwe_hinge_event_keeps_region(e, sp, ev.k, x)) e->region_keep = 1;
        return rc ? rc : -1;
    }
    nf = rwe_substeps_for(sc->r.fast_rate, &len);
    if (nf <= 8 || depth >= 40) return rwe_resolve(sc, L, len < L ? (int)RW_MAX_SUBSTEPS : nf, NULL);
    rc = rwe_fast_substep(sc, sp->t0 + 0.5 * L, NULL, depth + 1);
    if (rc) return rc;
    restart_span(sc, *sc->t, x);
    return rwe_fast_substep(sc, t_to, NULL, depth + 1);
}
