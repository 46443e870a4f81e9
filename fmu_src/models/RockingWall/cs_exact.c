/* Co-Simulation of RockingWall through the exact engine (rw_engine.h): fmu_model.exact_step.
 *
 * Inputs held or ramped over a communication step are exactly linear, and every support / hinge
 * law but the parapet is piecewise linear, so the step is exact: it does not depend on the
 * tolerance the master passes (cs_cvode.c's CVODE does). The FMU's parapet is Housner's nonlinear
 * block (the engine solves its small-rotation form only): it returns FMU_NOT_EXACT and stays on
 * CVODE. The engine applies the model's own event update
 * (rw_event_update) and collapse test, so the FMU's outputs (impacts, collapsed, condition,
 * dissipated) are the ones the CVODE path gives. One difference: CVODE runs RW_TERMINATE_DELAY
 * past a collapse before terminating; here the step ends at the collapse itself. */
#include <stdio.h>
#include <string.h>

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

/* A long step goes in pieces of RW_PIECE: after each, a wall at rest under held inputs (no
 * motion, no acceleration) stays so for the rest of the step, which is skipped (1e7 s at rest took
 * 8.5 s of CPU when the engine walked it). A wall that keeps moving may take at most
 * RW_MAX_MOVING_PIECES pieces in one step, so that every call returns in bounded time. */
#define RW_PIECE 1.0                /* s */
#define RW_MAX_MOVING_PIECES 10000L /* 1e4 s of motion in one step */

static int at_rest(const rw_data *S, const rw_linear_input *in)
{
    rw_input now;
    double dx[RW_NX];
    if (in->ag_slope != 0.0 || in->u_slope != 0.0) return 0;
    now.ag = in->ag;
    now.u_top = in->u_top;
    rw_derivatives(&S->P, &S->D, &S->regime, &now, S->x, dx);
    return dx[0] == 0.0 && dx[1] == 0.0 && dx[2] == 0.0 && dx[3] == 0.0;
}

/* add one piece's report to the step's */
static void add_report(rw_engine_step_report *total, const rw_engine_step_report *part)
{
    total->impacts += part->impacts;
    total->dissipated += part->dissipated;
    total->t_reached = part->t_reached;
    total->collapse_reason = part->collapse_reason;
    memcpy(total->message, part->message, sizeof total->message);
}

/* rw_engine_step over a step of any length, its report summed over the pieces (a step of at most
 * RW_PIECE is one call, as before) */
static int step_in_pieces(rw_data *S, rw_engine *engine, const rw_linear_input *in, double t, double h,
                          rw_engine_step_report *total)
{
    double done = 0.0;
    long pieces = 0;
    memset(total, 0, sizeof *total);
    for (;;) {
        const double len = h - done > RW_PIECE ? RW_PIECE : h - done;
        rw_linear_input piece = *in;
        rw_engine_step_report step;
        int rc;
        piece.ag += in->ag_slope * done;
        piece.u_top += in->u_slope * done;
        rc = rw_engine_step(engine, &S->regime, S->x, t + done, len, &piece, &step);
        add_report(total, &step);
        done += len;
        if (rc != 0 || done >= h) return rc;
        if (at_rest(S, in)) {
            total->t_reached = t + h;
            return 0;
        }
        if (++pieces >= RW_MAX_MOVING_PIECES) {
            snprintf(total->message, sizeof total->message, "the wall kept moving over %g s of this step of %g s: a "
                     "step may hold at most %g s of motion; take shorter steps", done, h, RW_MAX_MOVING_PIECES * RW_PIECE);
            return 2;
        }
    }
}

/* With a record the FMU read (agFile) the ground acceleration is the record, linear between its
 * samples, plus the master's input: the step goes from sample to sample, each piece exactly linear,
 * so the answer is the record's whatever the communication step. */
