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

/* fmax and fmin (a NaN gives the other operand), inline */
static double max2(double a, double b) { return a > b || b != b ? a : b; }
static double min2(double a, double b) { return a < b || b != b ? a : b; }

static int standing(const rw_scene *sc, int i) { return sc->S.has_wall[i] && !sc->collapsed[i]; }

static void line_set(const sx_line *L, int n, sx_line_set *set)
{
    static const sx_line far = {0.0, 0.0, 0.0, 0.0, 1.0}; /* z = 1: never near zero */
    int k;
    for (k = 0; k < SX_LINE_SLOTS; k++) {
        const sx_line *l = k < n ? &L[k] : &far;
        set->a0[k] = l->a0, set->a1[k] = l->a1, set->abs_a0[k] = fabs(l->a0), set->abs_a1[k] = fabs(l->a1);
        set->s[k] = l->s, set->t[k] = l->t, set->c[k] = l->c, set->abs_c[k] = fabs(l->c);
        set->slope[k] = l->s + fabs(l->t);
    }
}

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
        rw_indicator_lines(&sc->S.wall[i], &sc->D[i], &sc->regime[i], L);
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
        line_set(out, n, &R->line_set[i]);
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
    span z = {min2(zl, zh), max2(zl, zh)};
    if (w.lo < 0.0 && w.hi > 0.0) z.lo = min2(z.lo, L->c), z.hi = max2(z.hi, L->c);
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

static span scaled(span a, double c) { return c >= 0 ? (span){c * a.lo, c * a.hi} : (span){c * a.hi, c * a.lo}; }
static span sum(span a, span b) { return (span){a.lo + b.lo, a.hi + b.hi}; }

static double collapse_tol(const sx_collapse *c, double q1, double q2)
{
    return SX_TOL * (fabs(c->A[0][0] * q1 * q1) + fabs((c->A[0][1] + c->A[1][0]) * q1 * q2) + fabs(c->A[1][1] * q2 * q2) +
                     fabs(c->c[0] * q1) + fabs(c->c[1] * q2)) + DBL_MIN;
}

static span poly_span(const sx_lopoly *p);
static void combine(sx_lopoly *out, const sx_lopoly *a, double ca, const sx_lopoly *b, double cb);

/* G(q) = q.A q - c.q over the step: beyond the radius where it cannot vanish, or clear of zero as
 * sum_k mu_k (e_k.q)^2 - c.q with each combination's own range (a stiff tie's entries of A are
 * large and nearly cancel along the motion: the ranges of q1 and q2 alone would lose that) */
static int collapse_quiet(const sx_collapse *c, const sx_lopoly *q1, const sx_lopoly *q2, span s1, span s2)
{
    sx_lopoly p;
    span G = {0.0, 0.0};
    int k;
    if (!c->active) return 1;
    if (c->lam_min > 0.0) {
        const double d1 = s1.lo > 0 ? s1.lo : (s1.hi < 0 ? -s1.hi : 0.0), d2 = s2.lo > 0 ? s2.lo : (s2.hi < 0 ? -s2.hi : 0.0);
        if (sqrt(d1 * d1 + d2 * d2) * c->lam_min > 1.000001 * hypot(c->c[0], c->c[1])) return 1;
    }
    for (k = 0; k < 2; k++) {
        combine(&p, q1, c->e[k][0], q2, c->e[k][1]);
        G = sum(G, scaled(square_span(poly_span(&p)), c->mu[k]));
    }
    combine(&p, q1, -c->c[0], q2, -c->c[1]);
    G = sum(G, poly_span(&p));
    return clear_of_zero(G, collapse_tol(c, q1->coef[0], q2->coef[0]));
}

/* a cubic's range over [0, 1] from its Bernstein coefficients (sx_hermite_polys): its ends where
 * its control polygon is monotone, else also its values where its rate vanishes inside, widened by
 * its tail. The values' rounding is a few ulps of the coefficients, far inside the tail's margin
 * for the decomposition's rounding (SX_MODES_MARGIN). */
