/* The engine's linear regions: their modes (cached), and the region of the motion.
 * The modal decomposition of each region of the model between events (open hinges under a law's
 * affine moments, Doherty's 1DOF, closed rigid hinges), cached with the Stumpff coefficients of its
 * substeps, and the region of the motion with its indicator lines and collapse form. */
#include "rw_engine_span.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#define RW_SELECT_DT 1e-9 /* s: look-ahead of the direction that picks the region on a breakpoint */

static void identity_modes(rw_modes2 *E, double p10, double pi10)
{
    memset(E, 0, sizeof *E);
    E->P[0][0] = E->P[1][1] = E->Pi[0][0] = E->Pi[1][1] = 1.0;
    E->P[1][0] = p10;
    E->Pi[1][0] = pi10;
}

/* Symmetric generalised eigenproblem (Ks, M): Ks = k e e^T + G with e = (1, 1) and k = Kd h^2/4
 * (Eq. 3.3), so that the slow eigenvalue under a stiff spring (k up to 1e12) comes from the
 * determinant written without cancellation. M = L L^T; S = L^-1 Ks L^-T = k w w^T + Gs. */
static void modes_symmetric(const rw_derived *d, double k, const double G[2][2], rw_modes2 *E)
{
    const double l00 = sqrt(d->M[0][0]), l10 = d->M[1][0] / l00, l11 = sqrt(d->M[1][1] - l10 * l10);
    const double i00 = 1.0 / l00, i10 = -l10 / (l00 * l11), i11 = 1.0 / l11; /* L^-1 */
    const double w0 = i00, w1 = i10 + i11;
    const double gs00 = i00 * i00 * G[0][0];
    const double gs01 = i00 * (i10 * G[0][0] + i11 * G[0][1]);
    const double gs11 = i10 * i10 * G[0][0] + 2.0 * i10 * i11 * G[0][1] + i11 * i11 * G[1][1];
    const double a = k * w0 * w0 + gs00, b = k * w0 * w1 + gs01, c = k * w1 * w1 + gs11;
    const double det = k * (w0 * w0 * gs11 - 2.0 * w0 * w1 * gs01 + w1 * w1 * gs00) + (gs00 * gs11 - gs01 * gs01);
    const double half = 0.5 * (a + c), disc = sqrt(0.25 * (a - c) * (a - c) + b * b);
    const double big = half + (half >= 0.0 ? disc : -disc), small = big != 0.0 ? det / big : 0.0;
    const double phi = 0.5 * atan2(2.0 * b, a - c), cs = cos(phi), sn = sin(phi);
    double V[2][2];
    int i, j;
    /* column 0 of V has the eigenvalue half + disc, column 1 half - disc */
    V[0][0] = cs; V[1][0] = sn; V[0][1] = -sn; V[1][1] = cs;
    E->lam[0] = half >= 0.0 ? big : small;
    E->lam[1] = half >= 0.0 ? small : big;
    for (i = 0; i < 2; i++)
        for (j = 0; j < 2; j++) {
            /* P = L^-T V, Pi = V^T L^T */
            E->P[i][j] = (i == 0 ? i00 * V[0][j] + i10 * V[1][j] : i11 * V[1][j]);
            E->Pi[i][j] = (j == 0 ? V[0][i] * l00 : V[0][i] * l10 + V[1][i] * l11);
        }
    for (i = 0; i < 2; i++)
        for (j = 0; j < 2; j++) E->fm[i][j] = E->P[j][i]; /* P^T M P = I: modal force = P^T F */
}

