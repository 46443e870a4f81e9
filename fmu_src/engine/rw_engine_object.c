/* The engine object: its set-up, the stepper, the batch run's start and end.
 * And one region's motion on its own, for tests of the closed form. */
#include "rw_engine_span.h"

#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* rw_engine_init's memory need be aligned for a double only (rw_engine.h) */
struct rw_align_engine {
    char c;
    rw_engine e;
};

struct rw_align_double {
    char c;
    double d;
};

typedef char rw_check_engine_alignment[offsetof(struct rw_align_engine, e) <= offsetof(struct rw_align_double, d)
                                           ? 1
                                           : -1];

size_t rw_engine_size(void)
{
    return sizeof(rw_engine);
}

/* The slowest rate substeps follow (rw_engine.floor_rate): the counted rate turns by at most
 * RW_PHASE_PER_SUBSTEP per substep (rwe_substeps_for), and none is longer than a quarter radian of
 * the wall's own rocking rate p = sqrt(3g/4R) (Housner), which bounds the polynomial motion of
 * zero-stiffness regions (a plateau, a closed hinge). */
static double rocking_rate(const rw_engine *e)
{
    return sqrt(e->D.p2) * RW_PHASE_PER_SUBSTEP / 0.25;
}

/* The parapet is solved in Housner's small-rotation form (rw_engine_regions.c): a block stockier
 * than h/b = 1/RW_ENGINE_PARAPET_MAX_B_OVER_H, where that form's peaks depart from the nonlinear
 * block's by more than 1 % (docs/engine.md "The parapet"), is refused and stays on CVODE. */
int rwe_parapet_beyond_small_rotation(const rw_params *p, char *msg, size_t n)
{
    if (p->support != RW_PARAPET || p->b <= RW_ENGINE_PARAPET_MAX_B_OVER_H * p->h) return 0;
    snprintf(msg, n,
             "the parapet's b/h = %.4g is beyond the engine's small-rotation form (b/h <= %g, where its peaks stay "
             "within 1 %% of Housner's nonlinear block): use CVODE (fmi2sim)",
             p->b / p->h, RW_ENGINE_PARAPET_MAX_B_OVER_H);
    return 1;
}

int rw_engine_init(rw_engine *e, const rw_params *p, char *msg, size_t n)
{
    if (!e || !p) {
        snprintf(msg, n, "rw_engine_init: engine and parameters must not be NULL");
        return 1;
    }
    if (rw_params_validate(p, msg, n)) return 1;
    if (rwe_parapet_beyond_small_rotation(p, msg, n)) return 1;
    memset(e, 0, sizeof *e);
    e->P = *p;
    rw_derive(p, &e->D);
    e->law = rw_hinge_law_of(p->hingeLaw);
    e->rigid = rw_is_rigid(p);
    e->mid_is_bookkeeping = rw_mid_switch_is_bookkeeping(p);
    e->max_same_instant = 100;
    e->t_last_event = -INFINITY;
    e->floor_rate = rocking_rate(e);
    e->collapse_radius = INFINITY;
    {
        const double unit[2][RW_NX] = {{1.0, 0.0, 0.0, 0.0}, {0.0, 1.0, 0.0, 0.0}};
        int j;
        for (j = 0; j < 2; j++) {
            e->s_coef[0][j] = rw_s1(p, unit[j]);
            e->s_coef[1][j] = rw_s2(p, unit[j]);
        }
    }
    e->t_collapse = NAN;
    return 0;
}

rw_engine *rw_engine_new(const rw_params *p, char *msg, size_t n)
{
    rw_engine *e = (rw_engine *)calloc(1, sizeof *e);
    if (!e) {
        snprintf(msg, n, "out of memory");
        return NULL;
    }
    if (rw_engine_init(e, p, msg, n)) {
        free(e);
        return NULL;
    }
    return e;
}

void rw_engine_free(rw_engine *e)
{
    free(e);
}

void rw_engine_track_dissipated(rw_engine *e)
{
    e->track_dissipated = 1;
}

/* Did the inputs jump at t (a new step's values) so that an indicator changed sign? Then the
 * model's event iteration at t, as cs_cvode.c does at a communication point. */