static span bern_span(const sx_lopoly *p)
{
    const double *b = p->coef, e0 = b[1] - b[0], e1 = b[2] - b[1], e2 = b[3] - b[2];
    span s = {min2(b[0], b[3]), max2(b[0], b[3])};
    if (!((e0 >= 0.0 && e1 >= 0.0 && e2 >= 0.0) || (e0 <= 0.0 && e1 <= 0.0 && e2 <= 0.0))) {
        /* the rate over 3 is e0 + 2 (e1 - e0) u + (e0 - 2 e1 + e2) u^2 */
        const double a = e0 - 2.0 * e1 + e2, c = 2.0 * (e1 - e0), disc = c * c - 4.0 * a * e0;
        double roots[2];
        int n = 0, k;
        if (a == 0.0) {
            if (c != 0.0) roots[n++] = -e0 / c;
        } else if (disc >= 0.0) {
            const double q = -0.5 * (c + copysign(sqrt(disc), c));
            roots[n++] = q / a;
            if (q != 0.0) roots[n++] = e0 / q;
        }
        for (k = 0; k < n; k++)
            if (roots[k] > 0.0 && roots[k] < 1.0) {
                const double v = sx_lopoly_at(p, roots[k]);
                s.lo = min2(s.lo, v), s.hi = max2(s.hi, v);
            }
    }
    s.lo -= p->tail, s.hi += p->tail;
    return s;
}

static span poly_span(const sx_lopoly *p)
{
    span s = {p->coef[0] - p->tail, p->coef[0] + p->tail};
    int k;
    if (p->bern) return bern_span(p);
    for (k = 1; k <= p->deg; k++) {
        if (p->coef[k] < 0.0) s.lo += p->coef[k];
        else s.hi += p->coef[k];
    }
    return s;
}

static int monotone(const sx_lopoly *p)
{
    span d = {p->coef[1] - p->dtail, p->coef[1] + p->dtail};
    int k;
    if (p->bern) { /* the rate's Bernstein coefficients, 3 (b_k+1 - b_k) */
        const double r0 = 3.0 * (p->coef[1] - p->coef[0]), r1 = 3.0 * (p->coef[2] - p->coef[1]),
                     r2 = 3.0 * (p->coef[3] - p->coef[2]);
        return min2(r0, min2(r1, r2)) > p->dtail || max2(r0, max2(r1, r2)) < -p->dtail;
    }
    for (k = 2; k <= p->deg; k++) {
        if (p->coef[k] < 0.0) d.lo += k * p->coef[k];
        else d.hi += k * p->coef[k];
    }
    return d.lo > 0.0 || d.hi < 0.0;
}

/* a bound on |p| over [0, 1] from its coefficients alone */
static double coef_bound(const sx_lopoly *p)
{
    if (p->bern) return max2(max2(fabs(p->coef[0]), fabs(p->coef[1])), max2(fabs(p->coef[2]), fabs(p->coef[3])));
    return sx_poly_abs_sum(p->coef, p->deg);
}

/* the bound on |p| over the step */
static double bound_of(const sx_lopoly *P)
{
    const span s = poly_span(P);
    return max2(fabs(s.lo), fabs(s.hi));
}

/* the bound on |p| over the step if a peak quantity p can rise over `peak` inside it, else 0 (the
 * coefficients' bound and the tail first: most steps stay under the peak by that) */
static double may_rise_to(const sx_lopoly *P, double peak)
{
    double bound;
    if (P->tail + coef_bound(P) <= peak) return 0.0;
    bound = bound_of(P);
    return bound > peak && !monotone(P) ? bound : 0.0;
}

