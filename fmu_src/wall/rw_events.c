/* RockingWall event rules, which change the contact regime (rw_regime): the initial regime, base
 * impacts (Housner restitution, paper Sec. 3.2/4), mid-hinge switches, and the rest / closed-hinge
 * states of rigid hinges (docs/model.md "Rigid hinges"). Called only in event mode; continuous-time
 * code uses the stored regime.
 *
 * Robustness: a crossing is decided from the stored side and the hinge's own event indicator
 * (see crossed()); an event reported slightly before the root acts on the crossing about to
 * happen (direction of motion), a repeated call changes nothing (the side has flipped). */
#include "rw_physics.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>

static int sgni(double v) { return (v > 0.0) - (v < 0.0); }

static void logf_(rw_log_fn log, void *ctx, const char *fmt, ...)
{
    char buf[512];
    va_list ap;
    if (!log) return;
    va_start(ap, fmt);
    vsnprintf(buf, sizeof buf, fmt, ap);
    va_end(ap);
    log(ctx, buf);
}

/* Has an open hinge's rotation z (rate dz) crossed zero against its active side? Within `tiny` of
 * zero the direction of motion decides (an event reported slightly early or late acts on the
 * crossing, a repeated call does not flip back); outside, the position decides. The event
 * indicator side*z + eps_q has its root inside the zero zone (eps_q = tiny/10). */
static int crossed(int side, double z, double dz, const rw_derived *d)
{
    if (fabs(z) <= d->tiny) return side * dz < 0.0;
    return side * z < 0.0;
}

/* Offsets of the open-hinge indicators: eps_q, or more when the rotation sits (by integration
 * noise) slightly on the far side of zero while still moving toward its active side, so that the
 * indicator is never zero at a restart (CVODE would ignore that root function). */
static double offset_for(const rw_derived *d, double v)
{
    const double eps = RW_EPS_Q(d);
    return v < 0.0 ? eps - v : eps;
}

static void set_offsets(const rw_derived *d, rw_regime *m, const double x[RW_NX])
{
    m->zoff_b = offset_for(d, m->side_b * x[0]);
    m->zoff_m = offset_for(d, m->side_m * (x[1] - x[0]));
}

static void slave(const rw_params *p, double x[RW_NX])
{
    if (p->support == RW_PARAPET) { x[1] = x[0]; x[3] = x[2]; }
    else if (p->support == RW_SIMPLY_SUPPORTED) { x[1] = -x[0]; x[3] = -x[2]; }
}

static void close_base(const rw_params *p, rw_regime *m, double x[RW_NX])
{
    m->closed_b = 1;
    x[0] = x[2] = 0.0;
    if (m->tie_held) m->closed_m = 1; /* q2 = -q1: the mid-height hinge rests with the base */
    if (p->support != RW_FLEXIBLE_TOP || m->closed_m) x[1] = x[3] = 0.0;
}

static void close_mid(rw_regime *m, double x[RW_NX])
{
    m->closed_m = 1;
    x[1] = x[0];
    x[3] = x[2];
}

/* A held tie's rigid hinges rest and open together: when the mechanism's load passes its
 * capacity (rw_rigid_tie_closed_forces), the base to that side, the mid-height hinge to the other */
static int open_held(const rw_params *p, const rw_derived *d, rw_regime *m, const rw_input *in, double cb,
                     rw_log_fn log, void *ctx)
{
    double fb, fm;
    if (!(m->closed_b && m->closed_m)) return 0;
    rw_rigid_tie_closed_forces(p, d, in, &fb, &fm);
    if (!(fabs(fb) > cb)) return 0;
    m->closed_b = m->closed_m = 0;
    m->side_b = sgni(fb);
    m->side_m = -m->side_b;
    logf_(log, ctx, "both hinges open (sides %+d, %+d; the tie held rigid, |f| = %g > %g)", m->side_b, m->side_m,
          fabs(fb), cb);
    return 1;
}