/* General (nonsymmetric) Ks: A = M^-1 Ks, real distinct eigenvalues required. */
static int modes_general(const rw_derived *d, const double Ks[2][2], rw_modes2 *E)
{
    const double dm = d->M[0][0] * d->M[1][1] - d->M[0][1] * d->M[1][0];
    const double Mi[2][2] = {{d->M[1][1] / dm, -d->M[0][1] / dm}, {-d->M[1][0] / dm, d->M[0][0] / dm}};
    double A[2][2], tr, det, disc, dp;
    int i, j;
    for (i = 0; i < 2; i++)
        for (j = 0; j < 2; j++) A[i][j] = Mi[i][0] * Ks[0][j] + Mi[i][1] * Ks[1][j];
    tr = A[0][0] + A[1][1];
    det = A[0][0] * A[1][1] - A[0][1] * A[1][0];
    disc = 0.25 * tr * tr - det;
    if (!(disc > 1e-14 * (0.25 * tr * tr + fabs(det)))) return -1; /* complex or repeated */
    disc = sqrt(disc);
    E->lam[0] = 0.5 * tr + disc;
    E->lam[1] = 0.5 * tr - disc;
    for (j = 0; j < 2; j++) { /* eigenvector: the larger of the two null-vector candidates */
        const double u0 = A[0][1], u1 = E->lam[j] - A[0][0], w0 = E->lam[j] - A[1][1], w1 = A[1][0];
        const int first = u0 * u0 + u1 * u1 >= w0 * w0 + w1 * w1;
        E->P[0][j] = first ? u0 : w0;
        E->P[1][j] = first ? u1 : w1;
    }
    dp = E->P[0][0] * E->P[1][1] - E->P[0][1] * E->P[1][0];
    E->Pi[0][0] = E->P[1][1] / dp;
    E->Pi[0][1] = -E->P[0][1] / dp;
    E->Pi[1][0] = -E->P[1][0] / dp;
    E->Pi[1][1] = E->P[0][0] / dp;
    for (i = 0; i < 2; i++)
        for (j = 0; j < 2; j++) E->fm[i][j] = E->Pi[i][0] * Mi[0][j] + E->Pi[i][1] * Mi[1][j];
    return 0;
}

void rwe_modal_force(const rw_modes2 *E, const double F[2], double out[2])
{
    out[0] = E->fm[0][0] * F[0] + E->fm[0][1] * F[1];
    out[1] = E->fm[1][0] * F[0] + E->fm[1][1] * F[1];
}

/* 2DOF with open hinges: the region's stiffness K - J (Eq. 3.1, 3.3). */
int rwe_modes_open(const rw_engine *e, const double J[2][2], rw_modes2 *E)
{
    const rw_derived *d = &e->D;
    const double k = e->P.Kd * e->P.h * e->P.h / 4.0;
    double G[2][2], Ks[2][2], F[2];
    int i, j;
    memset(E, 0, sizeof *E);
    for (i = 0; i < 2; i++)
        for (j = 0; j < 2; j++) {
            G[i][j] = (d->K[i][j] - k) - J[i][j]; /* exact for a stiff spring (Sterbenz) */
            Ks[i][j] = d->K[i][j] - J[i][j];
        }
    if (J[0][1] == J[1][0]) modes_symmetric(d, k, G, E);
    else if (modes_general(d, Ks, E) != 0) return -1;
    rwe_modal_force(E, d->pa, E->ga);
    F[0] = F[1] = d->fu;
    rwe_modal_force(E, F, E->gu);
    return 0;
}

/* The cache of decompositions, keyed by the closed flags and J (or the 1DOF slope). */
static int cache_matches(const rw_cache_entry *c, int cb, int cm, const double key[4])
{
    return c->used && c->closed_b == cb && c->closed_m == cm && memcmp(c->key, key, sizeof c->key) == 0;
}

static rw_cache_entry *cache_find(rw_engine *e, int cb, int cm, const double key[4])
{
    int i;
    if (cache_matches(&e->cache[e->cache_last], cb, cm, key)) return &e->cache[e->cache_last];
    for (i = 0; i < RW_CACHE_SIZE; i++)
        if (cache_matches(&e->cache[i], cb, cm, key)) {
            e->cache_last = i;
            return &e->cache[i];
        }
    return NULL;
}

static rw_cache_entry *cache_add(rw_engine *e, int cb, int cm, const double key[4], const rw_modes2 *E)
{
    rw_cache_entry *c = &e->cache[e->cache_next];
    int i;
    e->cache_last = e->cache_next;
    e->cache_next = (e->cache_next + 1) % RW_CACHE_SIZE;
    memset(c, 0, sizeof *c);
    c->used = 1;
    c->closed_b = cb;
    c->closed_m = cm;
    memcpy(c->key, key, sizeof c->key);
    c->E = *E;
    for (i = 0; i < 2; i++) {
        c->w[i] = sqrt(fabs(E->lam[i]));
        c->col[i] = rw_max2(fabs(E->P[0][i]), fabs(E->P[1][i]));
        c->inv_lam[i] = 1.0 / E->lam[i]; /* used for lam > 0 only */
    }
    return c;
}