static void combine(sx_lopoly *out, const sx_lopoly *a, double ca, const sx_lopoly *b, double cb)
{
    int k;
    out->deg = b && b->deg > a->deg ? b->deg : a->deg;
    out->bern = a->bern;
    for (k = 0; k <= out->deg; k++) out->coef[k] = ca * a->coef[k] + (b ? cb * b->coef[k] : 0.0);
    out->tail = fabs(ca) * a->tail + (b ? fabs(cb) * b->tail : 0.0);
    out->dtail = fabs(ca) * a->dtail + (b ? fabs(cb) * b->dtail : 0.0);
    out->start = ca * a->start + (b ? cb * b->start : 0.0);
}

/* storey i's functionals' polynomials (NULL: the storey has none) */
typedef struct {
    const sx_lopoly *q1, *q2, *deform, *acc, *rate;
} storey_polys;

/* the peaks at a state xa of the region: a cleared step's exact end (its start was the end of the
 * step before, or a state after an event, sx_handle_events). Not from the step's polynomial: the
 * modes' quiet test holds a fast mode's quasi-static value there (its band covers the rest), which
 * could raise a peak above anything the motion reached. */
void sx_watch_peaks_at(sx_run *R, const sx_region *r, const double xa[])
{
    rw_scene_result *res = R->res;
    int i;
    for (i = 0; i < R->sc.S.n_storeys; i++) {
        const int *f = r->f_of[i];
        if (f[SX_Q1] >= 0) {
            const double h2 = 0.5 * R->sc.S.wall[i].h, q1 = sx_functional(r, f[SX_Q1], xa);
            res->peak_s1[i] = max2(res->peak_s1[i], fabs(h2 * q1));
            res->peak_s2[i] = max2(res->peak_s2[i], fabs(h2 * (q1 + sx_functional(r, f[SX_Q2], xa))));
        }
        res->peak_diaphragm[i] = max2(res->peak_diaphragm[i], fabs(sx_functional(r, f[SX_DEFORM], xa)));
        res->peak_base_acc[i] = max2(res->peak_base_acc[i], fabs(sx_functional(r, f[SX_BASE_ACC], xa)));
    }
}

/* each functional's polynomial over a step from its table (rows and tail) */
static void low_polys(const sx_region *r, const sx_step *st, const double xa0[], sx_lopoly P[SX_MAX_F])
{
    double Xt[SX_MAX_N], tn = 0.0, coef[SX_MAX_F * (SX_LO + 1)];
    const double q = st->rho / (SX_LO + 2);
    int f, k;
    sx_matvec_cols(r->n, r->na, st->T, xa0, Xt);
    for (k = 0; k < r->n; k++) tn = max2(tn, fabs(Xt[k]) / r->scale[k]);
    sx_matvec_cols(r->nf * (SX_LO + 1), r->na, st->rows, xa0, coef);
    for (f = 0; f < r->nf; f++) {
        sx_lopoly *p = &P[f];
        for (k = 0; k <= SX_LO; k++) p->coef[k] = coef[f * (SX_LO + 1) + k];
        p->tail = r->f_scale[f] * tn / (1.0 - q);
        p->dtail = r->f_scale[f] * tn * ((SX_LO + 1) / (1.0 - q) + q / ((1.0 - q) * (1.0 - q)));
        p->start = p->coef[0]; /* (the Taylor row of degree 0 is the functional's own) */
        p->deg = SX_LO;
        p->bern = 0;
    }
}

/* the storeys' polynomials from the functionals' */
static void storey_view(const sx_run *R, const sx_region *r, const sx_lopoly P[SX_MAX_F],
                        storey_polys S[RW_SCENE_MAX_STOREYS])
{
    int i;
    for (i = 0; i < R->sc.S.n_storeys; i++) {
        const int *f = r->f_of[i];
        S[i].q1 = f[SX_Q1] >= 0 ? &P[f[SX_Q1]] : NULL;
        S[i].q2 = f[SX_Q2] >= 0 ? &P[f[SX_Q2]] : NULL;
        S[i].deform = f[SX_DEFORM] >= 0 ? &P[f[SX_DEFORM]] : NULL;
        S[i].acc = f[SX_BASE_ACC] >= 0 ? &P[f[SX_BASE_ACC]] : NULL;
        S[i].rate = f[SX_DEFORM_RATE] >= 0 ? &P[f[SX_DEFORM_RATE]] : NULL;
    }
}

