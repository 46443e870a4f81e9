/* A step of the exact scene engine examined on its exact series (rw_scene_exact_watch.c's quiet
 * test did not clear it): the first root of any standing wall's event indicators, the peaks up to
 * it, and the work of the ground and the dashpots over it, on the polynomials of the series. */
#include "rw_scene_exact_internal.h"

#include <float.h>
#include <math.h>
#include <string.h>

#define SX_TOL 32.0 * DBL_EPSILON
#define SX_PMAX (2 * SX_MAX_DEG + 2)

static double sgn(double v) { return (v > 0.0) - (v < 0.0); }

/* functional f's polynomial over the step */
static void poly_of(const sx_region *r, int f, const sx_series *s, double *p)
{
    int k;
    for (k = 0; k <= s->deg; k++) p[k] = sx_functional(r, f, s->X + (size_t)k * (size_t)r->na);
}

/* the sign an indicator starts with: its own when clear of rounding, else its direction */
static double start_sign(double z0, double tol, double dz, double ddz)
{
    if (fabs(z0) > tol) return sgn(z0);
    if (dz != 0.0) return sgn(dz);
    if (ddz != 0.0) return sgn(ddz);
    return z0 < 0.0 ? -1.0 : 1.0;
}

/* the first root of g = sgn0 (c + m W) + 2 tol */
static double affine_root(const double *W, int deg, double c, double m, double sgn0, double tol)
{
    double g[SX_PMAX];
    int k;
    for (k = 0; k <= deg; k++) g[k] = sgn0 * m * W[k];
    g[0] += sgn0 * c + 2.0 * tol;
    return sx_poly_first_root(g, deg, 0.0);
}

/* z = c + s|w| + t w (s = 0, or s > 0 with c <= 0: one branch at most above zero) */
static double line_root(const sx_line *L, const double *Q1, const double *Q2, int deg)
{
    double W[SX_PMAX], z0, tol, sw, dz, s0;
    int k;
    for (k = 0; k <= deg; k++) W[k] = L->a0 * Q1[k] + L->a1 * Q2[k];
    z0 = L->c + L->s * fabs(W[0]) + L->t * W[0];
    tol = SX_TOL * (fabs(L->c) + fabs(L->a0 * Q1[0]) + fabs(L->a1 * Q2[0])) + DBL_MIN;
    sw = W[0] != 0.0 ? sgn(W[0]) : sgn(W[1]);
    dz = (L->s * sw + L->t) * W[1];
    s0 = start_sign(z0, tol, dz, (L->s * sw + L->t) * (deg >= 2 ? W[2] : 0.0));
    if (L->s == 0.0) return affine_root(W, deg, L->c, L->t, s0, tol);
    if (s0 > 0.0) return affine_root(W, deg, L->c, L->t + L->s * sw, 1.0, tol); /* the branch above zero */
    return fmin(affine_root(W, deg, L->c, L->t + L->s, -1.0, tol), affine_root(W, deg, L->c, L->t - L->s, -1.0, tol));
}

/* G(q) = q.A q - c.q along the step (degree 2 deg) */
static double collapse_root(const sx_collapse *c, const double *Q1, const double *Q2, int deg)
{
    double a[SX_PMAX], b[SX_PMAX], m[SX_PMAX], G[SX_PMAX], tol, s0;
    const double q1 = Q1[0], q2 = Q2[0];
    int k;
    sx_poly_square(Q1, deg, a);
    sx_poly_square(Q2, deg, b);
    sx_poly_product(Q1, Q2, deg, m);
    for (k = 0; k <= 2 * deg; k++) G[k] = c->A[0][0] * a[k] + (c->A[0][1] + c->A[1][0]) * m[k] + c->A[1][1] * b[k];
    for (k = 0; k <= deg; k++) G[k] -= c->c[0] * Q1[k] + c->c[1] * Q2[k];
    tol = SX_TOL * (fabs(c->A[0][0] * q1 * q1) + fabs((c->A[0][1] + c->A[1][0]) * q1 * q2) + fabs(c->A[1][1] * q2 * q2) +
                    fabs(c->c[0] * q1) + fabs(c->c[1] * q2)) + DBL_MIN;
    s0 = start_sign(G[0], tol, G[1], G[2]);
    for (k = 0; k <= 2 * deg; k++) G[k] *= s0;
    G[0] += 2.0 * tol;
    return sx_poly_first_root(G, 2 * deg, 0.0);
}