int rw_open_hinges(const rw_params *p, const rw_derived *d, rw_regime *m, const rw_input *in,
                   const double x[RW_NX], rw_log_fn log, void *ctx)
{
    int iter, opened = 0;
    double cb, cm;
    if (!rw_is_rigid(p)) return 0;
    rw_caps(p, d, &cb, &cm);
    if (m->tie_held) return open_held(p, d, m, in, cb, log, ctx);
    for (iter = 0; iter < 4; iter++) {
        double fb, fm;
        int ob, om;
        if (!m->closed_b && !m->closed_m) break;
        rw_closed_forces(p, d, m, in, x, &fb, &fm);
        ob = m->closed_b && fabs(fb) > cb;
        om = m->closed_m && fabs(fm) > cm;
        if (!ob && !om) break;
        if (ob && om) {
            /* both overloaded: base alone if the mid hinge then holds, else mid alone if the base
             * then holds, else both */
            rw_regime t = *m;
            double fb2, fm2;
            t.closed_b = 0;
            t.side_b = sgni(fb);
            rw_closed_forces(p, d, &t, in, x, &fb2, &fm2);
            if (fabs(fm2) <= cm) {
                *m = t;
                logf_(log, ctx, "base hinge opens on side %+d (|f_b| = %g > %g), mid hinge holds", t.side_b, fabs(fb), cb);
            } else {
                t = *m;
                t.closed_m = 0;
                t.side_m = sgni(fm);
                rw_closed_forces(p, d, &t, in, x, &fb2, &fm2);
                if (fabs(fb2) <= cb) {
                    *m = t;
                    logf_(log, ctx, "mid hinge opens on side %+d (|f_m| = %g > %g), base holds", t.side_m, fabs(fm), cm);
                } else {
                    m->closed_b = m->closed_m = 0;
                    m->side_b = sgni(fb);
                    m->side_m = sgni(fm);
                    logf_(log, ctx, "both hinges open (sides %+d, %+d)", m->side_b, m->side_m);
                }
            }
        } else if (ob) {
            m->closed_b = 0;
            m->side_b = sgni(fb);
            logf_(log, ctx, "base hinge opens on side %+d (|f_b| = %g > capacity %g)", m->side_b, fabs(fb), cb);
        } else {
            m->closed_m = 0;
            m->side_m = sgni(fm);
            logf_(log, ctx, "mid hinge opens on side %+d (|f_m| = %g > capacity %g)", m->side_m, fabs(fm), cm);
        }
        opened = 1;
    }
    return opened;
}

/* Semi-rigid laws: has the base passed the end of its elastic range, the law's first base
 * breakpoint (semiRigidHinge, semiRigidPaper: |q1| = theta_y; dohertyHinge and the simply supported
 * wall: the base displacement Delta_1)? The breakpoint is an event indicator, so the event at that
 * crossing sees |q1| at the breakpoint to rounding: a relative margin of 1e-6 accepts it. */
static int base_past_elastic(const rw_params *p, const rw_derived *d, const double x[RW_NX])
{
    const double D1 = d->dir[RW_SIDE(x[0])].D1, margin = 1e-6 * 2.0 * D1 / p->h; /* of the direction of q1 */
    if (p->support == RW_SIMPLY_SUPPORTED) return fabs(x[0]) - 2.0 * D1 / p->h >= -margin;
    return rw_line_value(&d->breaks[0], x, NULL, NULL) >= -margin;
}

/* Counting of base impacts: with rigid hinges every base crossing is one (the wall only moves
 * once uplifted); with a semi-rigid law the base oscillates elastically through q1 = 0 before any
 * uplift, so a crossing counts only when the base was past its elastic range since the last one. */
static void note_uplift(const rw_params *p, const rw_derived *d, int rigid, rw_regime *m, const double x[RW_NX])
{
    if (!rigid && base_past_elastic(p, d, x)) m->uplifted_b = 1;
}

void rw_init_regime(const rw_params *p, const rw_derived *d, const rw_input *in, double x[RW_NX],
                    rw_regime *m, rw_log_fn log, void *ctx)
{
    const int rigid = rw_is_rigid(p);
    int need_acc = 0;
    slave(p, x);
    m->closed_b = m->closed_m = 0;
    m->side_b = m->side_m = 1;
    m->uplifted_b = 0;
    m->tie_held = 0;
    note_uplift(p, d, rigid, m, x);
    /* base hinge: rotation q1 */
    if (x[0] != 0.0) m->side_b = sgni(x[0]);
    else if (x[2] != 0.0) m->side_b = sgni(x[2]);
    else if (rigid) m->closed_b = 1;
    else need_acc = 1;
    /* mid hinge (flexibleTop): rotation x = q2 - q1 */
    if (p->support == RW_FLEXIBLE_TOP) {
        const double xr = x[1] - x[0], dxr = x[3] - x[2];
        if (xr != 0.0) m->side_m = sgni(xr);
        else if (dxr != 0.0) m->side_m = sgni(dxr);
        else if (rigid) m->closed_m = 1;
        else need_acc |= 2;
    }
    if (need_acc) { /* semi-rigid hinge starting at zero: side from the initial acceleration */
        double dx[RW_NX];
        rw_derivatives(p, d, m, in, x, dx);
        if ((need_acc & 1) && dx[2] != 0.0) m->side_b = sgni(dx[2]);
        if ((need_acc & 2) && dx[3] - dx[2] != 0.0) m->side_m = sgni(dx[3] - dx[2]);
    }
    if (m->closed_b) close_base(p, m, x);
    logf_(log, ctx, "initial regime: base %s side %+d, mid %s side %+d", m->closed_b ? "closed" : "open",
          m->side_b, m->closed_m ? "closed" : "open", m->side_m);
    rw_open_hinges(p, d, m, in, x, log, ctx);
    set_offsets(d, m, x);
}

