/* The model's event indicators, with their rates, at a state of a span.
 * The region's lines and forms where they hold, the shared physics (rw_indicators.c) for the rest. */
#include "rw_engine_span.h"

#include <math.h>

#define RW_AFFINE_Q_CLEARANCE 1e-6 /* scale-free collapse indicator: below this, the law itself decides */

/* The indicators of the closed rigid hinges among `mask` at the state x (rates along xd, if not
 * NULL, with the input at the rate in[1]; in[0]: its value) from the region's affine form of their
 * moments (rw_closed_force_form): 1 - |f|/cap + eps_f, as rw_event_indicators computes it. Returns
 * those within RW_AFFINE_Q_CLEARANCE of zero, which the physics itself takes (the signs decided near
 * a root must come from one function, as for the collapse form). */
unsigned rwe_closed_hinge_values(const rw_engine *e, const rw_input in[2], const double x[RW_NX], const double *xd,
                                 unsigned mask, double *z, double *dz)
{
    const rw_closed_form *F = &e->closed_form;
    unsigned near_zero = 0;
    int j;
    for (j = 0; j < 2; j++) {
        const int k = j == 0 ? RW_Z_BASE : RW_Z_MID;
        double f;
        if (!((mask >> k) & 1u)) continue;
        f = F->c[j] + F->G[j][0] * x[0] + F->G[j][1] * x[1] + F->g_ag[j] * in[0].ag + F->g_u[j] * in[0].u_top;
        z[k] = 1.0 - fabs(f) * F->inv_cap[j] + RW_EPS_F;
        if (fabs(z[k]) < RW_AFFINE_Q_CLEARANCE) near_zero |= 1u << k;
        else if (xd) {
            const double df =
                F->G[j][0] * xd[0] + F->G[j][1] * xd[1] + F->g_ag[j] * in[1].ag + F->g_u[j] * in[1].u_top;
            dz[k] = -((f > 0.0) - (f < 0.0)) * df * F->inv_cap[j];
        }
    }
    return near_zero;
}

/* Does the region's collapse form hold at x? Always for a law of q alone (the other laws with a
 * form, rw_engine_regions.c); for the rigid law while each open hinge's rotation is on its side (or
 * zero), as the law's collapse test takes the sides from the rotations: in the moment before an
 * impact or a switch, where a rotation has just passed zero, the law's G keeps |rotation| terms
 * that the region's constant moments turn negative. */
static int collapse_form_holds(const rw_engine *e, const rw_regime *m, const double x[RW_NX])
{
    return !e->rigid || (m->side_b * x[0] >= 0.0 && m->side_m * (x[1] - x[0]) >= 0.0);
}

/* The model's indicators of `mask` at the state x of the span's motion and, if xd is not NULL,
 * their rates dz along it (x moving at xd, the input at the span's rate). The indicators that are
 * lines of the rotations (rw_indicator_lines, taken once per region) are evaluated here; the
 * others (collapse, toppling, closed hinges) by the shared physics, with the region's affine
 * hinge moments where the law has them (rw_hinge_law.q_only). */
void rwe_region_indicators(const rw_span_ctx *sc, const rw_input *in, const double x[RW_NX], const double xd[RW_NX],
                           unsigned mask, double *restrict z, double *restrict dz)
{
    const rw_engine *e = sc->e;
    const rw_regime *m = sc->m;
    const rw_span *sp = &sc->sp;
    const unsigned collapse = 1u << RW_Z_COLLAPSE, topple = 1u << RW_Z_TOPPLE;
    unsigned rest = mask & ~e->line_mask;
    int k;
    if (xd && mask == RW_Z_ALL) { /* every line, without a test per line (the others are overwritten below) */
        const rw_line_arrays *A = &e->line_arrays;
        /* z, dz never overlap the engine's arrays, which gcc cannot tell through the context's
         * pointer (restrict on z, dz serves only against other parameters): without this it tests
         * for an overlap at every call */
#pragma GCC ivdep
        for (k = 0; k < RW_NZ; k++) { /* rw_line_value's arithmetic on arrays, which the compiler vectorizes */
            const double w = A->a0[k] * x[0] + A->a1[k] * x[1], wd = A->a0[k] * xd[0] + A->a1[k] * xd[1];
            const double sign = (double)(w > 0.0) - (double)(w < 0.0);
            dz[k] = (A->s[k] * sign + A->t[k]) * wd;
            z[k] = A->c[k] + A->s[k] * fabs(w) + A->t[k] * w;
        }
    } else {
        for (k = 0; k < RW_NZ; k++)
            if ((mask & e->line_mask) >> k & 1u) z[k] = rw_line_value(&e->lines[k], x, xd, xd ? &dz[k] : NULL);
    }
    if ((rest & topple) && e->P.support == RW_FLEXIBLE_TOP) {
        z[RW_Z_TOPPLE] = rw_topple_value(&e->D, x, xd, xd ? &dz[RW_Z_TOPPLE] : NULL);
        rest &= ~topple;
    }
    if (rest & e->closed_mask) {
        const rw_input in_and_rate[2] = {*in, {sp->ag1, sp->u1}};
        rest = (rest & ~e->closed_mask) | rwe_closed_hinge_values(e, in_and_rate, x, xd, rest & e->closed_mask, z, dz);
    }
    if ((rest & collapse) && sp->aq.valid && collapse_form_holds(e, m, x)) {
        if (e->collapse_radius == 0.0) {
            /* a region that cannot collapse (rw_engine_regions.c collapse_form_of_region): its indicator, positive
             * everywhere in it, as its clipped value, at no cost */
            z[RW_Z_COLLAPSE] = RW_COLLAPSE_ZMAX;
            if (xd) dz[RW_Z_COLLAPSE] = 0.0;
        } else {
            z[RW_Z_COLLAPSE] = rw_collapse_form_value(&e->collapse_form, x, xd, xd ? &dz[RW_Z_COLLAPSE] : NULL);
            /* Near its root the collapse indicator is taken from the law itself: the region's form
             * differs from it by rounding, and every sign decided near zero (the root, the tracked
             * state set after an event, the collapse test) must come from one function, or an event
             * repeats at one instant. Away from zero both have the same sign. */
            if (fabs(z[RW_Z_COLLAPSE]) < RW_AFFINE_Q_CLEARANCE)
                rw_event_indicators_some(&e->P, &e->D, m, in, x, NULL, collapse, z);
        }
        rest &= ~collapse;
    }
    if (!rest) return;
    if (xd) {
        const rw_input rate = {sp->ag1, sp->u1};
        rw_event_indicator_rates(&e->P, &e->D, m, in, &rate, x, xd, NULL, NULL, rest, z, dz);
    } else {
        rw_event_indicators_some(&e->P, &e->D, m, in, x, NULL, rest, z);
    }
}