/* a bilinear diaphragm's indicator z = c + a v over the step (v its deformation or their rate) */
static double diaphragm_root(const sx_dline *L, const double *V, int deg)
{
    const double tol = SX_TOL * (fabs(L->c) + fabs(L->a * V[0])) + DBL_MIN;
    const double s0 = start_sign(L->c + L->a * V[0], tol, L->a * V[1], deg >= 2 ? L->a * V[2] : 0.0);
    return affine_root(V, deg, L->c, L->a, s0, tol);
}

/* a storey's polynomials over the step */
typedef struct {
    double q1[SX_PMAX], q2[SX_PMAX], deform[SX_PMAX], acc[SX_PMAX], rate[SX_PMAX];
    double err_q1, err_q2, err_deform, err_acc;
    int wall;
} storey_series;

static void storey_polys(const sx_region *r, const sx_series *s, storey_series *P, int only)
{
    int f;
    for (f = 0; f < r->nf; f++) {
        storey_series *S = &P[r->f_storey[f]];
        if (only >= 0 && r->f_storey[f] != only) continue;
        const double err = r->f_scale[f] * s->tail;
        switch (r->f_kind[f]) {
        case SX_Q1: poly_of(r, f, s, S->q1), S->err_q1 = err, S->wall = 1; break;
        case SX_Q2: poly_of(r, f, s, S->q2), S->err_q2 = err; break;
        case SX_DEFORM: poly_of(r, f, s, S->deform), S->err_deform = err; break;
        case SX_BASE_ACC: poly_of(r, f, s, S->acc), S->err_acc = err; break;
        default: poly_of(r, f, s, S->rate); break;
        }
    }
}

/* storey i's peak quantity `kind` over the series and its error (0: the storey has none) */
static int quantity(const sx_run *R, int i, const storey_series *S, int kind, int deg, double *p, double *err)
{
    const double h2 = S->wall ? 0.5 * R->sc.S.wall[i].h : 0.0;
    int k;
    switch (kind) {
    case SX_PEAK_S1:
        for (k = 0; k <= deg; k++) p[k] = h2 * S->q1[k];
        *err = h2 * S->err_q1;
        return S->wall;
    case SX_PEAK_S2:
        for (k = 0; k <= deg; k++) p[k] = h2 * (S->q1[k] + S->q2[k]);
        *err = h2 * (S->err_q1 + S->err_q2);
        return S->wall;
    case SX_PEAK_DEFORM: memcpy(p, S->deform, sizeof(double) * (size_t)(deg + 1)), *err = S->err_deform; return 1;
    default: memcpy(p, S->acc, sizeof(double) * (size_t)(deg + 1)), *err = S->err_acc; return 1;
    }
}

/* storey i's peaks over [0, u] of the series, of the kinds in the bits `kinds` (the others cannot
 * rise over the step) */
static void storey_peaks(sx_run *R, int i, const storey_series *S, int deg, double u, unsigned kinds)
{
    double p[SX_PMAX], err;
    int kind;
    for (kind = 0; kind < SX_PEAK_KINDS; kind++) {
        double *peak = sx_peak_of(R->res, i, kind);
        if (!(kinds & (1u << kind))) continue;
        if (quantity(R, i, S, kind, deg, p, &err)) *peak = sx_poly_max_abs(p, deg, err, u, *peak);
    }
}

/* every storey's polynomials over the series, or storey `only`'s (a storey without a functional:
 * zero) */
