/* An event applied: the model's event iteration and collapse test, the tracked indicator states.
 * Also whether the region stays after a hinge event. */
#include "rw_engine_internal.h"

#include <math.h>
#include <stdio.h>

#define RW_MAX_EVENT_ROUNDS 100 /* event-iteration rounds at one event, as cs_cvode.c allows 1000 */

/* the tracked indicator states (z > 0), and the same as +-1 for the quick test (clearance_suspects) */
void rwe_track_states(rw_engine *e, const double z[RW_NZ])
{
    int k;
    for (k = 0; k < RW_NZ; k++) {
        e->b[k] = z[k] > 0.0;
        e->b_sign[k] = e->b[k] ? 1.0 : -1.0;
    }
}

/* the tracked indicator states at the state x, from the model's own indicators */
void rwe_set_indicator_states(rw_engine *e, const rw_regime *m, const rw_input *in, const double x[RW_NX])
{
    double z[RW_NZ];
    rw_event_indicators(&e->P, &e->D, m, in, x, z);
    rwe_track_states(e, z);
}

/* The model's event iteration at t (as the FMU's hosts run it), then its collapse test.
 * Returns 0, 1 on collapse, or an error code + 1 (Zeno). */
int rwe_apply_event(rw_engine *e, rw_regime *m, double x[RW_NX], double t, const rw_input *in)
{
    rw_event_result r;
    int rounds = 0;
    e->events++;
    if (t <= e->t_last_event + 1e-14 * rw_max2(1.0, fabs(t))) {
        if (++e->same_instant > e->max_same_instant) {
            snprintf(e->msg, sizeof e->msg, "more than %d events at t = %.17g (Zeno): stopped", e->max_same_instant, t);
            return RW_ENGINE_ZENO + 1;
        }
    } else {
        e->same_instant = 0;
    }
    e->t_last_event = t;
    e->region_valid = e->carry_valid = e->slow_carry_valid = e->pending_valid = 0;
    do {
        /* the energy only for those who read it: the FMU's dissipated output and the impact log */
        const int energy_wanted = e->track_dissipated || e->impact_t;
        const double energy = energy_wanted ? rw_energy(&e->P, &e->D, m, in, x) : 0.0;
        rw_event_update(&e->P, &e->D, m, in, x, &r, NULL, NULL);
        if (r.states_changed && e->track_dissipated) e->dissipated += energy - rw_energy(&e->P, &e->D, m, in, x);
        if (r.impacts && e->impact_t && (size_t)e->impacts < e->impact_cap) {
            e->impact_t[e->impacts] = t;
            e->impact_energy[e->impacts] = energy;
        }
        e->impacts += r.impacts;
    } while ((r.regime_changed || r.states_changed) && ++rounds < RW_MAX_EVENT_ROUNDS);
    e->b_stale = 1; /* the indicator states at x: from the start point of the next span (rwe_advance) */
    e->reason = rw_collapse_reason(&e->P, &e->D, m, in, x);
    if (e->reason != RW_STANDING) {
        e->collapsed = 1;
        e->t_collapse = t;
        return 1;
    }
    return 0;
}

/* After an event of the base or mid-height hinge indicator under a law whose hinge moments depend
 * on q alone (rwe_q_fixes_region), the region is the same: the event maps change rates and
 * the regime, never q, and such a law's region is fixed by q, except on a breakpoint itself, where the
 * direction of motion picks it (then it is found again). Only the lines (sides, offsets) change. */
int rwe_hinge_event_keeps_region(const rw_engine *e, const rw_span *sp, int k_event, const double x[RW_NX])
{
    int k;
    if (!rwe_q_fixes_region(e, sp) || (k_event != RW_Z_BASE && k_event != RW_Z_MID)) return 0;
    for (k = RW_Z_BREAK; k < RW_Z_BREAK + RW_NBREAK; k++)
        if (fabs(rw_line_value(&e->lines[k], x, NULL, NULL)) < 1e-9 * e->D.q_topple) return 0;
    return 1;
}