static int step_over_record(rw_data *S, rw_engine *engine, const rw_linear_input *in, double t, double h,
                            rw_engine_step_report *total)
{
    double at = t;
    memset(total, 0, sizeof *total);
    total->t_reached = t;
    for (;;) {
        rw_engine_step_report part;
        rw_linear_input piece = *in;
        double slope, t_next;
        const double a = rw_gm_at(S->record, at, &slope, &t_next), end = t_next < t + h ? t_next : t + h;
        int rc;
        piece.ag += in->ag_slope * (at - t) + a;
        piece.ag_slope += slope;
        piece.u_top += in->u_slope * (at - t);
        rc = step_in_pieces(S, engine, &piece, at, end - at, &part);
        add_report(total, &part);
        if (rc != 0 || end >= t + h) return rc;
        at = end;
    }
}

/* Without agFile the FMU sees only the master's ag: warn once when the master holds a changing ag
 * (no derivative) over a step longer than RW_HELD_AG_STEP, for a record held so is step-wise */
static void warn_held_ag(rw_data *S, double t, double h, double ag_slope, const fmu_logger *log)
{
    char buf[512];
    const int changed = S->stepped && S->ag_input != S->ag_step_end;
    S->stepped = 1;
    if (S->record || S->held_ag_warned || ag_slope != 0.0 || !changed || !(h > RW_HELD_AG_STEP * (1 + 1e-9))) return;
    S->held_ag_warned = 1;
    if (!log || !log->warning) return;
    snprintf(buf, sizeof buf, "the input ag is held over a communication step of %g s (from t = %.9g s) and changes "
             "between steps: a ground-motion record held over steps longer than %g s loses its peaks. Give the record "
             "as agFile (the FMU then follows it exactly), or take steps no longer than its sample interval "
             "(fmpy: output_interval)", h, t, RW_HELD_AG_STEP);
    log->warning(log->ctx, buf);
}

int rw_exact_step(void *M, double t, double h, const unsigned *slope_vr, const double *slope, size_t n_in,
                  const fmu_logger *log, double *t_reached, char *msg, size_t n)
{
    rw_data *S = (rw_data *)M;
    rw_engine *engine = rw_engine_of(S);
    rw_linear_input in;
    rw_engine_step_report step;
    double rec_slope, rec_next;
    int rc;
    if (S->P.support == RW_PARAPET) {
        snprintf(msg, n, "the parapet (support = 1, Housner's nonlinear block) is not covered by the exact engine: use CVODE");
        return FMU_NOT_EXACT;
    }
    if (S->engine_state == 0) {
        S->engine_state = rw_engine_init(engine, &S->P, msg, n) ? -1 : 1;
        if (S->engine_state > 0) rw_engine_track_dissipated(engine); /* the FMU's dissipated output */
        if (S->engine_state > 0) S->regime.tie_held = 0; /* the engine solves the tie's mode exactly, at no cost */
    }
    warn_held_ag(S, t, h, slope_of(RW_VR_ag, slope_vr, slope, n_in), log);
    S->ag_step_end = S->ag_input + slope_of(RW_VR_ag, slope_vr, slope, n_in) * h; /* as the CVODE path leaves it */
    if (S->engine_state < 0) return FMU_NOT_EXACT;
    *t_reached = t;
    S->log = log;
    if (S->collapsed) return 1; /* collapsed already at the start (initial event iteration) */
    in.ag = S->ag_input;
    in.u_top = S->in.u_top;
    in.ag_slope = slope_of(RW_VR_ag, slope_vr, slope, n_in);
    in.u_slope = slope_of(RW_VR_u_top, slope_vr, slope, n_in);
    rc = S->record ? step_over_record(S, engine, &in, t, h, &step) : step_in_pieces(S, engine, &in, t, h, &step);
    *t_reached = step.t_reached;
    S->impacts += (int)step.impacts;
    S->dissipated += step.dissipated;
    S->time = *t_reached;
    /* the inputs where the step ended, as the CVODE path leaves them */
    S->ag_input = in.ag + in.ag_slope * (*t_reached - t);
    S->in.ag = S->ag_input + (S->record ? rw_gm_at(S->record, S->time, &rec_slope, &rec_next) : 0.0);
    S->in.u_top = in.u_top + in.u_slope * (*t_reached - t);
    if (rc == 1) {
        S->collapsed = 1;
        log_collapse(S, step.collapse_reason);
        return 1;
    }
    if (rc > 1) snprintf(msg, n, "%s", step.message);
    return rc > 1 ? -1 : 0;
}