/* Doherty's 1DOF (support 2): mode 0 = q1 with (W/3g) D'' = -(W/2g) ag + F0 + F1 D, D = q1 h/2;
 * mode 1 = q1 + q2 = 0 (slaved, nothing acts on it). */
static rw_cache_entry *region_1dof(rw_engine *e, const rw_regime *m, const double x[RW_NX], const double dq_sel[2],
                                   double g0[2])
{
    const rw_params *p = &e->P;
    double key[4] = {0, 0, 0, 0}, F0 = 0.0, F1 = 0.0;
    rw_cache_entry *c;
    const int closed = e->rigid && m->closed_b;
    g0[0] = g0[1] = 0.0;
    if (!closed) {
        rw_force_1dof_affine(p, &e->D, m, x[0] * p->h / 2.0, dq_sel[0] * p->h / 2.0, &F0, &F1);
        key[0] = F1;
        g0[0] = 6.0 * p->g * F0 / (p->W * p->h);
    }
    c = cache_find(e, closed, 0, key);
    if (!c) {
        rw_modes2 E;
        identity_modes(&E, -1.0, 1.0);
        if (!closed) {
            E.lam[0] = -3.0 * p->g / p->W * F1;
            E.ga[0] = -3.0 / p->h;
        }
        c = cache_add(e, closed, 0, key, &E);
    }
    return c;
}

/* The parapet (support 1) in Housner's small-rotation form: theta'' = p^2 (theta - s alpha) - p^2 ag/g,
 * the model's sin(s alpha - theta) and cos(s alpha - theta) taken as s alpha - theta and 1 (exact
 * for a slender block; docs/engine.md "The parapet" gives where it departs from the FMU's
 * nonlinear block). Mode 0 = q1 = theta (unstable: lam = -p^2), mode 1 = q2 - q1 = 0 (slaved);
 * at rest (base closed) nothing moves. */
static rw_cache_entry *region_parapet(rw_engine *e, const rw_regime *m, double g0[2])
{
    const double key[4] = {0, 0, 0, 0};
    const int closed = m->closed_b;
    rw_cache_entry *c = cache_find(e, closed, 0, key);
    g0[0] = closed ? 0.0 : -e->D.p2 * m->side_b * e->D.alpha;
    g0[1] = 0.0;
    if (!c) {
        rw_modes2 E;
        identity_modes(&E, 1.0, -1.0);
        if (!closed) {
            E.lam[0] = -e->D.p2;
            E.ga[0] = -e->D.p2 / e->P.g;
        }
        c = cache_add(e, closed, 0, key, &E);
    }
    return c;
}

/* Closed rigid hinges (docs/model.md "Rigid hinges"): base closed, mid open: q1 = 0 and row 2
 * alone; mid closed, base open: q1 = q2 = theta (mode 1 = q2 - q1 = 0); both closed: rest. */
static rw_cache_entry *region_closed(rw_engine *e, const rw_regime *m, double g0[2])
{
    const rw_derived *d = &e->D;
    const double key[4] = {0, 0, 0, 0};
    rw_cache_entry *c = cache_find(e, m->closed_b, m->closed_m, key);
    const double mt = d->M[0][0] + 2.0 * d->M[0][1] + d->M[1][1];
    g0[0] = g0[1] = 0.0;
    if (m->closed_b && !m->closed_m) g0[1] = -rw_cap_m_of(d, m->side_m) * m->side_m / d->M[1][1];
    if (!m->closed_b && m->closed_m) g0[0] = -rw_cap_b_of(d, m->side_b) * m->side_b / mt;
    if (!c) {
        rw_modes2 E;
        if (m->closed_b && m->closed_m) {
            identity_modes(&E, 0.0, 0.0);
        } else if (m->closed_b) {
            identity_modes(&E, 0.0, 0.0);
            E.lam[1] = d->K[1][1] / d->M[1][1];
            E.ga[1] = d->pa[1] / d->M[1][1];
            E.gu[1] = d->fu / d->M[1][1];
        } else {
            const double kt = d->K[0][0] + 2.0 * d->K[0][1] + d->K[1][1];
            identity_modes(&E, 1.0, -1.0);
            E.lam[0] = kt / mt;
            E.ga[0] = (d->pa[0] + d->pa[1]) / mt;
            E.gu[0] = 2.0 * d->fu / mt;
        }
        c = cache_add(e, m->closed_b, m->closed_m, key, &E);
    }
    return c;
}

