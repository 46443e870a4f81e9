/* The quiet test of a step from its exact ends, and its first pass: the common case between events,
 * in few operations. Every
 * functional's polynomial comes in one pass over the modes (the cubic Hermite interpolant of the
 * step's exact ends, rw_scene_exact_hermite.c, as arrays over the functionals, which the compiler
 * vectorises); each standing wall's lines are tested at once on the box of its rotations' ranges, and
 * each peak quantity is held against its peak by the bound its polynomial's coefficients give. A
 * step that passes is quiet, and its end's peaks are taken from the values the pass computed. One
 * that does not (a line or a peak near, a collapse indicator in play, a bilinear diaphragm's
 * indicators) is given the full test (sx_watch_quiet_polys), which clears everything this pass does. */
#include "rw_scene_exact_internal.h"

#include <float.h>
#include <math.h>
#include <string.h>

/* every functional's polynomial over the step: its Bernstein coefficients b[0..3] (a band's free
 * motion taken out), its tails, and its exact value at the end */
typedef struct {
    double b[4][SX_MAX_F + 1], tail[SX_MAX_F + 1], dtail[SX_MAX_F + 1], end[SX_MAX_F];
} quick_polys;

static sx_v2 load2(const double *p)
{
    sx_v2 v;
    memcpy(&v, p, sizeof v);
    return v;
}

static void store2(double *p, sx_v2 v) { memcpy(p, &v, sizeof v); }

/* the modes' tails and bands over the functionals two at a time (the share arrays hold zeros past the
 * last functional, and the polynomials' arrays room for them) */
static void modes_over(const sx_modes *m, const sx_mode_bounds *B, int nf, quick_polys *Q, double *d0, double *d1,
                       double *size)
{
    int f, k;
    for (k = 0; k < m->count; k++) {
        const sx_mode_bound *mb = &B->mode[k];
        const double mode_size = sx_mode_size(B, k);
        const sx_v2 err = {mb->err, mb->err}, derr = {mb->derr, mb->derr}, msize = {mode_size, mode_size};
        for (f = 0; f < nf; f += 2) {
            const sx_v2 a = load2(m->share_abs[k] + f);
            store2(Q->tail + f, load2(Q->tail + f) + a * err);
            store2(Q->dtail + f, load2(Q->dtail + f) + a * derr);
            store2(size + f, load2(size + f) + a * msize);
        }
        if (!mb->band || B->modal) continue;
        for (f = 0; f < nf; f += 2) { /* Re(a w) in real arithmetic */
            const sx_v2 ar = load2(m->share_re[k] + f), ai = load2(m->share_im[k] + f);
            store2(Q->b[0] + f, load2(Q->b[0] + f) - (ar * mb->re[0] - ai * mb->im[0]));
            store2(Q->b[3] + f, load2(Q->b[3] + f) - (ar * mb->re[1] - ai * mb->im[1]));
            store2(d0 + f, load2(d0 + f) - (ar * mb->re[2] - ai * mb->im[2]));
            store2(d1 + f, load2(d1 + f) - (ar * mb->re[3] - ai * mb->im[3]));
        }
    }
}

static void polys_of(const sx_region *r, const sx_mode_bounds *B, const double xa0[], const double xa1[], quick_polys *Q)
{
    const sx_modes *m = &r->modes;
    const int nf = r->nf;
    const double h = B->h, margin = SX_MODES_MARGIN(m->cond);
    double d0[SX_MAX_F + 1], d1[SX_MAX_F + 1], size[SX_MAX_F + 1];
    int f;
    for (f = 0; f < nf; f++) {
        Q->b[0][f] = sx_functional(r, f, xa0);
        Q->end[f] = Q->b[3][f] = sx_functional(r, f, xa1);
        d0[f] = h * sx_functional_rate(r, f, xa0);
        d1[f] = h * sx_functional_rate(r, f, xa1);
        Q->tail[f] = Q->dtail[f] = size[f] = 0.0;
    }
    if (B->modal) sx_ends_modal(r, B, xa0, xa1, Q->b[0], Q->b[3], d0, d1);
    Q->b[0][nf] = Q->b[3][nf] = d0[nf] = d1[nf] = Q->tail[nf] = Q->dtail[nf] = size[nf] = 0.0; /* (an odd count's pair) */
    modes_over(m, B, nf, Q, d0, d1, size);
    for (f = 0; f < nf; f++) {
        const double round =
            margin * (fabs(Q->b[0][f]) + fabs(Q->b[3][f]) + fabs(d0[f]) + fabs(d1[f]) + size[f]) + DBL_MIN;
        Q->b[1][f] = Q->b[0][f] + d0[f] * (1.0 / 3.0);
        Q->b[2][f] = Q->b[3][f] - d1[f] * (1.0 / 3.0);
        Q->tail[f] += round, Q->dtail[f] += round;
    }
}

/* the same as the full test's polynomials (sx_lopoly) */
static void lopolys_of(const sx_region *r, const quick_polys *Q, sx_lopoly P[SX_MAX_F])
{
    int f, k;
    for (f = 0; f < r->nf; f++) {
        for (k = 0; k < 4; k++) P[f].coef[k] = Q->b[k][f];
        P[f].tail = Q->tail[f], P[f].dtail = Q->dtail[f], P[f].deg = 3, P[f].bern = 1;
    }
}

/* the largest |b_k[f] + b_k[g]| (g < 0: |b_k[f]|) over the coefficients */
static double coef_max(const quick_polys *Q, int f, int g)
{
    double m = 0.0;
    int k;
    for (k = 0; k < 4; k++) {
        const double v = fabs(Q->b[k][f] + (g >= 0 ? Q->b[k][g] : 0.0));
        m = v > m || v != v ? v : m;
    }
    return m;
}

