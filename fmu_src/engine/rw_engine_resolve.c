/* A span resolved in full: its pieces and their events, the earliest first.
 * After an event that keeps the region the piece goes on in it. */
#include "rw_engine_hermite.h"
#include "rw_engine_span.h"

#include <float.h>
#include <math.h>
#include <string.h>

/* The start point of a span: the end point of the span before, where that holds (carried_start),
 * else evaluated into *buf */
static const rw_point *start_point(const rw_span_ctx *sc, rw_point *buf)
{
    const rw_engine *e = sc->e;
    if (e->carry_valid && e->region_valid && e->carry_t == sc->sp.t0 &&
        memcmp(e->carry.x, sc->sp.x0, sizeof e->carry.x) == 0)
        return carried_start(sc, buf);
    eval_point(sc, 0.0, NULL, buf);
    return buf;
}

/* What goes on after an event that keeps the region (rwe_hinge_event_keeps_region: a hinge's change of
 * side under semiRigidHinge or dohertyHinge), without going back to rwe_advance(): the lines and the
 * indicator states change, and
 * - if the event left the state as it was (a mid-height hinge's change of side), the motion goes
 *   on as it was: the span continues, and pb's values are taken again with the new lines;
 * - if it changed the rates (a base impact) and the span is the segment's only piece
 *   (`restart`), a new span of the same region starts at the event and pb is evaluated again at
 *   the segment's end t_end.
 * *at_event: the point at the event (the motion's state sc->x) with the new lines (its states are
 * the tracked ones, as a new span's start point would give them). The indicators other than lines
 * (toppling, the collapse form) need the rotations' rates alone there, not a propagation. Returns 0
 * where this does not apply (then the caller goes back to rwe_advance()). */
typedef struct {
    double t_end;
    int restart;
} rw_piece;

static int go_on_after_event(rw_span_ctx *sc, const rw_piece *pc, int state_kept, double s_ev, rw_point *at_event,
                             rw_point *pb)
{
    const unsigned from_rotations = (1u << RW_Z_TOPPLE) | (1u << RW_Z_COLLAPSE);
    rw_engine *e = sc->e;
    const double *x = sc->x;
    if (!state_kept && !pc->restart) return 0;
    rwe_region_lines(e, sc->m);
    if (e->P.support != RW_FLEXIBLE_TOP || !rwe_q_fixes_region(e, &sc->sp) ||
        (RW_Z_ALL & ~e->line_mask & ~from_rotations))
        return 0;
    e->region_valid = 1; /* rwe_apply_event let it go: the same region, with its new lines */
    if (state_kept) {
        point_from_state(sc, x, s_ev, RW_Z_ALL, at_event);
        point_from_state(sc, pb->x, pb->s, RW_Z_ALL, pb);
    } else {
        restart_span(sc, sc->sp.t0 + s_ev, x);
        point_from_state(sc, x, 0.0, RW_Z_ALL, at_event);
        eval_point(sc, pc->t_end - sc->sp.t0, NULL, pb);
    }
    rwe_track_states(e, at_event->z);
    e->b_stale = 0;
    e->steps++;
    return 1;
}

/* The events of the piece [*pa, pb] of the span (suspects: suspects_of), earliest first: each is
 * applied (the motion's x, *t at it); one after which go_on_after_event applies goes on in this
 * piece (*pa becomes *event_point, the point after it). Returns 0 when the piece has no more events
 * (its rest is quiet), -1 when an event ends the span (the caller starts a new one), or a collapse /
 * error code (rwe_apply_event). */
static int events_in_piece(rw_span_ctx *sc, const rw_piece *pc, const rw_point **pa, rw_point *pb, unsigned suspects,
                           rw_point *event_point)
{
    rw_engine *e = sc->e;
    double *x = sc->x;
    rw_root ev;
    while (suspects && rwe_first_event(sc, *pa, pb, suspects, &ev)) {
        const double s_ev = ev.s;
        const rw_input ie = span_input(&sc->sp, s_ev);
        double x_before[RW_NX];
        int rc, kept;
        memcpy(x, ev.x, sizeof ev.x);
        rwe_peaks_on(sc, (*pa)->x, (*pa)->s, x, s_ev);
        rwe_outputs_on(sc, s_ev);
        *sc->t = sc->sp.t0 + s_ev;
        memcpy(x_before, x, sizeof x_before);
        rc = rwe_apply_event(e, sc->m, x, *sc->t, &ie);
        if (rc) return rc;
        if (!rwe_hinge_event_keeps_region(e, &sc->sp, ev.k, x)) return -1;
        kept = memcmp(x_before, x, sizeof x_before) == 0;
        if (!go_on_after_event(sc, pc, kept, s_ev, event_point, pb)) {
            e->region_keep = 1;
            return -1;
        }
        *pa = event_point;
        suspects = suspects_of(e, event_point->z, event_point->dz, pb->z, pb->dz, pb->s - event_point->s);
    }
    return 0;
}

/* Full resolution over [0, len] of the span (which starts at the motion's x, *t) in n pieces:
 * events, peaks, outputs. Returns 0 (len reached: x, *t at its end), -1 (an event was applied at
 * *t: the caller starts a new region), or a collapse / error code (rwe_apply_event). C: Stumpff
 * coefficients of pieces of length len/n (NULL: computed). */
int rwe_resolve(rw_span_ctx *sc, double len, int n, const double (*C)[4])
{
    rw_engine *e = sc->e;
    const rw_span *sp = &sc->sp;
    const double h = len / n, t_end = sp->t0 + len;
    rw_point buf[2], event_point;
    const rw_point *pa = start_point(sc, &buf[0]);
    int j;
    for (j = 0; j < n; j++) {
        const double piece = j == n - 1 ? t_end - sp->t0 : h;
        /* the last piece differs from h by rounding of t_end - t0 at most: the same coefficients */
        const int same = fabs(piece - h) <= 4.0 * DBL_EPSILON * (fabs(t_end) + h);
        rw_point *pb = pa == &buf[0] ? &buf[1] : &buf[0];
        unsigned suspects;
        if (j == 0 && n == 1 && e->pending_valid && e->pending_t0 == sp->t0 && e->pending.s == piece) {
            pb = &e->pending; /* rwe_quiet_segment evaluated it: the same span, coefficients and start */
            suspects = e->pending_suspects;
        } else {
            eval_point(sc, piece, same ? C : NULL, pb);
            suspects = suspects_of(e, pa->z, pa->dz, pb->z, pb->dz, pb->s - pa->s);
        }
        e->pending_valid = 0;
        e->steps++;
        if (suspects) {
            const rw_piece pc = {t_end, n == 1};
            const int rc = events_in_piece(sc, &pc, &pa, pb, suspects, &event_point);
            if (rc) return rc;
        }
        rwe_peaks_on(sc, pa->x, pa->s, pb->x, pb->s);
        rwe_outputs_on(sc, pb->s);
        memcpy(sc->x, pb->x, sizeof pb->x);
        if (j == n - 1) {
            *sc->t = t_end;
            carry_point(e, pb, t_end);
        } else { /* the next piece starts here */
            restart_span(sc, sp->t0 + h, pb->x);
            *sc->t = sp->t0;
            pb->s = 0.0;
            pa = pb;
        }
    }
    return 0;
}