/* An affine line z = c + t w (w a Bernstein cubic) that moves away from zero all over the step in
 * the direction it starts with has no root, though it starts within rounding of zero (an event has
 * just set it there) or its range over the step reaches over zero (a band). The direction it starts
 * with is its exact start's sign: the cubic's b[0] lacks a band's free motion, and a wall's base
 * whose fast mode had carried it across a side's line (z > 0 at the start, b[0] on the far side)
 * was taken past the line with no event (a grid of output rows that split the step found it). */
static int moves_away(const sx_line *L, const sx_lopoly *w, double tol)
{
    const double *b = w->coef, z0 = L->c + L->t * w->start;
    const double r0 = 3.0 * L->t * (b[1] - b[0]), r1 = 3.0 * L->t * (b[2] - b[1]), r2 = 3.0 * L->t * (b[3] - b[2]);
    const double lo = (r0 < r1 ? (r0 < r2 ? r0 : r2) : (r1 < r2 ? r1 : r2)) - fabs(L->t) * w->dtail;
    const double hi = (r0 > r1 ? (r0 > r2 ? r0 : r2) : (r1 > r2 ? r1 : r2)) + fabs(L->t) * w->dtail;
    const double start = fabs(z0) > tol ? z0 : r0; /* its start sign: its own, else its direction (rw_scene_exact_roots.c) */
    if (L->s != 0.0 || !w->bern) return 0;
    return start > 0.0 ? lo > 0.0 : (start < 0.0 && hi < 0.0);
}

/* the centre and half-width of a polynomial's range over the step: its Bernstein coefficients'
 * hull, or its coefficients' sum, widened by its tail */
void sx_watch_box(const sx_lopoly *p, double *centre, double *radius)
{
    span s;
    double lo, hi;
    if (p->bern) {
        sx_cubic_box(p->coef[0], p->coef[1], p->coef[2], p->coef[3], p->tail, centre, radius);
        return;
    }
    s = poly_span(p);
    lo = s.lo + p->tail, hi = s.hi - p->tail;
    *centre = 0.5 * (lo + hi);
    *radius = 0.5 * (hi - lo) + p->tail;
}

/* the lines of a wall the box of q1's and q2's ranges (centres c, half-widths r) does not clear at
 * once: z = c + s|w| + t w moves by at most (s + |t|) |dw|, so a line whose value at the box's centre
 * is farther from zero than that over the box's half-width is clear (a few operations, and it clears
 * most lines: a wall at rest or rocking away from them). Every line in one loop without a branch,
 * which the compiler vectorises; bit k for line k. */
#if defined(__GNUC__) && defined(__x86_64__) && defined(__linux__)
__attribute__((target_clones("avx2", "default"))) /* (four lines to a register where it can: no FMA, the same bits) */
#endif
unsigned sx_watch_box_lines(const sx_run *R, int i, double c1, double r1, double c2, double r2, double Q1, double Q2)
{
    const sx_line_set *restrict L = &R->line_set[i];
    const int blocks = (R->nlines[i] + 3) / 4; /* (the lines past the last never fire: sx_line_set) */
    double margin[SX_LINE_SLOTS];
    unsigned bits = 0;
    int b, j;
    for (b = 0; b < blocks; b++)
        for (j = 4 * b; j < 4 * b + 4; j++) { /* (no branch: vectorised) */
            const double wc = L->a0[j] * c1 + L->a1[j] * c2, wr = L->abs_a0[j] * r1 + L->abs_a1[j] * r2;
            const double zc = L->c[j] + L->s[j] * fabs(wc) + L->t[j] * wc;
            const double tol = SX_TOL * (L->abs_c[j] + L->abs_a0[j] * Q1 + L->abs_a1[j] * Q2) + DBL_MIN;
            margin[j] = fabs(zc) - (L->slope[j] * wr + 2.0 * tol);
        }
    for (j = 0; j < 4 * blocks; j++) bits |= (unsigned)!(margin[j] > 0.0) << j;
    return bits;
}