/* The region the state x (moving along dq_sel) is in, under the regime m. NULL if the engine
 * cannot decompose it (msg filled). */
rw_cache_entry *rwe_region_of(rw_engine *e, const rw_regime *m, const double x[RW_NX], const double dq_sel[2],
                              double g0[2], rw_affine_Q *aq)
{
    double Q[2], J[2][2], c[2], key[4];
    rw_cache_entry *ce;
    aq->valid = 0;
    if (e->P.support == RW_SIMPLY_SUPPORTED) return region_1dof(e, m, x, dq_sel, g0);
    if (e->P.support == RW_PARAPET) return region_parapet(e, m, g0);
    e->law->moments(&e->D, m->side_b, m->side_m, x, dq_sel, Q, J);
    c[0] = Q[0] - J[0][0] * x[0] - J[0][1] * x[1];
    c[1] = Q[1] - J[1][0] * x[0] - J[1][1] * x[1];
    /* affine in q on the region: a law of q alone, and the rigid law, whose moments are constant for
     * the region's sides (its collapse test takes the sides from the rotations, which keep the
     * region's signs until the event that changes them) */
    if (rw_moments_of_q_alone(&e->P) || e->rigid) {
        aq->valid = 1;
        memcpy(aq->c, c, sizeof c);
        memcpy(aq->J, J, sizeof J);
    }
    if (e->rigid && (m->closed_b || m->closed_m)) return region_closed(e, m, g0);
    key[0] = J[0][0]; key[1] = J[0][1]; key[2] = J[1][0]; key[3] = J[1][1];
    ce = cache_find(e, 0, 0, key);
    if (!ce) {
        rw_modes2 E;
        if (rwe_modes_open(e, J, &E) != 0) {
            snprintf(e->msg, sizeof e->msg, "a region of hinge law %s has complex or repeated modes: not supported",
                     e->law->name);
            return NULL;
        }
        ce = cache_add(e, 0, 0, key, &E);
    }
    rwe_modal_force(&ce->E, c, g0);
    return ce;
}

/* The direction that picks the region on a breakpoint: dq a moment later (the acceleration is
 * continuous across a breakpoint, so this decides a grazing touch by its curvature). */
static void selection_rate(const rw_engine *e, const rw_regime *m, const rw_input *in, const double x[RW_NX],
                           double dq_sel[2])
{
    double dx[RW_NX];
    rw_derivatives(&e->P, &e->D, m, in, x, dx);
    dq_sel[0] = x[2] + RW_SELECT_DT * dx[2];
    dq_sel[1] = x[3] + RW_SELECT_DT * dx[3];
}

/* Stumpff coefficients of a full substep h, cached per region. A length within rounding of the
 * absolute time t of a cached one takes its coefficients: the record's sample spacing, t[i+1] - t[i],
 * differs from one segment to the next by the rounding of t, and so does the motion's time. */
const double (*rwe_substep_coefficients(rw_cache_entry *c, double h, double t))[4]
{
    const double same = 4.0 * DBL_EPSILON * (fabs(t) + h);
    int j, i;
    for (j = 0; j < 2; j++)
        if (c->h_valid[j] && fabs(c->h[j] - h) <= same) {
            c->h_next = j ^ 1; /* least recently used: the sample spacing stays after an event's odd remainder */
            return (const double(*)[4])c->C[j];
        }
    j = c->h_next;
    c->h_next ^= 1;
    c->h[j] = h;
    c->h_valid[j] = 1;
    for (i = 0; i < 2; i++) stumpff(c->E.lam[i] * h * h, c->C[j][i]);
    return (const double(*)[4])c->C[j];
}

/* the indicators that are lines of the rotations under the regime m (they change only at events).
 * Under a law of q alone the mid-height hinge's switch changes nothing in the motion
 * (rw_mid_switch_is_bookkeeping): its line is left out, so the engine does not stop there. Under a
 * wall held at its top that switch comes microseconds after each base crossing, and each such pair
 * of events cost as much as seven quiet segments. The side is brought up to date by the event
 * update at the next event and at the end of every step (rw_engine_step). */
