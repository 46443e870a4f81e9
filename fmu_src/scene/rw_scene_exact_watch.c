/* What the exact scene engine watches over a step: each standing wall's event indicators (its
 * lines under the current modes, rw_indicator_lines, the toppling limit and the collapse
 * indicator's G) and the peaks of s1, s2, the diaphragms' deformations and the walls' base
 * accelerations. A quiet test on a low-degree polynomial with a bounded tail clears most steps;
 * the others are examined on the exact series. An indicator's sign at a step's start is its own
 * where it is clear of rounding, else the direction it moves in; a root is where it has moved
 * 2 tol past zero (tol: its rounding), so that an event leaves it on its new side. */
#include "rw_scene_exact_internal.h"

#include <float.h>
#include <math.h>
#include <string.h>

#define SX_TOL 32.0 * DBL_EPSILON

static int standing(const rw_scene *sc, int i) { return sc->S.has_wall[i] && !sc->collapsed[i]; }

void sx_watch_lines(sx_run *R)
{
    const rw_scene *sc = &R->sc;
    int i, k;
    for (i = 0; i < sc->S.n_storeys; i++) {
        rw_indicator_line L[RW_NZ];
        sx_line *out = R->lines[i];
        int n = 0;
        R->nlines[i] = 0;
        if (!standing(sc, i)) continue;
        rw_indicator_lines(&sc->S.wall[i], &sc->D[i], &sc->mode[i], L);
        for (k = 0; k < RW_NZ; k++) {
            if (L[k].none || (L[k].a[0] == 0.0 && L[k].a[1] == 0.0)) continue;
            /* the mid-height switch under a law of q alone changes nothing but the side, which the
             * event update's own rule brings up to date at the next event */
            if (k == RW_Z_MID && rw_mid_switch_is_bookkeeping(&sc->S.wall[i])) continue;
            out[n].a0 = L[k].a[0], out[n].a1 = L[k].a[1], out[n].s = L[k].s, out[n].t = L[k].t, out[n].c = L[k].c;
            n++;
        }
        for (k = 0; k < 2; k++) { /* the toppling limit: |q_k| = 2b/h (rw_topple_value) */
            out[n].a0 = k == 0, out[n].a1 = k == 1, out[n].s = 1.0, out[n].t = 0.0, out[n].c = -sc->D[i].q_topple;
            n++;
        }
        R->nlines[i] = n;
    }
}

/* ---- ranges (the quiet test) ---- */

typedef struct {
    double lo, hi;
} span;

/* z = c + s|w| + t w over w in [lo, hi]: piecewise linear with its kink at 0 */
static span line_span(const sx_line *L, span w)
{
    const double zl = L->c + L->s * fabs(w.lo) + L->t * w.lo, zh = L->c + L->s * fabs(w.hi) + L->t * w.hi;
    span z = {fmin(zl, zh), fmax(zl, zh)};
    if (w.lo < 0.0 && w.hi > 0.0) z.lo = fmin(z.lo, L->c), z.hi = fmax(z.hi, L->c);
    return z;
}

static double line_tol(const sx_line *L, double q1, double q2)
{
    return SX_TOL * (fabs(L->c) + fabs(L->a0 * q1) + fabs(L->a1 * q2)) + DBL_MIN;
}

static int clear_of_zero(span z, double tol) { return z.lo > 2.0 * tol || z.hi < -2.0 * tol; }

static span square_span(span a)
{
    span s = {a.lo * a.lo, a.hi * a.hi};
    if (s.lo > s.hi) s = (span){s.hi, s.lo};
    if (a.lo < 0.0 && a.hi > 0.0) s.lo = 0.0;
    return s;
}