static int input_jump(rw_engine *e, rw_regime *m, double x[RW_NX], double t, const rw_input *now)
{
    double z[RW_NZ];
    int k;
    if (!e->b_valid) {
        rwe_set_indicator_states(e, m, now, x);
        e->b_valid = 1;
        return 0;
    }
    rw_event_indicators(&e->P, &e->D, m, now, x, z);
    for (k = 0; k < RW_NZ; k++)
        if ((z[k] > 0.0) != e->b[k]) return rwe_apply_event(e, m, x, t, now);
    return 0;
}

/* ---- the stepper (rw_engine.h) ---- */
int rw_engine_step(rw_engine *e, rw_regime *m, double x[RW_NX], double t, double h, const rw_linear_input *in,
                   rw_engine_step_report *out)
{
    const long before = e->impacts;
    const double dissipated_before = e->dissipated;
    double *t_reached = &out->t_reached;
    rw_input now;
    int rc;
    out->message[0] = '\0';
    /* the engine may be a byte copy restored from a serialized FMU state (fmi2SetFMUstate), made
     * by another process: its one reference into this binary, the law, is taken again */
    e->law = rw_hinge_law_of(e->P.hingeLaw);
    /* the caller owns x and m between steps */
    e->region_valid = e->region_keep = e->carry_valid = e->slow_carry_valid = e->pending_valid = 0;
    now.ag = in->ag;
    now.u_top = in->u_top;
    *t_reached = t;
    rc = input_jump(e, m, x, t, &now);
    if (rc == 0) rc = rwe_advance(e, m, x, t_reached, t + h, in, t);
    if (rc == 0 && e->mid_is_bookkeeping) rw_sync_mid_side(&e->P, &e->D, m, x); /* the `condition` it reports */
    if (rc == 0 && e->b_stale) { /* an event at the step's end: its states, for the next input_jump */
        rw_input end;
        end.ag = in->ag + in->ag_slope * (*t_reached - t);
        end.u_top = in->u_top + in->u_slope * (*t_reached - t);
        rwe_set_indicator_states(e, m, &end, x);
        e->b_stale = 0;
    }
    out->impacts = e->impacts - before;
    out->dissipated = e->dissipated - dissipated_before;
    out->collapse_reason = e->reason;
    if (rc > 1) snprintf(out->message, sizeof out->message, "%s", e->msg);
    return rc;
}

/* ---- for the batch run (rw_engine_batch.c) ---- */
/* The start of a run at t0 from the state x (the regime from it, the hosts' initial event iteration,
 * the collapse test): 0, 1 if collapsed, or an error code + 1. */
int rwe_begin(rw_engine *e, rw_regime *m, double x[RW_NX], double t0, const rw_input *in)
{
    memset(m, 0, sizeof *m);
    rw_init_regime(&e->P, &e->D, in, x, m, NULL, NULL);
    e->t_last_event = t0;
    e->same_instant = 0;
    e->events--; /* the initial iteration is not a located event */
    if (e->n_out > 0 && e->t_out[0] <= t0) rwe_record_output(e, x);
    rwe_track_peak(e, 0, rw_s1(&e->P, x));
    rwe_track_peak(e, 1, rw_s2(&e->P, x));
    return rwe_apply_event(e, m, x, t0, in);
}

void rwe_fill_outputs(rw_engine *e)
{
    while (e->i_out < e->n_out) { /* after a collapse or a Zeno stop: no values */
        const double nan4[RW_NX] = {NAN, NAN, NAN, NAN};
        rwe_record_output(e, nan4);
    }
}

/* ---- one region on its own (rw_engine.h) ---- */
int rw_engine_region_motion(rw_engine *e, const double J[2][2], const double c[2], const rw_linear_input *in,
                            const double x0[RW_NX], double s, double x[RW_NX])
{
    rw_cache_entry R;
    rw_span sp;
    double g0[2];
    if (!e || e->P.support != RW_FLEXIBLE_TOP) return RW_ENGINE_UNSUPPORTED;
    memset(&R, 0, sizeof R);
    if (rwe_modes_open(e, J, &R.E) != 0) return RW_ENGINE_UNSUPPORTED;
    rwe_modal_force(&R.E, c, g0);
    memset(&sp, 0, sizeof sp);
    span_start(&sp, &R, g0, 0.0, x0, in, 0.0);
    span_eval(&sp, s, NULL, x, NULL);
    return 0;
}