/* functional f's range over the step as the centre and half-width of its coefficients' hull, widened
 * by its tail (a NaN leaves them NaN: nothing is clear of it) */
static void box_of(const quick_polys *Q, int f, double *centre, double *radius)
{
    const double b0 = Q->b[0][f], b1 = Q->b[1][f], b2 = Q->b[2][f], b3 = Q->b[3][f];
    const double lo01 = b0 < b1 ? b0 : b1, lo23 = b2 < b3 ? b2 : b3, hi01 = b0 > b1 ? b0 : b1, hi23 = b2 > b3 ? b2 : b3;
    const double lo = lo01 < lo23 ? lo01 : lo23, hi = hi01 > hi23 ? hi01 : hi23;
    *centre = 0.5 * (lo + hi);
    *radius = lo == lo && hi == hi ? 0.5 * (hi - lo) + Q->tail[f] : NAN;
}

/* a collapse indicator G(q) = q.A q - c.q whose region's A has a positive definite symmetric part
 * cannot vanish beyond the radius |c| / lam_min: clear where the box of the rotations is beyond it */
static int collapse_far(const sx_collapse *c, double c1, double r1, double c2, double r2)
{
    const double d1 = fabs(c1) - r1 > 0.0 ? fabs(c1) - r1 : 0.0, d2 = fabs(c2) - r2 > 0.0 ? fabs(c2) - r2 : 0.0;
    return c->lam_min > 0.0 && sqrt(d1 * d1 + d2 * d2) * c->lam_min > 1.000001 * hypot(c->c[0], c->c[1]);
}

/* storey i's wall: no line within reach of its box, no collapse indicator in play, s1 and s2 under
 * their peaks */
static int wall_clear(const sx_run *R, const sx_region *r, const quick_polys *Q, int i)
{
    const int f1 = r->f_of[i][SX_Q1], f2 = r->f_of[i][SX_Q2];
    const double h2 = 0.5 * R->sc.S.wall[i].h;
    double c1, r1, c2, r2;
    box_of(Q, f1, &c1, &r1);
    box_of(Q, f2, &c2, &r2);
    if (r->col[i].active && !collapse_far(&r->col[i], c1, r1, c2, r2)) return 0;
    if (sx_watch_box_lines(R, i, c1, r1, c2, r2, fabs(Q->b[0][f1]), fabs(Q->b[0][f2]))) return 0;
    return h2 * (coef_max(Q, f1, -1) + Q->tail[f1]) <= R->res->peak_s1[i] &&
           h2 * (coef_max(Q, f1, f2) + Q->tail[f1] + Q->tail[f2]) <= R->res->peak_s2[i];
}

/* can peak quantity f not rise over peak inside the step? (a quantity of the record alone is linear
 * over it: its ends hold its peak) */
static int under(const sx_region *r, const quick_polys *Q, int f, double peak)
{
    return r->modes.share_max[f] == 0.0 || coef_max(Q, f, -1) + Q->tail[f] <= peak;
}

/* the end's peaks, as sx_watch_peaks_at takes them, from the values the pass computed */
static void end_peaks(sx_run *R, const sx_region *r, const quick_polys *Q)
{
    rw_scene_result *res = R->res;
    int i;
    for (i = 0; i < R->sc.S.n_storeys; i++) {
        const int *f = r->f_of[i];
        if (f[SX_Q1] >= 0) {
            const double h2 = 0.5 * R->sc.S.wall[i].h, q1 = Q->end[f[SX_Q1]], q2 = Q->end[f[SX_Q2]];
            if (fabs(h2 * q1) > res->peak_s1[i]) res->peak_s1[i] = fabs(h2 * q1);
            if (fabs(h2 * (q1 + q2)) > res->peak_s2[i]) res->peak_s2[i] = fabs(h2 * (q1 + q2));
        }
        if (fabs(Q->end[f[SX_DEFORM]]) > res->peak_diaphragm[i]) res->peak_diaphragm[i] = fabs(Q->end[f[SX_DEFORM]]);
        if (fabs(Q->end[f[SX_BASE_ACC]]) > res->peak_base_acc[i]) res->peak_base_acc[i] = fabs(Q->end[f[SX_BASE_ACC]]);
    }
}

/* the first pass over every storey: 1 quiet, 0 the full test must say */
static int first_pass(sx_run *R, const sx_region *r, const quick_polys *Q)
{
    const rw_scene_result *res = R->res;
    int i;
    for (i = 0; i < R->sc.S.n_storeys; i++) {
        const int *f = r->f_of[i];
        if (R->ndlines[i]) return 0;
        if (f[SX_Q1] >= 0 && !wall_clear(R, r, Q, i)) return 0;
        if (!under(r, Q, f[SX_DEFORM], res->peak_diaphragm[i]) || !under(r, Q, f[SX_BASE_ACC], res->peak_base_acc[i]))
            return 0;
    }
    return 1;
}

int sx_quiet_ends(sx_run *R, const sx_region *r, const sx_hermite_step *hs, const double xa0[], const double xa1[])
{
    sx_mode_bounds B;
    quick_polys Q;
    sx_lopoly P[SX_MAX_F];
    int why;
    sx_mode_bounds_of(r, hs, xa0, &B);
    polys_of(r, &B, xa0, xa1, &Q);
    if (first_pass(R, r, &Q)) {
        end_peaks(R, r, &Q);
        return 0;
    }
    lopolys_of(r, &Q, P);
    if ((why = sx_watch_quiet_polys(R, r, P, hs->h, xa0)) == 0) end_peaks(R, r, &Q);
    return why;
}