static span product_span(span a, span b)
{
    const double p[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
    span s = {p[0], p[0]};
    int k;
    for (k = 1; k < 4; k++) s.lo = fmin(s.lo, p[k]), s.hi = fmax(s.hi, p[k]);
    return s;
}

static span scaled(span a, double c) { return c >= 0 ? (span){c * a.lo, c * a.hi} : (span){c * a.hi, c * a.lo}; }
static span sum(span a, span b) { return (span){a.lo + b.lo, a.hi + b.hi}; }

static double collapse_tol(const sx_collapse *c, double q1, double q2)
{
    return SX_TOL * (fabs(c->A[0][0] * q1 * q1) + fabs((c->A[0][1] + c->A[1][0]) * q1 * q2) + fabs(c->A[1][1] * q2 * q2) +
                     fabs(c->c[0] * q1) + fabs(c->c[1] * q2)) + DBL_MIN;
}

/* G(q) = q.A q - c.q over the box of q: clear of zero, or beyond the radius where it cannot vanish */
static int collapse_quiet(const sx_collapse *c, span q1, span q2, double q10, double q20)
{
    span G;
    if (!c->active) return 1;
    if (c->lam_min > 0.0) {
        const double d1 = q1.lo > 0 ? q1.lo : (q1.hi < 0 ? -q1.hi : 0.0), d2 = q2.lo > 0 ? q2.lo : (q2.hi < 0 ? -q2.hi : 0.0);
        if (sqrt(d1 * d1 + d2 * d2) * c->lam_min > 1.000001 * hypot(c->c[0], c->c[1])) return 1;
    }
    G = sum(sum(scaled(square_span(q1), c->A[0][0]), scaled(product_span(q1, q2), c->A[0][1] + c->A[1][0])),
            sum(scaled(square_span(q2), c->A[1][1]), sum(scaled(q1, -c->c[0]), scaled(q2, -c->c[1]))));
    return clear_of_zero(G, collapse_tol(c, q10, q20));
}

/* a functional's polynomial on the step: value range, and whether it is monotone */
typedef struct {
    double coef[SX_LO + 1], tail, dtail, end;
} lo_poly;

static span poly_span(const double *coef, double tail)
{
    span s = {coef[0] - tail, coef[0] + tail};
    int k;
    for (k = 1; k <= SX_LO; k++) {
        if (coef[k] < 0.0) s.lo += coef[k];
        else s.hi += coef[k];
    }
    return s;
}

static int monotone(const double *coef, double dtail)
{
    span d = {coef[1] - dtail, coef[1] + dtail};
    int k;
    for (k = 2; k <= SX_LO; k++) {
        if (coef[k] < 0.0) d.lo += k * coef[k];
        else d.hi += k * coef[k];
    }
    return d.lo > 0.0 || d.hi < 0.0;
}

/* a peak quantity (a combination of functionals) can rise over its peak inside the step */
static int peak_may_rise(const lo_poly *P, double peak)
{
    const span s = poly_span(P->coef, P->tail);
    if (fmax(fabs(s.lo), fabs(s.hi)) <= peak) return 0;
    return !monotone(P->coef, P->dtail);
}

static void combine(lo_poly *out, const lo_poly *a, double ca, const lo_poly *b, double cb)
{
    int k;
    for (k = 0; k <= SX_LO; k++) out->coef[k] = ca * a->coef[k] + (b ? cb * b->coef[k] : 0.0);
    out->tail = fabs(ca) * a->tail + (b ? fabs(cb) * b->tail : 0.0);
    out->dtail = fabs(ca) * a->dtail + (b ? fabs(cb) * b->dtail : 0.0);
    out->end = ca * a->end + (b ? cb * b->end : 0.0);
}

/* the peak quantities of storey i from its functionals; a slot is NULL when the storey has none */
typedef struct {
    lo_poly q1, q2, s1, s2, deform, acc;
    int wall;
} storey_polys;

static void peaks_of_ends(rw_scene_result *res, int i, const storey_polys *P)
{
    if (P->wall) {
        res->peak_s1[i] = fmax(res->peak_s1[i], fmax(fabs(P->s1.coef[0]), fabs(P->s1.end)));
        res->peak_s2[i] = fmax(res->peak_s2[i], fmax(fabs(P->s2.coef[0]), fabs(P->s2.end)));
    }
    res->peak_diaphragm[i] = fmax(res->peak_diaphragm[i], fmax(fabs(P->deform.coef[0]), fabs(P->deform.end)));
    res->peak_base_acc[i] = fmax(res->peak_base_acc[i], fmax(fabs(P->acc.coef[0]), fabs(P->acc.end)));
}

static void low_polys(const sx_region *r, const sx_step *st, const double xa0[], const double xa1[],
                      storey_polys P[RW_SCENE_MAX_STOREYS])
{
    double Xt[SX_MAX_N], tn = 0.0;
    const double q = st->rho / (SX_LO + 2);
    int f, k;
    sx_matvec(r->n, r->na, st->T, xa0, Xt);
    for (k = 0; k < r->n; k++) tn = fmax(tn, fabs(Xt[k]) / r->scale[k]);
    for (f = 0; f < r->nf; f++) {
        storey_polys *S = &P[r->f_storey[f]];
        lo_poly *p = r->f_kind[f] == SX_Q1 ? &S->q1 : r->f_kind[f] == SX_Q2 ? &S->q2 : r->f_kind[f] == SX_DEFORM ? &S->deform : &S->acc;
        const double *row = st->rows + (size_t)f * (size_t)((SX_LO + 1) * r->na);
        for (k = 0; k <= SX_LO; k++) {
            double v = 0.0;
            int j;
            for (j = 0; j < r->na; j++) v += row[k * r->na + j] * xa0[j];
            p->coef[k] = v;
        }
        p->tail = r->f_scale[f] * tn / (1.0 - q);
        p->dtail = r->f_scale[f] * tn * ((SX_LO + 1) / (1.0 - q) + q / ((1.0 - q) * (1.0 - q)));
        p->end = 0.0;
        for (k = 0; k < r->na; k++) p->end += r->F[f][k] * xa1[k];
        if (r->f_kind[f] == SX_Q1) S->wall = 1;
    }
}

static int wall_quiet(const sx_run *R, const sx_region *r, int i, const storey_polys *P)
{
    const span q1 = poly_span(P->q1.coef, P->q1.tail), q2 = poly_span(P->q2.coef, P->q2.tail);
    int k;
    for (k = 0; k < R->nlines[i]; k++) {
        const sx_line *L = &R->lines[i][k];
        lo_poly w;
        combine(&w, &P->q1, L->a0, &P->q2, L->a1);
        if (!clear_of_zero(line_span(L, poly_span(w.coef, w.tail)), line_tol(L, P->q1.coef[0], P->q2.coef[0])))
            return 0;
    }
    return collapse_quiet(&r->col[i], q1, q2, P->q1.coef[0], P->q2.coef[0]);
}

int sx_watch_quiet(sx_run *R, const sx_region *r, const sx_step *st, const double xa0[], const double xa1[])
{
    storey_polys P[RW_SCENE_MAX_STOREYS];
    rw_scene_result *res = R->res;
    int i;
    memset(P, 0, sizeof P);
    low_polys(r, st, xa0, xa1, P);
    for (i = 0; i < R->sc.S.n_storeys; i++) {
        storey_polys *S = &P[i];
        const double h2 = 0.5 * R->sc.S.wall[i].h;
        if (S->wall) {
            combine(&S->s1, &S->q1, h2, NULL, 0.0);
            combine(&S->s2, &S->q1, h2, &S->q2, h2);
            if (!wall_quiet(R, r, i, S) || peak_may_rise(&S->s1, res->peak_s1[i]) ||
                peak_may_rise(&S->s2, res->peak_s2[i]))
                return 0;
        }
        if (peak_may_rise(&S->deform, res->peak_diaphragm[i]) || peak_may_rise(&S->acc, res->peak_base_acc[i])) return 0;
    }
    for (i = 0; i < R->sc.S.n_storeys; i++) peaks_of_ends(res, i, &P[i]);
    return 1;
}