void rwe_region_lines(rw_engine *e, const rw_regime *m)
{
    int k;
    rw_indicator_lines(&e->P, &e->D, m, e->lines);
    if (e->mid_is_bookkeeping) {
        const rw_indicator_line never = {{0.0, 0.0}, 0.0, 0.0, 1.0, 0};
        e->lines[RW_Z_MID] = never;
    }
    e->line_mask = 0;
    for (k = 0; k < RW_NZ; k++) {
        const rw_indicator_line *L = &e->lines[k];
        if (!L->none) e->line_mask |= 1u << k;
        e->line_arrays.a0[k] = L->a[0];
        e->line_arrays.a1[k] = L->a[1];
        e->line_arrays.s[k] = L->s;
        e->line_arrays.t[k] = L->t;
        e->line_arrays.c[k] = L->c;
    }
}

/* The region's collapse form (rw_collapse_form_of) and the radius beyond which it cannot vanish
 * (rw_engine_band.c collapse_cannot_vanish): |c|/lam_min with a 1 % margin, 0 when c is zero to rounding, infinite
 * when the symmetric part of A is not positive definite. */
static void collapse_form_of_region(rw_engine *e)
{
    const rw_collapse_form *f = &e->collapse_form;
    double mean, half_diff, off, lam_min, size, c_norm;
    rw_collapse_form_of(&e->D, e->region_aq.c, (const double(*)[2])e->region_aq.J, &e->collapse_form);
    mean = 0.5 * (f->A[0][0] + f->A[1][1]);
    half_diff = 0.5 * (f->A[0][0] - f->A[1][1]);
    off = 0.5 * (f->A[0][1] + f->A[1][0]);
    lam_min = mean - sqrt(half_diff * half_diff + off * off);
    size = fabs(mean) + fabs(half_diff) + fabs(off);
    c_norm = sqrt(f->c[0] * f->c[0] + f->c[1] * f->c[1]);
    e->collapse_radius = INFINITY;
    if (lam_min > 1e-9 * size)
        e->collapse_radius = c_norm <= 1e-12 * size * e->D.q_topple ? 0.0 : 1.01 * c_norm / lam_min;
}

/* The region of the motion at (sc->x, t), with its modal forcing (sc->g0) and affine hinge moments
 * (sc->sp.aq): kept from one input segment to the next, since without an event no indicator, so no
 * breakpoint and no regime, has changed; found again after each event. */
rw_cache_entry *rwe_current_region(rw_span_ctx *sc, double t)
{
    rw_engine *e = sc->e;
    const rw_regime *m = sc->m;
    const rw_linear_input *in = sc->in;
    const double *x = sc->x, t_in = sc->t_in;
    rw_cache_entry *R;
    if (!e->region_valid && e->region_keep) { /* rwe_hinge_event_keeps_region */
        rwe_region_lines(e, m);
        e->region_valid = 1;
    }
    e->region_keep = 0;
    if (!e->region_valid) {
        rw_input now;
        double dq_sel[2];
        now.ag = in->ag + in->ag_slope * (t - t_in);
        now.u_top = in->u_top + in->u_slope * (t - t_in);
        if (e->rigid && e->P.support == RW_FLEXIBLE_TOP) { /* its moments depend on the sides alone */
            dq_sel[0] = x[2];
            dq_sel[1] = x[3];
        } else {
            selection_rate(e, m, &now, x, dq_sel);
        }
        R = rwe_region_of(e, m, x, dq_sel, e->region_g0, &e->region_aq);
        if (!R) return NULL;
        rwe_region_lines(e, m);
        e->closed_mask = rw_closed_hinge_mask(&e->P, m);
        if (e->closed_mask) rw_closed_force_form(&e->P, &e->D, m, &e->closed_form);
        if (e->region_aq.valid)
            collapse_form_of_region(e);
        e->region = (int)(R - e->cache);
        e->region_valid = 1;
    }
    memcpy(sc->g0, e->region_g0, sizeof e->region_g0);
    sc->sp.aq = e->region_aq;
    return &e->cache[e->region];
}