/* Does a standing wall's line take opposite signs at a step's two exact ends, each farther from zero
 * than 1e-9 of the line's terms (rounding is 1e-16 of them)? Then no quiet test can clear the step:
 * the polynomials' ranges hold the ends' values, so the line's range over them spans zero. A piece
 * whose parent failed the test mostly holds the crossing that failed it, and this says so in a few
 * operations a line where the test takes thousands (rw_scene_exact_steps.c). */
int sx_watch_sure_cross(const sx_run *R, const sx_region *r, const double xa0[], const double xa1[])
{
    int i, k;
    for (i = 0; i < R->sc.S.n_storeys; i++) {
        const sx_line_set *L = &R->line_set[i];
        const int f1 = r->f_of[i][SX_Q1], f2 = r->f_of[i][SX_Q2];
        double p0, p1, q0, q1, P, Q;
        if (f1 < 0 || R->nlines[i] == 0) continue;
        p0 = sx_functional(r, f1, xa0), p1 = sx_functional(r, f1, xa1);
        q0 = sx_functional(r, f2, xa0), q1 = sx_functional(r, f2, xa1);
        P = fabs(p0) + fabs(p1), Q = fabs(q0) + fabs(q1);
        for (k = 0; k < R->nlines[i]; k++) {
            const double w0 = L->a0[k] * p0 + L->a1[k] * q0, w1 = L->a0[k] * p1 + L->a1[k] * q1;
            const double z0 = L->c[k] + L->s[k] * fabs(w0) + L->t[k] * w0;
            const double z1 = L->c[k] + L->s[k] * fabs(w1) + L->t[k] * w1;
            const double m = 1e-9 * (L->abs_c[k] + L->slope[k] * (L->abs_a0[k] * P + L->abs_a1[k] * Q));
            if ((z0 > m && z1 < -m) || (z0 < -m && z1 > m)) return 1;
        }
    }
    return 0;
}

/* a line the first pass did not clear: on the box's exact range, then on its own combination of the
 * two polynomials, whose range is tighter where q1 and q2 move together */
static int line_clear(const sx_line *L, const storey_polys *P, double c1, double r1, double c2, double r2)
{
    const double tol = line_tol(L, P->q1->coef[0], P->q2->coef[0]);
    const double wc = L->a0 * c1 + L->a1 * c2, wr = fabs(L->a0) * r1 + fabs(L->a1) * r2;
    sx_lopoly w;
    if (clear_of_zero(line_span(L, (span){wc - wr, wc + wr}), tol)) return 1;
    combine(&w, P->q1, L->a0, P->q2, L->a1);
    return clear_of_zero(line_span(L, poly_span(&w)), tol) || moves_away(L, &w, tol);
}

/* storey i's wall over the step: the lines it may cross (bits by line) and, as bit SX_COLLAPSE_BIT,
 * the collapse indicator; every one (all) or up to the first (else). A line is cleared first on the
 * box of q1's and q2's ranges (sx_watch_box_lines: a few operations, and it clears most lines),
 * then on the box's exact range; only a line neither clears is tested on its own combination of
 * the two polynomials, whose range is tighter where q1 and q2 move together. */