int rw_hold_tie(const rw_params *p, const rw_derived *d, rw_regime *m, const rw_input *in, double x[RW_NX],
                rw_log_fn log, void *ctx)
{
    const int rest = rw_is_rigid(p) && x[0] == 0.0 && x[1] == 0.0 && x[2] == 0.0 && x[3] == 0.0;
    rw_regime held = *m;
    if (rest) held.closed_b = held.closed_m = 1; /* undo what the free top's opening test did */
    if (!rw_tie_holds_rigid(p, d, &held, in, x)) return 0;
    held.tie_held = 1;
    if (rest) rw_open_hinges(p, d, &held, in, x, log, ctx);
    set_offsets(d, &held, x);
    *m = held;
    return 1;
}

/* The mid-height hinge's switch: its side changes where x = q2 - q1 crosses zero. 1 if it did. */
static int mid_switch(const rw_derived *d, rw_regime *m, const double x[RW_NX], rw_log_fn log, void *ctx)
{
    const double xr = x[1] - x[0], dxr = x[3] - x[2];
    if (!crossed(m->side_m, xr, dxr, d)) return 0;
    m->side_m = -m->side_m;
    logf_(log, ctx, "mid-hinge switch: q2-q1 = %g, rate %g, side %+d", xr, dxr, m->side_m);
    return 1;
}

int rw_sync_mid_side(const rw_params *p, const rw_derived *d, rw_regime *m, const double x[RW_NX])
{
    if (!rw_mid_switch_is_bookkeeping(p) || !mid_switch(d, m, x, NULL, NULL)) return 0;
    m->zoff_m = offset_for(d, m->side_m * (x[1] - x[0])); /* the base's offset stays: no event here */
    return 1;
}

void rw_event_update(const rw_params *p, const rw_derived *d, rw_regime *m, const rw_input *in,
                     double x[RW_NX], rw_event_result *r, rw_log_fn log, void *ctx)
{
    const int rigid = rw_is_rigid(p); /* once: a look-up in the law table, and events come in thousands */
    r->impacts = r->states_changed = r->regime_changed = 0;
    note_uplift(p, d, rigid, m, x);

    /* base: q1 crossing 0 = impact (paper Sec. 4): rates times er, pivot changes side; counted
     * when the wall had uplifted (note_uplift) */
    if (!(rigid && m->closed_b)) {
        if (crossed(m->side_b, x[0], x[2], d)) {
            const int eff = -m->side_b;
            const double v1 = x[2], v2 = x[3];
            x[2] *= p->er;
            x[3] *= p->er;
            slave(p, x);
            m->side_b = eff;
            if (rigid || m->uplifted_b) r->impacts++;
            m->uplifted_b = 0;
            r->regime_changed = 1;
            if (x[2] != v1 || x[3] != v2) r->states_changed = 1;
            logf_(log, ctx, "base impact: q1 = %g, dq1 %g -> %g, pivot side %+d", x[0], v1, x[2], eff);
            if (rigid && fabs(x[2]) < p->restRate) {
                close_base(p, m, x);
                r->states_changed = 1;
                logf_(log, ctx, "base hinge closes (|dq1| < restRate = %g)", p->restRate);
            }
        }
    }

    /* mid hinge (flexibleTop): x = q2 - q1 crossing 0 = switch of condition, no energy loss */
    if (p->support == RW_FLEXIBLE_TOP && !(rigid && m->closed_m) && mid_switch(d, m, x, log, ctx)) {
        r->regime_changed = 1;
        /* a held tie's mid-height hinge rests only with the base (close_base) */
        if (rigid && !m->tie_held && fabs(x[3] - x[2]) < p->restRate) {
            close_mid(m, x);
            r->states_changed = 1;
            logf_(log, ctx, "mid hinge closes (|dq2-dq1| < restRate = %g)", p->restRate);
        }
    }

    /* closed rigid hinges: opening test (applied at once, also right after a closing) */
    if (rigid && rw_open_hinges(p, d, m, in, x, log, ctx)) r->regime_changed = 1;
    set_offsets(d, m, x);
}
