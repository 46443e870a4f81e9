/* Co-Simulation of RockingWall through the exact engine (rw_engine.h): fmu_model.exact_step.
 *
 * Inputs held or ramped over a communication step are exactly linear, and every support / hinge
 * law but the parapet is piecewise linear, so the step is exact: it does not depend on the
 * tolerance the master passes (cs_cvode.c's CVODE does). The parapet's nonlinear Housner block
 * returns FMU_NOT_EXACT and stays on CVODE. The engine applies the model's own event update
 * (rw_event_update) and collapse test, so the FMU's outputs (impacts, collapsed, condition,
 * dissipated) are the ones the CVODE path gives. One difference: CVODE runs RW_TERMINATE_DELAY
 * past a collapse before terminating; here the step ends at the collapse itself. */
#include <stdio.h>

#include "rw_model_data.h"
#include "model_variables.h"

static double slope_of(unsigned vr, const unsigned *slope_vr, const double *slope, size_t n_in)
{
    size_t i;
    for (i = 0; i < n_in; i++)
        if (slope_vr[i] == vr) return slope[i];
    return 0.0;
}

static void log_collapse(rw_data *S, int reason)
{
    char buf[512];
    if (!S->log || !S->log->warning) return;
    snprintf(buf, sizeof buf,
             "collapse at t = %.9g s: s1 = %.6g m, s2 = %.6g m (q1 = %.6g, q2 = %.6g rad): %s; terminating the simulation",
             S->time, rw_s1(&S->P, S->x), rw_s2(&S->P, S->x), S->x[0], S->x[1],
             reason == RW_PAST_INSTABILITY ? "the wall passed its instability point"
                                                     : "a body turned past its toppling limit 2b/h");
    S->log->warning(S->log->ctx, buf);
}

int rw_exact_step(void *M, double t, double h, const unsigned *slope_vr, const double *slope, size_t n_in,
                  const fmu_logger *log, double *t_reached, char *msg, size_t n)
{
    rw_data *S = (rw_data *)M;
    rw_engine *engine = rw_engine_of(S);
    rw_linear_input in;
    rw_engine_step_report step;
    int rc;
    if (S->engine_state == 0) {
        S->engine_state = rw_engine_init(engine, &S->P, msg, n) ? -1 : 1;
        if (S->engine_state > 0) rw_engine_track_dissipated(engine); /* the FMU's dissipated output */
    }
    if (S->engine_state < 0) return FMU_NOT_EXACT;
    *t_reached = t;
    S->log = log;
    if (S->collapsed) return 1; /* collapsed already at the start (initial event iteration) */
    in.ag = S->in.ag;
    in.u_top = S->in.u_top;
    in.ag_slope = slope_of(RW_VR_ag, slope_vr, slope, n_in);
    in.u_slope = slope_of(RW_VR_u_top, slope_vr, slope, n_in);
    rc = rw_engine_step(engine, &S->regime, S->x, t, h, &in, &step);
    *t_reached = step.t_reached;
    S->impacts += (int)step.impacts;
    S->dissipated += step.dissipated;
    S->time = *t_reached;
    /* the inputs where the step ended, as the CVODE path leaves them */
    S->in.ag = in.ag + in.ag_slope * (*t_reached - t);
    S->in.u_top = in.u_top + in.u_slope * (*t_reached - t);
    if (rc == 1) {
        S->collapsed = 1;
        log_collapse(S, step.collapse_reason);
        return 1;
    }
    if (rc > 1) snprintf(msg, n, "%s", step.message);
    return rc > 1 ? -1 : 0;
}