static unsigned wall_suspects(const sx_run *R, const sx_region *r, int i, const storey_polys *P, int all)
{
    double c1, r1, c2, r2;
    unsigned bits = 0, box;
    int k;
    sx_watch_box(P->q1, &c1, &r1);
    sx_watch_box(P->q2, &c2, &r2);
    box = sx_watch_box_lines(R, i, c1, r1, c2, r2, fabs(P->q1->coef[0]), fabs(P->q2->coef[0]));
    for (k = 0; box; k++, box >>= 1)
        if ((box & 1u) && !line_clear(&R->lines[i][k], P, c1, r1, c2, r2)) {
            bits |= 1u << k;
            if (!all) return bits;
        }
    if (!collapse_quiet(&r->col[i], P->q1, P->q2, (span){c1 - r1, c1 + r1}, (span){c2 - r2, c2 + r2}))
        bits |= SX_COLLAPSE_BIT;
    return bits;
}

/* a bilinear diaphragm's indicators over the step: the ones that may change sign (bits) */
static unsigned diaphragm_suspects(const sx_run *R, int i, const storey_polys *P)
{
    unsigned bits = 0;
    int k;
    for (k = 0; k < R->ndlines[i]; k++) {
        const sx_dline *L = &R->dlines[i][k];
        const sx_lopoly *v = L->kind == SX_DEFORM ? P->deform : P->rate;
        const span z = scaled(poly_span(v), L->a);
        const double tol = SX_TOL * (fabs(L->c) + fabs(L->a * v->coef[0])) + DBL_MIN;
        if (!clear_of_zero((span){L->c + z.lo, L->c + z.hi}, tol)) bits |= 1u << k;
    }
    return bits;
}

/* storey i's peak quantity `kind` over the step (0: the storey has none) */
static int quantity(const sx_run *R, int i, const storey_polys *s, int kind, sx_lopoly *out)
{
    const double h2 = 0.5 * R->sc.S.wall[i].h;
    switch (kind) {
    case SX_PEAK_S1: return s->q1 ? (combine(out, s->q1, h2, NULL, 0.0), 1) : 0;
    case SX_PEAK_S2: return s->q1 ? (combine(out, s->q1, h2, s->q2, h2), 1) : 0;
    case SX_PEAK_DEFORM: return s->deform ? (*out = *s->deform, 1) : 0;
    default: return s->acc ? (*out = *s->acc, 1) : 0;
    }
}

/* a bound on |ca a + cb b| over the step from the coefficients and tails alone (b NULL: ca a) */
static double coarse_bound(const sx_lopoly *a, double ca, const sx_lopoly *b, double cb)
{
    double m = 0.0;
    int k;
    if (a->bern) {
        for (k = 0; k < 4; k++) {
            const double v = fabs(ca * a->coef[k] + (b ? cb * b->coef[k] : 0.0));
            m = v > m || v != v ? v : m;
        }
    } else {
        for (k = 0; k <= a->deg; k++) m += fabs(ca * a->coef[k] + (b ? cb * b->coef[k] : 0.0));
    }
    return m + fabs(ca) * a->tail + (b ? fabs(cb) * b->tail : 0.0);
}

/* that bound for storey i's peak quantity `kind` (0: the storey has none) */
static double coarse_quantity(const sx_run *R, int i, const storey_polys *s, int kind)
{
    const double h2 = 0.5 * R->sc.S.wall[i].h;
    switch (kind) {
    case SX_PEAK_S1: return s->q1 ? coarse_bound(s->q1, h2, NULL, 0.0) : 0.0;
    case SX_PEAK_S2: return s->q1 ? coarse_bound(s->q1, h2, s->q2, h2) : 0.0;
    case SX_PEAK_DEFORM: return s->deform ? coarse_bound(s->deform, 1.0, NULL, 0.0) : 0.0;
    default: return s->acc ? coarse_bound(s->acc, 1.0, NULL, 0.0) : 0.0;
    }
}

/* the step's peaks that may rise inside it are kept as doubts (1: one could not be); a quantity
 * whose coarse bound is under its peak (most, once a record's peaks have been reached) first */