static void storeys(const sx_run *R, const sx_region *r, const sx_series *s, storey_series P[], int only)
{
    const size_t used = sizeof(double) * (size_t)(s->deg + 1);
    int i;
    for (i = 0; i < R->sc.S.n_storeys; i++) {
        if (only >= 0 && i != only) continue;
        memset(P[i].q1, 0, used), memset(P[i].q2, 0, used), memset(P[i].deform, 0, used), memset(P[i].acc, 0, used);
        memset(P[i].rate, 0, used);
        P[i].err_q1 = P[i].err_q2 = P[i].err_deform = P[i].err_acc = 0.0;
        P[i].wall = 0;
    }
    storey_polys(r, s, P, only);
}

double sx_watch_step(sx_run *R, const sx_region *r, const sx_series *s, const sx_suspects *sus)
{
    storey_series P[RW_SCENE_MAX_STOREYS];
    int in_play[RW_SCENE_MAX_STOREYS];
    double first = 2.0;
    int i, k;
    for (i = 0; i < R->sc.S.n_storeys; i++) { /* a storey with nothing suspect needs no polynomial */
        in_play[i] = !sus || sus->wall[i] || sus->diaphragm[i] || sus->peaks[i];
        if (in_play[i]) storeys(R, r, s, P, i);
    }
    for (i = 0; i < R->sc.S.n_storeys; i++) {
        const unsigned diaphragm = sus ? sus->diaphragm[i] : ~0u, wall = sus ? sus->wall[i] : ~0u; /* (bits) */
        if (!in_play[i]) continue;
        for (k = 0; k < R->ndlines[i]; k++) {
            const sx_dline *L = &R->dlines[i][k];
            if (diaphragm & (1u << k))
                first = fmin(first, diaphragm_root(L, L->kind == SX_DEFORM ? P[i].deform : P[i].rate, s->deg));
        }
        if (!P[i].wall) continue;
        for (k = 0; k < R->nlines[i]; k++)
            if (wall & (1u << k)) first = fmin(first, line_root(&R->lines[i][k], P[i].q1, P[i].q2, s->deg));
        if (r->col[i].active && (wall & SX_COLLAPSE_BIT))
            first = fmin(first, collapse_root(&r->col[i], P[i].q1, P[i].q2, s->deg));
    }
    for (i = 0; i < R->sc.S.n_storeys; i++)
        if (in_play[i]) storey_peaks(R, i, &P[i], s->deg, fmin(first, 1.0), sus ? sus->peaks[i] : ~0u);
    return first;
}

double sx_series_peak(const sx_run *R, const sx_region *r, const sx_series *s, int storey, int kind, double best)
{
    storey_series P[RW_SCENE_MAX_STOREYS];
    double p[SX_PMAX], err;
    storeys(R, r, s, P, storey); /* the one storey a doubt is about */
    return quantity(R, storey, &P[storey], kind, s->deg, p, &err) ? sx_poly_max_abs(p, s->deg, err, 1.0, best) : best;
}

void sx_series_work(const sx_region *r, const sx_series *s, double u, double *w_ground, double *w_damping)
{
    double mom[SX_PMAX], prod[SX_PMAX], d[SX_PMAX];
    const int na = r->na, deg = s->deg;
    const double ag0 = s->X[r->n], ag1 = s->X[(size_t)na + (size_t)r->n]; /* ag over the step: ag0 + ag1 u */
    int k, t;
    for (k = 0; k <= deg; k++) mom[k] = sx_dot(r->mom, s->X + (size_t)k * (size_t)na, r->n);
    for (k = 0; k <= deg + 1; k++) /* (ag0 + ag1 u) mom(u) */
        prod[k] = (k <= deg ? ag0 * mom[k] : 0.0) + (k >= 1 ? ag1 * mom[k - 1] : 0.0);
    *w_ground = -s->L * sx_poly_integral(prod, deg + 1, u);
    *w_damping = 0.0;
    for (t = 0; t < r->nterms; t++) {
        for (k = 0; k <= deg; k++) d[k] = sx_row_dot(r->dvec[t], r->d_nz[t], r->n, &r->d_pair[t], s->X + (size_t)k * (size_t)na);
        *w_damping += r->dcoef[t] * s->L * sx_poly_square_integral(d, deg, u);
    }
}