static int doubt_peaks(sx_run *R, const storey_polys S[], double h, const double xa0[], unsigned storeys)
{
    int i, kind;
    for (i = 0; i < R->sc.S.n_storeys; i++) {
        if (!(storeys >> i & 1u)) continue;
        for (kind = 0; kind < SX_PEAK_KINDS; kind++) {
            const double peak = *sx_peak_of(R->res, i, kind);
            sx_lopoly p;
            double bound;
            if (coarse_quantity(R, i, &S[i], kind) <= peak || !quantity(R, i, &S[i], kind, &p)) continue;
            bound = may_rise_to(&p, peak);
            if (bound > 0.0 && sx_doubt_peak(R, i, kind, bound, h, xa0)) return 1;
        }
    }
    return 0;
}

double sx_watch_peak_bound(sx_run *R, const sx_region *r, double h, const double xa0[], const double xa1[], int storey,
                           int kind)
{
    sx_lopoly P[SX_MAX_F], p;
    storey_polys S[RW_SCENE_MAX_STOREYS];
    sx_hermite_step hs;
    if (!r->modes.valid) return INFINITY;
    sx_hermite_step_of(r, h, &hs);
    sx_hermite_polys(r, &hs, xa0, xa1, P);
    storey_view(R, r, P, S);
    return quantity(R, storey, &S[storey], kind, &p) ? may_rise_to(&p, *sx_peak_of(R->res, storey, kind)) : 0.0;
}

/* the crossings first: a peak that may rise costs a doubt, not a halving */
int sx_watch_quiet_polys(sx_run *R, const sx_region *r, sx_lopoly P[SX_MAX_F], double h, const double xa0[],
                         unsigned storeys)
{
    storey_polys S[RW_SCENE_MAX_STOREYS];
    int i;
    storey_view(R, r, P, S);
    for (i = 0; i < R->sc.S.n_storeys; i++)
        if ((storeys >> i & 1u) && ((S[i].q1 && wall_suspects(R, r, i, &S[i], 0)) || diaphragm_suspects(R, i, &S[i])))
            return SX_MAY_CROSS;
    return doubt_peaks(R, S, h, xa0, storeys) ? SX_MAY_PEAK : 0;
}

int sx_watch_suspects(sx_run *R, const sx_region *r, sx_lopoly P[SX_MAX_F], sx_suspects *sus)
{
    storey_polys S[RW_SCENE_MAX_STOREYS];
    int i, kind, any = 0;
    storey_view(R, r, P, S);
    for (i = 0; i < R->sc.S.n_storeys; i++) {
        sus->wall[i] = S[i].q1 ? wall_suspects(R, r, i, &S[i], 1) : 0;
        sus->diaphragm[i] = diaphragm_suspects(R, i, &S[i]);
        sus->peaks[i] = 0;
        for (kind = 0; kind < SX_PEAK_KINDS; kind++) {
            const double peak = *sx_peak_of(R->res, i, kind);
            sx_lopoly p;
            /* (a monotone one too: a piece's end is not watched where its series is) */
            if (coarse_quantity(R, i, &S[i], kind) > peak && quantity(R, i, &S[i], kind, &p) && bound_of(&p) > peak)
                sus->peaks[i] |= 1u << kind;
        }
        any |= sus->wall[i] || sus->diaphragm[i] || sus->peaks[i];
    }
    return any;
}

int sx_watch_quiet(sx_run *R, const sx_region *r, const sx_step *st, const double xa0[], double xa1[])
{
    sx_lopoly P[SX_MAX_F];
    if (r->modes.valid) { /* the ends first: the polynomials are their interpolants */
        sx_step_propagate(r, st, xa0, xa1);
        return !sx_watch_sure_cross(R, r, xa0, xa1) && sx_quiet_ends(R, r, &st->herm, xa0, xa1) == 0;
    }
    low_polys(r, st, xa0, P);
    if (sx_watch_quiet_polys(R, r, P, st->h, xa0, SX_ALL_STOREYS) != 0) return 0;
    sx_step_propagate(r, st, xa0, xa1);
    sx_watch_peaks_at(R, r, xa1);
    return 1;
}
